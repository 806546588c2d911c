#include "scene/json_read.hpp"

#include <set>
#include <vector>

#include "common/errors.hpp"
#include "common/limits.hpp"

namespace pdesurf {

namespace {

void checkNesting(const std::string& text) {
  int depth = 0;
  bool inString = false;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (inString) {
      if (c == '\\') ++i;
      else if (c == '"') inString = false;
    } else if (c == '"') {
      inString = true;
    } else if (c == '{' || c == '[') {
      if (++depth > limits::kJsonDepth)
        throw Error(ErrorCode::TooLarge, "JSON nested deeper than " + std::to_string(limits::kJsonDepth) + " levels");
    } else if (c == '}' || c == ']') {
      --depth;
    }
  }
}

}  // namespace

nlohmann::json readJson(const std::string& text) {
  if (text.size() > limits::kSceneBytes)
    throw Error(ErrorCode::TooLarge, "JSON text larger than " + std::to_string(limits::kSceneBytes >> 20) + " MiB (" +
                                         std::to_string(text.size()) + " bytes)");
  checkNesting(text);
  std::vector<std::set<std::string>> keys;  // per open object
  const auto strict = [&keys](int, nlohmann::json::parse_event_t event, nlohmann::json& parsed) {
    using E = nlohmann::json::parse_event_t;
    if (event == E::object_start) keys.emplace_back();
    else if (event == E::object_end) keys.pop_back();
    else if (event == E::key && !keys.back().insert(parsed.get<std::string>()).second)
      throw Error(ErrorCode::ParseError, "malformed JSON: the key \"" + parsed.get<std::string>().substr(0, 64) + "\" appears twice in one object");
    return true;
  };
  try {
    return nlohmann::json::parse(text, strict);
  } catch (const nlohmann::json::parse_error& e) {
    throw Error(ErrorCode::ParseError, "malformed JSON at byte " + std::to_string(e.byte));
  } catch (const nlohmann::json::exception& e) {
    // nlohmann reports number overflow ("1e999") and similar as its own exceptions.
    throw Error(ErrorCode::ParseError, std::string("malformed JSON: ") + e.what());
  }
}

}  // namespace pdesurf
