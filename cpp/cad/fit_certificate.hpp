// The certificate of a B-spline fit: a bound of max |S - B| over every cell of a grid aligned
// with the knot spans, from values at the cell's corners and rigorous bounds of fourth
// derivatives (bspline_fit.hpp gives the argument).
#pragma once
#include <Eigen/Core>
#include <array>
#include <vector>

#include "cad/bspline_surface.hpp"

namespace pdesurf {

class SurfaceOnGrid;  // cad/grid_partials.hpp

// Partial derivatives on a grid, in the order (0,0) (1,0) (0,1) (2,0) (0,2); per component
// a matrix (u rows, v columns).
constexpr int kFitPartials[5][2] = {{0, 0}, {1, 0}, {0, 1}, {2, 0}, {0, 2}};
using GridPartials = std::array<std::array<Eigen::MatrixXd, 3>, 5>;
// Bounds over the blocks of spans (u spans × v spans), per component, for ∂⁴u, ∂²u∂²v, ∂⁴v.
using FourthBounds = std::array<std::array<Eigen::MatrixXd, 3>, 3>;

struct CertificateGrid {
  std::vector<double> u, v;
  std::vector<int> uSpan, vSpan;  // the span holding the cell [u[i], u[i+1]] (resp. v)
  std::vector<bool> vCrease;      // v[j] is a crease: the normal there has two sides, not compared
};

// A cell [u_i, u_i+1] × [v_j, v_j+1] that fails: its bound over the tolerance, or the normals
// at its corners on a border row over their target.
struct FailedCell {
  Eigen::Index i = 0, j = 0;
  double bound = 0.0;      // the cell's bound of |S - B|
  double sampled = 0.0;    // its largest corner error
  double normalDeg = 0.0;  // its largest corner normal angle (border rows only)
  // The bound's slack (less its corners' part): the u (h²) terms and the v (k²) terms.
  double slackU = 0.0, slackV = 0.0;
};

struct Certificate {
  double bound = 0.0;      // max over cells
  double sampled = 0.0;    // max |S - B| at grid points
  double normalDeg = 0.0;  // max normal angle at the borders' grid points (where S's normal is defined)
  std::vector<FailedCell> failed;  // what the refinement acts on; the cells that pass are not kept
};

// Columns of the grid tabulated at once: the certificate holds one block's partials, never the
// whole grid's (2^20 points would be 126 MB of them).
constexpr Eigen::Index kCertificateBlock = 64;

// B's fourth-derivative bounds per block, from its differenced poles.
FourthBounds splineFourthBounds(const BSplineSurface& b);

// S on the grid's u (its columns tabulated block by block), B the fit, the fourth-derivative
// bounds of both; cells over `tolerance` or with normals over `normalToleranceDeg` are listed.
Certificate certify(const CertificateGrid& grid, const SurfaceOnGrid& S, const BSplineSurface& b, const FourthBounds& boundS,
                    const FourthBounds& boundB, double tolerance, double normalToleranceDeg);

}  // namespace pdesurf
