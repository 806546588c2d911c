// OBJ, STL and PLY writers (GLB: glb_writer.cpp). See mesh_writers.hpp.
#include "mesh_writers.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "common/text.hpp"
#include "number_text.hpp"

namespace pdesurf::cli {

// OBJ and the PLY header are line-based: a control character in a name would start a line of
// its own (for some readers NEL U+0085, U+2028 and U+2029 too). The scene parser refuses them
// already; this keeps the writers safe on their own.
std::string oneLine(std::string s) { return oneLineText(s); }

MeshFormat parseMeshFormat(const std::string& name) {
  if (name == "obj") return MeshFormat::Obj;
  if (name == "stl") return MeshFormat::Stl;
  if (name == "ply") return MeshFormat::Ply;
  if (name == "glb") return MeshFormat::Glb;
  if (name == "3mf") return MeshFormat::ThreeMf;
  throw std::runtime_error("unknown --format '" + oneLine(name) + "': expected obj, stl, ply, glb, 3mf, step, stp, iges or igs");
}

MeshFormat meshFormatFromPath(const std::string& path) {
  const size_t dot = path.rfind('.');
  const size_t slash = path.find_last_of("/\\");
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return MeshFormat::Obj;
  std::string ext = path.substr(dot + 1);
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == "stl") return MeshFormat::Stl;
  if (ext == "ply") return MeshFormat::Ply;
  if (ext == "glb") return MeshFormat::Glb;
  if (ext == "3mf") return MeshFormat::ThreeMf;
  return MeshFormat::Obj;
}

namespace detail {
size_t triangleCount(const ModelMesh& mesh) {
  size_t n = 0;
  for (const ModelMesh::Part& part : mesh.parts) n += part.indices.size() / 3;
  return n;
}
}  // namespace detail

