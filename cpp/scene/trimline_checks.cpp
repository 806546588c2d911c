#include "scene/trimline_checks.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>
#include <vector>

#include "common/errors.hpp"
#include "expr/interval.hpp"
#include "expr/program.hpp"

namespace pdesurf {

namespace {

constexpr int kSamples = 129;          // along the trimline
constexpr int kTauBudget = 20000;      // evaluations of tau while bracketing poles between samples
constexpr int kRefineDepth = 48;       // bisections of one sample interval at most
constexpr int kGoldenSteps = 56;       // golden-section steps from one sampled minimum (0.618^56 ~ 2e-12)
constexpr size_t kMinima = 24;         // sampled minima refined at most, the smallest first
constexpr int kEncloseDepth = 56;      // halvings of a sample interval whose enclosure leaves the range

using Vec3Expr = std::array<Expr, 3>;


double eval1(const Expr& e, double v) {
  const double vars[2] = {v, 0.0};
  return evaluate(*e, vars);
}

Eigen::Vector3d eval3(const Vec3Expr& e, double v) { return {eval1(e[0], v), eval1(e[1], v), eval1(e[2], v)}; }

// tau over [v0, v1] (the surface's whole v-range: the trim draws the surface from tau there):
// finite and inside [tLo, tHi]. Between samples, an interval whose midpoint departs from the
// cubic Hermite interpolant of its ends (tau and tau') is bisected, so a pole (tau growing
// without bound) is followed until tau leaves the range or stops being finite.
class TauCheck {
 public:
  TauCheck(const EndReference& ref, const PrimarySurface& S, const Expr& tau, double bv0, double bv1)
      : ref_(ref), S_(S), tau_(tau), dtau_(derivative(tau, ExprVar::V)), bv0_(std::min(bv0, bv1)), bv1_(std::max(bv0, bv1)) {
    lo_ = std::min(S.t0, S.t1), hi_ = std::max(S.t0, S.t1);
    ttol_ = 1e-9 * std::max(1.0, hi_ - lo_);
    hermiteTol_ = 1e-6 * std::max(1.0, hi_ - lo_);
  }

  void run() {
    const double v0 = S_.v0, v1 = S_.v1;
    std::vector<double> vs(kSamples), t(kSamples), d(kSamples);
    for (int k = 0; k < kSamples; ++k) {
      vs[k] = v0 + (v1 - v0) * k / (kSamples - 1);
      t[k] = at(vs[k]);
      d[k] = eval1(dtau_, vs[k]);
    }
    for (int k = 0; k + 1 < kSamples; ++k) refine(vs[k], vs[k + 1], t[k], t[k + 1], d[k], d[k + 1], 0);
    // A pole too narrow for the samples and the Hermite test (0.5 + 1e-9/(v - 2π/3) moved tau
    // by 1e-7 at the nearest midpoint: accepted on one grid, NonFinite on another, issue 38
    // #15): each sample interval's enclosure must lie in the range, else it is halved down to
    // the points, where at() names what is wrong.
    const IntervalProgram enclosure(tau_);
    for (int k = 0; k + 1 < kSamples; ++k) enclose(enclosure, vs[k], vs[k + 1], 0);
  }

 private:
  double at(double v) {
    ++evaluations_;
    const double t = eval1(tau_, v);
    if (!std::isfinite(t)) fail(ErrorCode::NonFinite, ref_.path + ".at", "the trimline is not finite at v = " + shortNumber(v) + " (a pole of τ?)");
    if (t < lo_ - ttol_ || t > hi_ + ttol_)
      fail(ErrorCode::InvalidField, ref_.path + ".at",
           "the trimline t = " + shortNumber(t) + " at v = " + shortNumber(v) + " is outside the t_range [" + shortNumber(S_.t0) + ", " +
               shortNumber(S_.t1) + "] of '" + ref_.surface + "'" + (insideBlend(v) ? "" : " (the trim applies over the surface's whole v_range)"));
    return t;
  }

  bool insideBlend(double v) const { return v >= bv0_ && v <= bv1_; }

