// Where two of a fill's sides meet (scene/fill_conditions.cpp, docs/chains-and-fills.md).
// Both are per corner and per side: (a, b) at the side's start, (a, b) at its end, linear in
// the side's σ between them. Internal to scene/.
#pragma once
#include <array>
#include <vector>

#include "scene/fill_sides.hpp"

namespace pdesurf {

using SideMix = std::array<double, 4>;

// Tangency: (γ, α) with X_u = γ k_k D_k + α T_k along side k, so that both sides leave each
// corner along one vector W (scale: each side's k_k).
std::vector<SideMix> cornerDirections(const std::vector<FillSide>& sides, const std::vector<double>& scale);

// Curvature: (δ_T, δ_D), the tangential part added to each side's X_uu so that both sides reach
// their mean at each corner; a corner where G2 is impossible is refused (Error InvalidField,
// naming it). radius: the loop's mean radius.
std::vector<SideMix> curvatureCorners(const FillLoop& loop, const std::vector<FillSide>& sides, const std::vector<double>& scale,
                                      const std::vector<SideMix>& mix, double radius);

}  // namespace pdesurf
