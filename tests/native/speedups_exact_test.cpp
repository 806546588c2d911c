// What the solver's speed-ups must keep exact (issue 37): each of them computes the same thing
// another way, and these tests hold it to what the plain way gives.
#include <doctest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <vector>

#include "basis/general_function.hpp"
#include "common/errors.hpp"
#include "expr/expr.hpp"
#include "expr/parse.hpp"
#include "expr/program.hpp"
#include "expr/split.hpp"
#include "methods/approximate.hpp"
#include "scene/scene.hpp"
#include "surface/separable_surface.hpp"

using namespace pdesurf;

// fourierSeriesMany (methods/approximate.hpp): several periodic expansions sampled by one
// program; each result must be fourierSeries's for that expansion alone, to the bit, and a
// sample that is not finite must still be named by its slot.

namespace {

VFunction general(const std::string& text) {
  VFunction g{Family::General, 1.0, 0};
  g.general = std::make_shared<const GeneralFunction>(text, parseExpression(text, {}, AllowedVariables{true, false}));
  return g;
}

}  // namespace

TEST_CASE("fourierSeriesMany: each expansion's series is fourierSeries's, to the bit, with shared subexpressions") {
  std::mt19937 rng(5309);
  std::uniform_real_distribution<double> c(-2, 2);
  std::uniform_int_distribution<int> pick(0, 5), k(1, 6);
  int checked = 0;
  for (int trial = 0; trial < 20; ++trial) {
    // A few curves sharing pieces (as a fill's slots share its sides), mixed with family terms.
    const std::string shared = "sin(" + std::to_string(k(rng)) + "*v)*cos(v)";
    std::vector<VExpansion> fs(2 + trial % 4);
    for (VExpansion& f : fs) {
      const int terms = 1 + pick(rng) % 3;
      for (int t = 0; t < terms; ++t) {
        switch (pick(rng)) {
          case 0: f.push_back({VFunction{Family::Cos, double(k(rng)), 0}, c(rng)}); break;
          case 1: f.push_back({VFunction{Family::Poly, 1.0, 0}, c(rng)}); break;
          case 2: f.push_back({general(shared), c(rng)}); break;
          case 3: f.push_back({general(shared + "^2 + " + std::to_string(c(rng)) + "*cos(" + std::to_string(k(rng)) + "*v)"), c(rng)}); break;
          default: f.push_back({general("exp(0.3*sin(v))*(" + shared + ")"), c(rng)}); break;
        }
      }
    }
    std::vector<const VExpansion*> ptrs;
    for (const VExpansion& f : fs) ptrs.push_back(&f);
    const int N = 8 + 8 * (trial % 5);
    const double v0 = trial % 2 ? 0.0 : -1.0, v1 = v0 + 2 * M_PI;
    const std::vector<VExpansion> many = fourierSeriesMany(ptrs, v0, v1, N, 0.0, trial % 3 != 0);
    REQUIRE(many.size() == fs.size());
    for (size_t i = 0; i < fs.size(); ++i) {
      const VExpansion one = fourierSeries(fs[i], v0, v1, N, 0.0, trial % 3 != 0);
      REQUIRE(many[i].size() == one.size());
      for (size_t t = 0; t < one.size(); ++t) {
        CHECK(many[i][t].coef == one[t].coef);  // bit for bit
        CHECK(many[i][t].g.family == one[t].g.family);
        CHECK(many[i][t].g.w == one[t].g.w);
        ++checked;
      }
    }
  }
  MESSAGE(checked << " coefficients compared");
}

TEST_CASE("fourierSeriesMany: a sample that is not finite is named by its term") {
  const VExpansion fine{{general("sin(v)"), 1.0}};
  const VExpansion pole{{general("log(v)"), 1.0}};     // -inf at v = 0, the first sample
  try {
    fourierSeriesMany({&fine, &pole}, 0.0, 2 * M_PI, 8);
    FAIL("no error");
  } catch (const Error& e) {
    CHECK(e.code() == ErrorCode::NonFinite);
    CHECK(std::string(e.what()).find("'log(v)' is not finite at v = 0") != std::string::npos);
  }
}

