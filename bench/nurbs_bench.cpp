// Benchmark section (not a test): drawing a NURBS surface (docs/cad-import.md). The example
// part's body is a 6 × 17 B-spline of degrees 3 × 5 (examples/cad-part.json); its neck a typed
// cylinder. Both are drawn with their partials at 64² and 256², side by side: a NURBS surface
// is a sum of spline nodes whose bases are computed once per point and shared
// (expr/program.hpp), a typed one a separable sum tabulated per grid line.
#include <cstdio>
#include <fstream>
#include <functional>
#include <sstream>

#include "common/errors.hpp"
#include "scene/scene.hpp"
#include "surface/mesh.hpp"

namespace pdesurf {

double benchMedianSeconds(const std::function<void()>& f);  // bench.cpp

void benchNurbs(const std::string& dir) {
  std::ifstream in(dir + "/cad-part.json", std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  const Scene scene = parseScene(ss.str());  // the solved patches point into it
  const auto solved = solveScene(scene);
  auto surfaceOf = [&](const char* name) -> const SeparableSurface& {
    for (const SolvedPatch& sp : solved)
      if (sp.patch->name == name) return sp.surface;
    throw Error(ErrorCode::Internal, std::string("no patch ") + name);
  };
  volatile size_t sink = 0;
  std::printf("\nNURBS drawing (cad-part: body 6 x 17 B-spline of degrees 3 x 5, neck a typed cylinder) [us, median; ns per vertex]\n");
  std::printf("%-6s %12s %12s %12s %12s %10s\n", "grid", "body", "per vertex", "neck", "per vertex", "body/neck");
  for (int n : {64, 256}) {
    const double body = benchMedianSeconds([&] { sink = tessellate(surfaceOf("body"), n, n).vertexCount(); });
    const double neck = benchMedianSeconds([&] { sink = tessellate(surfaceOf("neck"), n, n).vertexCount(); });
    const double vertices = double(n + 1) * double(n + 1);
    std::printf("%-6d %12.1f %12.1f %12.1f %12.1f %10.2f\n", n, body * 1e6, body * 1e9 / vertices, neck * 1e6, neck * 1e9 / vertices, body / neck);
  }
}

}  // namespace pdesurf
