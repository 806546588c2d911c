#include "cad/grid_partials.hpp"

#include <map>
#include <string>

#include "basis/general_function.hpp"
#include "cad/knots.hpp"
#include "common/errors.hpp"
#include "expr/program.hpp"

namespace pdesurf {

SurfaceOnGrid::SurfaceOnGrid(const SeparableSurface& s, std::vector<double> u) : s_(s), u_(std::move(u)) {
  const Eigen::Index mu = Eigen::Index(u_.size());
  std::vector<double> tab(size_t(mu) * 3);
  ExpOnGrid exps(u_.data(), int(mu));
  for (int c = 0; c < 3; ++c) {
    const auto& terms = s.component[size_t(c)];
    const Eigen::Index T = Eigen::Index(terms.size());
    for (auto& m : G_[size_t(c)]) m.resize(mu, T);
    for (Eigen::Index t = 0; t < T; ++t) {
      terms[size_t(t)].G.tabulate(u_.data(), int(mu), 2, tab.data(), nullptr, &exps);
      for (int a = 0; a < 3; ++a)
        for (Eigen::Index i = 0; i < mu; ++i) G_[size_t(c)][size_t(a)](i, t) = tab[size_t(a) * size_t(mu) + size_t(i)];
    }
    // X, X_u, X_v, X_uu, X_uv, X_vv of the pointwise part: one program, run along each row.
    pointwise_[size_t(c)] = pointwiseProgramOf(s, c);
  }
}

double SurfaceOnGrid::pointCost() const {
  double cost = 1.0;
  for (int c = 0; c < 3; ++c) {
    cost += double(s_.component[size_t(c)].size());
    if (pointwise_[size_t(c)]) cost += double(pointwise_[size_t(c)]->instructions());
  }
  return cost;
}

GridPartials SurfaceOnGrid::at(const std::vector<double>& v, int count) const {
  static const char* axis[3] = {"x", "y", "z"};
  const Eigen::Index mu = Eigen::Index(u_.size()), mv = Eigen::Index(v.size());
  GridPartials out;
  std::map<const void*, std::vector<std::vector<double>>> generalRows;
  for (int c = 0; c < 3; ++c) {
    const auto& terms = s_.component[size_t(c)];
    const Eigen::Index T = Eigen::Index(terms.size());
    std::array<Eigen::MatrixXd, 3> g;
    for (auto& m : g) m.resize(mv, T);
    for (Eigen::Index t = 0; t < T; ++t) {
      const VFunction& f = terms[size_t(t)].g;
      if (f.family == Family::General) {
        // g, g', g'' over every v at once: the function's own compiled program.
        auto& rows = generalRows[f.general.get()];
        if (rows.empty()) {
          rows.assign(3, std::vector<double>(size_t(mv)));
          double* outs[3] = {rows[0].data(), rows[1].data(), rows[2].data()};
          f.general->evalManyUpTo(v.data(), size_t(mv), 2, outs);
        }
        for (int b = 0; b < 3; ++b)
          for (Eigen::Index j = 0; j < mv; ++j) g[size_t(b)](j, t) = rows[size_t(b)][size_t(j)];
      } else {
        for (Eigen::Index j = 0; j < mv; ++j)
          for (int b = 0; b < 3; ++b) g[size_t(b)](j, t) = f.eval(v[size_t(j)], b);
      }
    }
    for (int k = 0; k < count; ++k) {
      Eigen::MatrixXd& m = out[size_t(k)][size_t(c)];
      m = T ? Eigen::MatrixXd(G_[size_t(c)][size_t(kFitPartials[k][0])] * g[size_t(kFitPartials[k][1])].transpose())
            : Eigen::MatrixXd::Zero(mu, mv);
    }
    if (pointwise_[size_t(c)]) {
      static const int slot[5] = {0, 1, 2, 3, 5};
      std::vector<std::vector<double>> rows(6, std::vector<double>(size_t(mv)));
      std::vector<double> uRow(static_cast<size_t>(mv));
      double* outs[6];
      for (int r = 0; r < 6; ++r) outs[r] = rows[size_t(r)].data();
      for (Eigen::Index i = 0; i < mu; ++i) {
        std::fill(uRow.begin(), uRow.end(), u_[size_t(i)]);
        pointwise_[size_t(c)]->runAll(v.data(), uRow.data(), size_t(mv), outs);
        for (int k = 0; k < count; ++k)
          for (Eigen::Index j = 0; j < mv; ++j) out[size_t(k)][size_t(c)](i, j) += rows[size_t(slot[k])][size_t(j)];
      }
    }
    for (int k = 0; k < count; ++k)
      if (!out[size_t(k)][size_t(c)].allFinite())
        throw Error(ErrorCode::NonFinite, std::string("component ") + axis[c] + " is not finite on the fit's grid");
  }
  return out;
}

namespace {

// B's partials on the grid, each handed to `use(k, c, matrix)` as it is made (one at a time:
// the certificate subtracts them in place rather than holding B's fifteen beside S's).
template <class Use>
void splinePartials(const BSplineSurface& b, const std::vector<double>& u, const std::vector<double>& v, Use&& use) {
  std::array<Eigen::SparseMatrix<double>, 3> nu, nvT;
  for (int d = 0; d < 3; ++d) {
    nu[size_t(d)] = collocation(b.knotsU, b.degreeU, u, d);
    nvT[size_t(d)] = collocation(b.knotsV, b.degreeV, v, d).transpose();
  }
  for (int c = 0; c < 3; ++c) {
    Eigen::MatrixXd net(b.countU, b.countV);
    for (int i = 0; i < b.countU; ++i)
      for (int j = 0; j < b.countV; ++j) net(i, j) = b.pole(i, j)[c];
    // nu (net nvT): the v-side first, so a block of few columns costs few products.
    for (int k = 0; k < 5; ++k) {
      const Eigen::MatrixXd netV = net * nvT[size_t(kFitPartials[k][1])];
      use(k, c, Eigen::MatrixXd(nu[size_t(kFitPartials[k][0])] * netV));
    }
  }
}

}  // namespace

GridPartials tabulateSpline(const BSplineSurface& b, const std::vector<double>& u, const std::vector<double>& v) {
  GridPartials out;
  splinePartials(b, u, v, [&](int k, int c, Eigen::MatrixXd&& m) { out[size_t(k)][size_t(c)] = std::move(m); });
  return out;
}

void subtractSpline(const BSplineSurface& b, const std::vector<double>& u, const std::vector<double>& v, GridPartials& X) {
  splinePartials(b, u, v, [&](int k, int c, Eigen::MatrixXd&& m) { X[size_t(k)][size_t(c)] -= m; });
}

}  // namespace pdesurf
