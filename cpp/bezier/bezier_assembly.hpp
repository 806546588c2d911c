// The matrices of seed 002's energy (bezier_problem.hpp), assembled through the tensor-product
// structure of the basis and of the node grids (tensor_gram.hpp).
//
// Nodes: the fairness term is always the exact integral on an (n+1)×(m+1) Gauss-Legendre grid;
// the normal and data terms are the exact integral on an (n+n1)×(m+m1) Gauss grid for a
// continuous field, or the discrete field's (np+1)×(mp+1) samples with trapezoidal weights
// (½ on edges, ¼ at corners, summing to 1) times the per-sample weights.
//
// Cost: per Gram matrix about Nu·Nv·(m+1)² + Nu·K² multiply-adds (a quarter of it, given the
// symmetry) on the Nu×Nv node grid, instead of Nu·Nv·K² row by row; 13 of them on the normal
// term's grid, 2 or 4 on the fairness grid.
#pragma once
#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "bezier/bezier_problem.hpp"

namespace pdesurf {

// A tensor grid of nodes u[a], v[b] in [0, 1] with weights w(a, b) (u.size() × v.size()).
struct NodeGrid {
  std::vector<double> u, v;
  Eigen::MatrixXd w;
};

// q_u × q_v Gauss-Legendre nodes; weights w(a, b) = wu_a wv_b, summing to 1.
NodeGrid gaussNodeGrid(int qu, int qv);
// u = a/np, v = b/mp; trapezoidal weights (½ on edges, ¼ at corners) / (np·mp), summing to 1.
NodeGrid trapezoidNodeGrid(int np, int mp);

struct BezierForms {
  Eigen::MatrixXd fairness;  // K×K: ∫ |R_u|² + |R_v|² or |R_uu|² + 2|R_uv|² + |R_vv|², per coordinate
  Eigen::MatrixXd mass;      // K×K: the data term with γ = 1 (and the per-sample γ weights)
  Eigen::MatrixXd normal;    // 3K×3K: the normal term with λ = 1 (and the per-sample λ weights);
                             // coordinate c of control point k at 3k + c
};

// K = (n+1)(m+1), control point (i, j) at i*(m+1)+j. Expects a validated problem. With Tu
// (Tv): the forms in the basis Σ_i Tu(i, c) B_i^n(u) (columns c) instead of B^n in u (v), so
// K = Tu.cols() · Tv.cols() (the solver's well-conditioned fallback, interior_basis.hpp).
BezierForms assembleBezierForms(const BezierProblem& p, const Eigen::MatrixXd* Tu = nullptr, const Eigen::MatrixXd* Tv = nullptr);

// The node grid size Nu × Nv of the normal and data terms.
void bezierNormalNodes(int n, int m, const BezierNormalField& f, int& Nu, int& Nv);
// Work units of one patch's assembly and solve, the quantity limits::kBezierAssembly bounds:
// Nu·Nv·(m+1)² + Nu·K² for the normal term's node grid (the fairness grid's share is smaller),
// and K³ for the factorisations (the energy alone, no normals: degree 16 costs 2.4·10⁷).
size_t bezierAssemblyWork(int n, int m, int Nu, int Nv);

}  // namespace pdesurf
