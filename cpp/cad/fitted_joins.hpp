// The join certificate (analysis/join_certificate.hpp) measured on the exported faces: every
// declared join between the fitted B-splines of its two patches, at the same points and by the
// same figures as between the solved surfaces. It checks what the certified fit implies,
// neighbour against neighbour: the gap within the two faces' deviations plus the surfaces' own,
// and, where the join promises G1 or more, normals within FitOptions::normalToleranceDeg.
#pragma once
#include <vector>

#include "analysis/join_certificate.hpp"
#include "cad/scene_fit.hpp"

namespace pdesurf {

struct FittedJoin {
  JoinResult faces;     // measured between the fitted faces (its ok: the fit's promise, below)
  double surfacesGap;   // the same join between the solved surfaces, scene units
  double allowedGap;    // surfacesGap + both faces' certified deviations, scene units
  double allowedNormalDeg;  // the fit's normal target, for G1 and G2 joins (else 180)
};

// fits[i] is solved[i]'s (fitScene's order). Each join's scale is its own (JoinResult::size).
std::vector<FittedJoin> certifyFittedJoins(const Scene& scene, const std::vector<SolvedPatch>& solved,
                                           const std::vector<PatchFit>& fits,
                                           double normalToleranceDeg = FitOptions{}.normalToleranceDeg);

}  // namespace pdesurf
