// The tensor-product assembly of seed 002's matrices (bezier_assembly.hpp, tensor_gram.hpp)
// against the row-by-row formula it replaced, kept here as the reference: every Gram matrix
// AᵀWA with A(q, (i,j)) = ∂B_i^n(u_q) ∂B_j^m(v_q), one row per node.
#include <doctest.h>

#include <Eigen/Dense>
#include <array>
#include <nlohmann/json.hpp>
#include <random>

#include "bezier/bernstein.hpp"
#include "bezier/bezier_assembly.hpp"
#include "bezier/tensor_gram.hpp"
#include "common/errors.hpp"
#include "common/limits.hpp"
#include "expr/parse.hpp"
#include "scene/scene.hpp"
#include "test_util.hpp"

using namespace pdesurf;
using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

// ---- the dense reference (the assembly as it was before the tensor-product one) ----

struct Points {
  std::vector<double> u, v, w;
};

Points gaussGrid(int qu, int qv) {
  const GaussRule a = gaussLegendre(qu), b = gaussLegendre(qv);
  Points p;
  for (int i = 0; i < qu; ++i)
    for (int j = 0; j < qv; ++j) p.u.push_back(a.x[i]), p.v.push_back(b.x[j]), p.w.push_back(a.w[i] * b.w[j]);
  return p;
}

Points trapezoidGrid(int np, int mp) {
  Points p;
  for (int i = 0; i <= np; ++i)
    for (int j = 0; j <= mp; ++j) {
      const double wi = (i == 0 || i == np) ? 0.5 : 1.0, wj = (j == 0 || j == mp) ? 0.5 : 1.0;
      p.u.push_back(static_cast<double>(i) / np), p.v.push_back(static_cast<double>(j) / mp), p.w.push_back(wi * wj / (np * mp));
    }
  return p;
}

MatrixXd basisRows(int n, int m, const Points& p, int du, int dv) {
  MatrixXd A(p.u.size(), (n + 1) * (m + 1));
  for (size_t q = 0; q < p.u.size(); ++q) {
    const auto bu = bernstein(n, p.u[q], du), bv = bernstein(m, p.v[q], dv);
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= m; ++j) A(q, i * (m + 1) + j) = bu[i] * bv[j];
  }
  return A;
}

MatrixXd gram(const MatrixXd& A, const VectorXd& w) { return A.transpose() * w.asDiagonal() * A; }

BezierForms denseForms(const BezierProblem& p) {
  const int n = p.n, m = p.m, K = (n + 1) * (m + 1);
  const BezierNormalField& f = p.normals;
  const Points fair = gaussGrid(n + 1, m + 1);
  const Points nrm = f.discrete ? trapezoidGrid(f.np, f.mp) : gaussGrid(n + f.n1, m + f.m1);
  const VectorXd wFair = Eigen::Map<const VectorXd>(fair.w.data(), fair.w.size());
  BezierForms out;
  if (p.energy == BezierEnergy::ThinPlate)
    out.fairness = gram(basisRows(n, m, fair, 2, 0), wFair) + 2 * gram(basisRows(n, m, fair, 1, 1), wFair) + gram(basisRows(n, m, fair, 0, 2), wFair);
  else
    out.fairness = gram(basisRows(n, m, fair, 1, 0), wFair) + gram(basisRows(n, m, fair, 0, 1), wFair);
  VectorXd wMass = Eigen::Map<const VectorXd>(nrm.w.data(), nrm.w.size());
  if (f.discrete && !f.gammaWeight.empty())
    for (int q = 0; q < wMass.size(); ++q) wMass(q) *= f.gammaWeight[q];
  out.mass = gram(basisRows(n, m, nrm, 0, 0), wMass);
  const MatrixXd Au = basisRows(n, m, nrm, 1, 0), Av = basisRows(n, m, nrm, 0, 1);
  std::vector<Eigen::Vector3d> N(nrm.u.size());
  for (size_t q = 0; q < nrm.u.size(); ++q) {
    if (f.discrete) {
      N[q] = f.vectors[q].normalized();
      if (!f.lambdaWeight.empty()) N[q] *= std::sqrt(f.lambdaWeight[q]);
    } else {
      const auto bu = bernstein(f.n1, nrm.u[q]), bv = bernstein(f.m1, nrm.v[q]);
      N[q].setZero();
      for (int i = 0; i <= f.n1; ++i)
        for (int j = 0; j <= f.m1; ++j) N[q] += bu[i] * bv[j] * f.vectors[i * (f.m1 + 1) + j];
    }
  }
  out.normal = MatrixXd::Zero(3 * K, 3 * K);
  for (int c = 0; c < 3; ++c)
    for (int d = c; d < 3; ++d) {
      VectorXd w(nrm.u.size());
      for (size_t q = 0; q < nrm.u.size(); ++q) w(q) = nrm.w[q] * N[q](c) * N[q](d);
      const MatrixXd block = gram(Au, w) + gram(Av, w);
      for (int k = 0; k < K; ++k)
        for (int l = 0; l < K; ++l) out.normal(3 * k + c, 3 * l + d) = out.normal(3 * k + d, 3 * l + c) = block(k, l);
    }
  return out;
}

