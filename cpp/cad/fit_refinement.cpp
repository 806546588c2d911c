#include "cad/fit_refinement.hpp"

#include "cad/bspline_fit.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace pdesurf {
namespace {

// Spans on either side cut with one whose border normal misses its target.
constexpr int kNormalSpread = 2;
// Certificate cells per span (a span starts with 4) before the span itself is cut.
constexpr int kMaxCellsPerSpan = 64;
// At most this many pieces of a span, or times its cells, in one round: the predictions come
// from asymptotic orders that a coarse round may not have reached.
constexpr int kMaxFactor = 4;

// Pieces that bring a span's residual r to a quarter of the tolerance when it falls as h^(p+1).
int piecesFor(double r, double tolerance, int degree) {
  if (r <= tolerance / 4) return 1;
  if (!std::isfinite(r)) return 2;
  const double k = std::ceil(std::pow(r / (tolerance / 4), 1.0 / (degree + 1)));
  return int(std::clamp(k, 2.0, double(kMaxFactor)));
}

// Times more cells that bring a slack s (falling as h²) within a budget b.
int cellFactor(double s, double b) {
  if (s <= b) return 1;
  return int(std::clamp(std::ceil(std::sqrt(s / b)), 2.0, double(kMaxFactor)));
}

}  // namespace

SpanSet initialSpans(double a, double b, int spans, int cells, const std::vector<double>& creases) {
  const double near = 0.1 * (b - a) / spans;
  std::vector<std::pair<double, bool>> all;
  for (int i = 0; i <= spans; ++i) {
    const double t = i == spans ? b : a + (b - a) * i / spans;
    const bool end = i == 0 || i == spans;
    bool clash = false;
    for (double c : creases) clash = clash || std::abs(c - t) < near;
    if (end || !clash) all.push_back({t, false});
  }
  for (double c : creases) all.push_back({c, true});
  std::sort(all.begin(), all.end());
  SpanSet out;
  for (size_t i = 0; i < all.size(); ++i) {
    // A piece between two creases (or a crease and an end) that is a single span is halved: a
    // degree-5 piece of one span has six poles against the five grid points a span starts
    // with (a fill of three sides has such pieces next to its seam).
    if (i > 0 && (all[i].second || i + 1 == all.size()) && (all[i - 1].second || i == 1))
      out.breaks.push_back((all[i - 1].first + all[i].first) / 2), out.crease.push_back(false);
    out.breaks.push_back(all[i].first), out.crease.push_back(all[i].second);
  }
  out.cuts.assign(out.breaks.size() - 1, cells);
  return out;
}

void certificateLine(const SpanSet& s, std::vector<double>* t, std::vector<int>* spanOf) {
  t->clear();
  spanOf->clear();
  for (int k = 0; k < s.count(); ++k)
    for (int c = 0; c < s.cuts[size_t(k)]; ++c) {
      t->push_back(s.breaks[size_t(k)] + (s.breaks[size_t(k) + 1] - s.breaks[size_t(k)]) * c / s.cuts[size_t(k)]);
      spanOf->push_back(k);
    }
  t->push_back(s.breaks.back());
}

bool RefinePlan::splitsSpans() const {
  auto any = [](const std::vector<int>& p) { return std::any_of(p.begin(), p.end(), [](int k) { return k > 1; }); };
  return any(piecesU) || any(piecesV);
}

