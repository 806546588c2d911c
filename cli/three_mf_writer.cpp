#include "three_mf_writer.hpp"

#include <Model/COM/NMR_DLLInterfaces.h>

#include <stdexcept>
#include <vector>

#include "mesh_writers.hpp"

namespace pdesurf::cli {

namespace {

// lib3mf's handles, released on every way out.
class Handle {
 public:
  Handle() = default;
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  ~Handle() {
    if (p_) NMR::lib3mf_release(p_);
  }
  NMR::PLib3MFBase* get() const { return p_; }
  NMR::PLib3MFBase** out() { return &p_; }

 private:
  NMR::PLib3MFBase* p_ = nullptr;
};

void check(LIB3MFRESULT r, NMR::PLib3MFBase* on, const std::string& what) {
  if (r == LIB3MF_OK) return;
  DWORD code = 0;
  LPCSTR message = nullptr;
  if (on) NMR::lib3mf_getlasterror(on, &code, &message);
  throw std::runtime_error("3MF: " + what + " failed (lib3mf error " + std::to_string(code ? code : DWORD(r)) + (message ? std::string(": ") + message : "") + ")");
}

}  // namespace

void write3mf(const std::string& path, const std::string& title, const ModelMesh& mesh) {
  Handle model;
  check(NMR::lib3mf_createmodel(model.out()), nullptr, "creating the model");
  check(NMR::lib3mf_model_setunit(model.get(), NMR::MODELUNIT_MILLIMETER), model.get(), "setting the unit");
  check(NMR::lib3mf_model_addmetadatautf8(model.get(), "Title", oneLine(title).c_str()), model.get(), "the title");
  check(NMR::lib3mf_model_addmetadatautf8(model.get(), "Application", "pdesurf"), model.get(), "the application");
  for (const BodyMesh& b : bodyMeshes(mesh)) {
    std::vector<NMR::MODELMESHVERTEX> vertices(b.positions.size() / 3);
    for (size_t k = 0; k < vertices.size(); ++k)
      for (int d = 0; d < 3; ++d) vertices[k].m_fPosition[d] = b.positions[3 * k + d];
    std::vector<NMR::MODELMESHTRIANGLE> triangles(b.indices.size() / 3);
    for (size_t t = 0; t < triangles.size(); ++t)
      for (int c = 0; c < 3; ++c) triangles[t].m_nIndices[c] = b.indices[3 * t + c];
    Handle object, item;
    check(NMR::lib3mf_model_addmeshobject(model.get(), object.out()), model.get(), "adding a mesh");
    check(NMR::lib3mf_object_setnameutf8(object.get(), oneLine(b.name).c_str()), object.get(), "naming '" + oneLine(b.name) + "'");
    check(NMR::lib3mf_meshobject_setgeometry(object.get(), vertices.data(), DWORD(vertices.size()), triangles.data(), DWORD(triangles.size())), object.get(),
          "the mesh of '" + oneLine(b.name) + "'");
    check(NMR::lib3mf_model_addbuilditem(model.get(), object.get(), nullptr, item.out()), model.get(), "adding a build item");
  }
  Handle writer;
  check(NMR::lib3mf_model_querywriter(model.get(), "3mf", writer.out()), model.get(), "making the writer");
  check(NMR::lib3mf_writer_writetofileutf8(writer.get(), path.c_str()), writer.get(), "writing '" + path + "'");
}

}  // namespace pdesurf::cli
