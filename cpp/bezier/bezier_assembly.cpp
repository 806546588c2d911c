#include "bezier/bezier_assembly.hpp"

#include <array>
#include <cmath>

#include "bezier/bernstein.hpp"
#include "bezier/tensor_gram.hpp"

namespace pdesurf {

using Eigen::MatrixXd;

NodeGrid gaussNodeGrid(int qu, int qv) {
  const GaussRule a = gaussLegendre(qu), b = gaussLegendre(qv);
  NodeGrid g{a.x, b.x, MatrixXd(qu, qv)};
  for (int i = 0; i < qu; ++i)
    for (int j = 0; j < qv; ++j) g.w(i, j) = a.w[i] * b.w[j];
  return g;
}

NodeGrid trapezoidNodeGrid(int np, int mp) {
  NodeGrid g{std::vector<double>(np + 1), std::vector<double>(mp + 1), MatrixXd(np + 1, mp + 1)};
  for (int i = 0; i <= np; ++i) g.u[i] = static_cast<double>(i) / np;
  for (int j = 0; j <= mp; ++j) g.v[j] = static_cast<double>(j) / mp;
  for (int i = 0; i <= np; ++i)
    for (int j = 0; j <= mp; ++j) {
      const double wi = (i == 0 || i == np) ? 0.5 : 1.0, wj = (j == 0 || j == mp) ? 0.5 : 1.0;
      g.w(i, j) = wi * wj / (np * mp);
    }
  return g;
}

void bezierNormalNodes(int n, int m, const BezierNormalField& f, int& Nu, int& Nv) {
  Nu = f.discrete ? f.np + 1 : n + f.n1;
  Nv = f.discrete ? f.mp + 1 : m + f.m1;
}

size_t bezierAssemblyWork(int n, int m, int Nu, int Nv) {
  const size_t K = static_cast<size_t>(n + 1) * (m + 1), mv = static_cast<size_t>(m + 1) * (m + 1);
  return static_cast<size_t>(Nu) * Nv * mv + static_cast<size_t>(Nu) * K * K + K * K * K;
}

namespace {

// The pair products of d^k/dt^k B^n on the nodes t, for k = 0..kmax; with T, of the basis
// Σ_i T(i, c) B_i^n (interior_basis.hpp) instead.
std::vector<MatrixXd> pairTables(int n, const std::vector<double>& t, int kmax, const MatrixXd* T) {
  std::vector<MatrixXd> P;
  for (int k = 0; k <= kmax; ++k) P.push_back(columnPairProducts(T ? MatrixXd(bernsteinTable(n, t, k) * *T) : bernsteinTable(n, t, k)));
  return P;
}

// The guiding normal at every node of g, per coordinate: N[c](a, b). Discrete fields are
// normalised and carry √(λ weight); continuous ones are Σ B_i^{n1}(u) B_j^{m1}(v) n_ij.
std::array<MatrixXd, 3> normalsOnGrid(const BezierNormalField& f, const NodeGrid& g) {
  const int Nu = static_cast<int>(g.u.size()), Nv = static_cast<int>(g.v.size());
  std::array<MatrixXd, 3> N;
  if (f.discrete) {
    for (auto& x : N) x.resize(Nu, Nv);
    for (int a = 0; a < Nu; ++a)
      for (int b = 0; b < Nv; ++b) {
        const size_t q = static_cast<size_t>(a) * Nv + b;
        Eigen::Vector3d v = f.vectors[q].normalized();
        if (!f.lambdaWeight.empty()) v *= std::sqrt(f.lambdaWeight[q]);
        for (int c = 0; c < 3; ++c) N[c](a, b) = v(c);
      }
    return N;
  }
  const MatrixXd Bu = bernsteinTable(f.n1, g.u, 0), Bv = bernsteinTable(f.m1, g.v, 0);
  MatrixXd V(f.n1 + 1, f.m1 + 1);
  for (int c = 0; c < 3; ++c) {
    for (int i = 0; i <= f.n1; ++i)
      for (int j = 0; j <= f.m1; ++j) V(i, j) = f.vectors[i * (f.m1 + 1) + j](c);
    N[c] = Bu * V * Bv.transpose();
  }
  return N;
}

}  // namespace

BezierForms assembleBezierForms(const BezierProblem& p, const MatrixXd* Tu, const MatrixXd* Tv) {
  const int n = p.n, m = p.m;
  const int nb = Tu ? static_cast<int>(Tu->cols()) - 1 : n, mb = Tv ? static_cast<int>(Tv->cols()) - 1 : m;  // the basis' "degrees"
  const int K = (nb + 1) * (mb + 1);
  const BezierNormalField& f = p.normals;
  const bool thin = p.energy == BezierEnergy::ThinPlate;
  BezierForms out;

  // Fairness: the exact integral, degree ≤ 2n in u (2m in v), n+1 (m+1) Gauss points.
  {
    const NodeGrid g = gaussNodeGrid(n + 1, m + 1);
    const int order = thin ? 2 : 1;
    const std::vector<MatrixXd> Pu = pairTables(n, g.u, order, Tu), Pv = pairTables(m, g.v, order, Tv);
    TensorGram F(nb, mb);
    if (thin) {
      F.add(Pu[2], Pv[0], g.w);
      F.add(Pu[1], Pv[1], g.w, 2.0);
      F.add(Pu[0], Pv[2], g.w);
    } else {
      F.add(Pu[1], Pv[0], g.w);
      F.add(Pu[0], Pv[1], g.w);
    }
    out.fairness = F.matrix();
  }

  // The normal and data terms' nodes: exact Gauss for a continuous field (degree
  // 2(n-1) + 2 n1 ≤ 2(n + n1) - 1), the trapezoidal samples for a discrete one.
  const NodeGrid g = f.discrete ? trapezoidNodeGrid(f.np, f.mp) : gaussNodeGrid(n + f.n1, m + f.m1);
  const std::vector<MatrixXd> Pu = pairTables(n, g.u, 1, Tu), Pv = pairTables(m, g.v, 1, Tv);

  // Data term γ|R - S|² with γ = 1 and the per-sample γ weights.
  {
    MatrixXd w = g.w;
    if (f.discrete && !f.gammaWeight.empty())
      for (Eigen::Index a = 0; a < w.rows(); ++a)
        for (Eigen::Index b = 0; b < w.cols(); ++b) w(a, b) *= f.gammaWeight[a * w.cols() + b];
    TensorGram M(nb, mb);
    M.add(Pu[0], Pv[0], w);
    out.mass = M.matrix();
  }

  // Normal term with λ = 1: Σ w N_c N_d (a_u a_uᵀ + a_v a_vᵀ) per coordinate pair (c, d), the
  // a_u (a_v) rows being ∂/∂u (∂/∂v) of the basis.
  const std::array<MatrixXd, 3> N = normalsOnGrid(f, g);
  out.normal = MatrixXd::Zero(3 * K, 3 * K);
  TensorGram block(nb, mb);
  MatrixXd w(g.w.rows(), g.w.cols());
  for (int c = 0; c < 3; ++c)
    for (int d = c; d < 3; ++d) {
      w = g.w.cwiseProduct(N[c]).cwiseProduct(N[d]);
      block.clear();
      block.add(Pu[1], Pv[0], w);
      block.add(Pu[0], Pv[1], w);
      for (int k = 0; k <= nb; ++k)  // column by column (Eigen is column-major)
        for (int l = 0; l <= mb; ++l)
          for (int i = 0; i <= nb; ++i)
            for (int j = 0; j <= mb; ++j) {
              const int r = i * (mb + 1) + j, s = k * (mb + 1) + l;
              out.normal(3 * r + c, 3 * s + d) = out.normal(3 * r + d, 3 * s + c) = block(i, j, k, l);
            }
    }
  return out;
}

}  // namespace pdesurf
