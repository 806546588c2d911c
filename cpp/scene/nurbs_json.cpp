#include "scene/nurbs_json.hpp"

#include <cmath>
#include <memory>
#include <vector>

#include "common/limits.hpp"
#include "expr/spline.hpp"

namespace pdesurf {

static_assert(limits::kNurbsDegree < SplineFn::kMaxBasis, "a scene's B-spline degree must fit the evaluator's basis");

using namespace scene_json;

namespace {

double finite(const json& j, const std::string& path) {
  if (!j.is_number()) fail(ErrorCode::InvalidField, path, "expected a number");
  const double x = j.get<double>();
  if (!std::isfinite(x)) fail(ErrorCode::NonFinite, path, "not a finite number");
  return x;
}

std::vector<double> numbers(const json& j, const std::string& path, size_t maxCount) {
  if (!j.is_array()) fail(ErrorCode::InvalidField, path, "expected an array of numbers");
  if (j.size() > maxCount) fail(ErrorCode::TooLarge, path, "more than " + std::to_string(maxCount) + " numbers");
  std::vector<double> out;
  for (size_t k = 0; k < j.size(); ++k) out.push_back(finite(j[k], path + "[" + std::to_string(k) + "]"));
  return out;
}

std::shared_ptr<const SplineFn> make(int degree, const std::vector<double>& knots, std::vector<double> coefs) {
  return std::make_shared<const SplineFn>(degree, knots, std::move(coefs));
}

}  // namespace

std::array<Expr, 3> parseNurbs(const json& j, const std::string& outer, NurbsDomain* domain) {
  const std::string path = outer + ".nurbs";
  if (!j.is_object()) fail(ErrorCode::InvalidField, path, "expected an object {degree, knots, points, weights}");
  allowOnly(j, path, {"degree", "knots", "points", "weights"});
  const json& dj = require(j, "degree", path);
  if (!dj.is_array() || dj.size() != 2) fail(ErrorCode::InvalidField, path + ".degree", "expected [degree in t, degree in v]");
  const int p = integerField(dj[0], path + ".degree[0]", 1, limits::kNurbsDegree);
  const int q = integerField(dj[1], path + ".degree[1]", 1, limits::kNurbsDegree);

  // The points first: their counts are bounded before anything is allocated for them.
  const json& pj = require(j, "points", path);
  const std::string pp = path + ".points";
  if (!pj.is_array() || pj.empty() || !pj[0].is_array()) fail(ErrorCode::InvalidField, pp, "expected rows (along t) of [x, y, z] points");
  const size_t nt = pj.size(), nv = pj[0].size();
  if (nt > limits::kNurbsPoints || nv > limits::kNurbsPoints || nt * nv > limits::kNurbsPoints)
    fail(ErrorCode::TooLarge, pp, std::to_string(nt) + " × " + std::to_string(nv) + " control points: at most " + std::to_string(limits::kNurbsPoints));
  std::vector<std::array<double, 3>> P(nt * nv);
  for (size_t i = 0; i < nt; ++i) {
    const std::string rp = pp + "[" + std::to_string(i) + "]";
    if (!pj[i].is_array() || pj[i].size() != nv)
      fail(ErrorCode::InvalidField, rp, "expected a row of " + std::to_string(nv) + " points, as the first row");
    for (size_t k = 0; k < nv; ++k) {
      const std::string kp = rp + "[" + std::to_string(k) + "]";
      const json& x = pj[i][k];
      if (!x.is_array() || x.size() != 3) fail(ErrorCode::InvalidField, kp, "expected [x, y, z]");
      for (int c = 0; c < 3; ++c) P[i * nv + k][size_t(c)] = finite(x[size_t(c)], kp + "[" + std::to_string(c) + "]");
    }
  }
  std::vector<double> W(nt * nv, 1.0);
  bool rational = false;
  if (j.contains("weights")) {
    const json& wj = j["weights"];
    const std::string wp = path + ".weights";
    if (!wj.is_array() || wj.size() != nt) fail(ErrorCode::InvalidField, wp, "expected " + std::to_string(nt) + " rows, one per row of points");
    for (size_t i = 0; i < nt; ++i) {
      const std::string rp = wp + "[" + std::to_string(i) + "]";
      const std::vector<double> row = numbers(wj[i], rp, nv);
      if (row.size() != nv) fail(ErrorCode::InvalidField, rp, "expected " + std::to_string(nv) + " weights, one per point");
      for (size_t k = 0; k < nv; ++k) {
        if (!(row[k] > 0)) fail(ErrorCode::InvalidField, rp + "[" + std::to_string(k) + "]", "a weight must be positive");
        W[i * nv + k] = row[k];
        rational = rational || row[k] != W[0];
      }
    }
  }

  const json& kj = require(j, "knots", path);
  if (!kj.is_array() || kj.size() != 2) fail(ErrorCode::InvalidField, path + ".knots", "expected [knots in t, knots in v]");
  std::array<std::vector<double>, 2> knots;
  const int degree[2] = {p, q};
  const size_t count[2] = {nt, nv};
  for (int d = 0; d < 2; ++d) {
    const std::string kp = path + ".knots[" + std::to_string(d) + "]";
    knots[size_t(d)] = numbers(kj[size_t(d)], kp, limits::kNurbsPoints + limits::kNurbsDegree + 1);
    const std::string why = SplineFn::problem(degree[d], knots[size_t(d)], std::vector<double>(count[d], 0.0));
    if (!why.empty()) fail(ErrorCode::InvalidField, kp, why);
  }
  domain->t0 = knots[0][size_t(p)], domain->t1 = knots[0][nt];
  domain->v0 = knots[1][size_t(q)], domain->v1 = knots[1][nv];

  // Sum over the direction with fewer rows: one basis function there, one curve per coordinate
  // (and the weights' curve) along the other.
  const bool overT = nt <= nv;
  const size_t outer_n = overT ? nt : nv, inner_n = overT ? nv : nt;
  const int outerDeg = overT ? p : q, innerDeg = overT ? q : p;
  const std::vector<double>& outerKnots = knots[overT ? 0 : 1];
  const std::vector<double>& innerKnots = knots[overT ? 1 : 0];
  const size_t work = outer_n * (size_t(outerDeg + 1) * size_t(outerDeg + 1) + (rational ? 4 : 3) * size_t(innerDeg + 1) * size_t(innerDeg + 1));
  if (work > limits::kNurbsEvaluation)
    fail(ErrorCode::TooLarge, path, "one evaluation would take " + std::to_string(work) + " de Boor steps (" + std::to_string(outer_n) +
                                        " rows of degree " + std::to_string(outerDeg) + " by " + std::to_string(innerDeg) + "): at most " +
                                        std::to_string(limits::kNurbsEvaluation) + "; fewer rows or a lower degree");
  const Expr outerVar = variable(overT ? ExprVar::U : ExprVar::V), innerVar = variable(overT ? ExprVar::V : ExprVar::U);
  std::array<Expr, 3> num = {constant(0.0), constant(0.0), constant(0.0)};
  Expr den = constant(0.0);
  for (size_t a = 0; a < outer_n; ++a) {
    std::vector<double> unit(outer_n, 0.0);
    unit[a] = 1.0;
    const Expr basis = spline(make(outerDeg, outerKnots, unit), outerVar);
    auto at = [&](size_t b) { return overT ? a * nv + b : b * nv + a; };
    for (int c = 0; c < 3; ++c) {
      std::vector<double> coefs(inner_n);
      for (size_t b = 0; b < inner_n; ++b) coefs[b] = W[at(b)] * P[at(b)][size_t(c)];
      num[size_t(c)] = add(num[size_t(c)], multiply(basis, spline(make(innerDeg, innerKnots, coefs), innerVar)));
    }
    if (rational) {
      std::vector<double> coefs(inner_n);
      for (size_t b = 0; b < inner_n; ++b) coefs[b] = W[at(b)];
      den = add(den, multiply(basis, spline(make(innerDeg, innerKnots, coefs), innerVar)));
    }
  }
  // Equal weights cancel: the surface is polynomial, its points divided by their common weight.
  std::array<Expr, 3> out;
  for (int c = 0; c < 3; ++c) out[size_t(c)] = rational ? divide(num[size_t(c)], den) : divide(num[size_t(c)], constant(W[0]));
  return out;
}

}  // namespace pdesurf
