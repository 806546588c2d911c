// Expressions as a shared graph (expr/expr.hpp, budget.hpp, program.hpp): equal subtrees are
// one node, derivatives stay O(nodes), the budget stops a build at its first node over the
// limit, and the flat program agrees with evaluate().
#include <doctest.h>

#include <chrono>
#include <cmath>
#include <random>

#include "common/errors.hpp"
#include "expr/budget.hpp"
#include "expr/parse.hpp"
#include "expr/program.hpp"
#include "scene/scene.hpp"
#include "test_util.hpp"

using namespace pdesurf;

namespace {

Expr parseTV(const std::string& text) {
  AllowedVariables vars{true, true};
  vars.uName = "t";
  return parseExpression(text, {}, vars);
}

std::string productText(int n) {
  std::string s = "t";
  for (int k = 1; k < n; ++k) s += "*t";
  return s;
}

}  // namespace

TEST_CASE("expression graph: structurally equal subexpressions are one node") {
  const Expr a = parseTV("sin(v)*t + 2"), b = parseTV("sin(v) * t + 2");
  CHECK((a == b));
  const Expr s = parseTV("(sin(v)*t)*(sin(v)*t)");
  CHECK((s->a == s->b));
  CHECK(nodeCount(s) == 5);  // v, sin, t, *, *
  CHECK((constant(0.5) == constant(0.5)));
  CHECK((constant(0.0) != constant(-0.0)));
  CHECK((add(variable(ExprVar::V), constant(1)) == add(variable(ExprVar::V), constant(1))));
  // 450 factors: one t and 449 products.
  CHECK(nodeCount(parseTV(productText(450))) == 450);
}

TEST_CASE("expression graph: derivatives and substitution stay O(n) distinct nodes") {
  const Expr p = parseTV("1 + " + productText(300));
  const size_t n = nodeCount(p);
  const Expr St = derivative(p, ExprVar::U), Stt = derivative(St, ExprVar::U);
  CHECK(nodeCount(St) <= 4 * n);
  CHECK(nodeCount(Stt) <= 12 * n);
  const Expr tau = parseTV("0.5 + 0.1*sin(v)");
  const Expr on = substitute(Stt, ExprVar::U, tau);
  CHECK(nodeCount(on) <= nodeCount(Stt) + nodeCount(tau));
  // Values agree with the closed form: d²/dt² (1 + t^300) = 300·299 t^298.
  const double vars[2] = {0.3, 0.9};
  CHECK(evaluate(*Stt, vars) == doctest::Approx(300.0 * 299.0 * std::pow(0.9, 298)).epsilon(1e-9));
  // A tower x_{k+1} = x_k * x_k: 41 nodes, a tree of 2^41; its derivative is a few nodes per level.
  Expr x = parseTV("1 + 1e-14*t");
  for (int k = 0; k < 40; ++k) x = multiply(x, x);
  CHECK(nodeCount(x) < 60);
  CHECK(x->treeSize > (uint64_t{1} << 40));
  const Expr dx = derivative(x, ExprVar::U);
  CHECK(nodeCount(dx) < 300);
  const double at[2] = {0.0, 0.5};
  double want = 1 + 1e-14 * 0.5;
  for (int k = 0; k < 40; ++k) want *= want;
  CHECK(evaluate(*x, at) == want);  // one pass over 41 nodes, not 2^41
  // Its text would be 2^40 characters: elided.
  const std::string text = toTextLimited(x, 2000);
  CHECK(text.size() < 2100);
  CHECK(text.find(kElided) != std::string::npos);
  CHECK(toTextLimited(parseTV("2*v + t"), 2000, "v", "t") == "2*v + t");
}

TEST_CASE("expression graph: the budget stops a build at the first node over the limit") {
  const Expr p = parseTV("1 + " + productText(300));
  {
    ExprBudget budget(1000000, "test");
    derivative(derivative(p, ExprVar::U), ExprVar::U);
    CHECK(budget.used() > 0);
    CHECK(budget.used() < 20000);
  }
  Expr x = parseTV("sin(t*v) + t");
  for (int k = 0; k < 30; ++k) x = multiply(x, add(x, constant(k)));
  ExprBudget budget(500, "the derived conditions");
  budget.setPath("patches[0].ends.u1");
  const auto t0 = std::chrono::steady_clock::now();
  try {
    Expr d = x;
    for (int k = 0; k < 8; ++k) d = derivative(d, ExprVar::U);
    FAIL("no TooLarge");
  } catch (const Error& e) {
    CHECK(e.code() == ErrorCode::TooLarge);
    CHECK(std::string(e.what()).rfind("patches[0].ends.u1: the derived conditions need more than 500", 0) == 0);
    CHECK(std::string(e.what()).size() <= 600);
  }
  CHECK(budget.used() == 501);
  CHECK(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() < 0.1 * pdesurf::testing::kTimeScale);
}

TEST_CASE("expression graph: the flat program agrees with evaluate()") {
  const char* texts[] = {"sin(v)*t^2 + exp(-t)/(1 + v^2)", "sqrt(1 + t*v) - abs(v - 0.5)^3", "atan(t)^v + cosh(v)*tanh(t)", "-t^2 - (-v)^3",
                         "general(log(2 + v)) * acos(t/4)"};
  std::vector<Expr> roots;
  for (const char* s : texts) roots.push_back(parseTV(s));
  roots.push_back(derivative(roots[0], ExprVar::U));
  roots.push_back(roots[1]);  // a root twice
  const ExprProgram prog(roots);
  CHECK(prog.outputs() == roots.size());
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> uni(-1.0, 1.0);
  const size_t n = 1000;  // several blocks
  std::vector<double> v(n), u(n);
  for (size_t i = 0; i < n; ++i) v[i] = uni(rng), u[i] = uni(rng);
  std::vector<std::vector<double>> out(roots.size(), std::vector<double>(n));
  std::vector<double*> outs;
  for (auto& o : out) outs.push_back(o.data());
  prog.runAll(v.data(), u.data(), n, outs.data());
  for (size_t r = 0; r < roots.size(); ++r)
    for (size_t i = 0; i < n; ++i) {
      const double vars[2] = {v[i], u[i]};
      const double want = evaluate(*roots[r], vars);
      if (std::isnan(want)) CHECK(std::isnan(out[r][i]));
      else CHECK(out[r][i] == want);  // the same operations in the same order: bit for bit
    }
  CHECK(prog.registers() < prog.instructions());  // registers are reused
}

TEST_CASE("expression graph: one budget per scene, summed over its blends, stops at the first end over it") {
  const std::string dir = pdesurf::testing::examplePath("../tests/hostile/expressions/");
  // One 450-factor surface met along a curve with curvature: derived (about 25 000 nodes).
  const Scene one = parseScene(pdesurf::testing::readText(dir + "product-450-curve.json"));
  CHECK(one.patches[2].primary().trimmed);
  CHECK(one.patches[2].primary().pointwisePartials[2].size() == 6);
  // 31 of them in one scene: refused at the end where the budget runs out (every end is
  // derived before any blend's conditions are written), in a fraction of a second.
  const auto t0 = std::chrono::steady_clock::now();
  try {
    parseScene(pdesurf::testing::readText(dir + "31-surfaces-on-curves.json"));
    FAIL("no TooLarge");
  } catch (const Error& e) {
    CHECK(e.code() == ErrorCode::TooLarge);
    CHECK(std::string(e.what()).find("patches[44].ends.u1: ") == 0);
  }
  CHECK(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() < 2.0 * pdesurf::testing::kTimeScale);
}
