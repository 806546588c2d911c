#include <iostream>

#include "cli.hpp"
#include "common/errors.hpp"
#include "retain_freed_memory.hpp"

int main(int argc, char** argv) {
  pdesurf::platform::retainFreedMemory();
  using namespace pdesurf::cli;
  Options o;
  try {
    o = parseArgs(std::vector<std::string>(argv + 1, argv + argc));
  } catch (const std::exception& e) {
    std::cerr << "pdesurf: " << e.what() << "\n" << kUsage;
    return 1;
  }
  try {
    if (o.command == "sample") return runSample(o, std::cout);
    if (o.command == "compare") return runCompare(o, std::cout);
    if (o.command == "check") return runCheck(o, std::cout);
    if (o.command == "import") return runImport(o, std::cout);
    if (o.command == "encode-link") return runEncodeLink(o, std::cout);
    if (o.command == "decode-link") return runDecodeLink(o, std::cout);
    return runExport(o);
  } catch (const pdesurf::Error& e) {
    // A link is not a file name: naming it would print up to 2 MiB of base64.
    const std::string source = o.command == "decode-link" ? std::string("the link") : o.scenePath;
    std::cerr << "pdesurf: " << source << ": " << pdesurf::errorCodeName(e.code()) << ": " << e.what() << "\n";
  } catch (const std::exception& e) {
    std::cerr << "pdesurf: " << e.what() << "\n";
  }
  return 1;
}
