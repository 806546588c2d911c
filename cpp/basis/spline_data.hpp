// Whether boundary data come from B-spline functions (a NURBS surface's border curves and
// their tangents, expr/spline.hpp): the modal method continues such open data differently
// (methods/modal.cpp, kSplineDataMatch).
#pragma once
#include "pde/pde_problem.hpp"

namespace pdesurf {

bool hasSplineData(const VExpansion& f);

}  // namespace pdesurf