  void enclose(const IntervalProgram& program, double a, double b, int depth) {
    if (enclosures_ >= kTauBudget) return;
    ++enclosures_;
    const Interval vars[2] = {{a, b}, {0.0, 0.0}};
    const Interval r = program.run(vars);
    if (r.bounded() && r.lo >= lo_ - ttol_ && r.hi <= hi_ + ttol_) return;  // proved inside
    const double m = 0.5 * (a + b);
    if (depth >= kEncloseDepth || !(m > a && m < b)) {
      // As narrow as it gets: a pole shows here as a value out of the range (or not finite),
      // an enclosure merely loose (a square root's edge, rounding at the range's end) does not.
      at(a), at(m), at(b);
      return;
    }
    enclose(program, a, m, depth + 1);
    enclose(program, m, b, depth + 1);
  }

  void refine(double a, double b, double ta, double tb, double da, double db, int depth) {
    if (depth >= kRefineDepth || evaluations_ >= kTauBudget) return;
    const double m = 0.5 * (a + b);
    const double tm = at(m);
    const double hermite = 0.5 * (ta + tb) + (b - a) * (da - db) / 8.0;
    if (std::abs(tm - hermite) <= hermiteTol_) return;  // NaN (a kink or pole at an end) refines
    const double dm = eval1(dtau_, m);
    refine(a, m, ta, tm, da, dm, depth + 1);
    refine(m, b, tm, tb, dm, db, depth + 1);
  }

