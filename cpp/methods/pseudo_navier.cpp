// Seed 000's pseudo-Navier method (Eqs. 9-15), for any even order 2n: each general boundary
// function g_s gets the Hermite polynomial h_s(u) of degree 2n-1 that carries its boundary
// slot (Eq. 10 for n = 2), and the correction
//   u^{n-1} (u-1)^n Σ_{m<=M, k<=N} A_mk sin(m u) sin(k v)
// (u (u-1)² … for n = 2, Eq. 9; it and its first n-1 u-derivatives vanish at both ends, so
// the boundary conditions stay exact) is fitted by least squares to the PDE residual at
// collocation points (Eqs. 11-15). The residual is formed exactly: L is applied to each
// separable piece analytically rather than through Eq. 13's printed expansion, whose
// sin nu / sin mu slip the seeds' README notes.
#include <Eigen/Dense>
#include <cmath>

#include "common/errors.hpp"
#include "methods/approximate.hpp"
#include "common/text.hpp"
#include "methods/boundary_lift.hpp"
#include "methods/method.hpp"
#include "pde/closed_form.hpp"

namespace pdesurf {

namespace {

// u^{n-1} (u-1)^n sin(m u) = Re(-i e^{i m u} · u^{n-1}(u-1)^n).
UFactor correctionFactor(int n, int m) {
  std::vector<double> poly{1.0};
  auto times = [&](double root) {  // poly *= (u - root)
    std::vector<double> next(poly.size() + 1, 0.0);
    for (size_t k = 0; k < poly.size(); ++k) next[k + 1] += poly[k], next[k] -= root * poly[k];
    poly.swap(next);
  };
  for (int k = 0; k < n - 1; ++k) times(0.0);
  for (int k = 0; k < n; ++k) times(1.0);
  UFactor f;
  ExpPoly piece;
  piece.rate = cplx(0.0, m);
  for (double c : poly) piece.poly.push_back(cplx(0.0, -c));
  f.pieces.push_back(piece);
  return f;
}

UFactor scaledPolynomial(const std::vector<double>& p, double s) {
  std::vector<double> q = p;
  for (double& c : q) c *= s;
  return UFactor::polynomial(q);
}

}  // namespace

SeparableSurface solvePseudoNavier(const PdeProblem& p, int M, int N, int points) {
  if (M < 1 || N < 1 || M * N > 400) throw Error(ErrorCode::InvalidField, "pseudo-navier needs 1 <= M, N and M*N <= 400");
  const int P = static_cast<int>(std::lround(std::sqrt(static_cast<double>(points))));
  if (P < 2 || P * P != points || P > 64)
    throw Error(ErrorCode::InvalidField, "pseudo-navier collocation points must be a square grid P×P, 4 <= P² <= 4096");
  SeparableSurface s = solveClosedForm(familyProblem(p));
  for (int c = 0; c < 3; ++c) {
    const ComponentProblem& cp = p.component[c];
    const int n = static_cast<int>(cp.alpha.size()) - 1;
    std::vector<VExpansion> g(2 * n);
    bool any = false;
    for (int end = 0; end < 2; ++end)
      for (int i = 0; i < n; ++i) {
        g[end * n + i] = generalPart((end == 0 ? cp.left : cp.right)[i]);
        any = any || !g[end * n + i].empty();
      }
    if (!any && cp.generalForce.empty()) continue;
    const auto h = hermiteBasis(n);
    std::vector<UFactor> hs(2 * n);
    for (int slot = 0; slot < 2 * n; ++slot) {
      hs[slot] = UFactor::polynomial(h[slot]);
      for (const VTerm& t : g[slot]) s.component[c].push_back({t.g, scaledPolynomial(h[slot], t.coef)});
    }
    std::vector<UFactor> phi;
    for (int m = 1; m <= M; ++m) phi.push_back(correctionFactor(n, m));

    // Residual rows at a uniform P×P grid inside the region, u_i = i/(P+1), v_j likewise
    // (seed 000 says only "uniformly"; with P = 7 this reproduces Section 3's E).
    Eigen::MatrixXd B(points, M * N);
    Eigen::VectorXd rhs(points);
    int row = 0;
    for (int iu = 0; iu < P; ++iu)
      for (int iv = 0; iv < P; ++iv, ++row) {
        const double u = (iu + 1.0) / (P + 1), v = p.v0 + (p.v1 - p.v0) * (iv + 1.0) / (P + 1);
        double known = 0.0;  // L[Σ h_s g_s] at (u, v)
        for (int slot = 0; slot < 2 * n; ++slot) {
          if (g[slot].empty()) continue;
          for (int k = 0; k <= n; ++k) known += cp.alpha[k] * hs[slot].eval(u, 2 * (n - k)) * expansionValue(g[slot], v, 2 * k);
        }
        double force = 0.0;  // the general force; family forces are solved exactly above
        const double vars[2] = {v, u};
        for (const GeneralForce& f : cp.generalForce) force += evaluate(*f.f, vars);
        if (!std::isfinite(known) || !std::isfinite(force))
          throw Error(ErrorCode::NonFinite, std::string("component ") + "xyz"[c] +
                                                ": a general boundary function or force is not finite at (u, v) = (" +
                                                numberText(u) + ", " + numberText(v) + ")");
        rhs(row) = force - known;  // minimise |L X - f| at the point
        for (int m = 1; m <= M; ++m)
          for (int k2 = 1; k2 <= N; ++k2) {
            double op = 0.0;
            for (int k = 0; k <= n; ++k) op += cp.alpha[k] * std::pow(-static_cast<double>(k2 * k2), k) * phi[m - 1].eval(u, 2 * (n - k));
            B(row, (m - 1) * N + (k2 - 1)) = op * std::sin(k2 * v);
          }
      }
    // Columns can vanish on the grid (sin(kv) at v = jπ/k); treat them as absent rather than
    // amplifying rounding: a rank-revealing QR with a relative threshold.
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(B);
    qr.setThreshold(1e-10);
    const Eigen::VectorXd A = qr.solve(rhs);
    if (!A.allFinite()) throw Error(ErrorCode::Singular, "pseudo-navier: the least-squares system has no finite solution");
    for (int m = 1; m <= M; ++m)
      for (int k2 = 1; k2 <= N; ++k2) {
        UFactor f = phi[m - 1];
        for (auto& piece : f.pieces)
          for (auto& coef : piece.poly) coef *= A((m - 1) * N + (k2 - 1));
        s.component[c].push_back({VFunction{Family::Sin, static_cast<double>(k2), 0}, f});
      }
  }
  return s;
}

}  // namespace pdesurf