RefinePlan planRefinement(const RefineInput& in) {
  const int nsu = in.u->count(), nsv = in.v->count();
  const double tol = in.tolerance;
  RefinePlan plan;
  plan.piecesU.resize(size_t(nsu));
  plan.piecesV.resize(size_t(nsv));
  // Cut a span whose own direction misses a quarter of the tolerance, into as many pieces as
  // its residual's order predicts.
  for (int i = 0; i < nsu; ++i) plan.piecesU[size_t(i)] = piecesFor((*in.uResidual)[size_t(i)], tol, in.degree);
  for (int j = 0; j < nsv; ++j) plan.piecesV[size_t(j)] = piecesFor((*in.vResidual)[size_t(j)], tol, in.degree);
  std::vector<int> finerU(size_t(nsu), 1), finerV(size_t(nsv), 1);
  const Certificate& cert = *in.cert;
  const CertificateGrid& grid = *in.grid;
  for (const FailedCell& f : cert.failed) {
    const bool normalMissed = !(f.normalDeg <= in.normalToleranceDeg);
    if (f.bound <= tol && !normalMissed) continue;
    const int su = grid.uSpan[size_t(f.i)], sv = grid.vSpan[size_t(f.j)];
    int& pu = plan.piecesU[size_t(su)];
    int& pv = plan.piecesV[size_t(sv)];
    if (normalMissed) {
      // A border's normal is B_u × B_v there, and both are v-fits (the u-ends are Hermite:
      // B_u is the v-fit of S_u, B_v the derivative of the v-fit of S): the v-spans decide
      // it. A span's position error e shows in B_v as about e / h, and least squares spreads
      // e from the neighbours into a span halved alone: halve its neighbours with it.
      for (int d = -kNormalSpread; d <= kNormalSpread; ++d) {
        const int k = in.periodicV ? ((sv + d) % nsv + nsv) % nsv : std::clamp(sv + d, 0, nsv - 1);
        plan.piecesV[size_t(k)] = std::max(plan.piecesV[size_t(k)], 2);
      }
    } else if (pu > 1 || pv > 1) {
      continue;  // cut anyway where its own direction's residual says so
    } else if (!(f.sampled <= tol / 2)) {
      pu = pv = 2;
    } else {
      // The samples are close and the bound's slack is the cause: finer cells in the
      // direction whose terms dominate it, as many times as the budget the other direction
      // leaves needs (finer in both at once multiplies the grid's points by both).
      const double budget = 0.9 * tol - f.sampled;
      const double left = std::max(budget - std::min(f.slackU, f.slackV), budget / 2);
      int& finer = f.slackU >= f.slackV ? finerU[size_t(su)] : finerV[size_t(sv)];
      finer = std::max({finer, 2, cellFactor(std::max(f.slackU, f.slackV), left)});
    }
  }
  // Finer cells shrink the bound's h² terms, but S's fourth-derivative bound stays the whole
  // span's: past kMaxCellsPerSpan a span is halved instead, so the bound becomes the halves'
  // own (a fill's boundary layer bounded over its first span had the cells of a span near its
  // end refined to 1024 and the certificate points run out 14 % short of the tolerance).
  auto cells = [](const SpanSet& s, std::vector<int>& pieces, const std::vector<int>& finer) {
    std::vector<int> cuts(s.cuts);
    for (size_t k = 0; k < cuts.size(); ++k) {
      if (pieces[k] > 1 || finer[k] == 1) continue;
      const int want = cuts[k] * finer[k];
      if (want <= kMaxCellsPerSpan) cuts[k] = want;
      else pieces[k] = 2, cuts[k] = std::max(cuts[k], std::min(want / 2, kMaxCellsPerSpan));
    }
    return cuts;
  };
  const std::vector<int> keepU = plan.piecesU, keepV = plan.piecesV;
  plan.cutsU = cells(*in.u, plan.piecesU, finerU);
  plan.cutsV = cells(*in.v, plan.piecesV, finerV);
  // Finer cells that would take the grid past its limit become halved spans with the cells
  // they have (as many points, and the halves' own, tighter, fourth-derivative bounds).
  auto points = [](const std::vector<int>& pieces, const std::vector<int>& cuts) {
    long n = 1;
    for (size_t k = 0; k < cuts.size(); ++k) n += long(pieces[k]) * cuts[k];
    return n;
  };
  if (points(plan.piecesU, plan.cutsU) * points(plan.piecesV, plan.cutsV) > kFitMaxGridPoints) {
    auto spansInstead = [](const SpanSet& s, const std::vector<int>& keep, const std::vector<int>& finer, RefinePlan::Pieces& pieces,
                           std::vector<int>& cuts) {
      for (size_t k = 0; k < cuts.size(); ++k)
        if (keep[k] == 1 && finer[k] > 1) pieces[k] = 2, cuts[k] = std::max(2, s.cuts[k] / 2);
    };
    spansInstead(*in.u, keepU, finerU, plan.piecesU, plan.cutsU);
    spansInstead(*in.v, keepV, finerV, plan.piecesV, plan.cutsV);
  }
  return plan;
}

void applyPlan(SpanSet& s, const std::vector<int>& pieces, const std::vector<int>& cuts) {
  SpanSet out;
  out.breaks.push_back(s.breaks.front());
  out.crease.push_back(s.crease.front());
  for (int k = 0; k < s.count(); ++k) {
    const double a = s.breaks[size_t(k)], b = s.breaks[size_t(k) + 1];
    const int n = pieces[size_t(k)];
    for (int m = 1; m <= n; ++m) {
      out.breaks.push_back(m == n ? b : a + (b - a) * m / n);
      out.crease.push_back(m == n ? bool(s.crease[size_t(k) + 1]) : false);
      out.cuts.push_back(cuts[size_t(k)]);
    }
  }
  s = std::move(out);
}

}  // namespace pdesurf
