// pdesurf encode-link / decode-link: the page's shareable links from the command line.
#include <nlohmann/json.hpp>
#include <ostream>
#include <stdexcept>

#include "cli.hpp"
#include "link_codec.hpp"
#include "scene/scene.hpp"

namespace pdesurf::cli {

int runEncodeLink(const Options& o, std::ostream& out) {
  const std::string text = readFile(o.scenePath);
  parseScene(text);  // a link to a scene that does not load helps nobody
  nlohmann::json state;
  state["scene"] = nlohmann::json::parse(text);
  if (o.gridGiven) state["grid"] = {{"nu", o.nu}, {"nv", o.nv}};
  out << encodeLink(state.dump()) << "\n";
  return 0;
}

int runDecodeLink(const Options& o, std::ostream& out) {
  const std::string json = decodeLink(o.scenePath);
  nlohmann::json state;
  try {
    state = nlohmann::json::parse(json);
  } catch (const nlohmann::json::exception&) {
    throw std::runtime_error("the link's content is not JSON");
  }
  if (!state.is_object() || !state.contains("scene") || !state["scene"].is_object())
    throw std::runtime_error("the link holds no scene");
  const std::string scene = state["scene"].dump(2);
  parseScene(scene);  // report a broken scene as such, by field
  out << scene << "\n";
  return 0;
}

}  // namespace pdesurf::cli
