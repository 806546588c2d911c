// Expression splitting: closed-form terms + remainder must equal the expression everywhere,
// and the family terms must be the ones a designer expects.
#include <doctest.h>

#include <cmath>

#include "expr/parse.hpp"
#include "expr/split.hpp"

using namespace pdesurf;

namespace {

const ParameterValues kParams{{"r0", 1.8}, {"xi", 0.5}, {"u0", 0.1}, {"R0", 0.9}, {"R1", 0.1}, {"k", 8},
                              {"r", 1.2}, {"k1", 0.5}, {"s", 0.7}, {"a2", 1e-4}, {"p0", 10}, {"eta", 120}, {"r0p", -0.5}};

Split split(const std::string& text, bool forceLike = false) {
  return splitExpression(parseExpression(text, kParams, AllowedVariables{true, true}), forceLike);
}

// terms + remainder == expression at scattered points.
double reconstructionError(const std::string& text, bool forceLike = false) {
  const Expr e = parseExpression(text, kParams, AllowedVariables{true, true});
  const Split sp = splitExpression(e, forceLike);
  double worst = 0.0;
  for (double v : {-1.3, 0.0, 0.4, 1.7, 3.9, 6.2})
    for (double s : {0.0, 0.3, 0.9}) {
      const double vars[2] = {v, s};
      double sum = sp.remainder ? evaluate(*sp.remainder, vars) : 0.0;
      for (const SplitTerm& t : sp.terms) sum += t.coef * t.v.eval(v) * t.s.eval(s);
      const double want = evaluate(*e, vars);
      worst = std::max(worst, std::abs(sum - want) / std::max(1.0, std::abs(want)));
    }
  return worst;
}

bool hasRemainder(const Split& s) { return s.remainder != nullptr; }

bool hasTerm(const Split& s, Family f, double w, double coef, int n = 0) {
  for (const SplitTerm& t : s.terms)
    if (t.v.family == f && (f == Family::Poly ? t.v.n == n : t.v.w == doctest::Approx(w)) && t.coef == doctest::Approx(coef)) return true;
  return false;
}

}  // namespace

TEST_CASE("split: family terms come out as a designer writes them") {
  Split s = split("r0*cos(v) + 0.1*cos(5*v)");
  CHECK(s.terms.size() == 2);
  CHECK_FALSE(hasRemainder(s));
  CHECK(hasTerm(s, Family::Cos, 1, 1.8));
  CHECK(hasTerm(s, Family::Cos, 5, 0.1));

  s = split("(1 + xi*u0^2)*(R0*sin(v) + R1*sin(k*v))");
  CHECK(s.terms.size() == 2);
  CHECK(hasTerm(s, Family::Sin, 1, 1.005 * 0.9));
  CHECK(hasTerm(s, Family::Sin, 8, 1.005 * 0.1));

  s = split("cos(v + pi/3)");
  CHECK(hasTerm(s, Family::Cos, 1, 0.5));
  CHECK(hasTerm(s, Family::Sin, 1, -std::sqrt(3.0) / 2));

  s = split("cos(v)^2");
  CHECK(hasTerm(s, Family::Poly, 0, 0.5));
  CHECK(hasTerm(s, Family::Cos, 2, 0.5));

  s = split("exp(v)*exp(2*v) + cosh(2*v)");
  CHECK(hasTerm(s, Family::Exp, 3, 1.0));
  CHECK(hasTerm(s, Family::Exp, 2, 0.5));
  CHECK(hasTerm(s, Family::Exp, -2, 0.5));

  s = split("3*v^2 - v + 2 - sin(-2*v)");
  CHECK(hasTerm(s, Family::Poly, 0, 3.0, 2));
  CHECK(hasTerm(s, Family::Poly, 0, -1.0, 1));
  CHECK(hasTerm(s, Family::Poly, 0, 2.0, 0));
  CHECK(hasTerm(s, Family::Sin, 2, 1.0));
}

TEST_CASE("split: what the families cannot hold stays in the remainder") {
  for (const char* text : {"sqrt((r+k1)^2 - s^2*cos(v)^2)", "v*cos(v)", "exp(v)*cos(v)", "a2*general(exp(v))", "1/(2 + cos(v))"}) {
    CAPTURE(text);
    const Split s = split(text);
    CHECK(hasRemainder(s));
    CHECK(s.terms.empty());
    CHECK(reconstructionError(text) < 1e-13);
  }
  const Split mixed = split("2*cos(v) + sqrt(1 + v^2)");
  CHECK(mixed.terms.size() == 1);
  CHECK(hasRemainder(mixed));
}

TEST_CASE("split: forces keep polynomials in u, surfaces any family in t") {
  Split s = split("p0*(1 + eta*u^2)*cos(v)", true);
  CHECK(s.terms.size() == 2);
  CHECK_FALSE(hasRemainder(s));
  s = split("cos(u)*cos(v)", true);  // not a polynomial in u: a general force
  CHECK(s.terms.empty());
  CHECK(hasRemainder(s));
  s = split("(r0 - r0p*u)*cos(v) + 2*sin(u)*sin(v)");
  CHECK(s.terms.size() == 3);
  CHECK_FALSE(hasRemainder(s));
}

TEST_CASE("split: terms plus remainder reproduce the expression") {
  for (const char* text : {"r0*cos(v) + 0.1*cos(5*v)", "(1 + xi*u0^2)*(R0*cos(v) + R1*cos(k*v))", "sin(v/2)*cos(3*v + 1)",
                           "(cos(v) + sin(2*v))^3", "cosh(v)*sinh(2*v) - exp(-v)", "v^3*(1 - v)^2", "-(2*v - 1)^4/3",
                           "sin(v)^4 - cos(2*v)^2 + 1", "sqrt(2)*cos(-v + 0.3) - e^2*sin(v)",
                           "4*sin(v) - 16.8*sin(v)^2 + 25.6*sin(v)^3 - 12.8*sin(v)^4", "tan(v) + cos(v)", "(u + v)^3", "cos(u + v)"}) {
    CAPTURE(text);
    CHECK(reconstructionError(text) < 1e-12);
    CHECK(reconstructionError(text, true) < 1e-12);
  }
}
