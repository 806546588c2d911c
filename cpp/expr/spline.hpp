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
  // Why (degree, knots, coefs) is not a B-spline function, or "" when it is one: n >= p + 1
  // coefficients, n + p + 1 finite non-decreasing knots, a non-empty domain, no interior knot
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
  int span(double x) const;  // k with t_k <= x < t_{k+1}, p <= k < n (clamped to the end pieces)
  int p_;
  std::vector<double> t_, c_;
  std::shared_ptr<const SplineFn> derivative_;
};

}  // namespace pdesurf
