// A fill's centre (docs/chains-and-fills.md): its border u = 1 collapses to one point, which must be a
// regular point of the surface. Measured from analytic derivatives of the solved fill:
//   the normal on rings closing in on the centre converges (its spread around the ring, in
//   degrees, at u = 1 - 2^-6 and at the innermost ring u = 1 - 2^-12);
//   no fold: the normal X_u × X_v never turns over between neighbouring samples of a 48 × 96
//   grid and of a 12 × 96 grid over u in [1 - 2^-6, 1 - 2^-12];
//   curvature bounded: the largest principal curvature on the inner grid's three innermost
//   rings against its three outermost.
#pragma once
#include <string>

#include "scene/scene.hpp"

namespace pdesurf {

struct FillCentre {
  std::string patch;
  double normalSpreadDeg = 0.0;       // at u = 1 - 2^-12
  double normalSpreadOuterDeg = 0.0;  // at u = 1 - 2^-6: a defined normal converges from it
  bool fold = false;
  double foldU = 0.0, foldV = 0.0;  // where the first fold was found
  double curvatureNear = 0.0;    // largest |principal curvature| next to the centre
  double curvatureRatio = 0.0;   // that over the largest 2^-6 away (bounded: about 1)
  bool ok = false;
};

// The normal is defined when the innermost ring's spread is below kCentreSpreadDeg or has
// fallen at least kCentreSpreadFall times from 2^-6 away (linearly it falls 64 times; a cone's
// does not fall at all).
constexpr double kCentreSpreadDeg = 0.1;
constexpr double kCentreSpreadFall = 8.0;
constexpr double kCentreCurvatureRatio = 2.0;

FillCentre measureFillCentre(const std::string& name, const SeparableSurface& fill);

// Throws Error(InvalidField) naming the fill and where it folds: solveScene calls it on every
// fill it solves, so a folding fill is never drawn. It looks for folds only (no curvature),
// on 32 × 64 and the inner 12 × 64: the drawing's resolution; the certificate's
// measureFillCentre keeps 48 × 96.
void checkFillRegular(const Patch& fill, const SeparableSurface& surface);

}  // namespace pdesurf
