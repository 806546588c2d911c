#include "pde/closed_form.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>

#include "common/errors.hpp"
#include "common/text.hpp"
#include "basis/general_function.hpp"
#include "ode/basis_cache.hpp"
#include "pde/poly_in_v.hpp"

namespace pdesurf {

namespace {

const char* kAxis[3] = {"x", "y", "z"};

// Everything attached to one v-basis function: its boundary values
// (values[end * n + i] = coefficient in ∂^i X/∂u^i at u = end) and its force polynomial in u.
struct Grouped {
  VFunction g;
  std::vector<double> values;
  std::vector<double> force;
};

std::vector<Grouped> groupEigenTerms(const ComponentProblem& p, int n) {
  std::vector<Grouped> out;
  auto refuse = [](const VFunction& g) {
    if (g.isGeneral())
      throw Error(ErrorCode::InvalidField, "'" + clipText(describeFunction(g), 200) + "' has no closed form: use the method auto, modal or pseudo-navier");
  };
  for (const VExpansion& e : p.left)
    for (const VTerm& t : e) refuse(t.g);
  for (const VExpansion& e : p.right)
    for (const VTerm& t : e) refuse(t.g);
  for (const ForceTerm& f : p.force) refuse(f.g);
  if (!p.generalForce.empty())
    throw Error(ErrorCode::InvalidField, "the force '" + clipText(p.generalForce.front().text, 200) + "' has no closed form: use the method auto, modal or pseudo-navier");
  auto slot = [&](const VFunction& g) -> Grouped& {
    auto it = std::find_if(out.begin(), out.end(), [&](const Grouped& gr) { return gr.g == g; });
    if (it != out.end()) return *it;
    out.push_back({g, std::vector<double>(2 * n, 0.0), {}});
    return out.back();
  };
  for (int end = 0; end < 2; ++end) {
    const auto& side = end == 0 ? p.left : p.right;
    for (int i = 0; i < n; ++i)
      for (const VTerm& t : side[i])
        if (!t.g.isPoly()) slot(t.g).values[end * n + i] += t.coef;
  }
  for (const ForceTerm& f : p.force) {
    if (f.g.isPoly()) continue;
    Grouped& gr = slot(f.g);
    if (gr.force.size() < f.uPoly.size()) gr.force.resize(f.uPoly.size(), 0.0);
    for (size_t k = 0; k < f.uPoly.size(); ++k) gr.force[k] += f.uPoly[k];
  }
  return out;
}

// The polynomial terms ((v - c) w)^m of one frame: with s = (v - c) w, d²/dv² = w² d²/ds², so
// the triangular system runs in s with alpha[j] scaled by w^{2j}.
void solvePolyFrame(const ComponentProblem& p, int n, double c, double w, std::vector<SeparableTerm>& terms) {
  auto inFrame = [&](const VFunction& g) { return g.isPoly() && g.c == c && g.w == w; };
  int top = -1;
  for (int end = 0; end < 2; ++end)
    for (const VExpansion& ex : end == 0 ? p.left : p.right)
      for (const VTerm& t : ex)
        if (inFrame(t.g)) top = std::max(top, t.g.n);
  for (const ForceTerm& f : p.force)
    if (inFrame(f.g)) top = std::max(top, f.g.n);
  std::vector<std::vector<std::vector<double>>> data(top + 1, std::vector<std::vector<double>>(2, std::vector<double>(n, 0.0)));
  for (int end = 0; end < 2; ++end) {
    const auto& side = end == 0 ? p.left : p.right;
    for (int i = 0; i < n; ++i)
      for (const VTerm& t : side[i])
        if (inFrame(t.g)) data[t.g.n][end][i] += t.coef;
  }
  std::vector<std::vector<double>> force(top + 1);
  for (const ForceTerm& f : p.force) {
    if (!inFrame(f.g)) continue;
    auto& q = force[f.g.n];
    if (q.size() < f.uPoly.size()) q.resize(f.uPoly.size(), 0.0);
    for (size_t k = 0; k < f.uPoly.size(); ++k) q[k] += f.uPoly[k];
  }
  std::vector<double> alpha = p.alpha;
  for (size_t j = 0; j < alpha.size(); ++j) alpha[j] *= std::pow(w, 2.0 * j);
  const auto g = solvePolyInV(alpha, data, force);
  for (int m = 0; m <= top; ++m) {
    VFunction f;
    f.family = Family::Poly;
    f.n = m;
    f.w = w;
    f.c = c;
    terms.push_back({f, UFactor::polynomial(g[m])});
  }
}

void solveComponent(const ComponentProblem& p, BasisCache& cache, std::vector<SeparableTerm>& terms) {
  const int n = static_cast<int>(p.alpha.size()) - 1;
  if (n < 1) throw Error(ErrorCode::InvalidField, "the operator has no coefficients");
  if (static_cast<int>(p.left.size()) != n || static_cast<int>(p.right.size()) != n)
    throw Error(ErrorCode::InvalidField, "an order-" + std::to_string(2 * n) + " operator needs " + std::to_string(n) +
                                             " boundary conditions at each end");
  for (double a : p.alpha)
    if (!std::isfinite(a)) throw Error(ErrorCode::NonFinite, "an operator coefficient is not finite");
  if (p.alpha[0] == 0.0)
    throw Error(ErrorCode::DegenerateOperator,
                "the coefficient of the highest u-derivative (b) is 0: the PDE loses its order in u");

  // Eigen-family terms: one ODE each (with its force, if any).
  for (Grouped& gr : groupEigenTerms(p, n)) {
    try {
      while (!gr.force.empty() && gr.force.back() == 0.0) gr.force.pop_back();
      const EvenOdeBasis& basis = cache.get(p.alpha, gr.g.sigma(), static_cast<int>(gr.force.size()) - 1);
      terms.push_back({gr.g, basis.solve(gr.values.data(), gr.values.data() + n, gr.force)});
    } catch (const Error& e) {
      throw Error(e.code(), "term " + describeFunction(gr.g) + ": " + e.what());
    }
  }

  // Polynomial terms: one triangular system per (centre, scale) over all powers.
  std::vector<std::pair<double, double>> frames;  // (c, w) of ((v - c) w)^m
  auto frameOf = [&](const VFunction& g) {
    for (size_t k = 0; k < frames.size(); ++k)
      if (frames[k].first == g.c && frames[k].second == g.w) return k;
    frames.emplace_back(g.c, g.w);
    return frames.size() - 1;
  };
  for (int end = 0; end < 2; ++end)
    for (const VExpansion& ex : end == 0 ? p.left : p.right)
      for (const VTerm& t : ex)
        if (t.g.isPoly()) frameOf(t.g);
  for (const ForceTerm& f : p.force)
    if (f.g.isPoly()) frameOf(f.g);
  for (size_t fr = 0; fr < frames.size(); ++fr) solvePolyFrame(p, n, frames[fr].first, frames[fr].second, terms);
}

}  // namespace

SeparableSurface solveClosedForm(const PdeProblem& problem, BasisCache* shared) {
  SeparableSurface s;
  s.v0 = problem.v0;
  s.v1 = problem.v1;
  BasisCache local;
  BasisCache& cache = shared ? *shared : local;
  for (int c = 0; c < 3; ++c) {
    try {
      solveComponent(problem.component[c], cache, s.component[c]);
    } catch (const Error& e) {
      throw Error(e.code(), std::string("component ") + kAxis[c] + ": " + e.what());
    }
  }
  return s;
}

}  // namespace pdesurf
