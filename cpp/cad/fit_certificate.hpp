// The certificate of a B-spline fit: a bound of max |S - B| over every cell of a grid aligned
// with the knot spans, from values at the cell's corners and rigorous bounds of fourth
// derivatives (bspline_fit.hpp gives the argument).
#pragma once
#include <Eigen/Core>
#include <array>
#include <vector>

#include "cad/bspline_surface.hpp"

namespace pdesurf {

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

struct Certificate {
  double bound = 0.0;         // max over cells
  double sampled = 0.0;       // max |S - B| at grid points
  double normalDeg = 0.0;     // max normal angle at the borders' grid points (where S's normal is defined)
  Eigen::MatrixXd cell;       // each cell's bound
  Eigen::MatrixXd cellSampled;  // each cell's largest corner error
  Eigen::MatrixXd cellNormalDeg;  // each cell's largest corner normal angle
  // Each cell's slack (the bound less its corners' part): the u (h²) terms and the v (k²) terms.
  Eigen::MatrixXd cellSlackU, cellSlackV;
};

// B's fourth-derivative bounds per block, from its differenced poles.
FourthBounds splineFourthBounds(const BSplineSurface& b);

// S tabulated on the grid (consumed: it becomes S - B in place), B the fit, and the
// fourth-derivative bounds of both.
Certificate certify(const CertificateGrid& grid, GridPartials&& S, const BSplineSurface& b, const FourthBounds& boundS,
                    const FourthBounds& boundB, double scale);

}  // namespace pdesurf
