#include <cstdio>
#include <fstream>
#include <ostream>
#include <stdexcept>

#include "cli.hpp"
#include "common/errors.hpp"
#include "scene/scene.hpp"
#include "surface/mesh.hpp"
#include "surface/tabulation.hpp"

namespace pdesurf::cli {

int runSample(const Options& o, std::ostream& out) {
  const Scene scene = parseScene(readFile(o.scenePath));
  checkGrid(o.nu, o.nv);
  const Patch* patch = o.patch.empty() ? scene.firstSolved() : scene.find(o.patch);
  if (!patch) throw std::runtime_error(o.patch.empty() ? "the scene has no PDE or Bezier patch" : "no patch named '" + o.patch + "'");
  Method method;
  if (!o.method.empty()) method = parseMethod(o.method);
  const SolvedPatch solved = solvePatch(*patch, o.method.empty() ? nullptr : &method);
  char line[160];
  if (o.controlNet) {
    if (patch->kind != PatchKind::Bezier) throw std::runtime_error("--control-net: patch '" + patch->name + "' is not a Bezier patch");
    out << "i,j,x,y,z\n";
    const int m = patch->bezier.m;
    for (size_t k = 0; k < solved.controlNet.size(); ++k) {
      const Eigen::Vector3d& p = solved.controlNet[k];
      std::snprintf(line, sizeof line, "%d,%d,%.17g,%.17g,%.17g\n", static_cast<int>(k) / (m + 1), static_cast<int>(k) % (m + 1), p.x(), p.y(), p.z());
      out << line;
    }
    return 0;
  }
  GridSamples g;
  try {
    g = sampleGrid(solved.surface, o.nu, o.nv);
  } catch (const Error& e) {
    throw Error(e.code(), "patch '" + patch->name + "': " + e.what());
  }
  out << "u,v,x,y,z\n";
  for (int j = 0; j <= g.nv; ++j)
    for (int i = 0; i <= g.nu; ++i) {
      const double* X = &g.X[3 * (static_cast<size_t>(j) * (g.nu + 1) + i)];
      std::snprintf(line, sizeof line, "%.17g,%.17g,%.17g,%.17g,%.17g\n", g.u[i], g.v[j], X[0], X[1], X[2]);
      out << line;
    }
  return 0;
}

namespace {
// OBJ is line-based: a control character in a name would start a line of its own. The scene
// parser refuses them already; this keeps the writer safe on its own.
std::string oneLine(std::string s) {
  for (char& c : s)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = ' ';
  return s;
}
}  // namespace

int runExport(const Options& o) {
  const Scene scene = parseScene(readFile(o.scenePath));
  checkSceneGrid(scene, o.nu, o.nv);
  const auto solved = solveScene(scene);
  std::ofstream f(o.output, std::ios::binary);
  if (!f) throw std::runtime_error("cannot write '" + o.output + "'");
  f << "# pdesurf export: " << oneLine(scene.title) << "\n";
  size_t base = 1;  // OBJ indices are 1-based and global across objects
  char line[160];
  for (const SolvedPatch& sp : solved) {
    Mesh m;
    try {
      m = tessellate(sp.surface, o.nu, o.nv);
    } catch (const Error& e) {
      throw Error(e.code(), "patch '" + sp.patch->name + "': " + e.what());
    }
    f << "o " << oneLine(sp.patch->name) << "\n";
    for (size_t k = 0; k < m.vertexCount(); ++k) {
      std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\n", m.positions[3 * k], m.positions[3 * k + 1], m.positions[3 * k + 2]);
      f << line;
    }
    for (size_t k = 0; k < m.vertexCount(); ++k) {
      std::snprintf(line, sizeof line, "vt %.9g %.9g\n", m.uvs[2 * k], m.uvs[2 * k + 1]);
      f << line;
    }
    for (size_t k = 0; k < m.vertexCount(); ++k) {
      std::snprintf(line, sizeof line, "vn %.9g %.9g %.9g\n", m.normals[3 * k], m.normals[3 * k + 1], m.normals[3 * k + 2]);
      f << line;
    }
    for (size_t t = 0; t < m.indices.size(); t += 3) {
      const size_t a = base + m.indices[t], b = base + m.indices[t + 1], c = base + m.indices[t + 2];
      f << "f " << a << '/' << a << '/' << a << ' ' << b << '/' << b << '/' << b << ' ' << c << '/' << c << '/' << c << "\n";
    }
    base += m.vertexCount();
  }
  if (!f) throw std::runtime_error("writing '" + o.output + "' failed");
  return 0;
}

}  // namespace pdesurf::cli
