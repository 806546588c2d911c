// Bad scenes get named errors that point at the field; nothing crashes.
#include <doctest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "analysis/join_certificate.hpp"
#include "common/errors.hpp"
#include "ode/even_ode.hpp"
#include "methods/method.hpp"
#include "scene/scene.hpp"
#include "surface/mesh.hpp"
#include "test_util.hpp"

using namespace pdesurf;
using namespace pdesurf::testing;
using nlohmann::json;

namespace {

// The version-1 file: these checks exercise the term-array reader and its field paths.
json fig2a() { return json::parse(readText(v1FixturePath("you2004-fig2a.json"))); }

// Returns "Code: message" of the error parse+solve+tessellate raises, or "ok".
std::string outcome(const std::string& text, int nu = 8, int nv = 8) {
  try {
    for (const SolvedPatch& sp : solveScene(parseScene(text))) tessellate(sp.surface, nu, nv);
  } catch (const Error& e) {
    return std::string(errorCodeName(e.code())) + ": " + e.what();
  }
  return "ok";
}

std::string outcomeOf(const json& j) { return outcome(j.dump()); }

}  // namespace

TEST_CASE("scene errors: malformed text") {
  CHECK(outcome("{\"format\": ") == "ParseError: malformed JSON at byte 12");
  CHECK(outcome("[1, 2]") == "InvalidField: scene: expected an object");
  CHECK(outcome(std::string(40, '[') + std::string(40, ']')).find("nested deeper") != std::string::npos);
  CHECK(outcome("{\"x\": 1e999}").rfind("ParseError", 0) == 0);
  CHECK(outcome(std::string((16 << 20) + 1, ' ')).find("larger than 16 MiB (16777217 bytes)") != std::string::npos);
  // Below it, a scene of megabytes parses (an imported CAD part's faces): 2 MiB of blanks is
  // malformed, not too large.
  CHECK(outcome(std::string(2 << 20, ' ')).rfind("ParseError", 0) == 0);
}

TEST_CASE("scene errors: the limits and strictness of docs/limits.md") {
  // Depth: 32 levels pass the scan (and fail later, as fields), 33 do not.
  const auto nest = [](int n) { return "{\"format\": " + std::string(n - 1, '[') + std::string(n - 1, ']') + "}"; };
  CHECK(outcome(nest(32)).rfind("InvalidField", 0) == 0);
  CHECK(outcome(nest(33)) == "TooLarge: JSON nested deeper than 32 levels");
  // The same key twice, also when spelled differently.
  CHECK(outcome("{\"format\": 1, \"format\": 2}").find("appears twice") != std::string::npos);
  CHECK(outcome("{\"format\": 1, \"\\u0066ormat\": 2}").find("appears twice") != std::string::npos);
  json j = json::parse(readText(examplePath("zhang-vase-fig2a.json")));  // expressions: version 2
  CHECK(outcomeOf(j) == "ok");
  // One-line strings: no control characters; descriptions may hold newlines.
  json t = j;
  t["title"] = "a\nv 1 2 3";
  CHECK(outcomeOf(t).rfind("InvalidField: title: a control character", 0) == 0);
  t = j;
  t["description"] = "two\nlines\tand a tab";
  CHECK(outcomeOf(t) == "ok");
  t["description"] = std::string("bell\x07");
  CHECK(outcomeOf(t).rfind("InvalidField: description", 0) == 0);
  // Decimal numbers only.
  t = j;
  t["patches"][0]["boundary"]["z"]["u0"][0] = "0x10";
  CHECK(outcomeOf(t).find("numbers are decimal") != std::string::npos);
  t["patches"][0]["boundary"]["z"]["u0"][0] = "1.5e-3*2";
  CHECK(outcomeOf(t) == "ok");
  // The total vertex cap: refused before any solve.
  const Scene scene = parseScene(j.dump());
  CHECK_NOTHROW(checkSceneGrid(scene, 2048, 2048));
  Scene two = scene;
  two.patches.push_back(two.patches[0]);
  CHECK_THROWS_WITH_AS(checkSceneGrid(two, 2048, 2048), doctest::Contains("vertices"), Error);
  CHECK_THROWS_AS(checkSceneGrid(scene, 2049, 8), Error);
}

