// Rigorous bounds of a separable surface's partial derivatives over the blocks of a grid of
// spans, for the fit certificate (cad/fit_certificate.hpp): each term's u-factor and v-factor
// bounded on each span from its closed form (exponential polynomials, Bernstein coefficients,
// the v-families' own formulas; general functions and pointwise parts by interval arithmetic
// over their symbolic derivatives), then |Σ_t G_t g_t| <= Σ_t max|G_t| max|g_t|.
#pragma once
#include <Eigen/Core>
#include <array>
#include <memory>
#include <map>
#include <tuple>
#include <vector>

#include "cad/fit_work.hpp"
#include "expr/interval.hpp"
#include "expr/program.hpp"
#include "surface/separable_surface.hpp"

namespace pdesurf {

// max |G^{(m)}(u)| over [a, b] (every u in the interval), slightly rounded up.
double boundUFactor(const UFactor& G, int m, double a, double b);
// max |g^{(k)}(v)| over [a, b]; +inf when it cannot be bounded (a general function's pole).
double boundVFunction(const VFunction& g, int k, double a, double b);

// Bounds of general functions already found during one fit, by (function, order, interval):
// refinement keeps most spans from one round to the next.
struct GeneralBoundCache {
  FitWork* work = nullptr;  // the scene's budget each enclosure is charged to (cad/fit_work.hpp)
  // A bound, the halvings found below its interval, and whether one of them stopped at the
  // halving limit (then it holds for that limit only).
  struct Bound {
    double value;
    int levels;
    bool limited;
  };
  std::map<std::tuple<const void*, int, double, double>, Bound> bounds;
  // Each general function's derivatives compiled once for enclosures and for sampling.
  struct Programs {
    std::shared_ptr<const IntervalProgram> enclose;
    std::shared_ptr<const ExprProgram> sample;
  };
  std::map<std::pair<const void*, int>, Programs> programs;
};

// bounds[c](i, j) >= |∂^du_u ∂^dv_v X_c| over [uBreaks[i], uBreaks[i+1]] × [vBreaks[j], vBreaks[j+1]].
// Throws Error(TooLarge) when a derivative of a general function or pointwise part would
// exceed the expression budget.
std::array<Eigen::MatrixXd, 3> boundPartials(const SeparableSurface& s, int du, int dv,
                                              const std::vector<double>& uBreaks, const std::vector<double>& vBreaks,
                                              GeneralBoundCache* cache = nullptr);

}  // namespace pdesurf
