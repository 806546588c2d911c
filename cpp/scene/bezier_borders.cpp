#include "scene/bezier_borders.hpp"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>

#include "analysis/curve_gap_bound.hpp"
#include "bezier/bernstein.hpp"
#include "bezier/bezier_solver.hpp"
#include "common/errors.hpp"
#include "scene/surface_reference.hpp"
#include "scene/trimline_checks.hpp"

namespace pdesurf {

namespace {

constexpr int kFitSamples = 129;            // Chebyshev-Lobatto points along an edge, both ends included
constexpr double kCornerTolerance = 1e-9;   // of the hole's size: the certificate's G0 tolerance
constexpr double kRhoFloor = 1e-3;          // a corner length below this share of the gap scale is not used

using Vec3 = Eigen::Vector3d;


// One edge e (kBezierEdge order: u0, u1, v0, v1) of an n×m net.
struct EdgeNet {
  int n = 0, m = 0, e = 0;
  int along() const { return e < 2 ? m : n; }   // N: the edge's degree
  int across() const { return e < 2 ? n : m; }  // M: the degree across it
  // The net index of point k along the edge (k = 0..N, in the edge parameter's direction) in ring r.
  int at(int k, int r) const {
    const int i = e == 0 ? r : e == 1 ? n - r : k;
    const int j = e == 0 || e == 1 ? k : e == 2 ? r : m - r;
    return i * (m + 1) + j;
  }
};

// A border given by reference, sampled: S and the cross direction d S_t (d = -1 at t0, +1 at
// t1: pointing away from the surface, into the hole) at the edge parameter's samples.
struct Border {
  BorderReference* ref = nullptr;
  Patch* surface = nullptr;
  size_t surfaceIndex = 0;
  EdgeNet net;
  std::array<Expr, 3> edge;  // S on the border, in v
  std::vector<Vec3> P, T;
  CurveGap gap;              // ring 0 against the edge (analysis/curve_gap_bound.hpp)
};

const std::vector<double>& samples() {
  static const std::vector<double> s = [] {
    std::vector<double> out(kFitSamples);
    for (int k = 0; k < kFitSamples; ++k) out[k] = 0.5 * (1.0 - std::cos(M_PI * k / (kFitSamples - 1)));
    out.front() = 0.0, out.back() = 1.0;
    return out;
  }();
  return s;
}

std::string num(double x) { return shortNumber(x); }

// The surface a border names: a "surface" patch, not trimmed along a curve.
void locate(Scene& scene, Border& b) {
  const BorderReference& ref = *b.ref;
  b.surfaceIndex = scene_json::referencedSurface(scene, ref.surface, ref.path, "a border");
  b.surface = &scene.patches[b.surfaceIndex];
  const Patch& s = *b.surface;
  if (s.primary().trimmed)
    fail(ErrorCode::InvalidField, ref.path + ".surface",
         "'" + ref.surface + "' is trimmed along a curve by a blend end; a Bezier border needs an untrimmed surface");
}

// S and S_t on the border, built under the scene's budget and checked as a blend end's
// trimline is (finite, S_t neither vanishing nor along the border), then sampled.
void derive(Border& b, ExprBudget& budget) {
  const BorderReference& ref = *b.ref;
  const PrimarySurface& S = b.surface->primary();
  budget.setPath(ref.path);
  TrimlineExprs x;
  x.tau = constant(ref.atT1 ? S.t1 : S.t0);
  for (int c = 0; c < 3; ++c) {
    x.P[c] = substitute(S.full[c], ExprVar::U, x.tau);
    x.T[c] = substitute(derivative(S.full[c], ExprVar::U), ExprVar::U, x.tau);
  }
  EndReference asEnd;  // the checks blend ends share (scene/trimline_checks.hpp)
  asEnd.given = true, asEnd.surface = ref.surface, asEnd.atT1 = ref.atT1, asEnd.path = ref.path;
  asEnd.power = constant(1.0);
  checkTrimline(asEnd, S, x, S.v0, S.v1);
  b.edge = x.P;
  const double d = ref.atT1 ? 1.0 : -1.0;
  for (double s : samples()) {
    const double v = ref.reverse ? S.v1 + s * (S.v0 - S.v1) : S.v0 + s * (S.v1 - S.v0);
    const double vars[2] = {v, 0.0};
    const Vec3 P(evaluate(*x.P[0], vars), evaluate(*x.P[1], vars), evaluate(*x.P[2], vars));
    const Vec3 T(evaluate(*x.T[0], vars), evaluate(*x.T[1], vars), evaluate(*x.T[2], vars));
    if (!P.allFinite() || !T.allFinite())
      fail(ErrorCode::NonFinite, ref.path, "'" + ref.surface + "' or dS/dt is not finite on its border at v = " + num(v));
    b.P.push_back(P);
    b.T.push_back(d * T);
  }
}

// The least-squares fit Σ c_j B_j^N of f at the samples, c_0 and c_N pinned.
std::vector<Vec3> fitPinned(int N, const std::vector<Vec3>& f, const Vec3& c0, const Vec3& cN) {
  const std::vector<double>& s = samples();
  Eigen::MatrixXd A(kFitSamples, N - 1), rhs(kFitSamples, 3);
  std::vector<double> B(N + 1);
  for (int k = 0; k < kFitSamples; ++k) {
    bernsteinValues(N, s[k], B.data());
    for (int j = 1; j < N; ++j) A(k, j - 1) = B[j];
    rhs.row(k) = (f[k] - B[0] * c0 - B[N] * cN).transpose();
  }
  const Eigen::MatrixXd c = A.colPivHouseholderQr().solve(rhs);
  std::vector<Vec3> out(N + 1);
  out[0] = c0, out[N] = cN;
  for (int j = 1; j < N; ++j) out[j] = c.row(j - 1).transpose();
  return out;
}

// The corners: where two given borders meet, their end points must agree (to the tolerance);
// the corner is their mean. Writes every given border's corner points into the net.
void closeCorners(std::vector<Border*>& edge, std::vector<Vec3>& net, double size) {
  for (int e = 2; e < 4; ++e) {
    if (!edge[e]) continue;
    const Border& b = *edge[e];
    for (int a = 0; a < 2; ++a) {  // v0/v1's start meets u0, its end u1
      if (!edge[a]) continue;
      const Border& o = *edge[a];
      const Vec3 mine = a == 0 ? b.P.front() : b.P.back();
      const Vec3 theirs = e == 2 ? o.P.front() : o.P.back();
      const double gap = (mine - theirs).norm();
      if (!(gap <= kCornerTolerance * size))
        fail(ErrorCode::InvalidField, b.ref->path,
             std::string("the corner (u, v) = (") + (a ? "1" : "0") + ", " + (e == 3 ? "1" : "0") + ") does not close: this border ends " + num(gap) +
                 " from where borders." + kBezierEdge[a] + " ends (more than " + num(kCornerTolerance) + " of the hole's size " + num(size) + ")");
    }
  }
  // Each corner: the mean of the end points of the given borders through it.
  std::vector<Vec3> sum(net.size(), Vec3::Zero());
  std::vector<int> count(net.size(), 0);
  for (Border* b : edge) {
    if (!b) continue;
    const int N = b->net.along();
    sum[b->net.at(0, 0)] += b->P.front(), ++count[b->net.at(0, 0)];
    sum[b->net.at(N, 0)] += b->P.back(), ++count[b->net.at(N, 0)];
  }
  for (size_t k = 0; k < net.size(); ++k)
    if (count[k]) net[k] = sum[k] / count[k];
}

// Mean distance from the border to the opposite edge's ring 0 (given or typed), sample by sample.
double meanGap(const Border& b, const std::vector<Vec3>& net) {
  EdgeNet opp = b.net;
  opp.e ^= 1;
  const int N = b.net.along();
  std::vector<double> B(N + 1);
  double sum = 0.0;
  for (int k = 0; k < kFitSamples; ++k) {
    bernsteinValues(N, samples()[k], B.data());
    Vec3 q = Vec3::Zero();
    for (int j = 0; j <= N; ++j) q += B[j] * net[opp.at(j, 0)];
    sum += (q - b.P[k]).norm();
  }
  return sum / kFitSamples;
}

// Ring 1 of one border: the fit of ρ(s) d S_t with ρ linear, ends pinned to the neighbours'
// ring-0 points next to the corners (ρ's end values match their length along d S_t); adds
// its proposals for points 1..N-1 of ring 1 (the corner twists get one from each edge).
void ringOne(const Border& b, const std::vector<Vec3>& net, std::vector<Vec3>& sum, std::vector<int>& count) {
  const EdgeNet& g = b.net;
  const int N = g.along(), M = g.across();
  const Vec3 c0 = M * (net[g.at(0, 1)] - net[g.at(0, 0)]), cN = M * (net[g.at(N, 1)] - net[g.at(N, 0)]);
  double meanT = 0.0;
  for (const Vec3& T : b.T) meanT += T.norm() / kFitSamples;
  double gap = meanGap(b, net) / meanT;  // the "gap" scale: mean |D| = the mean distance across
  if (!(gap > 0) || !std::isfinite(gap)) gap = 1.0;
  const auto rho = [&](const Vec3& c, const Vec3& T) {
    const double r = c.dot(T) / T.squaredNorm();
    return r > kRhoFloor * gap && std::isfinite(r) ? r : gap;
  };
  const double r0 = rho(c0, b.T.front()), r1 = rho(cN, b.T.back());
  std::vector<Vec3> D(kFitSamples);
  for (int k = 0; k < kFitSamples; ++k) D[k] = ((1 - samples()[k]) * r0 + samples()[k] * r1) * b.T[k];
  const std::vector<Vec3> c = fitPinned(N, D, c0, cN);
  for (int k = 1; k < N; ++k) {
    sum[g.at(k, 1)] += net[g.at(k, 0)] + c[k] / M;
    ++count[g.at(k, 1)];
  }
}

// The join for the certificate: the surface's border meets this edge of the patch.
void recordJoin(const Border& b, const Patch& patch) {
  const BorderReference& ref = *b.ref;
  Meets m;
  const PrimarySurface& S = b.surface->primary();
  m.borderGap = b.gap.verdict == CurveGap::Undecided ? INFINITY : b.gap.verdict == CurveGap::Found ? b.gap.gap : 0.0;
  m.borderGapV = ref.reverse ? S.v1 + b.gap.s * (S.v0 - S.v1) : S.v0 + b.gap.s * (S.v1 - S.v0);
  m.patch = patch.name;
  m.end = b.net.e & 1;
  m.alongU = b.net.e >= 2;
  m.atT1 = ref.atT1;
  m.reversed = ref.reverse;
  m.by = ref.path;
  for (Meets& have : b.surface->meets) {
    if (have.patch != m.patch || have.end != m.end || have.alongU != m.alongU) continue;
    if (have.atT1 == m.atT1 && have.reversed == m.reversed && std::isnan(have.v0)) {  // the scene's own meets says the same
      have.borderGap = m.borderGap, have.borderGapV = m.borderGapV;
      return;
    }
    fail(ErrorCode::InvalidField, "patches[" + std::to_string(b.surfaceIndex) + "].meets",
         "disagrees with " + ref.path + " (which makes edge " + (ref.atT1 ? "t1" : "t0") + " meet " + kBezierEdge[b.net.e] + " over the whole v_range" +
             (ref.reverse ? ", reversed" : "") + ")");
  }
  b.surface->meets.push_back(m);
}

void deriveOne(Scene& scene, size_t index, ExprBudget& budget, size_t& proofWork) {
  Patch& patch = scene.patches[index];
  BezierProblem& p = patch.bezier();
  const std::string path = "patches[" + std::to_string(index) + "].borders";
  if (p.n < 3 || p.m < 3)
    fail(ErrorCode::InvalidField, path,
         "degree " + std::to_string(p.n) + "x" + std::to_string(p.m) + " is too low: a border by reference fixes two rings of control points, which needs degree 3 or more each way");
  std::vector<Border> all;
  all.reserve(4);
  std::vector<Border*> edge(4, nullptr);
  for (int e = 0; e < 4; ++e) {
    if (!patch.borders()[e].given) continue;
    Border& b = all.emplace_back();
    b.ref = &patch.borders()[e];
    b.net = {p.n, p.m, e};
    locate(scene, b);
    derive(b, budget);
    edge[e] = &b;
  }
  // The hole's size: the diagonal of the given borders' bounding box.
  Vec3 lo = Vec3::Constant(INFINITY), hi = -lo;
  for (const Border& b : all)
    for (const Vec3& P : b.P) lo = lo.cwiseMin(P), hi = hi.cwiseMax(P);
  const double size = (hi - lo).norm();
  if (!(size > 0)) fail(ErrorCode::InvalidField, path, "the borders are a single point: there is no hole to fill");

  const bool built = p.initial.empty();
  std::vector<Vec3>& net = p.initial;
  if (built) net.assign(static_cast<size_t>(p.n + 1) * (p.m + 1), Vec3::Zero());
  closeCorners(edge, net, size);
  for (Border& b : all) {  // ring 0, corners pinned; its distance from the edge proven or found
    const int N = b.net.along();
    const std::vector<Vec3> c = fitPinned(N, b.P, net[b.net.at(0, 0)], net[b.net.at(N, 0)]);
    for (int k = 1; k < N; ++k) net[b.net.at(k, 0)] = c[k];
    const PrimarySurface& S = b.surface->primary();
    budget.setPath(b.ref->path);
    b.gap = boundCurveGap(b.edge, b.ref->reverse ? S.v1 : S.v0, b.ref->reverse ? S.v0 : S.v1, c, kCornerTolerance * size, kCurveGapPieces, &proofWork);
  }
  std::vector<Vec3> sum(net.size(), Vec3::Zero());
  std::vector<int> count(net.size(), 0);
  for (const Border& b : all) ringOne(b, net, sum, count);
  for (size_t k = 0; k < net.size(); ++k)
    if (count[k]) net[k] = sum[k] / count[k];
  for (const Border& b : all)
    for (int r = 0; r < 2; ++r)
      for (int k = 0; k <= b.net.along(); ++k)
        if (!net[b.net.at(k, r)].allFinite()) fail(ErrorCode::NonFinite, b.ref->path, "the derived control points are not finite");
  if (built) {
    // The interior starts at the discrete Coons patch of the four ring-0 polygons.
    const int n = p.n, m = p.m;
    const auto P = [&](int i, int j) -> const Vec3& { return net[p.index(i, j)]; };
    for (int i = 2; i <= n - 2; ++i)
      for (int j = 2; j <= m - 2; ++j) {
        const double a = static_cast<double>(i) / n, c = static_cast<double>(j) / m;
        net[p.index(i, j)] = (1 - a) * P(0, j) + a * P(n, j) + (1 - c) * P(i, 0) + c * P(i, m) -
                             ((1 - a) * (1 - c) * P(0, 0) + a * (1 - c) * P(n, 0) + (1 - a) * c * P(0, m) + a * c * P(n, m));
      }
    try {
      validateBezierProblem(p);
    } catch (const Error& err) {
      throw Error(err.code(), "patches[" + std::to_string(index) + "]: " + err.what());
    }
  }
  for (const Border& b : all) recordJoin(b, patch);
}

}  // namespace

void deriveBorders(Scene& scene, ExprBudget& budget) {
  size_t proofWork = kCurveGapWork;  // the borders' proofs, over the scene (analysis/curve_gap_bound.hpp)
  for (size_t i = 0; i < scene.patches.size(); ++i) {
    const Patch& patch = scene.patches[i];
    if (patch.kind != PatchKind::Bezier) continue;
    bool any = false;
    for (const BorderReference& ref : patch.borders()) any = any || ref.given;
    if (any) deriveOne(scene, i, budget, proofWork);
  }
}

}  // namespace pdesurf
