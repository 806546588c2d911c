// Creases inside a patch, judged from outside as zebra shows them (docs/analysis.md): a(h), the
// largest angle between the unit normals of neighbouring samples (along u and along v) of a
// grid of step h over u in [u0 + 5 %, u1 - 5 %] and the whole v-range. On a smooth surface
// a(h) ≈ κ h, so a(h/2) ≈ a(h)/2; a crease of angle θ keeps a(h) ≥ θ at every h, so
// 2 a(h/2) - a(h) ≈ θ. The 5 % margins leave out the patch's own borders (a fill's corners,
// a pole), where the parametrisation, not the surface, turns fast. The two maxima may lie in
// different places: a smooth region whose turn varies fast (next to a fill's corner) can show
// a few hundredths of a degree at 128² that fall with refinement; a crease does not fall.
#pragma once
#include <string>

#include "surface/separable_surface.hpp"

namespace pdesurf {

struct InteriorCreases {
  std::string patch;
  double coarseDeg = 0.0, fineDeg = 0.0;  // a(h) on n × n and a(h/2) on 2n × 2n
  double creaseDeg = 0.0;                 // max(0, 2 a(h/2) - a(h))
  double u = 0.0, v = 0.0;                // where the fine grid's largest angle is
  bool ok = false;                        // creaseDeg <= kCreaseToleranceDeg
};

constexpr double kCreaseToleranceDeg = 0.01;
constexpr int kCreaseGrid = 128;

// margin: the part of the u-range left out at each end (0.05: the measure above). sharpSeam:
// the patch's seam is a declared edge (sharp in its data: a trailing edge), a border like
// u0 and u1, with the same margin left out of the v-range next to it (the edge rounds off
// inside as the PDE's modes decay: a turn the grid does not resolve, not a crease).
InteriorCreases measureCreases(const std::string& name, const SeparableSurface& s, int n = kCreaseGrid, double margin = 0.05,
                               bool sharpSeam = false);

}  // namespace pdesurf
