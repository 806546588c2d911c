#include <fstream>
#include <iostream>
#include <ostream>
#include <stdexcept>
#include <vector>

#include "cli.hpp"
#include "analysis/join_certificate.hpp"
#include "mesh_writers.hpp"
#include "three_mf_writer.hpp"
#include "number_text.hpp"
#include "common/errors.hpp"
#include "scene/scene.hpp"
#include "surface/mesh.hpp"
#include "surface/tabulation.hpp"

namespace pdesurf::cli {

int runSample(const Options& o, std::ostream& out) {
  const Scene scene = parseScene(readFile(o.scenePath));
  checkGrid(o.nu, o.nv);
  // Without --patch: the first solved patch, or with --control-net the first Bézier one.
  const Patch* patch = !o.patch.empty() ? scene.find(o.patch) : o.controlNet ? scene.firstBezier() : scene.firstSolved();
  if (!patch)
    throw std::runtime_error(!o.patch.empty() ? "no patch named '" + o.patch + "'" : o.controlNet ? "--control-net: the scene has no Bezier patch" : "the scene has no PDE or Bezier patch");
  Method method;
  if (!o.method.empty()) method = parseMethod(o.method);
  const SolvedPatch solved = solvePatchIn(scene, *patch, o.method.empty() ? nullptr : &method);
  OutBuffer b(out, "standard output");
  if (o.controlNet) {
    if (patch->kind != PatchKind::Bezier) throw std::runtime_error("--control-net: patch '" + patch->name + "' is not a Bezier patch");
    b.put("i,j,x,y,z\n");
    const int m = patch->bezier().m;
    for (size_t k = 0; k < solved.controlNet.size(); ++k) {
      const Eigen::Vector3d& x = solved.controlNet[k];
      char* p = putNumber(b.reserve(), static_cast<int>(k) / (m + 1));
      *p++ = ',';
      p = putNumber(p, static_cast<int>(k) % (m + 1));
      for (int c = 0; c < 3; ++c) *p++ = ',', p = putNumber(p, x[c]);
      *p++ = '\n';
      b.commit(p);
    }
    b.flush();
    return 0;
  }
  const GridSamples g = inPatch(patch->name, [&] { return sampleGrid(solved.surface, o.nu, o.nv); });
  // Doubles in shortest round-trip form; u repeats down the columns and v along the rows, so
  // their text is made once.
  std::vector<NumberText> uText(g.nu + 1);
  for (int i = 0; i <= g.nu; ++i) uText[i].set(g.u[i]);
  b.put("u,v,x,y,z\n");
  for (int j = 0; j <= g.nv; ++j) {
    NumberText vText;
    vText.set(g.v[j]);
    for (int i = 0; i <= g.nu; ++i) {
      const double* X = &g.X[3 * (static_cast<size_t>(j) * (g.nu + 1) + i)];
      char* p = uText[i].put(b.reserve());
      *p++ = ',';
      p = vText.put(p);
      for (int c = 0; c < 3; ++c) *p++ = ',', p = putNumber(p, X[c]);
      *p++ = '\n';
      b.commit(p);
    }
  }
  b.flush();
  return 0;
}

namespace {

// Each patch its own nu×nv grid (tessellate's layout and (u, v)), nothing shared.
ModelMesh loosePatches(const std::vector<SolvedPatch>& solved, int nu, int nv) {
  ModelMesh out;
  for (const SolvedPatch& sp : solved) {
    const Mesh m = tessellatePatch(sp, nu, nv);
    ModelMesh::Part part;
    part.name = sp.patch->name;
    const uint32_t base = uint32_t(out.vertexCount());
    for (uint32_t i : m.indices) part.indices.push_back(base + i);
    out.positions.insert(out.positions.end(), m.positions.begin(), m.positions.end());
    out.normals.insert(out.normals.end(), m.normals.begin(), m.normals.end());
    out.uvs.insert(out.uvs.end(), m.uvs.begin(), m.uvs.end());
    out.parts.push_back(std::move(part));
  }
  return out;
}

}  // namespace

int runExport(const Options& o) {
  if (const CadFormat cad = cadFormatOf(o); cad != CadFormat::None) {
    if (o.loosePatches) throw std::runtime_error("--patches applies to mesh formats (obj, stl, ply, glb) only");
    return runCadExport(o, cad, std::cout);
  }
  const Scene scene = parseScene(readFile(o.scenePath));
  checkSceneGrid(scene, o.nu, o.nv);
  const MeshFormat format = o.format.empty() ? meshFormatFromPath(o.output) : parseMeshFormat(o.format);
  const auto solved = solveScene(scene);
  const ModelMesh mesh = o.loosePatches ? loosePatches(solved, o.nu, o.nv) : watertightMesh(solved, sceneSizeOf(solved), o.nu, o.nv);
  if (format == MeshFormat::ThreeMf) {
    write3mf(o.output, scene.title, mesh);
    return 0;
  }
  std::ofstream f(o.output, std::ios::binary);
  if (!f) throw std::runtime_error("cannot write '" + o.output + "'");
  writeMesh(format, f, "'" + o.output + "'", scene.title, mesh);
  f.close();
  if (!f) throw std::runtime_error("writing '" + o.output + "' failed");
  return 0;
}

}  // namespace pdesurf::cli
