// A proven bound of the distance between a curve typed as expressions and a Bézier curve that
// approximates it: a Bézier border given by reference is a fit of the surface's edge at
// samples, and a narrow feature of the edge between them would pass any sampled certificate
// (issue 38: a 0.3 spike between the fit's and the certificate's samples was certified G0).
//
// First a scan of the distance at 257 points (a border the degree cannot follow is found
// there, with no derivative built); then, on each piece [a, b] of the Bézier parameter s, with
// g = f(v(s)) - B(s) and h = b - a,
//   |g(s)| <= |g(m)| + |g'(m)| h/2 + |g''(m)| h²/8 + max|g'''| h³/48   (Taylor at the middle m),
// max|g'''| enclosed by interval arithmetic on f''' (expr/interval.hpp) minus the hull of the
// Bernstein coefficients of B's third derivative on [a, b] (where B follows f the two nearly
// cancel: a border that is the edge's polynomial is proven in few pieces); pieces are halved
// until the bound is within the tolerance, or a middle is farther than it (a gap found), or
// the piece or node budget is spent (undecided: never proven).
#pragma once
#include <Eigen/Core>
#include <array>
#include <vector>

#include "expr/expr.hpp"

namespace pdesurf {

struct CurveGap {
  enum Verdict { Within, Found, Undecided } verdict = Within;
  double gap = 0.0;  // Within: the proven bound; Found: the distance at s; Undecided: the bound left
  double s = 0.0;    // where (Found), or the piece with the largest bound left (Undecided)
  int pieces = 0;    // pieces looked at
};

constexpr int kCurveGapPieces = 1 << 14;
// Points of the first scan (no derivatives), and the nodes the derivatives of one border may
// take (a budget of its own: the scene's derivations keep theirs).
constexpr int kScanPoints = 257;
constexpr size_t kCurveGapNodes = 50000;
// Operations (interval steps and program instructions) a scene's borders may spend in all.
constexpr size_t kCurveGapWork = size_t{1} << 25;

// f: x, y, z as expressions in v (ExprVar::V); v(s) = v0 + s (v1 - v0), s in [0, 1] (v1 < v0:
// backwards); B: the control points of a Bézier curve in s. tol: an absolute distance.
// The derivatives of f are built symbolically (under the caller's ExprBudget, if any).
// work: the operations left to spend (each level of pieces is charged before it is done;
// undecided when it would overdraw), null: no limit but maxPieces.
CurveGap boundCurveGap(const std::array<Expr, 3>& f, double v0, double v1, const std::vector<Eigen::Vector3d>& B, double tol,
                       int maxPieces = kCurveGapPieces, size_t* work = nullptr);

}  // namespace pdesurf
