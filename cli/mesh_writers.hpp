// pdesurf export's file formats, written straight from the tessellated meshes:
//   obj  text: o/v/vt/vn/f per patch, 1-based global indices, floats in shortest round-trip form
//   stl  binary: 80-byte header, uint32 triangle count, per triangle normal, 3 vertices, uint16 0
//   ply  binary little endian: vertex x y z nx ny nz (float), face list uchar uint
//   glb  glTF 2.0 binary: one mesh and node per patch (POSITION, NORMAL, TEXCOORD_0, uint32 indices)
// Every binary value is little endian, written byte by byte (no host-order assumption).
#pragma once
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

#include "surface/mesh.hpp"

namespace pdesurf::cli {

enum class MeshFormat { Obj, Stl, Ply, Glb };

// "obj", "stl", "ply", "glb"; anything else throws std::runtime_error naming the choices.
MeshFormat parseMeshFormat(const std::string& name);
// From the file name's extension (case-insensitive); obj when it names none of the formats.
MeshFormat meshFormatFromPath(const std::string& path);

// What a writer knows before the first mesh: the patches' names, and the grid, the same nu×nv
// for every patch, so the headers' counts are known up front (each mesh is checked against them).
struct ExportInfo {
  std::string title;
  std::vector<std::string> names;  // in scene order
  int nu = 0, nv = 0;
};

class MeshWriter {
 public:
  virtual ~MeshWriter() = default;
  // One patch, in scene order. OBJ and STL write it at once and keep nothing; PLY writes its
  // vertices and keeps its indices (faces follow all vertices); GLB keeps the mesh (its JSON,
  // which comes first, holds every patch's bounds).
  virtual void add(const std::string& name, Mesh&& mesh) = 0;
  // After the last patch: writes what remains and flushes; throws when writing fails.
  virtual void finish() = 0;
};

// `what` names the destination in errors.
std::unique_ptr<MeshWriter> makeMeshWriter(MeshFormat format, std::ostream& out, const std::string& what, const ExportInfo& info);

// Control characters replaced by spaces: names stay on one line (OBJ, PLY comments, STL header).
std::string oneLine(std::string s);

namespace detail {
std::unique_ptr<MeshWriter> makeGlbWriter(std::ostream& out, const std::string& what, const ExportInfo& info);
// Throw std::logic_error when a mesh or the number of patches differs from what `info` says.
void checkMeshShape(const ExportInfo& info, const std::string& name, const Mesh& m);
void checkPatchCount(const ExportInfo& info, size_t added);
}  // namespace detail

}  // namespace pdesurf::cli
