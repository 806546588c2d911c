// pdesurf export SCENE -o F.step|.stp|.igs|.iges [--tol T] [--degree 3|5] [--jobs N]: every patch as a
// B-spline face with its certified deviation (cpp/cad/). Written to a temporary file beside F
// and renamed: a patch that cannot reach the tolerance leaves nothing behind.
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <unistd.h>

#include "cad/border_joins.hpp"
#include "cad/brep_topology.hpp"
#include "cad/fitted_joins.hpp"
#include "cad/iges_writer.hpp"
#include "cad/scene_fit.hpp"
#include "cad/step_writer.hpp"
#include "cli.hpp"
#include "common/errors.hpp"
#include "parallel_fit.hpp"

namespace pdesurf::cli {

namespace {
std::string lowerExtension(const std::string& path) {
  const size_t dot = path.rfind('.'), slash = path.find_last_of("/\\");
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot + 1);
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}
}  // namespace

CadFormat cadFormatOf(const Options& o) {
  const std::string f = o.format.empty() ? lowerExtension(o.output) : o.format;
  if (f == "step" || f == "stp") return CadFormat::Step;
  if (f == "iges" || f == "igs") return CadFormat::Iges;
  return CadFormat::None;
}

int runCadExport(const Options& o, CadFormat format, std::ostream& out) {
  const std::string text = readFile(o.scenePath);
  const Scene scene = parseScene(text);
  const auto solved = solveScene(scene);
  SceneFitOptions options;
  options.tolerance = o.tolerance;
  options.degree = o.degree;
  const FitOptions fit = resolveFitOptions(solved, options);
  const double tolerance = fit.tolerance;
  const std::vector<PatchFit> fits = fitSceneOnThreads(text, solved, fit, o.jobs > 0 ? o.jobs : defaultJobs());
  std::vector<BSplineSurface> faces;
  char line[400];
  std::snprintf(line, sizeof line, "tolerance %.3g (scene units; %s)\n", tolerance,
                o.tolerance > 0 ? "given" : "1e-6 of the scene's diagonal");
  out << line;
  for (const PatchFit& f : fits) {
    const FitReport& r = f.report;
    if (r.exact) {
      std::snprintf(line, sizeof line, "  %s: exact (a Bezier net), degree %dx%d, poles %dx%d\n", f.surface.name.c_str(),
                    f.surface.degreeU, f.surface.degreeV, f.surface.countU, f.surface.countV);
    } else {
      std::snprintf(line, sizeof line,
                    "  %s: certified deviation %.3g (sampled %.3g), normals at the ends within %.2g deg%s, degree %dx%d, "
                    "poles %dx%d%s\n",
                    f.surface.name.c_str(), r.deviation, r.sampledDeviation, r.normalDeviationDeg,
                    r.normalsMet ? "" : " (target 0.01 deg not reached)", f.surface.degreeU, f.surface.degreeV,
                    f.surface.countU, f.surface.countV, r.creases ? ", knots at creases" : "");
    }
    out << line;
    faces.push_back(f.surface);
  }
  // The joins between the written faces, by the join certificate's own measure.
  const std::vector<FittedJoin> joins = certifyFittedJoins(scene, solved, fits);
  if (!joins.empty()) out << "joins of the written faces:\n";
  for (const FittedJoin& j : joins) {
    const JoinResult& r = j.faces;
    char normals[120] = "";
    if (r.level >= 1) std::snprintf(normals, sizeof normals, ", normals %.2g deg (target %.2g)", r.g1Deg, j.allowedNormalDeg);
    std::snprintf(line, sizeof line, "  %s %s - %s %s: %s, gap %.3g (allowed %.3g)%s: %s\n", r.patch.c_str(), r.end.c_str(),
                  r.surface.c_str(), r.edge.c_str(), levelName(r.level), r.g0 * r.size, j.allowedGap, normals,
                  r.ok ? "ok" : r.fold ? "FOLDS" : "NOT MET");
    out << line;
  }
  CadFileInfo info;
  info.title = scene.title;
  info.tolerance = tolerance;
  // The topology: every join one shared edge, each connected set of faces a shell.
  const BrepTopology topology = buildTopology(faces, borderJoins(solved), tolerance);
  int shared = 0, free = 0;
  for (const BrepEdge& e : topology.edges) (e.uses == 2 ? shared : free) += 1;
  std::snprintf(line, sizeof line, "topology: %zu faces, %zu edges (%d shared or seams, %d free), %zu vertices\n", faces.size(),
                topology.edges.size(), shared, free, topology.vertices.size());
  out << line;
  for (const BrepShell& sh : topology.shells) {
    std::string names;
    for (int f : sh.faces) names += (names.empty() ? "" : ", ") + faces[size_t(f)].name;
    if (sh.closed) std::snprintf(line, sizeof line, "  closed shell (a solid), volume %.6g: ", sh.volume);
    else std::snprintf(line, sizeof line, "  open shell: ");
    out << line << names << "\n";
  }
  for (const std::string& why : topology.unshared) out << "  not shared: " << why << "\n";
  std::snprintf(line, sizeof line, "  largest gap closed: edges %.2g, vertices %.2g (the file states %.3g)\n", topology.edgeGap, topology.vertexSpread,
                std::max({tolerance, topology.edgeGap, topology.vertexSpread}));
  out << line;
  const std::string file = format == CadFormat::Step ? writeStep(faces, info, &topology) : writeIges(faces, info, &topology);
  // Beside the target, so the rename stays on one file system.
  const std::string temporary = o.output + ".part-" + std::to_string(getpid());
  {
    std::ofstream f(temporary, std::ios::binary);
    if (!f) throw std::runtime_error("cannot write '" + o.output + "'");
    f << file;
    f.close();
    if (!f) {
      std::remove(temporary.c_str());
      throw std::runtime_error("writing '" + o.output + "' failed");
    }
  }
  if (std::rename(temporary.c_str(), o.output.c_str()) != 0) {
    std::remove(temporary.c_str());
    throw std::runtime_error("cannot write '" + o.output + "'");
  }
  return 0;
}

}  // namespace pdesurf::cli
