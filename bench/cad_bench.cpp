// Benchmark section (not a test): the CAD export (docs/cad-export.md). Each scene solved once,
// then its certified fit of every patch, the joins between the faces and the STEP text, timed
// together (median); the poles of each face and the files' sizes. Issue 20's goal: fig. 4a
// within 50 ms natively.
#include <cstdio>
#include <fstream>
#include <functional>
#include <sstream>

#include "analysis/join_certificate.hpp"
#include "cad/fitted_joins.hpp"
#include "cad/iges_writer.hpp"
#include "cad/scene_fit.hpp"
#include "cad/step_writer.hpp"
#include "scene/scene.hpp"

namespace pdesurf {

double benchMedianSeconds(const std::function<void()>& f);  // bench.cpp

void benchCad(const std::string& dir) {
  std::printf("\nCAD export at the default tolerance: fit + joins + STEP text [ms, median]\n%-18s %8s %10s %9s %9s  %s\n", "scene", "ms",
              "tolerance", "STEP B", "IGES B", "poles per face");
  for (const char* id : {"you2004-fig4a", "you2004-fig4c", "zhang-vase-fig1b", "wu2015-fig4"}) {
    std::ifstream in(dir + "/" + id + ".json", std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    const Scene scene = parseScene(ss.str());
    const auto solved = solveScene(scene);
    double tolerance = 0;
    std::vector<PatchFit> fits;
    std::string step;
    const double seconds = benchMedianSeconds([&] {
      fits = fitScene(solved, SceneFitOptions{}, &tolerance);
      certifyFittedJoins(scene, solved, fits, sceneSizeOf(solved));
      std::vector<BSplineSurface> faces;
      for (const PatchFit& f : fits) faces.push_back(f.surface);
      step = writeStep(faces, CadFileInfo{scene.title, tolerance});
    });
    std::vector<BSplineSurface> faces;
    std::string poles;
    for (const PatchFit& f : fits) {
      faces.push_back(f.surface);
      poles += (poles.empty() ? "" : ", ") + std::to_string(f.surface.countU) + "x" + std::to_string(f.surface.countV);
    }
    const std::string iges = writeIges(faces, CadFileInfo{scene.title, tolerance});
    std::printf("%-18s %8.2f %10.2g %9zu %9zu  %s\n", id, seconds * 1e3, tolerance, step.size(), iges.size(), poles.c_str());
  }
}

}  // namespace pdesurf