namespace {

// Each vertex's v, vt (when the mesh has them) and vn just before the first part that uses it,
// in index order: a patch's own grid stays under its o, in the grid's order.
void writeObj(OutBuffer& b, const std::string& title, const ModelMesh& m) {
  b.put("# pdesurf export: " + oneLine(title) + "\n");
  const bool uv = !m.uvs.empty();
  std::vector<uint64_t> objIndex(m.vertexCount(), 0);  // 1-based once written
  uint64_t written = 0;
  std::vector<uint32_t> fresh;
  const auto vector = [&](const char* kind, const float* x, int n) {
    char* p = b.reserve();
    for (const char* k = kind; *k; ++k) *p++ = *k;
    for (int d = 0; d < n; ++d) *p++ = ' ', p = putNumber(p, x[d]);
    *p++ = '\n';
    b.commit(p);
  };
  for (const ModelMesh::Part& part : m.parts) {
    b.put("o " + oneLine(part.name) + "\n");
    fresh.clear();
    for (uint32_t v : part.indices)
      if (objIndex[v] == 0) objIndex[v] = UINT64_MAX, fresh.push_back(v);
    std::sort(fresh.begin(), fresh.end());
    for (uint32_t v : fresh) objIndex[v] = ++written, vector("v", &m.positions[3 * size_t(v)], 3);
    if (uv)
      for (uint32_t v : fresh) vector("vt", &m.uvs[2 * size_t(v)], 2);
    for (uint32_t v : fresh) vector("vn", &m.normals[3 * size_t(v)], 3);
    for (size_t t = 0; t < part.indices.size(); t += 3) {
      char* p = b.reserve();
      *p++ = 'f';
      for (int c = 0; c < 3; ++c) {
        NumberText k;
        k.set(objIndex[part.indices[t + c]]);
        *p++ = ' ';
        p = k.put(p);
        *p++ = '/';
        if (uv) p = k.put(p);
        *p++ = '/';
        p = k.put(p);
      }
      *p++ = '\n';
      b.commit(p);
    }
  }
}

// The facet normal: the unit cross product of the triangle's edges (b - a) × (c - a), the
// right-hand rule over the vertex order as STL defines it; (0, 0, 0) for a zero-area triangle,
// which has no normal (readers then compute their own).
void facetNormal(const float* P, uint32_t a, uint32_t b, uint32_t c, float out[3]) {
  double e1[3], e2[3];
  for (int d = 0; d < 3; ++d) {
    e1[d] = double(P[3 * size_t(b) + d]) - P[3 * size_t(a) + d];
    e2[d] = double(P[3 * size_t(c) + d]) - P[3 * size_t(a) + d];
  }
  const double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
  const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  for (int d = 0; d < 3; ++d) out[d] = len > 0 && std::isfinite(len) ? static_cast<float>(n[d] / len) : 0.0f;
}

void writeStl(OutBuffer& b, const std::string& title, const ModelMesh& m) {
  // The header must not start with "solid" (readers would take the file for ASCII STL).
  std::string header = "pdesurf export: " + oneLine(title);
  if (header.size() > 80) {
    size_t cut = 80;
    while (cut > 0 && (static_cast<unsigned char>(header[cut]) & 0xc0) == 0x80) --cut;  // not inside a UTF-8 character
    header.resize(cut);
  }
  header.resize(80, '\0');
  b.put(header);
  const size_t triangles = detail::triangleCount(m);
  if (triangles > UINT32_MAX) throw std::runtime_error("too many triangles for STL");
  b.commit(putU32(b.reserve(), static_cast<uint32_t>(triangles)));
  const float* P = m.positions.data();
  for (const ModelMesh::Part& part : m.parts)
    for (size_t t = 0; t < part.indices.size(); t += 3) {
      const uint32_t v[3] = {part.indices[t], part.indices[t + 1], part.indices[t + 2]};
      float normal[3];
      facetNormal(P, v[0], v[1], v[2], normal);
      char* p = b.reserve();
      for (float x : normal) p = putF32(p, x);
      for (uint32_t k : v)
        for (int d = 0; d < 3; ++d) p = putF32(p, P[3 * size_t(k) + d]);
      p = putU16(p, 0);
      b.commit(p);
    }
}

void writePly(OutBuffer& b, const std::string& title, const ModelMesh& m) {
  const size_t vertices = m.vertexCount(), faces = detail::triangleCount(m);
  if (vertices > UINT32_MAX || faces > UINT32_MAX) throw std::runtime_error("too many vertices for 32-bit PLY indices");
  std::string h = "ply\nformat binary_little_endian 1.0\ncomment pdesurf export: " + oneLine(title) + "\n";
  h += "comment " + std::to_string(m.parts.size()) + " patches sharing the vertices; their faces in this order:\n";
  for (const ModelMesh::Part& part : m.parts) h += "comment patch " + oneLine(part.name) + " faces " + std::to_string(part.indices.size() / 3) + "\n";
  h += "element vertex " + std::to_string(vertices) +
       "\nproperty float x\nproperty float y\nproperty float z\nproperty float nx\nproperty float ny\nproperty float nz\n";
  h += "element face " + std::to_string(faces) + "\nproperty list uchar uint vertex_indices\nend_header\n";
  b.put(h);
  for (size_t k = 0; k < vertices; ++k) {
    char* p = b.reserve();
    for (int d = 0; d < 3; ++d) p = putF32(p, m.positions[3 * k + d]);
    for (int d = 0; d < 3; ++d) p = putF32(p, m.normals[3 * k + d]);
    b.commit(p);
  }
  for (const ModelMesh::Part& part : m.parts)
    for (size_t t = 0; t < part.indices.size(); t += 3) {
      char* p = putU8(b.reserve(), 3);
      for (int c = 0; c < 3; ++c) p = putU32(p, part.indices[t + c]);
      b.commit(p);
    }
}

}  // namespace

void writeMesh(MeshFormat format, std::ostream& out, const std::string& what, const std::string& title, const ModelMesh& mesh) {
  if (format == MeshFormat::ThreeMf) throw std::logic_error("3MF is written by write3mf (to a file)");
  if (format == MeshFormat::Glb) return detail::writeGlb(out, what, title, mesh);
  OutBuffer b(out, what);
  switch (format) {
    case MeshFormat::Stl: writeStl(b, title, mesh); break;
    case MeshFormat::Ply: writePly(b, title, mesh); break;
    default: writeObj(b, title, mesh); break;
  }
  b.flush();
}

}  // namespace pdesurf::cli
