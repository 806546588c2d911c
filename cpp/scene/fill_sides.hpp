// A fill's loop border by border (scene/fill_conditions.cpp, docs/chains-and-fills.md): each
// border as expressions in the fill's v, over its part of the loop (fillSideRange), and as
// samples. Internal to scene/.
#pragma once
#include <Eigen/Core>
#include <string>
#include <vector>

#include "scene/chain_conditions.hpp"
#include "scene/solved_edges.hpp"
#include "scene/trimline_checks.hpp"  // shortNumber, for messages

namespace pdesurf {

constexpr int kPerSide = 96;       // samples per border for the loop's figures
constexpr double kInside = 1e-9;   // of a side's length: where its corner values are taken

struct FillSide {
  Vec3Expr X, D;   // in the fill's v
  Vec3Expr T;      // the edge's tangent along its own parameter (times the part's length): never 0
  // Curvature only: the source's second derivatives along (ss), along and across (sw) and
  // across (ww) its edge, in the parameters of T and D.
  Vec3Expr Xss, Xsw, Xww;
  Expr sigma;      // the side's parameter 0..1 as a function of v (see sideOf)
  double v0 = 0, v1 = 0;
  std::string name;  // "'rear' u0", for messages
  std::vector<Eigen::Vector3d> x, d, t, dd;  // samples at kPerSide + 1 evenly spaced v (ends included)
};

// Border k of the fill's loop. depth: the derivatives across the loop the fill takes from its
// borders (0 position, 1 tangency, 2 curvature).
FillSide fillSideOf(const Patch& fill, size_t k, const SolvedLookup& solved, int depth);

Eigen::Vector3d valueAt(const Vec3Expr& e, double v);

}  // namespace pdesurf
