// The Bloor-Wilson baselines that seed 000 Section 3 compares against (Eqs. 20-23).
// fourier:N expands every boundary function in an N-term Fourier series on the v-range (the
// periodic extension: open data such as v and e^v on [0, 2π] become saw-tooth-like) and
// solves each mode exactly. pseudo-spectral:N adds the remainder
//   R = r1(v) e^{ωu} + r2(v) u e^{ωu} + r3(v) e^{-ωu} + r4(v) u e^{-ωu}      (Eq. 22)
// with r_i(v) fixed pointwise by the boundary conditions, so those hold exactly again. The
// papers leave ω open; pdesurf takes ω = a (N + 1), the decay rate of the first omitted mode
// (a = (d/b)^{1/4}, Bloor-Wilson's a for b = 1, c = 2a², d = a⁴). For order 2n the remainder
// space is the kernel of (∂²/∂u² - ω²)^n (n = 2: Eq. 22).
#include <cmath>

#include "common/errors.hpp"
#include "methods/approximate.hpp"
#include "methods/method.hpp"
#include "ode/even_ode.hpp"
#include "pde/closed_form.hpp"

namespace pdesurf {

namespace {

PdeProblem fourierProblem(const PdeProblem& p, int N) {
  for (const auto& c : p.component)
    if (!c.force.empty()) throw Error(ErrorCode::InvalidField, "the Bloor-Wilson methods do not take forces");
  return mapSlots(p, [&](const VExpansion& slot) { return fourierSeries(slot, p.v0, p.v1, N); });
}

}  // namespace

SeparableSurface solveFourier(const PdeProblem& p, int N) {
  if (N < 1 || N > 1000) throw Error(ErrorCode::InvalidField, "fourier needs 1 <= N <= 1000 terms");
  return solveClosedForm(fourierProblem(p, N));
}

SeparableSurface solvePseudoSpectral(const PdeProblem& p, int N) {
  if (N < 1 || N > 1000) throw Error(ErrorCode::InvalidField, "pseudo-spectral needs 1 <= N <= 1000 terms");
  const PdeProblem q = fourierProblem(p, N);
  SeparableSurface s = solveClosedForm(q);
  for (int c = 0; c < 3; ++c) {
    const ComponentProblem& cp = p.component[c];
    const int n = static_cast<int>(cp.alpha.size()) - 1;
    const double ratio = cp.alpha[n] / cp.alpha[0];
    const double a = ratio > 0 ? std::pow(ratio, 1.0 / (2 * n)) : 1.0;
    const double omega = a * (N + 1);
    std::vector<double> binomial(n + 1, 1.0);
    for (int k = 1; k <= n; ++k) binomial[k] = binomial[k - 1] * (n - k + 1) / k;
    const EvenOdeBasis remainder(binomial, -omega * omega);
    for (int end = 0; end < 2; ++end)
      for (int i = 0; i < n; ++i) {
        // psi carries a unit value in this boundary slot and zero in the others.
        std::vector<double> left(n, 0.0), right(n, 0.0);
        (end == 0 ? left : right)[i] = 1.0;
        const UFactor psi = remainder.solve(left.data(), right.data());
        auto add = [&](const VExpansion& terms, double sign) {
          for (const VTerm& t : terms) {
            UFactor f = psi;
            for (auto& piece : f.pieces)
              for (auto& coef : piece.poly) coef *= sign * t.coef;
            s.component[c].push_back({t.g, f});
          }
        };
        add((end == 0 ? cp.left : cp.right)[i], 1.0);   // exact boundary function
        add((end == 0 ? q.component[c].left : q.component[c].right)[i], -1.0);  // minus its series
      }
  }
  return s;
}

}  // namespace pdesurf
