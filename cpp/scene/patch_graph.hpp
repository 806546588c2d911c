// Version 4: patches whose conditions come from other patches (chained ends, fills' borders,
// docs/chains-and-fills.md). Once every patch is read: each reference is checked
// against the patch it names, recorded as a join on that patch (Patch::meets, for the
// certificate) and as a dependency; the scene gets an order to solve in, or a cycle is refused.
#pragma once
#include "scene/scene.hpp"

namespace pdesurf {

// Throws Error(UnknownName | InvalidField) naming the reference ("patches[2].ends.u0: ...");
// a cycle is named patch by patch ("a cycle of references: 'a' -> 'b' -> 'a'").
void linkPatches(Scene& scene);

// Every edge is met by one other patch at most over any part of it: two would make three
// sheets meet along it (a non-manifold model the certificate would pass join by join). Parts
// may touch (a fill's sides end where the next begins). Throws Error(InvalidField) naming
// the later reference and the earlier one. Run once every join is recorded.
void checkEdgesMetOnce(const Scene& scene);

// The parameter range of a patch's edge (kBezierEdge's order; a surface's t0/t1 as u0/u1):
// a surface's or pde patch's v-range, a Bézier border's [0, 1].
std::array<double, 2> edgeRange(const Patch& p);

// "t0", "u1", "v0": an edge's name on that kind of patch.
std::string edgeName(const Patch& p, int edge);

}  // namespace pdesurf
