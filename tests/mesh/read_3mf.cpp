// The 3MF read-back used by the tests (tests/cli/watertight-export.test.mjs, tests/js/
// mesh-export-page.test.mjs): lib3mf, the 3MF Consortium's library, reads a package and says
// for each build item's mesh object its name, counts and whether lib3mf finds it manifold and
// oriented (what a slicer asks of a printable body). One JSON line:
//   {"objects":[{"name":"body 1","vertices":5090,"triangles":10176,"manifold":true}]}
// Exit 1 with a message on stderr when lib3mf cannot read the file.
//   read_3mf FILE.3mf
#include <Model/COM/NMR_DLLInterfaces.h>

#include <cstdio>
#include <string>

namespace {

bool ok(LIB3MFRESULT r, NMR::PLib3MFBase* on, const char* what) {
  if (r == LIB3MF_OK) return true;
  DWORD code = 0;
  LPCSTR message = nullptr;
  if (on) NMR::lib3mf_getlasterror(on, &code, &message);
  std::fprintf(stderr, "read_3mf: %s failed (lib3mf error %u: %s)\n", what, unsigned(code), message ? message : "");
  return false;
}

std::string jsonString(const std::string& s) {
  std::string out = "\"";
  for (unsigned char c : s) {
    if (c == '"' || c == '\\') out += '\\', out += char(c);
    else if (c < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
    } else out += char(c);
  }
  return out + "\"";
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: read_3mf FILE.3mf\n");
    return 2;
  }
  NMR::PLib3MFModel* model = nullptr;
  NMR::PLib3MFModelReader* reader = nullptr;
  NMR::PLib3MFModelBuildItemIterator* items = nullptr;
  if (!ok(NMR::lib3mf_createmodel(&model), nullptr, "creating a model")) return 1;
  if (!ok(NMR::lib3mf_model_queryreader(model, "3mf", &reader), model, "making the reader")) return 1;
  if (!ok(NMR::lib3mf_reader_readfromfileutf8(reader, argv[1]), reader, "reading the file")) return 1;
  if (!ok(NMR::lib3mf_model_getbuilditems(model, &items), model, "listing the build items")) return 1;
  std::string out = "{\"objects\":[";
  BOOL more = false;
  bool first = true;
  while (ok(NMR::lib3mf_builditemiterator_movenext(items, &more), items, "the next build item") && more) {
    NMR::PLib3MFModelBuildItem* item = nullptr;
    NMR::PLib3MFModelObjectResource* object = nullptr;
    if (!ok(NMR::lib3mf_builditemiterator_getcurrent(items, &item), items, "a build item")) return 1;
    if (!ok(NMR::lib3mf_builditem_getobjectresource(item, &object), item, "its object")) return 1;
    BOOL isMesh = false, manifold = false;
    DWORD vertices = 0, triangles = 0;
    char name[512] = {0};
    ULONG needed = 0;
    NMR::lib3mf_object_getnameutf8(object, name, sizeof name, &needed);
    NMR::lib3mf_object_ismeshobject(object, &isMesh);
    if (isMesh) {
      NMR::lib3mf_meshobject_getvertexcount(object, &vertices);
      NMR::lib3mf_meshobject_gettrianglecount(object, &triangles);
      if (!ok(NMR::lib3mf_meshobject_ismanifoldandoriented(object, &manifold), object, "the manifold check")) return 1;
    }
    out += std::string(first ? "" : ",") + "{\"name\":" + jsonString(name) + ",\"mesh\":" + (isMesh ? "true" : "false") +
           ",\"vertices\":" + std::to_string(vertices) + ",\"triangles\":" + std::to_string(triangles) + ",\"manifold\":" + (manifold ? "true" : "false") + "}";
    first = false;
    NMR::lib3mf_release(object);
    NMR::lib3mf_release(item);
  }
  std::printf("%s]}\n", out.c_str());
  NMR::lib3mf_release(items);
  NMR::lib3mf_release(reader);
  NMR::lib3mf_release(model);
  return 0;
}
