// A boundary function of v outside the closed-form families, typed as an expression
// ("sqrt((r+k1)^2 - s^2*cos(v)^2)"). Its first two v-derivatives (normals, curvature) are
// formed symbolically on demand and cached; higher ones (the general methods' residuals and
// end matching) come from Taylor arithmetic at the point (expr/taylor.hpp).
#pragma once
#include <string>
#include <vector>

#include "basis/vfunction.hpp"
#include "expr/expr.hpp"
#include "expr/program.hpp"

namespace pdesurf {

class GeneralFunction {
 public:
  GeneralFunction(std::string text, Expr e) : text_(std::move(text)) { derivs_.push_back(std::move(e)); }
  const std::string& text() const { return text_; }
  const Expr& expr() const { return derivs_.front(); }
  // A family function marked "general" in the scene remembers what it is, so the exact
  // (closed) solution stays available to measure the general methods against.
  bool hasOrigin = false;
  VFunction origin;
  // d^k g / dv^k at v; NaN or inf where the expression is not finite (callers check).
  double eval(double v, int k) const;
  // The same at v[0..n) into out: for k <= 2 one compiled program over all the points (each
  // shared node once per point, each instruction across the points), which is what a Fourier
  // projection or a grid needs; a fill's loop is a graph of thousands of nodes. A large
  // expression's eval (k <= 2) runs the same program at its one point.
  void evalMany(const double* v, size_t n, int k, double* out) const;
  // Orders 0..maxK (≤ 2) at once: outs[k][i] = d^k g / dv^k (v[i]); one program whose shared
  // nodes (the value's sines and powers recur in its derivatives) run once per point.
  void evalManyUpTo(const double* v, size_t n, int maxK, double* const* outs) const;
  // d^k g / dv^k as an expression, built on first use under the derivative budget (throws
  // Error(TooLarge) when one order would exceed it).
  const Expr& derivativeExpr(int k) const;

 private:
  std::string text_;
  mutable std::vector<Expr> derivs_;  // derivs_[k] = k-th derivative, grown on demand
  // One compiled program per highest order, for every caller (point, line, orders at once):
  // the same derivative compiled once, not once per way of asking.
  const ExprProgram& upTo(int maxK) const;
  mutable std::vector<std::shared_ptr<const ExprProgram>> upTo_;  // upTo_[k] runs derivs_[0..k]
};

}  // namespace pdesurf
