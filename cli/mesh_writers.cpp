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
  throw std::runtime_error("unknown --format '" + oneLine(name) + "': expected obj, stl, ply, glb, step, stp, iges or igs");
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
  return MeshFormat::Obj;
}

namespace detail {
void checkMeshShape(const ExportInfo& info, const std::string& name, const Mesh& m) {
  const size_t vertices = static_cast<size_t>(info.nu + 1) * (info.nv + 1);
  const size_t indices = static_cast<size_t>(6) * info.nu * info.nv;
  if (m.vertexCount() != vertices || m.normals.size() != 3 * vertices || m.uvs.size() != 2 * vertices || m.indices.size() != indices)
    throw std::logic_error("patch '" + name + "': the mesh does not have the grid's vertex and triangle counts");
}

void checkPatchCount(const ExportInfo& info, size_t added) {
  if (added != info.names.size()) throw std::logic_error("the header promised " + std::to_string(info.names.size()) + " patches, " + std::to_string(added) + " came");
}
}  // namespace detail

namespace {

using detail::checkMeshShape;
using detail::checkPatchCount;

class ObjWriter : public MeshWriter {
 public:
  ObjWriter(std::ostream& out, const std::string& what, const ExportInfo& info) : b_(out, what), info_(info) {
    b_.put("# pdesurf export: " + oneLine(info.title) + "\n");
  }

  void add(const std::string& name, Mesh&& m) override {
    checkMeshShape(info_, name, m);
    b_.put("o " + oneLine(name) + "\n");
    const size_t n = m.vertexCount();
    vectors(n, 'v', m.positions.data());
    textureCoordinates(m);
    vectors(n, 'n', m.normals.data());
    for (size_t t = 0; t < m.indices.size(); t += 3) {
      char* p = b_.reserve();
      *p++ = 'f';
      for (int c = 0; c < 3; ++c) {
        NumberText k;
        k.set(static_cast<uint64_t>(base_ + m.indices[t + c]));
        *p++ = ' ';
        p = k.put(p);
        *p++ = '/';
        p = k.put(p);
        *p++ = '/';
        p = k.put(p);
      }
      *p++ = '\n';
      b_.commit(p);
    }
    base_ += n;
  }

  void finish() override { b_.flush(); }

 private:
  // "v x y z" or "vn x y z"
  void vectors(size_t n, char kind, const float* xyz) {
    for (size_t k = 0; k < n; ++k, xyz += 3) {
      char* p = b_.reserve();
      *p++ = 'v';
      if (kind != 'v') *p++ = kind;
      *p++ = ' ';
      p = putNumber(p, xyz[0]);
      *p++ = ' ';
      p = putNumber(p, xyz[1]);
      *p++ = ' ';
      p = putNumber(p, xyz[2]);
      *p++ = '\n';
      b_.commit(p);
    }
  }

  // "vt u v": u repeats down the columns and v along the rows, so each value's text is made
  // once and reused while the float is bit for bit the same.
  void textureCoordinates(const Mesh& m) {
    const size_t w = static_cast<size_t>(m.nu) + 1, n = m.vertexCount();
    std::vector<float> uKey(w);
    std::vector<NumberText> uText(w);
    std::vector<bool> uSet(w, false);
    float vKey = 0;
    NumberText vText;
    bool vSet = false;
    auto same = [](float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; };
    for (size_t k = 0, i = 0; k < n; ++k, i = i + 1 == w ? 0 : i + 1) {
      const float u = m.uvs[2 * k], v = m.uvs[2 * k + 1];
      if (!uSet[i] || !same(uKey[i], u)) uKey[i] = u, uText[i].set(u), uSet[i] = true;
      if (!vSet || !same(vKey, v)) vKey = v, vText.set(v), vSet = true;
      char* p = b_.reserve();
      *p++ = 'v';
      *p++ = 't';
      *p++ = ' ';
      p = uText[i].put(p);
      *p++ = ' ';
      p = vText.put(p);
      *p++ = '\n';
      b_.commit(p);
    }
  }

