// Issue 17: one-line strings refuse every control character a line-splitting reader breaks at
// (C0, DEL, C1 with NEL U+0085, U+2028, U+2029); the writers' own guard replaces them; every
// error message is at most kErrorMessageChars; a size limit is TooLarge.
#include <doctest.h>

#include <nlohmann/json.hpp>

#include "common/errors.hpp"
#include "common/text.hpp"
#include "scene/scene.hpp"
#include "test_util.hpp"

using namespace pdesurf;
using namespace pdesurf::testing;
using json = nlohmann::json;

namespace {

struct Outcome {
  std::string code, message;
};

Outcome parse(const json& j) {
  try {
    parseScene(j.dump());
  } catch (const Error& e) {
    return {errorCodeName(e.code()), e.what()};
  }
  return {"ok", ""};
}

const char* const kBreaks[] = {"\xc2\x85", "\xe2\x80\xa8", "\xe2\x80\xa9", "\xc2\x80", "\xc2\x9f", "\x0b", "\x7f"};
const char* const kNames[] = {"U+0085", "U+2028", "U+2029", "U+0080", "U+009F", "U+000B", "U+007F"};

}  // namespace

TEST_CASE("text rules: control characters, C1 and the Unicode line separators included") {
  for (size_t k = 0; k < std::size(kBreaks); ++k) {
    const std::string s = std::string("a") + kBreaks[k] + "b";
    CAPTURE(kNames[k]);
    CHECK(controlCharacterAt(s, 1) == s.size() - 2);
    CHECK(codePointName(s, 1) == kNames[k]);
    CHECK(oneLineText(s) == "a b");
  }
  // Neighbours that are not control characters stay: é (U+00E9), U+00A0, U+2027, U+202A, …
  for (const char* s : {"\xc3\xa9", "\xc2\xa0", "\xe2\x80\xa7", "\xe2\x80\xaa", "\xe2\x80\xa6", "\xef\xbb\xbf"}) {
    CAPTURE(s);
    CHECK(controlCharacterAt(s, 0) == 0);
    CHECK(oneLineText(s) == s);
  }
  CHECK(oneLineText("a\r\nv 1 2 3") == "a  v 1 2 3");
}

TEST_CASE("text rules: one-line scene strings refuse C1 and U+2028/2029 with a named error") {
  const json base = json::parse(readText(examplePath("zhang-vase-fig2a.json")));
  for (size_t k = 0; k < std::size(kBreaks); ++k) {
    CAPTURE(kNames[k]);
    const std::string hostile = std::string("x") + kBreaks[k] + "v 1 2 3";
    json j = base;
    j["title"] = hostile;
    Outcome o = parse(j);
    CHECK(o.code == "InvalidField");
    CHECK(o.message == std::string("title: a control character ") + kNames[k] + " (names and titles are one line)");
    j = base;
    j["patches"][0]["name"] = hostile;
    CHECK(parse(j).message.rfind("patches[0].name: a control character " + std::string(kNames[k]), 0) == 0);
    j = base;
    j["parameters"]["a1"]["label"] = hostile;
    CHECK(parse(j).message.rfind("parameters.a1.label: a control character", 0) == 0);
  }
  // Descriptions keep newlines and tabs, and still refuse C1.
  json j = base;
  j["description"] = "two\nlines\tand a tab";
  CHECK(parse(j).code == "ok");
  j["description"] = "nel\xc2\x85";
  CHECK(parse(j).message == "description: a control character U+0085 (only newline and tab are allowed)");
}

TEST_CASE("text rules: error messages are at most 600 characters; size limits are TooLarge") {
  CHECK(std::string(Error(ErrorCode::Internal, std::string(22000, 'x')).what()).size() <= kErrorMessageChars);
  const std::string head = "patches[0].x: ", tail = ": the reason";
  const std::string clipped = Error(ErrorCode::InvalidField, head + std::string(22000, 'y') + tail).what();
  CHECK(clipped.size() <= kErrorMessageChars);
  CHECK(clipped.rfind(head, 0) == 0);  // the path and the reason survive the clip
  CHECK(clipped.substr(clipped.size() - tail.size()) == tail);
  // UTF-8 is never cut inside a character.
  std::string accents;
  for (int k = 0; k < 1000; ++k) accents += "\xc3\xa9";
  const std::string cut = clipText(accents, 101);
  CHECK(cut.size() <= 101);
  CHECK(cut.substr(cut.size() - 3) == "\xe2\x80\xa6");
  CHECK(cut.size() % 2 == 1);  // whole é's (2 bytes) and the ellipsis (3)

  // A 22 KB expression, in an expression field and in a number field: TooLarge, short message.
  const std::string big = [] {
    std::string s = "v";
    while (s.size() < 22000) s += "+v";
    return s;
  }();
  const json base = json::parse(readText(examplePath("zhang-vase-fig2a.json")));
  json j = base;
  j["patches"][0]["boundary"]["x"]["u0"][0] = big;
  Outcome o = parse(j);
  CHECK(o.code == "TooLarge");
  CHECK(o.message == "patches[0].boundary.x.u0[0]: longer than 1000 characters");
  j = base;
  j["patches"][0]["v_range"][1] = big;  // was ParseError from the expression parser
  o = parse(j);
  CHECK(o.code == "TooLarge");
  CHECK(o.message.size() <= kErrorMessageChars);
  j = base;
  j["patches"][0][big] = 1;  // an unknown key of 22 KB lands in the message's path
  o = parse(j);
  CHECK(o.code == "InvalidField");
  CHECK(o.message.size() <= kErrorMessageChars);
  CHECK(o.message.find("unknown field") != std::string::npos);
}
