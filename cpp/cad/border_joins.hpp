// The joins of a solved scene as parts of its faces' borders (issue 36): what the certificate
// records (Patch::meets), in the faces' own parameters, so that the CAD topology can make each
// join one shared edge (cad/brep_topology.hpp). A face is a patch, in the solved order; its
// (u, v) are the patch's own, as the fitted B-spline's are.
#pragma once
#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace pdesurf {

// A part of one face's border: border in kBezierEdge's order (0 u0, 1 u1 run along v; 2 v0,
// 3 v1 run along u), parameter from -> to (to < from: run backwards).
struct BorderPart {
  size_t face = 0;
  int border = 0;
  double from = 0, to = 0;
};

// Two parts that are one curve: a.from meets b.from and a.to meets b.to. a is the patch that
// promises the join (a blend's end, a fill's side, a Bézier border), b the border it meets.
// Between the ends the parameters correspond linearly, or (eased, a fill's side) b's runs as
// σ(w) = w - kFillEase sin(2πw)/2π of a's w in [0, 1].
struct BorderJoin {
  BorderPart a, b;
  bool eased = false;
  // The whole correspondence the parameters follow (a0 <-> b0, a1 <-> b1); a's part lies in
  // it shifted by aShift (one half of a side wrapped through a closed border's seam).
  double a0 = 0, a1 = 1, b0 = 0, b1 = 1, aShift = 0;
  std::string label;  // "'mid_top' u0 - 'rootL' u0", for messages
};

// b's parameter at a's parameter x (inside a's part), and the inverse.
double mapAtoB(const BorderJoin& j, double x);
double mapBtoA(const BorderJoin& j, double y);
// d(mapBtoA)/dy at y: finite everywhere (the easing's speed is at least 1 - kFillEase).
double mapBtoADerivative(const BorderJoin& j, double y);

// Every join of the scene; a part that wraps through a closed border's seam (a fill's first
// side) is split there into two joins.
std::vector<BorderJoin> borderJoins(const std::vector<SolvedPatch>& solved);

}  // namespace pdesurf
