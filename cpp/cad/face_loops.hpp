// A face's loop as the B-rep writers (IGES, .3dm) hand it to CAD: counter-clockwise in the
// surface's own (u, v), each use of an edge with its curve in that (u, v).
#pragma once
#include <vector>

#include "cad/brep_topology.hpp"
#include "cad/bspline_surface.hpp"

namespace pdesurf {

// The curve in face f's (u, v) of a use of an edge in its loop, over the edge curve's
// parameter (running with the curve, whatever the use's direction): the join's map where the
// topology made one (the other face of a shared edge), else the border's iso-line; a seam's two
// uses lie on v0 and v1 (the use running with the curve is v0's: the loop takes v0 forward).
BrepPcurve usePcurve(const BSplineSurface& s, const BrepTopology& t, int f, const BrepEdgeUse& u);

// Face f's loop counter-clockwise about its surface's own normal: a flipped face's topology
// loop turned back.
std::vector<BrepEdgeUse> surfaceLoop(const BrepTopology& t, size_t f);

}  // namespace pdesurf
