// pdesurf import FILE -o SCENE.json (cli/import/cad_import.hpp).
#include <fstream>

#include "cli.hpp"
#include "common/errors.hpp"
#ifdef PDESURF_CAD_IMPORT
#include "import/cad_import.hpp"
#endif

namespace pdesurf::cli {

int runImport(const Options& o, std::ostream& out) {
#ifdef PDESURF_CAD_IMPORT
  // Compact: the scene it checked (parseScene, within the 16 MiB of a scene) is the text written.
  const std::string text = cad_import::importCadFile(o.scenePath).dump() + "\n";
  if (o.output.empty()) {
    out << text;
    return 0;
  }
  std::ofstream file(o.output, std::ios::binary);
  if (!(file << text) || !file.flush()) throw std::runtime_error("cannot write '" + o.output + "'");
  return 0;
#else
  (void)o, (void)out;
  throw std::runtime_error("this build of pdesurf has no CAD import (Open CASCADE was not found when it was configured)");
#endif
}

}  // namespace pdesurf::cli
