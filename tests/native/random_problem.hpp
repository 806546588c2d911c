// Random boundary-value problems shared by the solver tests: random mixtures of every basis
// family with random data, in each discriminant regime of the fourth-order operator.
#pragma once
#include <random>

#include "pde/pde_problem.hpp"

namespace pdesurf::testing {

enum class Regime { RealDistinct, Repeated, Complex };

// {b, c, d} with c² > 4bd, c² = 4bd or c² < 4bd.
inline std::vector<double> fourthOrderAlpha(Regime regime, std::mt19937& rng) {
  std::uniform_real_distribution<double> U(0.2, 3.0);
  const double b = U(rng), d = U(rng);
  const double crit = 2.0 * std::sqrt(b * d);
  switch (regime) {
    case Regime::RealDistinct: return {b, crit * (1.2 + U(rng)), d};
    case Regime::Repeated: return {b * b, 2 * b * d, d * d};  // exactly c² = 4bd in floating point
    case Regime::Complex: return {b, crit * (U(rng) - 0.2) / 3.0, d};
  }
  return {};
}

// Operator coefficients of order 2n with positive leading and trailing coefficients.
inline std::vector<double> randomAlpha(int order, std::mt19937& rng) {
  std::uniform_real_distribution<double> U(0.2, 3.0);
  std::vector<double> a(order / 2 + 1);
  for (double& x : a) x = U(rng);
  return a;
}

inline VExpansion randomExpansion(std::mt19937& rng, int terms) {
  std::uniform_real_distribution<double> C(-2.0, 2.0);
  std::uniform_real_distribution<double> W(0.1, 4.0);
  std::uniform_int_distribution<int> F(0, 5), P(0, 4);
  VExpansion e;
  for (int k = 0; k < terms; ++k) {
    VTerm t;
    t.g.family = static_cast<Family>(F(rng));
    t.g.w = t.g.family == Family::Exp || t.g.family == Family::Cosh || t.g.family == Family::Sinh ? W(rng) / 4 : W(rng);
    if (t.g.isPoly()) t.g.w = 1.0;  // scene polynomials are plain powers of v
    t.g.n = P(rng);
    t.coef = C(rng);
    e.push_back(t);
  }
  return e;
}

inline std::vector<ForceTerm> randomForce(std::mt19937& rng, int terms) {
  std::uniform_real_distribution<double> C(-3.0, 3.0);
  std::uniform_int_distribution<int> D(0, 3);
  std::vector<ForceTerm> out;
  for (const VTerm& t : randomExpansion(rng, terms)) {
    ForceTerm f{t.g, {}};
    for (int k = 0, deg = D(rng); k <= deg; ++k) f.uPoly.push_back(C(rng));
    out.push_back(f);
  }
  return out;
}

inline PdeProblem randomProblem(const std::vector<double>& alpha, std::mt19937& rng, double v1 = 6.283185307179586) {
  PdeProblem p;
  p.v1 = v1;
  const int n = static_cast<int>(alpha.size()) - 1;
  for (auto& c : p.component) {
    c.alpha = alpha;
    for (int i = 0; i < n; ++i) {
      c.left.push_back(randomExpansion(rng, 3));
      c.right.push_back(randomExpansion(rng, 3));
    }
  }
  return p;
}

}  // namespace pdesurf::testing