// ---- random problems ----

BezierProblem randomProblem(std::mt19937& rng, int n, int m, BezierEnergy e, bool discrete, bool weights) {
  std::uniform_real_distribution<double> U(-1.0, 1.0), P(0.0, 2.0);
  BezierProblem p;
  p.n = n, p.m = m, p.energy = e, p.lambda = 3, p.gamma = 0.5;
  for (int k = 0; k < (n + 1) * (m + 1); ++k) p.initial.emplace_back(U(rng), U(rng), U(rng));
  BezierNormalField& f = p.normals;
  f.discrete = discrete;
  if (discrete) {
    std::uniform_int_distribution<int> G(1, 24);
    f.np = G(rng), f.mp = G(rng);
  } else {
    std::uniform_int_distribution<int> D(0, 6);
    f.n1 = D(rng), f.m1 = D(rng);
  }
  const int count = discrete ? (f.np + 1) * (f.mp + 1) : (f.n1 + 1) * (f.m1 + 1);
  for (int q = 0; q < count; ++q) f.vectors.emplace_back(U(rng), U(rng), 1.0 + 0.5 * U(rng));
  if (weights)
    for (int q = 0; q < count; ++q) f.lambdaWeight.push_back(P(rng)), f.gammaWeight.push_back(P(rng));
  return p;
}

// max |A - B| relative to max |B|.
double relativeDiff(const MatrixXd& A, const MatrixXd& B) {
  REQUIRE(A.rows() == B.rows());
  REQUIRE(A.cols() == B.cols());
  return (A - B).cwiseAbs().maxCoeff() / B.cwiseAbs().maxCoeff();
}

}  // namespace

TEST_CASE("bezier assembly: a tensor Gram matrix equals AᵀWA for arbitrary (non-separable) weights") {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  for (const std::array<int, 6>& c : {std::array{3, 5, 7, 4, 1, 0}, std::array{6, 2, 3, 9, 0, 1}, std::array{16, 16, 20, 17, 2, 1}}) {
    const int n = c[0], m = c[1], Nu = c[2], Nv = c[3], du = c[4], dv = c[5];
    std::vector<double> u(Nu), v(Nv);
    for (double& x : u) x = U(rng);
    for (double& x : v) x = U(rng);
    const MatrixXd W = MatrixXd::NullaryExpr(Nu, Nv, [&] { return U(rng) - 0.3; });  // also negative
    TensorGram G(n, m);
    G.add(columnPairProducts(bernsteinTable(n, u, du)), columnPairProducts(bernsteinTable(m, v, dv)), W, 1.5);
    Points p;
    VectorXd w(Nu * Nv);
    for (int a = 0; a < Nu; ++a)
      for (int b = 0; b < Nv; ++b) p.u.push_back(u[a]), p.v.push_back(v[b]), w(a * Nv + b) = W(a, b);
    const MatrixXd ref = 1.5 * gram(basisRows(n, m, p, du, dv), w), got = G.matrix();
    CAPTURE(n);
    CHECK(relativeDiff(got, ref) < 1e-13);
    CHECK(got == got.transpose());  // symmetric by construction, bit for bit
  }
}

