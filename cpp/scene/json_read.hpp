// Reading JSON text from outside (scene files, links, the page): the limits of
// common/limits.hpp checked before nlohmann builds anything, and strictness where JSON itself
// is loose.
#pragma once
#include <nlohmann/json.hpp>
#include <string>

namespace pdesurf {

// Throws Error(TooLarge) over limits::kSceneBytes or deeper than limits::kJsonDepth (checked
// by a scan before parsing: nothing deep is ever built, dumped or destroyed), and
// Error(ParseError) for malformed JSON or an object with a key twice ("last wins" would let
// two readers of the same text disagree).
nlohmann::json readJson(const std::string& text);

}  // namespace pdesurf
