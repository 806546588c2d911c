// Version 3: the checks of one end given by reference (docs/blends-by-reference.md, "Checks"),
// on the untrimmed surface S(t, v). The trimline t = tau(v) of a curve end must stay finite and
// inside the surface's t_range over the surface's whole v_range (where the trim applies);
// along the blend's v_range S and its t-derivatives must be finite and dS/dt must cross the
// trimline. Between the samples, a pole of tau is bracketed by refining where tau departs from
// its cubic Hermite interpolant, and a zero of dS/dt (or dS/dt parallel to the trimline) by a
// golden-section search from every sampled local minimum, so the verdict does not depend on a
// drawing grid. Every error names the end's path (".at" for the trimline) and the v at fault.
#pragma once
#include <array>

#include "scene/scene.hpp"

namespace pdesurf {

struct TrimlineExprs {
  Expr tau;                      // in v (a constant for an iso-line)
  std::array<Expr, 3> P, T, C;   // S, S_t, S_tt on the trimline, in v (C may be null)
};

// Throws Error(InvalidField | NonFinite) naming ref.path; returns the mean |S_t| along the
// blend's v-range [bv0, bv1] (for the "gap" scale).
double checkTrimline(const EndReference& ref, const PrimarySurface& S, const TrimlineExprs& e, double bv0, double bv1);

// Shortest text of a number for messages (6 significant digits).
std::string shortNumber(double x);

}  // namespace pdesurf