TEST_CASE("bezier assembly: equals the row-by-row assembly on random problems") {
  std::mt19937 rng(2024);
  const std::array<std::array<int, 2>, 6> degrees{{{2, 2}, {2, 5}, {4, 4}, {7, 6}, {9, 12}, {16, 16}}};
  double worst = 0;
  for (const auto& nm : degrees)
    for (BezierEnergy e : {BezierEnergy::Membrane, BezierEnergy::ThinPlate}) {
      const int n = nm[0], m = nm[1];
      if (e == BezierEnergy::ThinPlate && (n < 4 || m < 4)) continue;
      for (bool discrete : {false, true})
        for (bool weights : {false, true}) {
          if (!discrete && weights) continue;  // per-sample weights exist for discrete fields only
          const BezierProblem p = randomProblem(rng, n, m, e, discrete, weights);
          const BezierForms got = assembleBezierForms(p), ref = denseForms(p);
          CAPTURE(n);
          CAPTURE(m);
          CAPTURE(discrete);
          CAPTURE(weights);
          const double d = std::max({relativeDiff(got.fairness, ref.fairness), relativeDiff(got.mass, ref.mass), relativeDiff(got.normal, ref.normal)});
          CHECK(d < 1e-12);
          CHECK(got.normal == got.normal.transpose());
          worst = std::max(worst, d);
        }
    }
  MESSAGE("largest relative difference " << worst);
}

TEST_CASE("bezier assembly: the work bound counts the tensor-product cost") {
  int Nu = 0, Nv = 0;
  BezierNormalField f;
  f.discrete = true, f.np = f.mp = 256;
  bezierNormalNodes(16, 16, f, Nu, Nv);
  CHECK((Nu == 257 && Nv == 257));
  // 257² samples × 17² + 257 × 289² + 289³ (the factorisations): degree 16 with the largest
  // discrete field.
  CHECK(bezierAssemblyWork(16, 16, Nu, Nv) == size_t{66049} * 289 + size_t{257} * 289 * 289 + size_t{289} * 289 * 289);
  f = {};
  f.n1 = 24, f.m1 = 3;
  bezierNormalNodes(16, 10, f, Nu, Nv);
  CHECK((Nu == 40 && Nv == 13));
}

TEST_CASE("bezier assembly: degree 16 with a 256² field is accepted; the scene's total work is capped") {
  // wu2015-fig1a's patch at degree 16 with a 256² discrete field, copied `count` times.
  auto scene = [](int count) {
    auto doc = nlohmann::json::parse(pdesurf::testing::readText(pdesurf::testing::examplePath("wu2015-fig1a.json")));
    nlohmann::json patch = doc["patches"][0];
    patch["degree"] = {16, 16};
    patch["control_net"] = nlohmann::json::array();
    for (int i = 0; i <= 16; ++i)
      for (int j = 0; j <= 16; ++j) patch["control_net"].push_back({i / 16.0, j / 16.0, 0.0});
    patch["normals"] = {{"grid", {256, 256}}, {"field", {{"x", "0"}, {"y", "0.2*u"}, {"z", "1"}}}};
    doc["patches"] = nlohmann::json::array();
    for (int k = 0; k < count; ++k) {
      patch["name"] = "p" + std::to_string(k);
      doc["patches"].push_back(patch);
    }
    return doc.dump();
  };
  const size_t perPatch = bezierAssemblyWork(16, 16, 257, 257);
  const int fit = static_cast<int>(limits::kBezierAssembly / perPatch);
  CHECK(fit >= 8);  // the page's solver cache holds 8 factorisations
  CHECK(parseScene(scene(1)).patches.size() == 1);
  CHECK(parseScene(scene(fit)).patches.size() == static_cast<size_t>(fit));
  std::string error;
  try {
    parseScene(scene(fit + 1));
  } catch (const Error& e) {
    error = std::string(errorCodeName(e.code())) + ": " + e.what();
  }
  CHECK(error.rfind("TooLarge: patches[" + std::to_string(fit) + "].normals.grid: ", 0) == 0);
  CHECK(error.find("units of assembly work") != std::string::npos);
}

