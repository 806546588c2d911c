// A surface written as separable sums: each coordinate is Σ_t G_t(u) g_t(v) with a closed-form
// u-factor G_t and a basis function g_t of v. Every surface pdesurf makes (PDE blends, ruled
// primary surfaces) has this form, so evaluation, sampling and tessellation are shared.
#pragma once
#include <Eigen/Core>
#include <array>
#include <vector>

#include "basis/vfunction.hpp"
#include "expr/expr.hpp"
#include "expr/program.hpp"
#include "ode/u_factor.hpp"

namespace pdesurf {

struct SeparableTerm {
  VFunction g;
  UFactor G;
};

struct SeparableSurface {
  double u0 = 0.0, u1 = 1.0;  // u-range (t-range for ruled surfaces)
  double v0 = 0.0, v1 = 0.0;
  std::array<std::vector<SeparableTerm>, 3> component;  // x, y, z
  // Parts of a primary surface that do not separate (an expression in u and v, evaluated
  // point by point); nullptr when none. PDE solutions never have them.
  std::array<Expr, 3> pointwise;
  // When not empty: pointwise[c] and its partial derivatives, X, X_u, X_v, X_uu, X_uv, X_vv,
  // built (and bounded) beforehand, e.g. for a surface trimmed along a curve.
  std::array<std::vector<Expr>, 3> pointwisePartials;
  // Those six partials compiled into one program per component, when they are built (a
  // primary's, once per solve): every tabulation of the surface (its mesh, each join's edge,
  // the crossings) runs it instead of compiling its own.
  std::array<std::shared_ptr<const ExprProgram>, 3> pointwisePrograms;
};

// ∂^{du+dv} X_c / ∂u^du ∂v^dv at (u, v) for component c (0, 1, 2).
double evalComponent(const SeparableSurface& s, int c, double u, double v, int du = 0, int dv = 0);
Eigen::Vector3d evalPoint(const SeparableSurface& s, double u, double v, int du = 0, int dv = 0);
// The six partials of pointwise[c] as one program: the surface's own when built, else
// compiled here; nullptr when the component has no pointwise part.
std::shared_ptr<const ExprProgram> pointwiseProgramOf(const SeparableSurface& s, int c);

}  // namespace pdesurf
