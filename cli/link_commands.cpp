// pdesurf encode-link / decode-link: the page's shareable links from the command line.
#include <nlohmann/json.hpp>
#include <ostream>
#include <stdexcept>

#include "cli.hpp"
#include "link_codec.hpp"
#include "common/errors.hpp"
#include "scene/json_read.hpp"
#include "scene/scene.hpp"

namespace pdesurf::cli {

int runEncodeLink(const Options& o, std::ostream& out) {
  const std::string text = readFile(o.scenePath);
  parseScene(text);  // a link to a scene that does not load helps nobody
  nlohmann::json state;
  state["scene"] = readJson(text);
  if (o.gridGiven) state["grid"] = {{"nu", o.nu}, {"nv", o.nv}};
  out << encodeLink(state.dump()) << "\n";
  return 0;
}

int runDecodeLink(const Options& o, std::ostream& out) {
  const std::string json = decodeLink(o.scenePath);
  nlohmann::json state;
  try {
    state = readJson(json);  // limits first: nothing nested deeper than 32 is built or dumped
  } catch (const Error& e) {
    if (e.code() == ErrorCode::ParseError) throw std::runtime_error(std::string("the link's content is not JSON: ") + e.what());
    throw std::runtime_error(std::string("the link's content is refused: ") + errorCodeName(e.code()) + ": " + e.what());
  }
  if (!state.is_object() || !state.contains("scene") || !state["scene"].is_object())
    throw std::runtime_error("the link holds no scene");
  const std::string scene = state["scene"].dump(2);
  parseScene(scene);  // report a broken scene as such, by field
  out << scene << "\n";
  return 0;
}

}  // namespace pdesurf::cli
