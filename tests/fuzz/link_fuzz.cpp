// libFuzzer target: a link as `pdesurf decode-link LINK` receives it -> runDecodeLink (the
// CLI's own code: decodeLink, the JSON state, the scene's dump, parseScene). Expected
// outcome for bad input: a std::runtime_error (pdesurf::Error is one) naming the problem.
// A finding is anything else: a crash or sanitizer report, or another exception type
// escaping (nlohmann's own exceptions, std::length_error, ...).
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>

#include "cli.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  pdesurf::cli::Options o;
  o.command = "decode-link";
  o.scenePath.assign(reinterpret_cast<const char*>(data), size);
  std::ostringstream out;
  try {
    pdesurf::cli::runDecodeLink(o, out);
  } catch (const std::runtime_error&) {
  }
  return 0;
}
