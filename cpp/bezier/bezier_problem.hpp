// Seed 002: a tensor-product Bézier surface R of degree n×m whose boundary control points are
// fixed and whose free ones minimise
//   membrane (Eq. 1):   ½∫ |R_u|² + |R_v|² + λ[(R_u·N)² + (R_v·N)²] + γ|R - S|²   (one ring fixed)
//   thin plate (Eq. 2): ½∫ |R_uu|² + 2|R_uv|² + |R_vv|² + λ[…] + γ|R - S|²         (two rings fixed)
// under a guiding normal field N: continuous (a Bézier vector function of its own degree) or
// discrete (unit normals on a sample grid with per-sample weights, Eqs. 5-7: the normal and
// data terms become trapezoidal sums over the samples; the fairness term stays exact). S is the initial surface, whose
// control net also supplies the fixed boundary control points.
#pragma once
#include <Eigen/Core>
#include <vector>

namespace pdesurf {

enum class BezierEnergy { Membrane, ThinPlate };

struct BezierNormalField {
  bool discrete = false;
  // continuous: degree n1×m1, (n1+1)(m1+1) control vectors, row i (u) major
  int n1 = 0, m1 = 0;
  // discrete: (np+1)×(mp+1) unit normals at u = i/np, v = j/mp, row i major, and weights
  // multiplying λ and γ per sample
  int np = 0, mp = 0;
  std::vector<Eigen::Vector3d> vectors;
  std::vector<double> lambdaWeight, gammaWeight;  // discrete only; empty means 1
};

struct BezierProblem {
  int n = 0, m = 0;
  BezierEnergy energy = BezierEnergy::Membrane;
  std::vector<Eigen::Vector3d> initial;  // S's control net, (n+1)(m+1), row i major
  double lambda = 0.0, gamma = 0.0;
  BezierNormalField normals;

  int index(int i, int j) const { return i * (m + 1) + j; }
  // Fixed: the outer ring (membrane) or two rings (thin plate).
  bool isFixed(int i, int j) const {
    const int r = energy == BezierEnergy::Membrane ? 1 : 2;
    return i < r || j < r || i > n - r || j > m - r;
  }
};

}  // namespace pdesurf