// What is kept by expression between solves: GeneralFunction's compiled programs
// (basis/general_function.cpp). A function parsed again from the same text (an edited scene's
// unchanged profile) takes the program compiled before; whatever it takes must be the
// function's own: values and derivatives equal to a freshly compiled program's, through
// evictions and mixed orders.

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

// A typed surface is split into separable terms T(t)·g(v) and a pointwise rest
// (scene/expression_fields.cpp). Parts the split gives up on but that are still a product of a
// t-part made of families and any function of v (a wing's profile) become separable terms
// with a general g: drawn by tabulating g once per grid line. Random surfaces of such parts,
// of families and of parts that do not separate: the drawn surface is the typed expression.

namespace {

std::string num(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", x);
  return std::string("(") + b + ")";
}

}  // namespace

TEST_CASE("typed surfaces: parts separable over v with a general profile are drawn as the expression says") {
  std::mt19937 rng(7121);
  std::uniform_real_distribution<double> c(-1.5, 1.5), at(0, 1);
  std::uniform_int_distribution<int> pick(0, 4);
  int separated = 0, checked = 0;
  for (int trial = 0; trial < 40; ++trial) {
    // A profile the split gives up on (a high power of a trig sum), times family parts of t.
    const std::string profile = "(cos(v/4) - sin(v/4))*(1 - (cos(v/4) - sin(v/4))^2)*(2.9 - 2.1*(cos(v/4) - sin(v/4))^2 + 3.3*(cos(v/4) - sin(v/4))^4 - 2*(cos(v/4) - sin(v/4))^6)";
    std::string xyz[3];
    for (std::string& e : xyz) {
      e = num(c(rng)) + "*t";
      for (int k = 0; k < 3; ++k) {
        switch (pick(rng)) {
          case 0: e += " - " + num(c(rng)) + "*(1 - " + num(c(rng)) + "*t)*" + profile; break;  // separable over v
          case 1: e += " + " + num(c(rng)) + "*t^2*" + profile; break;                         // separable over v
          case 2: e += " + " + num(c(rng)) + "*cos(v)*(1 + t)"; break;                          // families
          case 3: e += " + " + num(c(rng)) + "*sin(t*v)"; break;                                // not separable
          default: e += " + " + num(c(rng)) + "*exp(t)*sqrt(2 + sin(v))"; break;               // separable over v
        }
      }
    }
    nlohmann::json scene = {{"format", "pdesurf-scene"}, {"version", 2}, {"title", "t"}};
    scene["patches"] = nlohmann::json::array({{{"name", "s"}, {"kind", "surface"}, {"t_range", {0, 1}}, {"v_range", {0, 2 * M_PI}},
                                               {"x", xyz[0]}, {"y", xyz[1]}, {"z", xyz[2]}}});
    CAPTURE(scene.dump());
    const Scene parsed = parseScene(scene.dump());
    const auto solved = solveScene(parsed);
    const SeparableSurface& s = solved.front().surface;
    const PrimarySurface& p = parsed.patches.front().primary();
    for (int k = 0; k < 3; ++k) {
      for (const SeparableTerm& t : s.component[k]) separated += t.g.isGeneral();
      if (xyz[k].find("sin(t*v)") == std::string::npos) CHECK(!s.pointwise[k]);  // all of it separable
      for (int q = 0; q < 12; ++q) {
        const double t = at(rng), v = 2 * M_PI * at(rng);
        const double vars[2] = {v, t};
        const double want = evaluate(*p.full[k], vars), got = evalPoint(s, t, v)[k];
        CHECK(std::abs(got - want) <= 1e-12 * std::max(1.0, std::abs(want)));
        ++checked;
      }
    }
  }
  CHECK(separated > 0);
  MESSAGE(checked << " points, " << separated << " general profile terms");
}