  const EndReference& ref_;
  const PrimarySurface& S_;
  Expr tau_, dtau_;
  double bv0_, bv1_;
  double lo_ = 0, hi_ = 0, ttol_ = 0, hermiteTol_ = 0;
  int evaluations_ = 0, enclosures_ = 0;
};

// The smallest f over [a, b] by golden-section search (f unimodal there); returns its v.
double goldenMin(const std::function<double(double)>& f, double a, double b) {
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double c = b - g * (b - a), d = a + g * (b - a), fc = f(c), fd = f(d);
  for (int i = 0; i < kGoldenSteps && b - a > 1e-15 * std::max(1.0, std::abs(a)); ++i) {
    if (fc <= fd || !std::isfinite(fd)) {
      b = d, d = c, fd = fc, c = b - g * (b - a), fc = f(c);
    } else {
      a = c, c = d, fc = fd, d = a + g * (b - a), fd = f(d);
    }
  }
  return fc <= fd ? c : d;
}

// The sampled local minima of f (at most kMinima, the smallest first) refined between their
// neighbours: calls bad(v) at the first v where f(v) <= threshold (at a sample or between two).
void minimaBelow(const std::vector<double>& vs, const std::vector<double>& fs, const std::function<double(double)>& f, double threshold,
                 const std::function<void(double)>& bad) {
  const int n = static_cast<int>(vs.size());
  std::vector<int> minima;
  for (int k = 0; k < n; ++k) {
    if (!std::isfinite(fs[k])) continue;
    if (fs[k] <= threshold) bad(vs[k]);
    const double left = k > 0 ? fs[k - 1] : INFINITY, right = k + 1 < n ? fs[k + 1] : INFINITY;
    // A local minimum (strict on one side, so a constant f is not searched everywhere) low
    // enough to hide a zero between the samples: f(v_k) at most (twice) the rise to a
    // neighbour, as for |v - v*| or (v - v*)² with v* within half a step.
    const bool minimum = fs[k] <= left && fs[k] <= right && (fs[k] < left || fs[k] < right);
    if (minimum && fs[k] <= 2 * std::max(left - fs[k], right - fs[k])) minima.push_back(k);
  }
  std::sort(minima.begin(), minima.end(), [&](int a, int b) { return fs[a] < fs[b]; });
  if (minima.size() > kMinima) minima.resize(kMinima);
  for (int k : minima) {
    const double v = goldenMin(f, vs[std::max(0, k - 1)], vs[std::min(n - 1, k + 1)]);
    if (f(v) <= threshold) bad(v);
  }
}

}  // namespace

std::string shortNumber(double x) {
  std::ostringstream s;
  s.precision(6);
  s << x;
  return s.str();
}

double checkTrimline(const EndReference& ref, const PrimarySurface& S, const TrimlineExprs& e, double bv0, double bv1) {
  const std::string at = ref.path + ".at";
  const double vtol = 1e-9 * std::max(1.0, std::abs(S.v1 - S.v0));
  if (std::min(bv0, bv1) < std::min(S.v0, S.v1) - vtol || std::max(bv0, bv1) > std::max(S.v0, S.v1) + vtol)
    fail(ErrorCode::InvalidField, ref.path + ".surface",
         "the blend's v_range [" + shortNumber(bv0) + ", " + shortNumber(bv1) + "] is not inside the v_range [" + shortNumber(S.v0) + ", " +
             shortNumber(S.v1) + "] of '" + ref.surface + "'");
  if (ref.curve) TauCheck(ref, S, e.tau, bv0, bv1).run();

  // Along the blend: S and its t-derivatives finite; dS/dt neither vanishing nor along the trimline.
  const bool curvature = ref.continuity == Continuity::Curvature;
  const Vec3Expr dP = {derivative(e.P[0], ExprVar::V), derivative(e.P[1], ExprVar::V), derivative(e.P[2], ExprVar::V)};
  std::vector<double> vs(kSamples), speed(kSamples), sine(kSamples);
  std::vector<Eigen::Vector3d> Ts(kSamples);  // S_t at each sample, evaluated once
  double maxT = 0.0, sum = 0.0;
  const auto sineAt = [&](const Eigen::Vector3d& T, const Eigen::Vector3d& along) {
    // A trimline that stops (a pole) or has no finite tangent there has no direction to be parallel to.
    if (!along.allFinite() || !(along.norm() > 1e-9 * maxT) || !(T.norm() > 0)) return double(INFINITY);
    return T.normalized().cross(along.normalized()).norm();  // unit first: tiny surfaces do not underflow
  };
  for (int k = 0; k < kSamples; ++k) vs[k] = bv0 + (bv1 - bv0) * k / (kSamples - 1);
  // Every sample of every expression by one program: they share the surface's terms (a
  // profile's powers of cos(v/4) - sin(v/4)), which a walk of each tree computed again and again.
  // Rows: tau, P, T, dP, power, then C (curvature).
  std::vector<Expr> roots{e.tau, e.P[0], e.P[1], e.P[2], e.T[0], e.T[1], e.T[2], dP[0], dP[1], dP[2], ref.power};
  if (curvature) roots.insert(roots.end(), {e.C[0], e.C[1], e.C[2]});
  std::vector<std::vector<double>> rows(roots.size(), std::vector<double>(kSamples));
  std::vector<double*> outs;
  for (std::vector<double>& r : rows) outs.push_back(r.data());
  ExprProgram(roots).runAll(vs.data(), nullptr, vs.size(), outs.data());
  const auto row3 = [&](size_t first, int k) { return Eigen::Vector3d(rows[first][k], rows[first + 1][k], rows[first + 2][k]); };
  for (int k = 0; k < kSamples; ++k) {
    const double v = vs[k];
    if (!std::isfinite(rows[0][k])) fail(ErrorCode::NonFinite, at, "the trimline is not finite at v = " + shortNumber(v));
    const Eigen::Vector3d P = row3(1, k), T = row3(4, k);
    if (!P.allFinite() || !std::isfinite(T.norm()) || (curvature && !row3(11, k).allFinite()))
      fail(ErrorCode::NonFinite, ref.path, "'" + ref.surface + "' or its t-derivatives are not finite on the trimline at v = " + shortNumber(v));
    if (!std::isfinite(rows[10][k])) fail(ErrorCode::NonFinite, ref.path + ".power", "not finite at v = " + shortNumber(v));
    Ts[k] = T;
    speed[k] = T.norm();
    maxT = std::max(maxT, speed[k]);
    sum += speed[k];
  }
  for (int k = 0; k < kSamples; ++k) sine[k] = sineAt(Ts[k], row3(7, k));
  const auto speedAt = [&](double v) { return eval3(e.T, v).norm(); };
  minimaBelow(vs, speed, speedAt, 1e-9 * maxT, [&](double v) {
    fail(ErrorCode::InvalidField, at, "dS/dt of '" + ref.surface + "' vanishes on the trimline at v = " + shortNumber(v) + ": no direction across it");
  });
  const auto sineOf = [&](double v) { return sineAt(eval3(e.T, v), eval3(dP, v)); };
  minimaBelow(vs, sine, sineOf, 1e-6, [&](double v) {
    fail(ErrorCode::InvalidField, at, "dS/dt of '" + ref.surface + "' is parallel to the trimline at v = " + shortNumber(v) + ": no direction across it");
  });
  return sum / kSamples;
}

}  // namespace pdesurf
