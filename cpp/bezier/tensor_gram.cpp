#include "bezier/tensor_gram.hpp"

#include <array>

#include "bezier/bernstein.hpp"
#include "common/errors.hpp"

namespace pdesurf {

using Eigen::MatrixXd;

MatrixXd bernsteinTable(int n, const std::vector<double>& t, int k) {
  MatrixXd B = MatrixXd::Zero(static_cast<Eigen::Index>(t.size()), n + 1);
  if (k > n) return B;
  std::array<double, kMaxBernsteinDegree + 1> low;
  for (size_t a = 0; a < t.size(); ++a) {
    bernsteinValues(n - k, t[a], low.data());
    for (int i = 0; i <= n; ++i) B(static_cast<Eigen::Index>(a), i) = bernsteinBasisFrom(low.data(), n, i, k);
  }
  return B;
}

namespace {

int pairCount(int n) { return (n + 1) * (n + 2) / 2; }

// index[i*(n+1)+k] = index[k*(n+1)+i] = the column of the pair (min, max), numbered as in
// columnPairProducts.
std::vector<int> pairIndex(int n) {
  std::vector<int> index((n + 1) * (n + 1));
  int c = 0;
  for (int i = 0; i <= n; ++i)
    for (int k = i; k <= n; ++k, ++c) index[i * (n + 1) + k] = index[k * (n + 1) + i] = c;
  return index;
}

}  // namespace

MatrixXd columnPairProducts(const MatrixXd& B) {
  const int n = static_cast<int>(B.cols()) - 1;
  MatrixXd P(B.rows(), pairCount(n));
  int c = 0;
  for (int i = 0; i <= n; ++i)
    for (int k = i; k <= n; ++k, ++c) P.col(c) = B.col(i).cwiseProduct(B.col(k));
  return P;
}

TensorGram::TensorGram(int n, int m)
    : n_(n), m_(m), pairU_(pairIndex(n)), pairV_(pairIndex(m)), H_(MatrixXd::Zero(pairCount(n), pairCount(m))) {}

void TensorGram::add(const MatrixXd& Pu, const MatrixXd& Pv, const MatrixXd& W, double scale) {
  if (Pu.cols() != H_.rows() || Pv.cols() != H_.cols() || W.rows() != Pu.rows() || W.cols() != Pv.rows())
    throw Error(ErrorCode::Internal, "tensor Gram: the tables do not match the degree or the node grid");
  T_.noalias() = W * Pv;                        // T(a, (j,l)) = Σ_b W(a,b) Bv(b,j) Bv(b,l)
  H_.noalias() += scale * Pu.transpose() * T_;  // H((i,k), (j,l)) = Σ_a Bu(a,i) Bu(a,k) T(a, (j,l))
}

MatrixXd TensorGram::matrix() const {
  const int K = (n_ + 1) * (m_ + 1);
  MatrixXd G(K, K);
  for (int k = 0; k <= n_; ++k)  // column (k, l) by column: Eigen is column-major
    for (int l = 0; l <= m_; ++l)
      for (int i = 0; i <= n_; ++i) {
        const int pu = pairU_[i * (n_ + 1) + k];
        for (int j = 0; j <= m_; ++j) G(i * (m_ + 1) + j, k * (m_ + 1) + l) = H_(pu, pairV_[j * (m_ + 1) + l]);
      }
  return G;
}

}  // namespace pdesurf
