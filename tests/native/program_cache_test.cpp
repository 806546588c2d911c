// What is kept by expression between solves. GeneralFunction's compiled programs
// (basis/general_function.cpp): a
// function parsed again from the same text (an edited scene's unchanged profile) takes the
// program compiled before. Whatever it takes must be the function's own: values and
// derivatives equal to a freshly compiled program's, through evictions and mixed orders.
#include <doctest.h>

#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "basis/general_function.hpp"
#include "expr/parse.hpp"
#include "expr/program.hpp"
#include "expr/split.hpp"

using namespace pdesurf;

TEST_CASE("general functions' programs kept by expression: the same values as a fresh program's, through evictions") {
  std::mt19937 rng(6007);
  std::uniform_int_distribution<int> pick(0, 399), order(0, 2);
  const AllowedVariables v{true, false};
  // 400 texts (more than the cache keeps), asked for again and again in random order, each
  // time as a new GeneralFunction (as a new parse makes them).
  const auto text = [](int i) { return "sin(" + std::to_string(1 + i % 7) + "*v)*cos(v/" + std::to_string(2 + i / 7) + ") + " + std::to_string(i) + "*v^2"; };
  std::vector<double> vs;
  for (int k = 0; k <= 16; ++k) vs.push_back(-1.0 + 0.37 * k);
  int checked = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const int i = pick(rng), maxK = order(rng);
    const Expr e = parseExpression(text(i), {}, v);
    const GeneralFunction g(text(i), e);
    std::vector<std::vector<double>> got(size_t(maxK) + 1, std::vector<double>(vs.size()));
    std::vector<double*> outs;
    for (auto& o : got) outs.push_back(o.data());
    g.evalManyUpTo(vs.data(), vs.size(), maxK, outs.data());
    // The reference: the derivatives formed and compiled here, apart from the cache.
    std::vector<Expr> roots{e};
    for (int k = 1; k <= maxK; ++k) roots.push_back(derivative(roots.back(), ExprVar::V));
    std::vector<std::vector<double>> want(size_t(maxK) + 1, std::vector<double>(vs.size()));
    std::vector<double*> wouts;
    for (auto& o : want) wouts.push_back(o.data());
    ExprProgram(roots).runAll(vs.data(), nullptr, vs.size(), wouts.data());
    for (int k = 0; k <= maxK; ++k)
      for (size_t p = 0; p < vs.size(); ++p) {
        CHECK(got[size_t(k)][p] == want[size_t(k)][p]);
        ++checked;
      }
    CHECK(g.derivativeExpr(maxK) == roots.back());  // interned: the same node
  }
  MESSAGE(checked << " values compared");
}

TEST_CASE("splits kept by expression: a split taken again still sums to its expression, through evictions and new expressions") {
  // splitExpression keeps its last splits by (interned) expression. Expressions made and
  // dropped in turn (their addresses free for others) must never get another's split: each
  // split's terms plus its remainder evaluate to the expression at random points.
  std::mt19937 rng(6011);
  std::uniform_int_distribution<int> pick(0, 599);
  std::uniform_real_distribution<double> at(-2, 2);
  const AllowedVariables uv{true, true};
  int checked = 0;
  for (int trial = 0; trial < 1500; ++trial) {
    const int i = pick(rng);
    const std::string text = std::to_string(1 + i % 5) + "*cos(" + std::to_string(1 + i % 3) + "*v)*u^" + std::to_string(i % 4) + " + sin(v)^2*" +
                             std::to_string(i) + " + exp(u*v/" + std::to_string(1 + i / 60) + ")";
    const Expr e = parseExpression(text, {}, uv);
    const Split sp = splitExpression(e);
    for (int q = 0; q < 4; ++q) {
      const double v = at(rng), u = at(rng);
      const double vars[2] = {v, u};
      double sum = sp.remainder ? evaluate(*sp.remainder, vars) : 0.0;
      for (const SplitTerm& t : sp.terms) sum += t.coef * t.v.eval(v) * t.s.eval(u);
      const double want = evaluate(*e, vars);
      CHECK(std::abs(sum - want) <= 1e-12 * std::max(1.0, std::abs(want)));
      ++checked;
    }
  }
  MESSAGE(checked << " points compared");
}
