#include "scene/derived_ends.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <sstream>

#include "common/limits.hpp"
#include "expr/budget.hpp"
#include "expr/program.hpp"
#include "scene/expression_fields.hpp"

namespace pdesurf {

namespace {

constexpr int kSamples = 129;  // along the trimline, for the checks and the power's scale

using Vec3Expr = std::array<Expr, 3>;

std::string num(double x) {
  std::ostringstream s;
  s.precision(6);
  s << x;
  return s.str();
}

[[noreturn]] void fail(ErrorCode code, const std::string& path, const std::string& why) { throw Error(code, path + ": " + why); }

// Values of expressions in v at the kSamples points of [v0, v1]: one flat program, each
// distinct node evaluated once over all samples. values[r][k] for root r at sample k.
struct Sampled {
  std::vector<double> v;
  std::vector<std::vector<double>> values;
  Eigen::Vector3d at3(size_t r, int k) const { return {values[r][k], values[r + 1][k], values[r + 2][k]}; }
};

Sampled sample(const std::vector<Expr>& roots, double v0, double v1) {
  Sampled s;
  for (int k = 0; k < kSamples; ++k) s.v.push_back(v0 + (v1 - v0) * k / (kSamples - 1));
  s.values.assign(roots.size(), std::vector<double>(kSamples));
  std::vector<double*> outs;
  for (auto& r : s.values) outs.push_back(r.data());
  ExprProgram(roots).runAll(s.v.data(), nullptr, kSamples, outs.data());
  return s;
}

Vec3Expr map3(const Vec3Expr& e, Expr (*f)(const Expr&, ExprVar)) {
  return {f(e[0], ExprVar::U), f(e[1], ExprVar::U), f(e[2], ExprVar::U)};
}

Vec3Expr onTrimline(const Vec3Expr& e, const Expr& tau) {
  return {substitute(e[0], ExprVar::U, tau), substitute(e[1], ExprVar::U, tau), substitute(e[2], ExprVar::U, tau)};
}

Vec3Expr dv(const Vec3Expr& e) { return {derivative(e[0], ExprVar::V), derivative(e[1], ExprVar::V), derivative(e[2], ExprVar::V)}; }

// One referenced end: the surface's position and t-derivatives on its trimline, in v.
struct DerivedEnd {
  Patch* surface = nullptr;
  size_t surfaceIndex = 0;
  Expr tau;
  Vec3Expr P, T, C;
  double meanT = 0.0;  // mean |S_t| along the trimline
};

DerivedEnd resolve(Scene& scene, const Patch& blend, const EndReference& ref) {
  DerivedEnd d;
  for (size_t i = 0; i < scene.patches.size(); ++i)
    if (scene.patches[i].name == ref.surface) d.surface = &scene.patches[i], d.surfaceIndex = i;
  if (!d.surface) fail(ErrorCode::UnknownName, ref.path + ".surface", "no patch named '" + ref.surface + "'");
  const Patch& s = *d.surface;
  if (s.kind != PatchKind::Primary || !s.primary.full[0] || !s.primary.full[1] || !s.primary.full[2])
    fail(ErrorCode::InvalidField, ref.path + ".surface",
         "'" + ref.surface + "' is a " + s.kindName + " patch; an end refers to a \"surface\" patch (expressions in t and v)");
  if (s.primary.trimmed)
    fail(ErrorCode::InvalidField, ref.path + ".surface", "'" + ref.surface + "' is already trimmed along a curve by another end");
  const PrimarySurface& S = s.primary;
  d.tau = ref.curve ? ref.tau : constant(ref.atT1 ? S.t1 : S.t0);
  // Built under the scene's budget (deriveEnds); S_tt only where curvature is asked.
  const bool curvature = ref.continuity == Continuity::Curvature;
  const Vec3Expr St = map3(S.full, derivative);
  d.P = onTrimline(S.full, d.tau);
  d.T = onTrimline(St, d.tau);
  if (curvature) d.C = onTrimline(map3(St, derivative), d.tau);

  // The checks, along the blend's v-range.
  const double bv0 = blend.pde.v0, bv1 = blend.pde.v1;
  const double vtol = 1e-9 * std::max(1.0, std::abs(S.v1 - S.v0));
  if (std::min(bv0, bv1) < std::min(S.v0, S.v1) - vtol || std::max(bv0, bv1) > std::max(S.v0, S.v1) + vtol)
    fail(ErrorCode::InvalidField, ref.path + ".surface",
         "the blend's v_range [" + num(bv0) + ", " + num(bv1) + "] is not inside the v_range [" + num(S.v0) + ", " + num(S.v1) + "] of '" + ref.surface + "'");
  const Vec3Expr dP = dv(d.P);
  const double ttol = 1e-9 * std::max(1.0, std::abs(S.t1 - S.t0));
  // Roots: tau 0, power 1, P 2-4, S_t 5-7, dP/dv 8-10, S_tt 11-13 (curvature only).
  std::vector<Expr> roots{d.tau, ref.power, d.P[0], d.P[1], d.P[2], d.T[0], d.T[1], d.T[2], dP[0], dP[1], dP[2]};
  if (curvature) roots.insert(roots.end(), d.C.begin(), d.C.end());
  const Sampled at = sample(roots, bv0, bv1);
  std::vector<Eigen::Vector3d> Ts, alongs;  // S_t and the trimline's tangent at each sample
  double maxT = 0.0;
  for (int k = 0; k < kSamples; ++k) {
    const double v = at.v[k];
    const double t = at.values[0][k];
    if (!std::isfinite(t)) fail(ErrorCode::NonFinite, ref.path + ".at", "the trimline is not finite at v = " + num(v));
    if (t < std::min(S.t0, S.t1) - ttol || t > std::max(S.t0, S.t1) + ttol)
      fail(ErrorCode::InvalidField, ref.path + ".at",
           "the trimline t = " + num(t) + " at v = " + num(v) + " is outside the t_range [" + num(S.t0) + ", " + num(S.t1) + "] of '" + ref.surface + "'");
    const Eigen::Vector3d P = at.at3(2, k), T = at.at3(5, k);
    if (!P.allFinite() || !std::isfinite(T.norm()) || (curvature && !at.at3(11, k).allFinite()))
      fail(ErrorCode::NonFinite, ref.path, "'" + ref.surface + "' or its t-derivatives are not finite on the trimline at v = " + num(v));
    const double p = at.values[1][k];
    if (!std::isfinite(p)) fail(ErrorCode::NonFinite, ref.path + ".power", "not finite at v = " + num(v));
    Ts.push_back(T);
    alongs.push_back(at.at3(8, k));
    maxT = std::max(maxT, T.norm());
  }
  for (int k = 0; k < kSamples; ++k) {
    const double v = at.v[k];
    const Eigen::Vector3d& T = Ts[k];
    const Eigen::Vector3d& along = alongs[k];
    if (!(T.norm() > 1e-9 * maxT))
      fail(ErrorCode::InvalidField, ref.path, "dS/dt of '" + ref.surface + "' vanishes on the trimline at v = " + num(v) + ": no direction across it");
    // A trimline that stops (a pole) has no direction to be parallel to.
    if (along.allFinite() && along.norm() > 1e-9 * maxT && T.cross(along).norm() < 1e-6 * T.norm() * along.norm())
      fail(ErrorCode::InvalidField, ref.path, "dS/dt of '" + ref.surface + "' is parallel to the trimline at v = " + num(v) + ": no direction across it");
  }
  double sum = 0.0;
  for (const Eigen::Vector3d& T : Ts) sum += T.norm();
  d.meanT = sum / kSamples;
  return d;
}

// Mean distance between the two ends' curves over the blend's v-range.
double meanGap(const std::array<Vec3Expr, 2>& pos, double v0, double v1) {
  const Sampled at = sample({pos[0][0], pos[0][1], pos[0][2], pos[1][0], pos[1][1], pos[1][2]}, v0, v1);
  double sum = 0.0;
  for (int k = 0; k < kSamples; ++k) {
    const double g = (at.at3(3, k) - at.at3(0, k)).norm();
    if (std::isfinite(g)) sum += g;
  }
  return sum / kSamples;
}

// The surface met along a curve is drawn from its trimline: t = tau + s (t_far - tau), s in [0, 1].
// Its pointwise expression and the partial derivatives drawing needs are built here, under the
// scene's budget, so tessellation never differentiates an unbounded graph.
void trim(Patch& surface, const EndReference& ref) {
  PrimarySurface& S = surface.primary;
  const Expr tFar = constant(ref.atT1 ? S.t0 : S.t1);
  const Expr t = add(ref.tau, multiply(variable(ExprVar::U), subtract(tFar, ref.tau)));
  for (int c = 0; c < 3; ++c) {
    S.terms[c].clear();
    S.pointwise[c] = substitute(S.full[c], ExprVar::U, t);
    S.pointwisePartials[c] = partialDerivatives(S.pointwise[c], true);
  }
  S.t0 = 0.0;
  S.t1 = 1.0;
  S.trimmed = true;
}

void recordJoin(const DerivedEnd& d, const Patch& blend, const EndReference& ref, int end) {
  Meets m;
  m.patch = blend.name;
  m.end = end;
  m.atT1 = ref.curve ? false : ref.atT1;
  Meets& have = d.surface->meets;
  if (have.patch.empty()) {
    have = m;
    return;
  }
  if (have.patch == m.patch && (have.end != m.end || have.atT1 != m.atT1 || have.alongU))
    fail(ErrorCode::InvalidField, "patches[" + std::to_string(d.surfaceIndex) + "].meets",
         "disagrees with " + ref.path + " (which makes edge " + (m.atT1 ? "t1" : "t0") + " meet " + (end ? "u1" : "u0") + ")");
}

}  // namespace

void deriveEnds(Scene& scene) {
  // One budget for the whole scene: every node built for any end (and for the surfaces they
  // trim) counts, and the first node over the limit stops the derivation.
  ExprBudget budget(limits::kDerivedNodes, "the derived conditions of the scene's ends and the surfaces they trim");
  for (Patch& blend : scene.patches) {
    if (blend.kind != PatchKind::Pde || !(blend.ends[0].given || blend.ends[1].given)) continue;
    std::array<DerivedEnd, 2> derived;
    std::array<Vec3Expr, 2> pos;
    for (int end = 0; end < 2; ++end) {
      if (blend.ends[end].given) {
        budget.setPath(blend.ends[end].path);
        derived[end] = resolve(scene, blend, blend.ends[end]);
        pos[end] = derived[end].P;
      } else {
        for (int c = 0; c < 3; ++c) pos[end][c] = blend.typedPosition[end][c] ? blend.typedPosition[end][c] : constant(0.0);
      }
    }
    const double gap = meanGap(pos, blend.pde.v0, blend.pde.v1);
    for (int end = 0; end < 2; ++end) {
      EndReference& ref = blend.ends[end];
      if (!ref.given) continue;
      budget.setPath(ref.path);
      const DerivedEnd& d = derived[end];
      // "gap" scale, power 1: a mean tangent as long as the mean gap (of unit length when the
      // ends touch); "surface": power 1 continues the surface's t at its own speed.
      const double k = ref.surfaceScale ? 1.0 : (gap > 0 ? gap : 1.0) / d.meanT;
      const double away = (ref.atT1 ? 1.0 : -1.0) * (ref.flip ? -1.0 : 1.0);  // the blend's side, in t
      const double sign = end == 0 ? away : -away;
      const int level = static_cast<int>(ref.continuity);
      for (int c = 0; c < 3; ++c) {
        ComponentProblem& cp = blend.pde.component[c];
        std::vector<VExpansion>& slots = end == 0 ? cp.left : cp.right;
        const int n = blend.op[c].order / 2;
        slots.assign(n, {});
        std::array<Expr, 3> e;
        e[0] = d.P[c];
        if (n >= 2) e[1] = level >= 1 ? multiply(constant(sign * k), multiply(ref.power, d.T[c])) : subtract(pos[1][c], pos[0][c]);
        if (n >= 3) e[2] = level >= 2 ? multiply(constant(k * k), multiply(multiply(ref.power, ref.power), d.C[c])) : constant(0.0);
        ref.derived[c].clear();
        for (int i = 0; i < n; ++i) {
          ref.derived[c].push_back(toTextLimited(e[i], limits::kDerivedTextChars));
          slots[i] = scene_json::slotFromExpr(e[i], ref.path + " (" + ref.derived[c].back() + ")");
        }
      }
      recordJoin(d, blend, ref, end);
    }
    for (int end = 0; end < 2; ++end)
      if (blend.ends[end].given && blend.ends[end].curve) {
        budget.setPath(blend.ends[end].path);
        trim(*derived[end].surface, blend.ends[end]);
      }
  }
}

}  // namespace pdesurf