TEST_CASE("tessellation refuses output a float cannot hold") {
  json j = json::parse(readText(examplePath("zhang-vase-fig2a.json")));
  j["patches"][0]["boundary"]["x"]["u0"][0] = "1e200*cos(a1*v)";
  CHECK(outcomeOf(j).find("NonFinite: the surface at (t, v) = (0, 0) is beyond what a float holds") == 0);
  j["patches"][0]["boundary"]["x"]["u0"][0] = "1e30*cos(a1*v)";  // within float: fine
  CHECK(outcomeOf(j) == "ok");
}

TEST_CASE("scene errors: fields") {
  json j = fig2a();
  j["format"] = "other";
  CHECK(outcomeOf(j) == "InvalidField: format: expected \"pdesurf-scene\"");
  j = fig2a();
  j["version"] = 7;
  CHECK(outcomeOf(j) == "InvalidField: version: this build reads scene versions 1 to 4");
  j = fig2a();
  j["colour"] = "red";
  CHECK(outcomeOf(j) == "InvalidField: scene.colour: unknown field");
  j = fig2a();
  j.erase("patches");
  CHECK(outcomeOf(j) == "InvalidField: scene.patches: missing");
  j = fig2a();
  j["parameters"]["r0"]["value"] = 99;
  CHECK(outcomeOf(j).rfind("InvalidField: parameters.r0.value: outside [min, max]", 0) == 0);
  j = fig2a();
  j["parameters"]["pi"] = {{"value", 1}, {"min", 0}, {"max", 2}};
  CHECK(outcomeOf(j) == "InvalidField: parameters.pi: 'pi' is reserved");
  j = fig2a();
  j["patches"][0]["boundary"]["x"]["u0"][0][0]["fn"] = "cosine";
  CHECK(outcomeOf(j) == "UnknownName: patches[0].boundary.x.u0[0][0].fn: unknown basis function 'cosine' (poly, cos, sin, exp, cosh, sinh, expr)");
  j = fig2a();
  j["patches"][0]["boundary"]["z"]["u1"] = json::array({json::array(), json::array(), json::array()});
  CHECK(outcomeOf(j) == "InvalidField: patches[0].boundary.z.u1: an order-4 operator takes at most 2 conditions [X, dX/du]");
  j = fig2a();
  j["patches"][0]["operator"]["order"] = 3;
  CHECK(outcomeOf(j) == "InvalidField: patches[0].operator.order: order must be 2, 4 or 6");
  j = fig2a();
  j["patches"][1]["name"] = "blend";
  CHECK(outcomeOf(j) == "InvalidField: patches[1].name: duplicate patch name 'blend'");
  j = fig2a();
  j["patches"][1]["meets"]["patch"] = "nowhere";
  CHECK(outcomeOf(j) == "UnknownName: patches[1].meets.patch: no pde or bezier patch named 'nowhere'");
  j = fig2a();
  j["patches"][0]["v_range"] = {1, 0};
  CHECK(outcomeOf(j) == "InvalidField: patches[0].v_range: end must be greater than start");
}

TEST_CASE("scene errors: non-finite and degenerate numbers") {
  json j = fig2a();
  j["patches"][0]["operator"]["c"] = "exp(1000)";
  CHECK(outcomeOf(j) == "NonFinite: patches[0].operator.c: col 1: exp(1000.000000) is not finite");
  j = fig2a();
  j["patches"][0]["operator"]["b"] = json::array({1, 0, 1});
  CHECK(outcomeOf(j) == "DegenerateOperator: patches[0].operator.b[1]: b_y = 0 removes the 4th u-derivative: the PDE loses its order");
  j = fig2a();
  j["patches"][0]["boundary"]["x"]["u0"][0].push_back({{"fn", "exp"}, {"w", 200}});
  CHECK(outcomeOf(j) == "NonFinite: component x: term exp(200*v) is not finite on the grid (v from 0 to 6.28319)");
}

TEST_CASE("scene errors: grid sizes") {
  const std::string text = fig2a().dump();
  CHECK(outcome(text, 0, 8) == "GridSize: grid 0x8 is outside 1x1 .. 2048x2048");
  CHECK(outcome(text, 8, 2049) == "GridSize: grid 8x2049 is outside 1x1 .. 2048x2048");
  CHECK(outcome(text, -5, 8).rfind("GridSize", 0) == 0);
  CHECK(outcome(text, 1, 1) == "ok");
}

