// fourierSeriesMany (methods/approximate.hpp): several periodic expansions sampled by one
// program; each result must be fourierSeries's for that expansion alone, to the bit, and a
// sample that is not finite must still be named by its slot.
#include <doctest.h>

#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "basis/general_function.hpp"
#include "common/errors.hpp"
#include "expr/parse.hpp"
#include "methods/approximate.hpp"

using namespace pdesurf;

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
