// Taylor arithmetic (expr/taylor.hpp) against the symbolic derivatives, for every function the
// grammar has, to the orders the general methods use (up to 8), at points where each is
// smooth; and the cases where the recurrences would divide by a base near zero.
#include <doctest.h>

#include <cmath>

#include "expr/parse.hpp"
#include "expr/taylor.hpp"

using namespace pdesurf;

namespace {

Expr parse(const char* text) { return parseExpression(text, {}, AllowedVariables{true, true, "u"}); }

double symbolic(const Expr& e, int k, double v, double u) {
  Expr d = e;
  for (int i = 0; i < k; ++i) d = derivative(d, ExprVar::V);
  const double vars[2] = {v, u};
  return evaluate(*d, vars);
}

}  // namespace

TEST_CASE("Taylor arithmetic agrees with symbolic derivatives of every function, to order 8") {
  const char* texts[] = {
      "sqrt(2 + sin(v)*u)", "exp(0.3*v^2 - u)",      "log(3 + cos(2*v))", "tan(0.4*v + 0.1)", "asin(0.5*sin(v))",
      "acos(0.4*cos(v) + 0.1)", "atan(v^2 - 1)",     "sinh(0.7*v)*cosh(0.2*v*u)", "tanh(v - 0.5)", "abs(v - 5)",
      "general(v^3)/(2 + v^2)", "(1 + v^2)^1.5",     "(2 + cos(v))^(u + v)", "v^7 - 3*v^2 + 1", "(cos(v))^-3",
      "-(v*u)/(1 + v)",
  };
  for (const char* text : texts) {
    const Expr e = parse(text);
    for (double v : {0.3, 1.1, 2.0}) {
      const double u = 0.7, vars[2] = {v, u};
      const std::vector<double> c = taylorCoefficients(*e, ExprVar::V, vars, 8);
      double factorial = 1.0;
      for (int k = 0; k <= 8; ++k) {
        if (k > 0) factorial *= k;
        const double want = symbolic(e, k, v, u);
        CAPTURE(text);
        CAPTURE(v);
        CAPTURE(k);
        CHECK(c[k] * factorial == doctest::Approx(want).epsilon(1e-9).scale(1.0));
        CHECK(derivativeAt(*e, ExprVar::V, vars, k) == doctest::Approx(want).epsilon(1e-9).scale(1.0));
      }
    }
  }
}

TEST_CASE("Taylor arithmetic: whole powers of a base near zero stay exact; sqrt at zero has no derivative") {
  // cos(v)^2 at v = π/2, where cos(v) is 6e-17: the general power recurrence divides by it.
  const Expr e = parse("(3*cos(v))^2*0.2");
  const double vars[2] = {M_PI / 2, 0.0};
  CHECK(derivativeAt(*e, ExprVar::V, vars, 2) == doctest::Approx(3.6).epsilon(1e-12));
  CHECK(derivativeAt(*e, ExprVar::V, vars, 4) == doctest::Approx(-14.4).epsilon(1e-12));
  const Expr r = parse("sqrt(v - 1)");
  const double one[2] = {1.0, 0.0};
  CHECK(!std::isfinite(derivativeAt(*r, ExprVar::V, one, 1)));
  // A derivative in the other variable.
  const Expr w = parse("sin(u*v)");
  const double at[2] = {2.0, 0.5};
  CHECK(derivativeAt(*w, ExprVar::U, at, 3) == doctest::Approx(-8 * std::cos(1.0)).epsilon(1e-12));
}