TEST_CASE("bezier normal fields: expressions are sampled as the point-by-point values, under the scene's sampling budget") {
  auto doc = nlohmann::json::parse(pdesurf::testing::readText(pdesurf::testing::examplePath("wu2015-fig1a.json")));
  nlohmann::json patch = doc["patches"][0];
  const std::string x = "sin(3*u + v)*exp(v - u)", y = "0.2*u*v^2", z = "1 + cos(u*v)";
  patch["normals"] = {{"grid", {12, 9}}, {"field", {{"x", x}, {"y", y}, {"z", z}}}};
  doc["patches"] = nlohmann::json::array({patch});
  const Scene typed = parseScene(doc.dump());
  const BezierNormalField& f = typed.patches[0].bezier().normals;
  REQUIRE(f.vectors.size() == 13 * 10);
  const Expr ex = parseExpression(x, {}, AllowedVariables{true, true}), ey = parseExpression(y, {}, AllowedVariables{true, true}),
             ez = parseExpression(z, {}, AllowedVariables{true, true});
  for (int i = 0; i <= 12; ++i)
    for (int k = 0; k <= 9; ++k) {
      const double vars[2] = {k / 9.0, i / 12.0};  // v, u
      const Eigen::Vector3d& n = f.vectors[size_t(i) * 10 + size_t(k)];
      CHECK(n.x() == evaluate(*ex, vars));
      CHECK(n.y() == evaluate(*ey, vars));
      CHECK(n.z() == evaluate(*ez, vars));
    }
  // Long expressions on the largest grid: refused before they are sampled, by the scene's total.
  std::string heavy = "0";
  for (int k = 1; k <= 40; ++k) heavy += "+sin(" + std::to_string(k) + "*u+v)*exp(" + std::to_string(k) + "*v-u)";
  patch["normals"] = {{"grid", {256, 256}}, {"field", {{"x", heavy}, {"y", heavy + "+1"}, {"z", heavy + "+2"}}}};
  doc["patches"] = nlohmann::json::array();
  for (int k = 0; k < 8; ++k) {
    patch["name"] = "p" + std::to_string(k);
    doc["patches"].push_back(patch);
  }
  const std::string error = pdesurf::testing::parseErrorOf(doc.dump());
  CAPTURE(error);
  CHECK(error.rfind("TooLarge: patches[", 0) == 0);
  CHECK(error.find("].normals.field.") != std::string::npos);
  CHECK(error.find("over the limit") != std::string::npos);
}

TEST_CASE("bezier assembly: a patch without normals still counts its energy and factorisation") {
  // Issue 38 re-attack: 64 degree-16 membranes without normals charged nothing (wasm 5 s).
  const size_t perPatch = bezierAssemblyWork(16, 16, 16, 16);
  const int fit = static_cast<int>(limits::kBezierAssembly / perPatch);
  nlohmann::json patch = {{"kind", "bezier"}, {"energy", "membrane"}, {"degree", {16, 16}}, {"gamma", 1}, {"control_net", nlohmann::json::array()}};
  for (int i = 0; i <= 16; ++i)
    for (int j = 0; j <= 16; ++j) patch["control_net"].push_back({i / 16.0, j / 16.0, 0.0});
  nlohmann::json doc = {{"format", "pdesurf-scene"}, {"version", 4}, {"patches", nlohmann::json::array()}};
  for (int k = 0; k <= fit; ++k) {
    patch["name"] = "p" + std::to_string(k);
    doc["patches"].push_back(patch);
  }
  const std::string error = pdesurf::testing::parseErrorOf(doc.dump());
  CAPTURE(error);
  CHECK(fit >= 16);
  CHECK(error.rfind("TooLarge: patches[" + std::to_string(fit) + "].degree: a patch of degree 16x16 is ", 0) == 0);
}
