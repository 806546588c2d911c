// Splits an expression into the terms the closed form solves and a remainder for the general
// methods. The expression is expanded into a sum of products (sums, constant factors, integer
// powers, products of exponentials, product-to-sum rules for sines and cosines, shifts
// cos(w v + φ) = cos φ cos(wv) - sin φ sin(wv)); each product that reduces to
//   constant × F(v) × H(s)
// with F and H in the families (v^n, cos, sin, exp, cosh/sinh as exponentials) becomes a term;
// everything else (sqrt(...), v cos v, general(...)) stays in the remainder, as an expression.
// s is the second variable (u in forces, t in primary surfaces); H must be a power of s when
// `secondPolynomialOnly` (forces keep a polynomial in u).
#pragma once
#include <vector>

#include "basis/vfunction.hpp"
#include "expr/expr.hpp"

namespace pdesurf {

struct SplitTerm {
  double coef = 0.0;
  VFunction v;  // family function of v
  VFunction s;  // family function of the second variable (Poly n = 0 when absent)
};

struct Split {
  std::vector<SplitTerm> terms;
  Expr remainder;                   // their sum; nullptr when everything split
  std::vector<Expr> remainderParts; // one per product that did not split
};

Split splitExpression(const Expr& e, bool secondPolynomialOnly = false);

}  // namespace pdesurf
