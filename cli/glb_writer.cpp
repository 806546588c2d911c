// GLB (glTF 2.0 binary) writer: a 12-byte header, a JSON chunk padded with spaces, a BIN chunk
// padded with zeros, every length a multiple of 4. Per patch: one mesh and one node (both named
// after the patch), one triangle primitive with POSITION (with its min and max), NORMAL and
// TEXCOORD_0 float accessors and uint32 indices, each accessor over a bufferView of its own.
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

class GlbWriter : public MeshWriter {
 public:
  GlbWriter(std::ostream& out, const std::string& what, const ExportInfo& info) : b_(out, what), info_(info) {}

  void add(const std::string& name, Mesh&& m) override {
    checkMeshShape(info_, name, m);
    meshes_.push_back(std::move(m));
  }

  void finish() override {
    checkPatchCount(info_, meshes_.size());
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
    for (const Mesh& m : meshes_) writeBinary(m);
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
    for (size_t k = 0; k < meshes_.size(); ++k) {
      const Mesh& m = meshes_[k];
      const size_t n = m.vertexCount();
      const size_t position = accessor(view(12 * n, kArrayBuffer), kFloat, n, "VEC3");
      const auto [lo, hi] = bounds(m);
      accessors[position]["min"] = {lo[0], lo[1], lo[2]};
      accessors[position]["max"] = {hi[0], hi[1], hi[2]};
      const size_t normal = accessor(view(12 * n, kArrayBuffer), kFloat, n, "VEC3");
      const size_t uv = accessor(view(8 * n, kArrayBuffer), kFloat, n, "VEC2");
      const size_t indices = accessor(view(4 * m.indices.size(), kElementArrayBuffer), kUnsignedInt, m.indices.size(), "SCALAR");
      json primitive = {{"attributes", {{"POSITION", position}, {"NORMAL", normal}, {"TEXCOORD_0", uv}}}, {"indices", indices}, {"mode", kTriangles}};
      meshes.push_back({{"name", info_.names[k]}, {"primitives", json::array({primitive})}});
      nodes.push_back({{"name", info_.names[k]}, {"mesh", k}});
      sceneNodes.push_back(k);
    }
    binSize_ = offset;
    return {{"asset", {{"version", "2.0"}, {"generator", "pdesurf export"}}},
            {"scene", 0},
            {"scenes", json::array({{{"name", info_.title}, {"nodes", sceneNodes}}})},
            {"nodes", nodes},
            {"meshes", meshes},
            {"buffers", json::array({{{"byteLength", offset}}})},
            {"bufferViews", views},
            {"accessors", accessors}};
  }

  // The float bounds of the positions, exactly (glTF validators compare them with the data).
  static std::pair<std::array<float, 3>, std::array<float, 3>> bounds(const Mesh& m) {
    std::array<float, 3> lo{m.positions[0], m.positions[1], m.positions[2]}, hi = lo;
    for (size_t k = 0; k < m.vertexCount(); ++k)
      for (int d = 0; d < 3; ++d) {
        lo[d] = std::min(lo[d], m.positions[3 * k + d]);
        hi[d] = std::max(hi[d], m.positions[3 * k + d]);
      }
    return {lo, hi};
  }

  // The same order as document(): positions, normals, texture coordinates, indices.
  void writeBinary(const Mesh& m) {
    constexpr size_t kPerRound = OutBuffer::kSlack / 4;  // floats per reserve()
    auto floats = [&](const float* x, size_t count) {
      for (size_t k = 0; k < count; k += kPerRound) {
        char* p = b_.reserve();
        for (size_t t = k, e = std::min(count, k + kPerRound); t < e; ++t) p = putF32(p, x[t]);
        b_.commit(p);
      }
    };
    floats(m.positions.data(), m.positions.size());
    floats(m.normals.data(), m.normals.size());
    for (size_t k = 0; k < m.vertexCount(); ++k) {
      char* p = b_.reserve();
      p = putF32(p, m.uvs[2 * k]);
      p = putF32(p, 1.0f - m.uvs[2 * k + 1]);
      b_.commit(p);
    }
    for (size_t k = 0; k < m.indices.size(); k += kPerRound) {
      char* p = b_.reserve();
      for (size_t e = std::min(m.indices.size(), k + kPerRound), t = k; t < e; ++t) p = putU32(p, m.indices[t]);
      b_.commit(p);
    }
  }

  OutBuffer b_;
  ExportInfo info_;
  std::vector<Mesh> meshes_;
  uint64_t binSize_ = 0;
};

}  // namespace

std::unique_ptr<MeshWriter> makeGlbWriter(std::ostream& out, const std::string& what, const ExportInfo& info) {
  return std::make_unique<GlbWriter>(out, what, info);
}

}  // namespace pdesurf::cli::detail