TEST_CASE("two-point problems without a unique solution are reported, not solved") {
  // G'' + pi² G = 0 with G(0) = G(1) = 0 has the solution sin(pi u) besides 0.
  try {
    EvenOdeBasis basis({1.0, -1.0}, -M_PI * M_PI);
    FAIL("expected Singular");
  } catch (const Error& e) {
    CHECK(e.code() == ErrorCode::Singular);
  }
  // Slightly off resonance the problem is fine.
  CHECK_NOTHROW(EvenOdeBasis({1.0, -1.0}, -M_PI * M_PI * 1.1));
}

TEST_CASE("version-2 expressions: a corpus of bad ones, each with its field, column and cause") {
  const json base = json::parse(readText(examplePath("you2004-fig2a.json")));
  auto withSlot = [&](const std::string& text) {
    json j = base;
    j["patches"][0]["boundary"]["x"]["u0"][1] = text;
    return outcomeOf(j);
  };
  const std::string at = "patches[0].boundary.x.u0[1]: ";
  CHECK(withSlot("r0p*cso(v)") == "UnknownName: " + at + "col 5: unknown function 'cso'");
  CHECK(withSlot("r9*cos(v)") == "UnknownName: " + at + "col 1: unknown parameter 'r9'");
  CHECK(withSlot("(r0p*cos(v)") == "ParseError: " + at + "col 12: unbalanced '(': missing ')'");
  CHECK(withSlot("r0p*cos(v))") == "ParseError: " + at + "col 11: unbalanced ')'");
  CHECK(withSlot("r0p*cos(u)") == "UnknownName: " + at + "col 9: 'u' cannot be used here: the variables are v");
  CHECK(withSlot("r0p*t") == "UnknownName: " + at + "col 5: 't' cannot be used here: the variables are v");
  CHECK(withSlot("r0p**cos(v)") == "ParseError: " + at + "col 5: unexpected '*'");
  CHECK(withSlot("1/0") == "NonFinite: " + at + "expression '1/0' is not finite");
  CHECK(withSlot(std::string(1001, 'v')).find("longer than 1000 characters") != std::string::npos);
  CHECK(withSlot(std::string(100, '(') + "v" + std::string(100, ')')).find("nested too deeply") != std::string::npos);
  json j = base;
  j["patches"][0]["boundary"]["x"]["u0"][1] = 7;  // a plain number is an expression too
  CHECK(outcomeOf(j) == "ok");
  j["patches"][0]["boundary"]["x"]["u0"][1] = json::array({1});
  CHECK(outcomeOf(j) == "InvalidField: " + at + "expected a string");
  j = base;
  j["parameters"]["t"] = {{"value", 1}, {"min", 0}, {"max", 2}};
  CHECK(outcomeOf(j) == "InvalidField: parameters.t: 't' is reserved");
  j = base;
  j["patches"][1]["x"] = "r0*cos(v) + t*sqrt(-1 - t)";  // finite nowhere on the surface
  CHECK(outcomeOf(j).rfind("NonFinite: component x: the surface is not finite at (t, v) = (0, 0)", 0) == 0);
}

TEST_CASE("version-2 expressions: a corpus of good ones solves") {
  const json base = json::parse(readText(examplePath("you2004-fig2a.json")));
  for (const char* text : {"r0p*cos(v)", "r0p*cos(v + 0)", "r0p*(cos(v)^2 + sin(v)^2)*cos(v)", "-0.5*cos(v) + 0*sin(3*v)",
                           "r0p*cos(v) + 0.01*sqrt(2 + cos(v))", "r0p*cos(-v)", "r0p/2*cos(v)*2", "general(r0p*cos(v))",
                           "r0p*cos(v) + 1e-3*v^2", "r0p*cos(v) + 0.001*exp(sin(v))"}) {
    json j = base;
    j["patches"][0]["boundary"]["x"]["u0"][1] = text;
    CAPTURE(text);
    CHECK(outcomeOf(j) == "ok");
  }
}

TEST_CASE("scene: version 4 may be empty (the page's new scene); older versions may not") {
  const Scene empty = parseScene(R"({"format": "pdesurf-scene", "version": 4, "patches": []})");
  CHECK(empty.patches.empty());
  CHECK(solveScene(empty).empty());
  CHECK(checkScene(empty, {}, 64).ok);
  CHECK_THROWS_WITH(parseScene(R"({"format": "pdesurf-scene", "version": 3, "patches": []})"),
                    "patches: expected a non-empty array (an empty scene needs version 4)");
}
