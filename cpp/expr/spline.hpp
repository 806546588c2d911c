// A piecewise polynomial of one argument in B-spline form, Σ_i c_i N_{i,p}(x) over a knot
// vector of n + p + 1 non-decreasing knots: what the expression language's spline nodes call
// (expr/expr.hpp spline()). A NURBS surface's coordinates, weights and border curves are
// built from them (scene/nurbs_surface.hpp), so every part of the core that takes a typed
// surface — drawing, blends by reference, trimlines, fills, the certified CAD fit — takes a
// B-spline surface too, evaluated in the basis its data live in (de Boor), never converted.
#pragma once
#include <memory>
#include <string>
#include <vector>

namespace pdesurf {

class SplineFn {
 public:
  // Degrees up to kMaxBasis - 1 (the scene's limit, limits::kNurbsDegree, is below it).
  static constexpr int kMaxBasis = 32;
  // Why (degree, knots, coefs) is not a B-spline function, or "" when it is one: n >= p + 1
  // coefficients, 0 <= p < kMaxBasis, n + p + 1 finite non-decreasing knots, a non-empty domain, no interior knot
  // repeated more than p times (the function is continuous), finite coefficients.
  static std::string problem(int degree, const std::vector<double>& knots, const std::vector<double>& coefs);
  // Assumes problem(...) is empty.
  SplineFn(int degree, std::vector<double> knots, std::vector<double> coefs);

  int degree() const { return p_; }
  const std::vector<double>& knots() const { return t_; }
  const std::vector<double>& coefs() const { return c_; }
  // The domain [t_p, t_n]; outside it the end pieces continue as polynomials.
  double lo() const { return t_[size_t(p_)]; }
  double hi() const { return t_[c_.size()]; }
  double eval(double x) const;
  // The same in two steps, so that splines on one knot vector share the first (a NURBS
  // surface's many basis and coefficient splines; expr/program.cpp): the piece k holding x and
  // the p + 1 basis functions non-zero there, N[j] = N_{k-p+j,p}(x) (past the domain, the end
  // piece's polynomials); then Σ_j c_{k-p+j} N[j]. eval(x) is exactly these two.
  int span(double x) const;  // t_k <= x < t_{k+1}, p <= k < n (clamped to the end pieces)
  void basis(int k, double x, double* N) const;
  double combine(int k, const double* N) const;
  // The same degree and knots: one basis for both.
  bool sameBasis(const SplineFn& o) const { return p_ == o.p_ && t_ == o.t_; }
  // The derivative as a B-spline of degree p - 1 (built with this one); null for degree 0.
  const std::shared_ptr<const SplineFn>& derivative() const { return derivative_; }
  // The k-th derivative at x (0 past the degree).
  double derivativeAt(double x, int k) const;
  // lo <= f <= hi on [a, b]: the coefficients of the pieces it spans (convex hull), and past
  // the domain's ends the end pieces' Taylor bounds; false when [a, b] is not finite.
  bool range(double a, double b, double* lo, double* hi) const;
  // The distinct knots inside the domain, where a derivative may jump.
  std::vector<double> breaks() const;
  // Those repeated p times: the function is only continuous there (a crease of a surface).
  std::vector<double> kinks() const;

 private:
  int p_;
  std::vector<double> t_, c_;
  // The coefficients' non-zero index range [nonzeroFirst_, nonzeroLast_] (empty when all are
  // zero): a piece whose p + 1 coefficients are all zero is 0 without any arithmetic (a unit
  // basis function is non-zero on p + 1 of its pieces).
  int nonzeroFirst_ = 0, nonzeroLast_ = -1;
  std::shared_ptr<const SplineFn> derivative_;
};

}  // namespace pdesurf
