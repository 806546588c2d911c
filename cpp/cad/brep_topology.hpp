// The B-rep topology of a model's faces (issue 36): every join the certificate records
// (cad/border_joins.hpp) becomes one edge shared by the two faces, with shared vertices at its
// ends; a border met over parts (a fill over a range, a T-junction) is split where the parts
// end, so both faces use the same edges. A closed face's seam is one edge it uses twice; a
// collapsed border (a fill's centre) is a vertex. Faces are oriented consistently across
// their shared edges, and a closed shell outward. Built on the fitted faces, whose borders
// are pole rows: an edge's curve is the part of one face's border row (exact knot insertion).
#pragma once
#include <Eigen/Core>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "cad/border_joins.hpp"
#include "cad/bspline_curve.hpp"
#include "cad/bspline_surface.hpp"
#include "cad/topology_face.hpp"

namespace pdesurf {

// An edge's curve in one face's (u, v), as a function of the edge curve's own parameter.
struct BrepPcurve {
  int face = 0;
  int degree = 1;
  std::vector<double> knots;            // clamped, over the edge curve's parameter range
  std::vector<Eigen::Vector2d> poles;   // (u, v)
};

struct BrepEdge {
  int start = 0, end = 0;  // vertices, along the curve
  BSplineCurve curve;
  // A shared edge: its curve in each of its two faces (a straight line in the one whose border
  // it is; in the other, the join's parameter map: a line, or a fill side's easing as cubic
  // Hermite pieces). Free edges and seams: none (a reader takes the face's own iso-line).
  std::vector<BrepPcurve> pcurves;
  int uses = 0;            // 1: a free (open) border; 2: shared, or a seam
  // Where it lies: along `border` of `face` from t0 to t1 (the curve's own parameter); a shared
  // edge also along `otherBorder` of `otherFace`, at mapBtoA(joins[join], t) there.
  int face = 0, border = 0;
  double t0 = 0, t1 = 0;
  int otherFace = -1, otherBorder = 0, join = -1;
  double gap = 0;          // largest distance between the two sides' borders (sampled), scene units
};

struct BrepEdgeUse {
  int edge = 0;
  bool forward = true;  // along the edge's curve
};

struct BrepFace {
  std::vector<BrepEdgeUse> loop;  // the outer loop, counter-clockwise seen from the face's normal
  bool flipped = false;           // the face's normal is -(S_u × S_v)
};

struct BrepShell {
  std::vector<int> faces;
  bool closed = false;    // every edge of it used twice: a solid's boundary, oriented outward
  double volume = 0;      // closed only: enclosed volume (from the faces given)
  double area = 0;        // the faces' area
};

struct BrepTopology {
  std::vector<Eigen::Vector3d> vertices;
  // The largest distance of a vertex's points (the faces' corners it joins) from it, and of a
  // shared edge's two borders from each other: a file's stated tolerance is at least these.
  double vertexSpread = 0, edgeGap = 0;
  std::vector<BrepEdge> edges;
  std::vector<BrepFace> faces;  // one per fitted face, same order
  std::vector<BrepShell> shells;
  // Joins not made into shared edges, and why ("'fill' u0 - 'strip' t0: the borders are 2e-3
  // apart, beyond the tolerance 1e-6"): their faces keep their own edges there.
  std::vector<std::string> unshared;
};

// faces[i] is the join list's face i. tolerance (scene units): borders farther apart than
// twice it are not shared (named in `unshared`); pieces shorter than it are vertices. Edges
// have curves and pcurves only where faces have splines.
BrepTopology buildTopology(const std::vector<TopologyFace>& faces, const std::vector<BorderJoin>& joins, double tolerance);
// The fitted faces, for the CAD writers.
BrepTopology buildTopology(const std::vector<BSplineSurface>& faces, const std::vector<BorderJoin>& joins, double tolerance);

}  // namespace pdesurf
