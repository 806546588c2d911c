#include "analysis/fill_centre.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <sstream>

#include "common/errors.hpp"
#include "surface/combine_rows.hpp"
#include "surface/tabulation.hpp"

namespace pdesurf {

namespace {

constexpr int kRings = 48, kAround = 96, kInner = 12;  // the inner grid: 12 rings over u in [1 - 2^-6, 1 - 2^-12]
constexpr int kCheckRings = 32, kCheckAround = 64;       // the solve's fold check (checkFillRegular)
constexpr double kInnerFrom = 1.0 / 64, kInnerTo = 1.0 / 4096;

// Unit normals (zero where X_u × X_v vanishes) and, with second derivatives, the largest
// |principal curvature|, on a grid of `s` at the u-values of one or more ranges.
struct GridFigures {
  int nu = 0, nv = 0;
  std::vector<Eigen::Vector3d> n;  // [j * (nu + 1) + i]
  std::vector<double> k;
};

// The u-values i/n of [from, to], i = 0..n.
struct URange {
  double from = 0, to = 1;
  int n = 1;
  double at(int i) const { return i == n ? to : from + (to - from) * i / n; }
};

// The figures on each range's grid (by `around` along v), from one tabulation: a fill's loop
// terms are expressions of v, evaluated once for every range.
std::vector<GridFigures> figures(const SeparableSurface& s, const std::vector<URange>& ranges, int around, bool curvature) {
  std::vector<double> us, vs(static_cast<size_t>(around) + 1);
  std::vector<GridFigures> out(ranges.size());
  std::vector<int> firstColumn;
  for (size_t r = 0; r < ranges.size(); ++r) {
    firstColumn.push_back(static_cast<int>(us.size()));
    for (int i = 0; i <= ranges[r].n; ++i) us.push_back(ranges[r].at(i));
    out[r].nu = ranges[r].n, out[r].nv = around;
    out[r].n.resize(static_cast<size_t>(ranges[r].n + 1) * (around + 1));
    if (curvature) out[r].k.resize(out[r].n.size());
  }
  for (int j = 0; j <= around; ++j) vs[j] = j == around ? s.v1 : s.v0 + (s.v1 - s.v0) * j / around;
  const Tabulation t = tabulateAt(s, std::move(us), std::move(vs), curvature ? 2 : 1);
  combineRows(t, [&](int j, const GridRow& row) {
    for (size_t r = 0; r < ranges.size(); ++r) {
      GridFigures& f = out[r];
      for (int i = 0; i <= f.nu; ++i) {
        const int col = firstColumn[r] + i;
        const auto vec = [&](int q) { return Eigen::Vector3d(row.at(q, 0)[col], row.at(q, 1)[col], row.at(q, 2)[col]); };
        const Eigen::Vector3d xu = vec(1), xv = vec(2), cross = xu.cross(xv);
        const size_t at = static_cast<size_t>(j) * (f.nu + 1) + i;
        f.n[at] = cross.norm() > 0 ? Eigen::Vector3d(cross.normalized()) : Eigen::Vector3d::Zero();
        if (!curvature) continue;
        const Eigen::Vector3d& n = f.n[at];
        const double E = xu.dot(xu), F = xu.dot(xv), G = xv.dot(xv), L = vec(3).dot(n), M = vec(4).dot(n), N = vec(5).dot(n);
        const double det = E * G - F * F;
        const double K = (L * N - M * M) / det, H = (E * N - 2 * F * M + G * L) / (2 * det);
        f.k[at] = std::abs(H) + std::sqrt(std::max(H * H - K, 0.0));
      }
    }
  });
  return out;
}

}  // namespace

namespace {

// The figures above on the fill's outer and inner grids, folds found; with `curvature`, the
// rest of the centre's measures too (the solve's check needs only the folds: no second
// derivatives, whose symbolic form and tabulation were half its cost).
FillCentre centreOf(const std::string& name, const SeparableSurface& s, bool curvature) {
  FillCentre r;
  r.patch = name;
  // The solve's check (no curvature) looks for folds on the drawing's resolution, 32 rings by
  // 64 around (plus the inner rings): a third of the certificate's 48 × 96, which it keeps.
  const int rings = curvature ? kRings : kCheckRings, around = curvature ? kAround : kCheckAround;
  const double dv = (s.v1 - s.v0) / around;
  // The fill's grid up to u = 1 - 1/rings, then the inner grid closing in on the centre.
  const URange outer{s.u0, s.u0 + (s.u1 - s.u0) * (rings - 1) / rings, rings - 1};
  const URange inner{s.u1 - (s.u1 - s.u0) * kInnerFrom, s.u1 - (s.u1 - s.u0) * kInnerTo, kInner};
  const std::vector<GridFigures> grids = figures(s, {outer, inner}, around, curvature);
  const GridFigures &a = grids[0], &b = grids[1];
  const auto foldAt = [&](const GridFigures& g, const URange& range) {
    for (int j = 0; j <= g.nv && !r.fold; ++j)
      for (int i = 0; i <= g.nu && !r.fold; ++i) {
        const Eigen::Vector3d& n = g.n[static_cast<size_t>(j) * (g.nu + 1) + i];
        const bool nextU = i < g.nu && n.dot(g.n[static_cast<size_t>(j) * (g.nu + 1) + i + 1]) < 0;
        const bool nextV = j < g.nv && n.dot(g.n[static_cast<size_t>(j + 1) * (g.nu + 1) + i]) < 0;
        const double u = range.at(i);
        // The loop's corners (u = 0) may turn sharply; a fold is inside the fill.
        if (u > s.u0 && (nextU || nextV || n.squaredNorm() == 0)) r.fold = true, r.foldU = u, r.foldV = s.v0 + dv * j;
      }
  };
  foldAt(a, outer);
  foldAt(b, inner);
  // The two grids meet: the outer grid's last ring against the inner grid's first.
  for (int j = 0; j <= around && !r.fold; ++j)
    if (a.n[static_cast<size_t>(j) * rings + rings - 1].dot(b.n[static_cast<size_t>(j) * (kInner + 1)]) < 0)
      r.fold = true, r.foldU = outer.to, r.foldV = s.v0 + dv * j;
  if (!curvature) return r;
  // A ring's spread: the largest angle of its normals from their mean.
  const auto spread = [&](int ring) {
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (int j = 0; j < around; ++j) mean += b.n[static_cast<size_t>(j) * (kInner + 1) + ring];
    mean.normalize();
    double worst = 0.0;
    for (int j = 0; j < around; ++j) {
      const Eigen::Vector3d& n = b.n[static_cast<size_t>(j) * (kInner + 1) + ring];
      worst = std::max(worst, std::atan2(n.cross(mean).norm(), n.dot(mean)) * 180.0 / M_PI);
    }
    return std::isfinite(worst) ? worst : 180.0;
  };
  r.normalSpreadDeg = spread(kInner);
  r.normalSpreadOuterDeg = spread(0);
  // Curvature: the three innermost rings against the three outermost of the inner grid.
  double far = 0.0;
  for (int j = 0; j < around; ++j)
    for (int i = 0; i < 3; ++i) {
      far = std::max(far, b.k[static_cast<size_t>(j) * (kInner + 1) + i]);
      r.curvatureNear = std::max(r.curvatureNear, b.k[static_cast<size_t>(j) * (kInner + 1) + kInner - i]);
    }
  r.curvatureRatio = far > 0 ? r.curvatureNear / far : (r.curvatureNear > 0 ? INFINITY : 1.0);
  const bool normalDefined = r.normalSpreadDeg <= kCentreSpreadDeg || r.normalSpreadDeg * kCentreSpreadFall <= r.normalSpreadOuterDeg;
  r.ok = !r.fold && normalDefined && std::isfinite(r.curvatureNear) && r.curvatureRatio <= kCentreCurvatureRatio;
  return r;
}

}  // namespace

FillCentre measureFillCentre(const std::string& name, const SeparableSurface& s) { return centreOf(name, s, true); }

void checkFillRegular(const Patch& fill, const SeparableSurface& surface) {
  const FillCentre c = centreOf(fill.name, surface, false);
  if (!c.fold) return;
  std::ostringstream o;
  o.precision(3);
  o << "the fill folds at u = " << c.foldU << ", v = " << c.foldV << " (its normal turns over): move its centre, lower its height or its borders' power";
  throw Error(ErrorCode::InvalidField, fill.fill().path + ": " + o.str());
}

}  // namespace pdesurf
