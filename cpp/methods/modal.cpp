// pdesurf's converging method: each general boundary function is replaced by N of its Fourier
// modes (when it is periodic on the v-range) or by its Chebyshev interpolant of degree
// min(N, 20) (when not), and the whole problem is then solved exactly. Family terms are
// untouched. The error falls with N like the approximation of the boundary data:
// geometrically for smooth periodic data; for open data down to ~1e-7 (see kMaxOpenDegree).
#include <cmath>

#include "basis/general_function.hpp"
#include "common/errors.hpp"
#include "methods/approximate.hpp"
#include "methods/method.hpp"
#include "pde/closed_form.hpp"
#include "surface/mesh.hpp"

namespace pdesurf {

namespace {

// Past degree ~20 the polynomial solution diverges: the triangular system multiplies the
// interpolant's tiny high-degree coefficients by factors that grow like factorials, faster
// than they shrink (measured on seed 000 Eq. 17: E = 4e-7 at 20, 8e-4 at 24; the same with
// long double, so it is the map, not rounding).
constexpr int kMaxOpenDegree = 20;

PdeProblem modalProblem(const PdeProblem& p, int N) {
  PdeProblem q = mapSlots(p, [&](const VExpansion& slot) {
    VExpansion out = familyPart(slot);
    const VExpansion gen = generalPart(slot);
    if (gen.empty()) return out;
    const VExpansion approx = isPeriodic(gen, p.v0, p.v1) ? fourierSeries(gen, p.v0, p.v1, N)
                                                          : chebyshevInterpolant(gen, p.v0, p.v1, std::min(N, kMaxOpenDegree));
    out.insert(out.end(), approx.begin(), approx.end());
    return out;
  });
  static const char* axis[3] = {"x", "y", "z"};
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

}  // namespace

SeparableSurface solveModal(const PdeProblem& p, int N, BasisCache* cache) {
  if (N < 1 || N > 2048) throw Error(ErrorCode::InvalidField, "modal needs 1 <= N <= 2048 terms");
  return solveClosedForm(modalProblem(p, N), cache);
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
  // Periodic data: Fourier modes converge geometrically; double N until nothing changes.
  // Open data: Chebyshev degrees up to kMaxOpenDegree, stopping where the change is smallest
  // (past it, rounding in the polynomial solve grows faster than the interpolant improves).
  const bool periodic = allPeriodic(p);
  std::vector<int> steps;
  if (periodic)
    for (int N = 16; N <= 1024; N *= 2) steps.push_back(N);
  else
    for (int N = 4; N <= kMaxOpenDegree; N += 2) steps.push_back(N);
  SeparableSurface prev = solveModal(p, steps[0], cache);
  double best = INFINITY;
  for (size_t k = 1; k < steps.size(); ++k) {
    SeparableSurface cur = solveModal(p, steps[k], cache);
    const double c = change(prev, cur);
    if (!periodic && c > best) break;  // the previous step was the most accurate
    best = c;
    out.surface = cur;
    out.referenceTerms = steps[k];
    out.referenceChange = c;
    if (c < tolerance) break;
    prev = std::move(cur);
  }
  return out;
}

}  // namespace pdesurf
