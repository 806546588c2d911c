// A real function of u in closed form: G(u) = Re Σ_k e^{c_k (u - s_k)} P_k(u - s_k),
// with complex rates c_k, shifts s_k and complex polynomials P_k. Every u-factor pdesurf
// builds (exponentials, exponentials times polynomials, oscillating or growing, and plain
// polynomials) has this form, so one evaluator serves every PDE order and basis family.
// The shift keeps |e^{c(u-s)}| <= 1 on [0,1]: s = 1 when Re c > 0, so e^{ru} with large
// positive r is never formed unscaled.
#pragma once
#include <complex>
#include <map>
#include <utility>
#include <vector>

namespace pdesurf {

class BernsteinOnGrid;
using cplx = std::complex<double>;

// e^{c (u_i - s)} on one grid of u, kept per (c, s): a surface's terms share their rates (the
// x, y and z terms of one mode, its cosine and sine terms), so each exponential of a grid line
// is computed once, not once per term.
class ExpOnGrid {
 public:
  ExpOnGrid(const double* u, int count) : u_(u), count_(count) {}
  const cplx* values(cplx rate, double shift);

 private:
  const double* u_;
  int count_;
  std::map<std::pair<std::pair<double, double>, double>, std::vector<cplx>> kept_;
};

struct ExpPoly {
  cplx rate = 0.0;             // c
  double shift = 0.0;          // s
  std::vector<cplx> poly;      // P, ascending powers of (u - s)
};

// Coefficients of (c + d/dx)^m P, ascending powers.
std::vector<cplx> derivativePoly(const std::vector<cplx>& p, cplx rate, int m);
cplx evalPoly(const std::vector<cplx>& p, cplx x);

class UFactor {
 public:
  std::vector<ExpPoly> pieces;
  // Or, when not empty: G(u) = Σ_i b_i B_i^n(u) on [0, 1] in Bernstein form (n = size - 1), the
  // u-factor of a Bézier patch, evaluated in the basis its data live in (pieces then empty).
  std::vector<double> bernstein;

  static UFactor polynomial(const std::vector<double>& ascending);  // a real polynomial in u
  static UFactor bernsteinForm(const std::vector<double>& coefs);
  // The m-th derivative at u.
  double eval(double u, int m = 0) const;
  // out[k * count + i] = G^{(k)}(u[i]) for k = 0..maxDerivative. Derivative polynomials are
  // formed once per piece, the exponential once per point and piece, or taken from `exps` (the
  // same points) when given, shared with other terms. A Bernstein-form factor takes its basis
  // values from `basis` (the same points) when given, shared with other terms.
  void tabulate(const double* u, int count, int maxDerivative, double* out, BernsteinOnGrid* basis = nullptr,
                ExpOnGrid* exps = nullptr) const;
};

}  // namespace pdesurf
