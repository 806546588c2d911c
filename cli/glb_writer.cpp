// GLB (glTF 2.0 binary) writer: a 12-byte header, a JSON chunk padded with spaces, a BIN chunk
// padded with zeros, every length a multiple of 4. The model's vertices are one POSITION (with
// its min and max), one NORMAL and, for patches' own grids, one TEXCOORD_0 float accessor;
// per patch one mesh and one node (both named after the patch), one triangle primitive with
// those attributes and its own uint32 indices: the patches share the vertices of their joins.
// TEXCOORD_0 is (u, 1 - v) of the mesh's (u, v) = (i/nu, j/nv): glTF puts the texture origin
// at the top left where OBJ's vt puts it at the bottom left, so a texture maps the same way.
#include <algorithm>
#include <array>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <vector>

#include "mesh_writers.hpp"
#include "number_text.hpp"

namespace pdesurf::cli::detail {

namespace {

constexpr uint32_t kGlbMagic = 0x46546C67;  // "glTF"
constexpr uint32_t kChunkJson = 0x4E4F534A, kChunkBin = 0x004E4942;
constexpr int kFloat = 5126, kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;
constexpr int kTriangles = 4;

class GlbWriter {
 public:
  GlbWriter(std::ostream& out, const std::string& what, const std::string& title, const ModelMesh& m) : b_(out, what), title_(title), m_(m) {}

  void write() {
    std::string json = document().dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    json.resize((json.size() + 3) / 4 * 4, ' ');
    const uint64_t bin = binSize_;  // a sum of 4-byte multiples: no padding needed
    const uint64_t total = 12 + 8 + json.size() + 8 + bin;
    if (total > UINT32_MAX) throw std::runtime_error("the scene is too large for one GLB file (4 GiB)");
    char* p = b_.reserve();
    p = putU32(p, kGlbMagic);
    p = putU32(p, 2);
    p = putU32(p, static_cast<uint32_t>(total));
    p = putU32(p, static_cast<uint32_t>(json.size()));
    p = putU32(p, kChunkJson);
    b_.commit(p);
    b_.put(json);
    p = b_.reserve();
    p = putU32(p, static_cast<uint32_t>(bin));
    p = putU32(p, kChunkBin);
    b_.commit(p);
    writeBinary();
    b_.flush();
  }

 private:
  nlohmann::json document() {
    using nlohmann::json;
    json nodes = json::array(), meshes = json::array(), views = json::array(), accessors = json::array(), sceneNodes = json::array();
    uint64_t offset = 0;
    auto view = [&](uint64_t bytes, int target) {
      views.push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes}, {"target", target}});
      offset += bytes;
      return views.size() - 1;
    };
    auto accessor = [&](size_t bufferView, int componentType, size_t count, const char* type) {
      accessors.push_back({{"bufferView", bufferView}, {"componentType", componentType}, {"count", count}, {"type", type}});
      return accessors.size() - 1;
    };
    const size_t n = m_.vertexCount();
    const size_t position = accessor(view(12 * n, kArrayBuffer), kFloat, n, "VEC3");
    const auto [lo, hi] = bounds();
    accessors[position]["min"] = {lo[0], lo[1], lo[2]};
    accessors[position]["max"] = {hi[0], hi[1], hi[2]};
    json attributes = {{"POSITION", position}, {"NORMAL", accessor(view(12 * n, kArrayBuffer), kFloat, n, "VEC3")}};
    if (!m_.uvs.empty()) attributes["TEXCOORD_0"] = accessor(view(8 * n, kArrayBuffer), kFloat, n, "VEC2");
    for (size_t k = 0; k < m_.parts.size(); ++k) {
      const std::vector<uint32_t>& idx = m_.parts[k].indices;
      const size_t indices = accessor(view(4 * idx.size(), kElementArrayBuffer), kUnsignedInt, idx.size(), "SCALAR");
      json primitive = {{"attributes", attributes}, {"indices", indices}, {"mode", kTriangles}};
      meshes.push_back({{"name", m_.parts[k].name}, {"primitives", json::array({primitive})}});
      nodes.push_back({{"name", m_.parts[k].name}, {"mesh", k}});
      sceneNodes.push_back(k);
    }
    binSize_ = offset;
    return {{"asset", {{"version", "2.0"}, {"generator", "pdesurf export"}}},
            {"scene", 0},
            {"scenes", json::array({{{"name", title_}, {"nodes", sceneNodes}}})},
            {"nodes", nodes},
            {"meshes", meshes},
            {"buffers", json::array({{{"byteLength", offset}}})},
            {"bufferViews", views},
            {"accessors", accessors}};
  }

  // The float bounds of the positions, exactly (glTF validators compare them with the data).
  std::pair<std::array<float, 3>, std::array<float, 3>> bounds() const {
    const std::vector<float>& P = m_.positions;
    if (P.empty()) return {{0, 0, 0}, {0, 0, 0}};
    std::array<float, 3> lo{P[0], P[1], P[2]}, hi = lo;
    for (size_t k = 0; k < m_.vertexCount(); ++k)
      for (int d = 0; d < 3; ++d) {
        lo[d] = std::min(lo[d], P[3 * k + d]);
        hi[d] = std::max(hi[d], P[3 * k + d]);
      }
    return {lo, hi};
  }

  // The same order as document(): positions, normals, texture coordinates, each part's indices.
  void writeBinary() {
    constexpr size_t kPerRound = OutBuffer::kSlack / 4;  // values per reserve()
    auto floats = [&](const float* x, size_t count) {
      for (size_t k = 0; k < count; k += kPerRound) {
        char* p = b_.reserve();
        for (size_t t = k, e = std::min(count, k + kPerRound); t < e; ++t) p = putF32(p, x[t]);
        b_.commit(p);
      }
    };
    floats(m_.positions.data(), m_.positions.size());
    floats(m_.normals.data(), m_.normals.size());
    for (size_t k = 0; k < m_.uvs.size(); k += 2) {
      char* p = b_.reserve();
      p = putF32(p, m_.uvs[k]);
      p = putF32(p, 1.0f - m_.uvs[k + 1]);
      b_.commit(p);
    }
    for (const ModelMesh::Part& part : m_.parts)
      for (size_t k = 0; k < part.indices.size(); k += kPerRound) {
        char* p = b_.reserve();
        for (size_t e = std::min(part.indices.size(), k + kPerRound), t = k; t < e; ++t) p = putU32(p, part.indices[t]);
        b_.commit(p);
      }
  }

  OutBuffer b_;
  std::string title_;
  const ModelMesh& m_;
  uint64_t binSize_ = 0;
};

}  // namespace

void writeGlb(std::ostream& out, const std::string& what, const std::string& title, const ModelMesh& mesh) {
  GlbWriter(out, what, title, mesh).write();
}

}  // namespace pdesurf::cli::detail
