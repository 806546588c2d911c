// pdesurf's converging method: each general boundary function is replaced by N of its Fourier
// modes (periodic data), or, on an open v-range, by its Chebyshev interpolant of degree N
// (N <= 20) or N Fourier modes of what is left after a Hermite polynomial matching its ends is
// taken off (N > 20, methods/end_matched_fourier.cpp); the whole problem is then solved
// exactly. Family terms are untouched. The boundary data are then imposed exactly
// (methods/boundary_lift.hpp), so N decides the interior only, measured by the PDE residual
// (interiorResidual, methods/measures.hpp): geometric convergence for smooth periodic data, for open data
// geometric up to degree 20 and then algebraic (like N^-(m+1)).
#include <algorithm>
#include <cmath>

#include "basis/spline_data.hpp"
#include "basis/general_function.hpp"
#include "common/errors.hpp"
#include "methods/approximate.hpp"
#include "methods/boundary_lift.hpp"
#include "methods/method.hpp"
#include "pde/closed_form.hpp"
#include "surface/mesh.hpp"

namespace pdesurf {

namespace {

// Open data up to this N: the Chebyshev interpolant of degree N, in scaled powers of v. Past
// degree ~20 the closed form cannot take it (the triangular system multiplies the tiny
// high-degree coefficients by factors that grow like factorials, faster than they shrink:
// seed 000 Eq. 17 gives E = 4e-7 at 20, 8e-4 at 24), so past it, N Fourier modes after an end
// match. A polynomial continues the data past the v-range analytically, as the closed form
// does its families (on an open range the PDE has no conditions at the v ends, so the
// continuation decides the interior); the end-matched series continues them periodically,
// stably for any smooth data. Derivatives matched at the ends: 2n + 2 for order 2n, so the
// lift's residual, which takes 2n v-derivatives of the approximation error, still falls like
// N^-3; at most 8 (a Hermite polynomial of degree 17, well conditioned in scaled powers).
constexpr int kMaxOpenDegree = 20;
int endMatchOrder(const ComponentProblem& c) { return std::min(2 * static_cast<int>(c.alpha.size()), 8); }
// B-spline data (a NURBS border, its tangents) are matched at the ends to this order at most.
// Their ends' higher derivatives belong to the end pieces (or to a rational curve whose weights
// bend them), not to one smooth function: the Hermite polynomial through them has v-derivatives
// far beyond the data's, which its closed form multiplies into the blend. On 36 random NURBS
// blends (tests/native/nurbs_surface_test.cpp), order 2 left blends 6..2 400 times the sheets'
// size, 4 also failed a join (G2 3.7e-5), 6 (the order for smooth data) gave 10^5; orders 0
// and 1 kept every blend at the sheets' size and every join certified.
constexpr int kSplineDataMatch = 1;

PdeProblem modalProblem(const PdeProblem& p, int N, bool loop) {
  PdeProblem q = p;
  static const char* axis[3] = {"x", "y", "z"};
  // The slots expanded as Fourier series, over every component: sampled together below (a
  // loop's slots are its sides' curves and their derivatives: one program runs what they share).
  struct Periodic {
    int component;
    VExpansion* slot;
    VExpansion data;
  };
  std::vector<Periodic> periodic;
  for (int k = 0; k < 3; ++k) {
    auto& c = q.component[k];
    const int m = endMatchOrder(c);
    try {
      for (auto* side : {&c.left, &c.right})
        for (VExpansion& slot : *side) {
          // A loop's data are periodic as a whole, not term by term (a side's family terms, a
          // power of v, do not close): the whole slot is expanded. A fill's slot of families
          // alone (one closed border given by families, a wing's tip) stays exact: its seam
          // closes to 8e-15 so, and the Fourier modes of its corner would leave 0.33° beside a
          // round leading edge (0.0009° kept exact); a tube's is expanded, or it tears.
          const VExpansion general = generalPart(slot);
          if (general.empty() && (!loop || p.periodicV)) continue;
          VExpansion gen = loop ? slot : general;
          slot = loop ? VExpansion{} : familyPart(slot);
          if (loop || isPeriodic(gen, p.v0, p.v1)) {
            periodic.push_back({k, &slot, std::move(gen)});
            continue;
          }
          // Open data from a B-spline border (a NURBS surface's, expr/spline.hpp) are matched
          // at the ends to first order at most, and never by one polynomial of high degree.
          const bool spline = hasSplineData(gen);
          const VExpansion approx = N <= kMaxOpenDegree && !spline ? chebyshevInterpolant(gen, p.v0, p.v1, N)
                                                                   : endMatchedFourier(gen, p.v0, p.v1, N, spline ? std::min(m, kSplineDataMatch) : m);
          slot.insert(slot.end(), approx.begin(), approx.end());
        }
    } catch (const Error& e) {
      throw Error(e.code(), std::string("component ") + axis[k] + ": " + e.what());
    }
  }
  if (!periodic.empty()) {
    std::vector<const VExpansion*> data;
    for (const Periodic& d : periodic) data.push_back(&d.data);
    std::vector<VExpansion> series;
    try {
      series = fourierSeriesMany(data, p.v0, p.v1, N, 0.0, true);
    } catch (const Error& e) {
      // A sample that is not finite: named by the first slot that has one, with its component.
      for (const Periodic& d : periodic) {
        try {
          fourierSeries(d.data, p.v0, p.v1, N, 0.0, true);
        } catch (const Error& one) {
          throw Error(one.code(), std::string("component ") + axis[d.component] + ": " + one.what());
        }
      }
      throw;
    }
    for (size_t i = 0; i < periodic.size(); ++i) periodic[i].slot->insert(periodic[i].slot->end(), series[i].begin(), series[i].end());
  }
  for (int k = 0; k < 3; ++k) {
    auto& c = q.component[k];
    for (const GeneralForce& f : c.generalForce) {
      try {
        const auto terms = approximateForce(f, p.v0, p.v1, N);
        c.force.insert(c.force.end(), terms.begin(), terms.end());
      } catch (const Error& e) {
        throw Error(e.code(), std::string("component ") + axis[k] + ": force: " + e.what());
      }
    }
    c.generalForce.clear();
  }
  return q;
}

// Largest difference between two surfaces over a 33×33 grid, relative to the first's size
// (tabulated: both are separable).
double change(const SeparableSurface& a, const SeparableSurface& b) {
  const GridSamples ga = sampleGrid(a, 32, 32), gb = sampleGrid(b, 32, 32);
  double diff = 0.0, size = 0.0;
  for (size_t k = 0; k < ga.X.size(); k += 3) {
    const Eigen::Vector3d pa(ga.X[k], ga.X[k + 1], ga.X[k + 2]), pb(gb.X[k], gb.X[k + 1], gb.X[k + 2]);
    diff = std::max(diff, (pa - pb).norm());
    size = std::max(size, pa.norm());
  }
  return diff / std::max(size, 1e-300);
}

bool allPeriodic(const PdeProblem& p) {
  if (p.periodicV) return true;
  for (const auto& c : p.component)
    for (const GeneralForce& f : c.generalForce)
      for (double u : {0.0, 0.5, 1.0}) {
        VFunction g;
        g.family = Family::General;
        g.general = std::make_shared<GeneralFunction>(f.text, substitute(f.f, ExprVar::U, u));
        if (!isPeriodic({{g, 1.0}}, p.v0, p.v1)) return false;
      }
  for (const auto& c : p.component)
    for (const auto* side : {&c.left, &c.right})
      for (const VExpansion& slot : *side) {
        const VExpansion gen = generalPart(slot);
        if (!gen.empty() && !isPeriodic(gen, p.v0, p.v1)) return false;
      }
  return true;
}

// Solves at each N of `steps` until one changes the surface by less than the tolerance. The
// change is not monotone (a mode that happens to be small, rounding), so one step that does
// not improve does not end the search: two in a row do, or the last step, keeping the step
// whose change was smallest.
void refine(const PdeProblem& p, const std::vector<int>& steps, double tolerance, BasisCache* cache, MethodSolution* out) {
  constexpr int kPatience = 2;
  SeparableSurface prev = solveModal(p, steps[0], cache);
  double best = INFINITY;
  int worse = 0;
  out->referenceChange = INFINITY;
  for (size_t k = 1; k < steps.size(); ++k) {
    SeparableSurface cur = solveModal(p, steps[k], cache);
    const double c = change(prev, cur);
    if (c < best) {
      best = c;
      out->surface = cur;
      out->referenceTerms = steps[k];
      out->referenceChange = c;
      worse = 0;
      if (c < tolerance) return;
    } else if (++worse >= kPatience) {
      return;
    }
    prev = std::move(cur);
  }
}

bool hasGeneralSlots(const PdeProblem& p) {
  for (const auto& c : p.component)
    for (const auto* side : {&c.left, &c.right})
      for (const VExpansion& slot : *side)
        if (!generalPart(slot).empty()) return true;
  return false;
}

}  // namespace

SeparableSurface solveModal(const PdeProblem& p, int N, BasisCache* cache) {
  if (N < 1 || N > 2048) throw Error(ErrorCode::InvalidField, "modal needs 1 <= N <= 2048 terms");
  const bool loop = p.periodicV || hasSeamCorner(p);
  SeparableSurface s = solveClosedForm(modalProblem(p, N, loop), cache);
  // The joins exact, whatever N; a loop's corners (a fill's, a tube's seam) carried only near
  // the edge that has them. A fill's u = 1 is its centre, given whole: no remainder to carry.
  if (loop || hasGeneralSlots(p)) {
    const double rate = 2 * (N + 1.0);
    LiftDecay decay;
    if (loop) decay = {rate, p.periodicV ? 0.0 : rate};
    imposeBoundaryData(s, p, decay);
  }
  return s;
}

MethodSolution solveReference(const PdeProblem& p, double tolerance, BasisCache* cache) {
  MethodSolution out;
  PdeProblem restored;
  if (restoreFamilies(p, &restored)) {
    out.surface = solveClosedForm(restored, cache);
    out.used.kind = MethodKind::Closed;
    return out;
  }
  out.used.kind = MethodKind::Reference;
  // N doubles until the surface stops changing. Open data go straight to the end-matched
  // Fourier modes (N > 20): the Chebyshev interpolants' polynomial continuation is unstable
  // near degree 20 (the interior can move by 7 % between degrees 16 and 20 with the boundary
  // data met to 1e-9), the periodic one is not.
  std::vector<int> steps;
  for (int N = allPeriodic(p) ? 16 : 32; N <= 1024; N *= 2) steps.push_back(N);
  refine(p, steps, tolerance, cache, &out);
  return out;
}

}  // namespace pdesurf
