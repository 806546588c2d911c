#include <doctest.h>

#include <cmath>

#include "common/errors.hpp"
#include "scene/expression.hpp"

using namespace pdesurf;

TEST_CASE("expressions: precedence, functions and parameters") {
  const ParameterValues p{{"a", 3.0}, {"r0", 1.8}, {"h_1", -2.0}};
  CHECK(evaluateExpression("1 + 2*3", p) == 7);
  CHECK(evaluateExpression("-a^2", p) == -9);
  CHECK(evaluateExpression("2^-1", p) == 0.5);
  CHECK(evaluateExpression("2^3^2", p) == 512);
  CHECK(evaluateExpression("(1 + 2)*3", p) == 9);
  CHECK(evaluateExpression("sqrt(2)/2*r0", p) == doctest::Approx(std::sqrt(2.0) / 2 * 1.8));
  CHECK(evaluateExpression("-30*pi/180", p) == doctest::Approx(-M_PI / 6));
  CHECK(evaluateExpression(" h_1 - -1 ", p) == -1);
  CHECK(evaluateExpression("1.5e-3", p) == 0.0015);
  CHECK(evaluateExpression("cos(0) + e^0", p) == 2);
}

TEST_CASE("expressions: errors name the column and the cause") {
  const ParameterValues p{{"r0", 1.0}};
  auto message = [&](const char* text) {
    try {
      evaluateExpression(text, p);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  CHECK(message("r0 + cso(1)") == "col 6: unknown function 'cso'");
  CHECK(message("2*r9") == "col 3: unknown parameter 'r9'");
  CHECK(message("(1 + 2))") == "col 8: unbalanced ')'");
  CHECK(message("(1 + 2") == "col 7: unbalanced '(': missing ')'");
  CHECK(message("1 +") == "col 4: expression ends too early");
  CHECK(message("sqrt(-1)") == "col 1: sqrt(-1.000000) is not finite");
  CHECK(message("1/0") == "expression '1/0' is not finite");
  CHECK(message("1 $ 2") == "col 3: unexpected '$'");
  CHECK(message(std::string(200, '(').c_str()).find("nested too deeply") != std::string::npos);
  CHECK(message(std::string(2000, '1').c_str()).find("longer than") != std::string::npos);
}
