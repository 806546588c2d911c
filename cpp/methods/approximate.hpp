// Approximations of boundary functions by basis families, so that the closed form can solve
// what the families cannot express: truncated Fourier series (periodic data; also the
// Bloor-Wilson baselines, which expand every boundary function so) and Chebyshev
// interpolants written as scaled powers ((v - c) w)^n (open data).
#pragma once
#include <functional>

#include "pde/pde_problem.hpp"

namespace pdesurf {

double expansionValue(const VExpansion& f, double v, int k = 0);

// f ≈ a_0 + Σ_{k=1}^{N} a_k cos(k ω v) + b_k sin(k ω v), ω = 2π / (v1 - v0): the Fourier series
// of f's periodic extension, coefficients by the trapezoidal rule (which takes the mean of a
// jump at the ends, as the series does).
// dropNoise (the modal method): modes below 1e-15 of the largest, or below noiseFloor (the
// rounding of f's samples), are left out: their noise would enter v-derivatives times (kω)^j.
// The Bloor-Wilson baselines keep every mode, as published.
VExpansion fourierSeries(const VExpansion& f, double v0, double v1, int N, double noiseFloor = 0.0, bool dropNoise = false);
// The same for several expansions over one period: their general terms are sampled by one
// program, so what they share (a fill's loop: its sides' curves, in every slot) runs once.
// Each result is fourierSeries's for that expansion, to the bit.
std::vector<VExpansion> fourierSeriesMany(const std::vector<const VExpansion*>& fs, double v0, double v1, int N, double noiseFloor = 0.0,
                                          bool dropNoise = false);

// The degree-N Chebyshev interpolant of f on [v0, v1] as powers of s = (v - c) w in [-1, 1].
VExpansion chebyshevInterpolant(const VExpansion& f, double v0, double v1, int N);

// Open data: p + the Fourier series of f - p, p the Hermite interpolant of degree 2m+1 (scaled
// powers) matching f's derivatives 0..m at v0 and v1 (methods/end_matched_fourier.cpp).
VExpansion endMatchedFourier(const VExpansion& f, double v0, double v1, int N, int m);

// Whether f and its first two derivatives agree at v0 and v1 (so Fourier modes converge fast).
bool isPeriodic(const VExpansion& f, double v0, double v1);
// A tube with a corner on its seam (a lens rim, a trailing edge): every slot of both ends takes
// the same value at v0 and v1 (both u-edges are loops), but some slot's first or second
// derivative differs there. The closed form continues such data past v1 analytically, not
// periodically: unless its families close term by term (familyTermsClose), its interior does
// not close. The modal method expands the loop whole instead.
bool hasSeamCorner(const PdeProblem& p);
// Whether every family term of every slot takes the same value at v0 and v1: the closed form,
// which solves term by term, then closes (seed 000 Fig. 4a's sin(v/2) edge: sharp along its
// whole seam, as the paper has it), whatever the data's corners.
bool familyTermsClose(const PdeProblem& p);

// A general force f(u, v) as family force terms: in v its Fourier series (periodic in v) or
// Chebyshev interpolant (not), N terms as above; in u the Chebyshev interpolant of degree
// min(N, 16) of each coefficient on [0, 1].
std::vector<ForceTerm> approximateForce(const GeneralForce& f, double v0, double v1, int N);

// The problem without anything general (slots' general terms and general forces dropped).
PdeProblem familyProblem(const PdeProblem& p);

// A copy of the problem with every boundary slot (component, end, derivative) replaced by map(slot).
PdeProblem mapSlots(const PdeProblem& p, const std::function<VExpansion(const VExpansion&)>& map);

// The general (expression) terms of a slot, and the rest.
VExpansion generalPart(const VExpansion& slot);
VExpansion familyPart(const VExpansion& slot);
bool hasGeneralTerms(const PdeProblem& p);
// Family terms marked "general" turned back into their families; true if nothing general is left.
bool restoreFamilies(const PdeProblem& p, PdeProblem* out);

}  // namespace pdesurf
