// pdesurf export's mesh formats, written from the model's mesh (analysis/watertight_mesh.hpp):
// vertices shared along every join (or, with --patches, each patch its own grid with texture
// coordinates), one named part per patch:
//   obj  text: v/vn (and vt) for each vertex once, just before the first part that uses it;
//        o and f per patch, 1-based global indices; floats in shortest round-trip form
//   stl  binary: 80-byte header, uint32 triangle count, per triangle normal, 3 vertices, uint16 0
//   ply  binary little endian: vertex x y z nx ny nz (float), face list uchar uint; a comment
//        per patch with its number of faces, in the faces' order
//   glb  glTF 2.0 binary: one POSITION, NORMAL (and TEXCOORD_0) accessor for the whole model,
//        one mesh and node per patch with its own indices
// Every binary value is little endian, written byte by byte (no host-order assumption).
#pragma once
#include <iosfwd>
#include <string>

#include "analysis/watertight_mesh.hpp"

namespace pdesurf::cli {

enum class MeshFormat { Obj, Stl, Ply, Glb, ThreeMf };  // 3mf: three_mf_writer.hpp

// "obj", "stl", "ply", "glb", "3mf"; anything else throws std::runtime_error naming the choices.
MeshFormat parseMeshFormat(const std::string& name);
// From the file name's extension (case-insensitive); obj when it names none of the formats.
MeshFormat meshFormatFromPath(const std::string& path);

// `what` names the destination in errors; throws when writing fails or the model is too
// large for the format (STL's and PLY's 32-bit counts, GLB's 4 GiB).
void writeMesh(MeshFormat format, std::ostream& out, const std::string& what, const std::string& title, const ModelMesh& mesh);

// Control characters replaced by spaces: names stay on one line (OBJ, PLY comments, STL header).
std::string oneLine(std::string s);

namespace detail {
void writeGlb(std::ostream& out, const std::string& what, const std::string& title, const ModelMesh& mesh);
size_t triangleCount(const ModelMesh& mesh);
}  // namespace detail

}  // namespace pdesurf::cli
