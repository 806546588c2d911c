// Weighted Gram matrices of a tensor-product basis on a tensor grid of nodes, assembled
// through the tensor-product structure instead of row by row.
//
// Nodes (u_a, v_b), a < Nu, b < Nv, with arbitrary weights W(a, b) (not necessarily a product
// wu_a wv_b: the normal term's weights carry N_c N_d of each sample). Basis functions
// φ_(i,j)(u, v) = U_i(u) V_j(v), i ≤ n, j ≤ m, numbered i*(m+1)+j (K = (n+1)(m+1)); U and V
// are tabulated as Bu(a, i) = U_i(u_a) (Nu × (n+1)) and Bv(b, j) = V_j(v_b) (Nv × (m+1)). The
// Gram matrix (K × K) is
//   G((i,j),(k,l)) = Σ_ab W(a,b) Bu(a,i) Bv(b,j) Bu(a,k) Bv(b,l)
//                  = Σ_a Bu(a,i) Bu(a,k) [Σ_b W(a,b) Bv(b,j) Bv(b,l)].
// The bracket, for every a and every pair j ≤ l, costs Nu·Nv·(m+1)(m+2)/2; the outer sum, for
// every pair i ≤ k and j ≤ l, costs Nu·(n+1)(n+2)/2·(m+1)(m+2)/2; both are matrix products
// (Eigen GEMMs). The row-by-row product AᵀWA costs Nu·Nv·K². Symmetry in i↔k and j↔l is
// built in, so G is exactly symmetric.
#pragma once
#include <Eigen/Core>
#include <vector>

namespace pdesurf {

// B(a, i) = d^k/dt^k B_i^n(t_a), in Bernstein form (bernstein.hpp). Shape t.size() × (n+1).
Eigen::MatrixXd bernsteinTable(int n, const std::vector<double>& t, int k);

// The products of a table's columns per node, for pairs i ≤ k only:
// P(a, pair(i, k)) = B(a, i) B(a, k), pairs numbered row by row (i = 0: k = 0..n; i = 1:
// k = 1..n; ...). Shape nodes × (n+1)(n+2)/2.
Eigen::MatrixXd columnPairProducts(const Eigen::MatrixXd& B);

// Sums of tensor-product Gram matrices over one node grid: add() any number of terms
// (scale · Gram of Bu ⊗ Bv under W), then matrix() gives their sum as a K × K matrix. Holds its
// workspace, so repeated add() calls allocate nothing once the first has run.
class TensorGram {
 public:
  TensorGram(int n, int m);
  // Pu = columnPairProducts(Bu) (Nu × (n+1)(n+2)/2), Pv = columnPairProducts(Bv)
  // (Nv × (m+1)(m+2)/2), W: Nu × Nv.
  void add(const Eigen::MatrixXd& Pu, const Eigen::MatrixXd& Pv, const Eigen::MatrixXd& W, double scale = 1.0);
  // The sum so far, K × K with K = (n+1)(m+1), control point (i, j) at i*(m+1)+j.
  Eigen::MatrixXd matrix() const;
  // G((i,j),(k,l)) of the sum so far.
  double operator()(int i, int j, int k, int l) const { return H_(pairU_[i * (n_ + 1) + k], pairV_[j * (m_ + 1) + l]); }
  void clear() { H_.setZero(); }

 private:
  int n_, m_;
  std::vector<int> pairU_, pairV_;  // (i, k) -> pair column, both orders
  Eigen::MatrixXd H_;               // (n+1)(n+2)/2 × (m+1)(m+2)/2: G by (u pair, v pair)
  Eigen::MatrixXd T_;               // Nu × (m+1)(m+2)/2: the sums over b
};

}  // namespace pdesurf
