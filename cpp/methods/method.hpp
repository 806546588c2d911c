// How a PDE patch is solved. Family terms always get the closed form; the method decides what
// happens to the rest (boundary functions typed as expressions, or family terms marked
// "general"), or, for the Bloor-Wilson baselines, to everything.
//   closed            every term in closed form (fails on general terms)
//   pseudo-navier     seed 000 Eqs. 9-15: Hermite polynomial in u times each general function,
//                     plus u^{n-1}(u-1)^n Σ A_mn sin(mu) sin(nv) fitted to the PDE residual
//                     at collocation points; options ":M,N,L" (default 3,3,49)
//   modal:N           general functions replaced by N Fourier modes (periodic data), or (open
//                     data) a degree-N Chebyshev interpolant (N <= 20) or N Fourier modes
//                     after a Hermite end match (N > 20), then solved exactly; the boundary
//                     data are then imposed exactly (a Hermite lift in u)
//   fourier:N         Bloor-Wilson: every boundary function as an N-term Fourier series
//   pseudo-spectral:N fourier:N plus Bloor-Wilson's remainder meeting the boundary conditions
//   reference         modal with N raised until the surface stops changing (1e-12)
//   auto              closed if possible, else modal with N raised until the change is below
//                     1e-9 (cheaper than reference, far below what a screen shows)
// Every method auto picks meets the boundary data exactly (to rounding): a blend is judged at
// its joins. The interior's accuracy is the PDE residual (interiorResidual, methods/measures.hpp).
#pragma once
#include <string>
#include <vector>

#include "pde/pde_problem.hpp"
#include "surface/separable_surface.hpp"

namespace pdesurf {

enum class MethodKind { Auto, Closed, PseudoNavier, Modal, Fourier, PseudoSpectral, Reference };

struct Method {
  MethodKind kind = MethodKind::Auto;
  int terms = 0;                                    // N of modal, fourier, pseudo-spectral
  int navierM = 3, navierN = 3, navierPoints = 49;  // pseudo-navier
};

// Throws Error(InvalidField) for an unknown name or bad option.
Method parseMethod(const std::string& text);
std::string methodName(const Method& m);

// The methods that can solve this problem, by name (for pickers and `pdesurf compare`).
std::vector<std::string> applicableMethods(const PdeProblem& p);

struct MethodSolution {
  SeparableSurface surface;
  Method used;  // auto resolved
  int referenceTerms = 0;        // reference: the N it settled on
  double referenceChange = 0.0;  // reference: the last change between N and 2N
};

class BasisCache;
// `cache` (optional) keeps the closed form's ODE bases between solves.
MethodSolution solveWithMethod(const PdeProblem& p, const Method& m, BasisCache* cache = nullptr);

// The pieces, for tests and benchmarks.
SeparableSurface solvePseudoNavier(const PdeProblem& p, int M, int N, int points);
SeparableSurface solveModal(const PdeProblem& p, int N, BasisCache* cache = nullptr);
SeparableSurface solveFourier(const PdeProblem& p, int N);
SeparableSurface solvePseudoSpectral(const PdeProblem& p, int N);
MethodSolution solveReference(const PdeProblem& p, double tolerance = 1e-12, BasisCache* cache = nullptr);

}  // namespace pdesurf