  OutBuffer b_;
  ExportInfo info_;
  size_t base_ = 1;  // OBJ indices are 1-based and global across objects
};

// The facet normal: the unit cross product of the triangle's edges (b - a) × (c - a), the
// right-hand rule over the vertex order as STL defines it; (0, 0, 0) for a zero-area triangle
// (two vertices at a pole), which has no normal (readers then compute their own).
void facetNormal(const float* P, uint32_t a, uint32_t b, uint32_t c, float out[3]) {
  double e1[3], e2[3];
  for (int d = 0; d < 3; ++d) {
    e1[d] = double(P[3 * b + d]) - P[3 * a + d];
    e2[d] = double(P[3 * c + d]) - P[3 * a + d];
  }
  const double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
  const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  for (int d = 0; d < 3; ++d) out[d] = len > 0 && std::isfinite(len) ? static_cast<float>(n[d] / len) : 0.0f;
}

class StlWriter : public MeshWriter {
 public:
  StlWriter(std::ostream& out, const std::string& what, const ExportInfo& info) : b_(out, what), info_(info) {
    // The header must not start with "solid" (readers would take the file for ASCII STL).
    std::string header = "pdesurf export: " + oneLine(info.title);
    if (header.size() > 80) {
      size_t cut = 80;
      while (cut > 0 && (static_cast<unsigned char>(header[cut]) & 0xc0) == 0x80) --cut;  // not inside a UTF-8 character
      header.resize(cut);
    }
    header.resize(80, '\0');
    b_.put(header);
    const uint64_t triangles = static_cast<uint64_t>(info.names.size()) * 2 * info.nu * info.nv;
    if (triangles > UINT32_MAX) throw std::runtime_error("too many triangles for STL");
    b_.commit(putU32(b_.reserve(), static_cast<uint32_t>(triangles)));
  }

  void add(const std::string& name, Mesh&& m) override {
    checkMeshShape(info_, name, m);
    ++added_;
    const float* P = m.positions.data();
    for (size_t t = 0; t < m.indices.size(); t += 3) {
      const uint32_t v[3] = {m.indices[t], m.indices[t + 1], m.indices[t + 2]};
      float normal[3];
      facetNormal(P, v[0], v[1], v[2], normal);
      char* p = b_.reserve();
      for (float x : normal) p = putF32(p, x);
      for (uint32_t k : v)
        for (int d = 0; d < 3; ++d) p = putF32(p, P[3 * k + d]);
      p = putU16(p, 0);
      b_.commit(p);
    }
  }

  void finish() override {
    checkPatchCount(info_, added_);
    b_.flush();
  }

 private:
  OutBuffer b_;
  ExportInfo info_;
  size_t added_ = 0;
};

class PlyWriter : public MeshWriter {
 public:
  PlyWriter(std::ostream& out, const std::string& what, const ExportInfo& info) : b_(out, what), info_(info) {
    const size_t vertices = static_cast<size_t>(info.nu + 1) * (info.nv + 1);
    const size_t faces = static_cast<size_t>(2) * info.nu * info.nv;
    const size_t patches = info.names.size();
    std::string h = "ply\nformat binary_little_endian 1.0\ncomment pdesurf export: " + oneLine(info.title) + "\n";
    h += "comment " + std::to_string(patches) + " patches of " + std::to_string(vertices) + " vertices and " + std::to_string(faces) +
         " faces each, in this order:\n";
    for (const std::string& name : info.names) h += "comment patch " + oneLine(name) + "\n";
    h += "element vertex " + std::to_string(patches * vertices) +
         "\nproperty float x\nproperty float y\nproperty float z\nproperty float nx\nproperty float ny\nproperty float nz\n";
    h += "element face " + std::to_string(patches * faces) + "\nproperty list uchar uint vertex_indices\nend_header\n";
    if (patches * vertices > UINT32_MAX) throw std::runtime_error("too many vertices for 32-bit PLY indices");
    b_.put(h);
  }

  void add(const std::string& name, Mesh&& m) override {
    checkMeshShape(info_, name, m);
    const float* P = m.positions.data();
    const float* N = m.normals.data();
    for (size_t k = 0; k < m.vertexCount(); ++k) {
      char* p = b_.reserve();
      for (int d = 0; d < 3; ++d) p = putF32(p, P[3 * k + d]);
      for (int d = 0; d < 3; ++d) p = putF32(p, N[3 * k + d]);
      b_.commit(p);
    }
    indices_.push_back(std::move(m.indices));
  }

  void finish() override {
    checkPatchCount(info_, indices_.size());
    const uint32_t perPatch = static_cast<uint32_t>((info_.nu + 1) * (info_.nv + 1));
    uint32_t base = 0;
    for (const std::vector<uint32_t>& indices : indices_) {
      for (size_t t = 0; t < indices.size(); t += 3) {
        char* p = putU8(b_.reserve(), 3);
        for (int c = 0; c < 3; ++c) p = putU32(p, base + indices[t + c]);
        b_.commit(p);
      }
      base += perPatch;
    }
    b_.flush();
  }

 private:
  OutBuffer b_;
  ExportInfo info_;
  std::vector<std::vector<uint32_t>> indices_;
};

}  // namespace

std::unique_ptr<MeshWriter> makeMeshWriter(MeshFormat format, std::ostream& out, const std::string& what, const ExportInfo& info) {
  switch (format) {
    case MeshFormat::Stl: return std::make_unique<StlWriter>(out, what, info);
    case MeshFormat::Ply: return std::make_unique<PlyWriter>(out, what, info);
    case MeshFormat::Glb: return detail::makeGlbWriter(out, what, info);
    case MeshFormat::Obj: break;
  }
  return std::make_unique<ObjWriter>(out, what, info);
}

}  // namespace pdesurf::cli
