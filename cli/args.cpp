#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "cli.hpp"
#include "mesh_writers.hpp"

namespace pdesurf::cli {

const char* kUsage =
    "usage:\n"
    "  pdesurf sample SCENE.json [--patch NAME] [--grid NUxNV] [--method M]   print u,v,x,y,z on the grid\n"
    "  pdesurf sample SCENE.json --control-net [--patch NAME]                 print a Bezier patch's solved control points\n"
    "  pdesurf export SCENE.json -o FILE [--format F] [--grid NUxNV]          the model's mesh to FILE, F: obj (text),\n"
    "      stl, ply (binary), glb (glTF 2.0 binary) or 3mf (for printing, an object per body); default:\n"
    "      FILE's extension, else obj. Patches share\n"
    "      their vertices along every join (watertight); --patches: each its own grid, with (u, v)\n"
    "  pdesurf export SCENE.json -o FILE.step|.igs [--tol T] [--degree 3|5]  every patch as a B-spline face within the\n"
    "      certified deviation T (scene units; default 1e-6 of the scene's diagonal); STEP AP214 or IGES 5.3;\n"
    "      [--jobs N]: patches fitted on N threads (default: the machine's, at most 8; the same file)\n"
    "  pdesurf compare SCENE.json [--patch NAME] [--grid 100x100] [--json]    every applicable method:\n"
    "      E (seed 000 Eq. 24) against the closed form or the reference, boundary error, solve time\n"
    "  pdesurf check SCENE.json [--json] [--grid NxN]                         join certificate (G0/G1/G2, folds) and\n"
    "      crossings on an NxN mesh per patch (default 64); exit 1 when a join fails its promise or a patch crosses\n"
    "  pdesurf import FILE.step|.stp|.igs|.iges [-o SCENE.json]             a scene of the file's faces, each a NURBS\n"
    "      surface over its parameter bounds (trims not kept; Open CASCADE reads the file); default: standard output\n"
    "  pdesurf encode-link SCENE.json [--grid NUxNV]                          print the shareable link's fragment\n"
    "  pdesurf decode-link 'URL-or-fragment'                                  print the scene of a shared link\n"
    "  methods: auto, closed, pseudo-navier[:M,N,L], modal:N, fourier:N, pseudo-spectral:N, reference\n";

namespace {
void parseGrid(const std::string& s, Options& o) {
  const size_t x = s.find('x');
  try {
    size_t used = 0;
    if (x == std::string::npos) throw std::invalid_argument("");
    o.nu = std::stoi(s.substr(0, x), &used);
    if (used != x) throw std::invalid_argument("");
    o.nv = std::stoi(s.substr(x + 1), &used);
    if (used != s.size() - x - 1) throw std::invalid_argument("");
  } catch (const std::logic_error&) {
    throw std::runtime_error("--grid expects NUxNV, e.g. 64x64, got '" + s + "'");
  }
}
}  // namespace

Options parseArgs(const std::vector<std::string>& args) {
  if (args.empty()) throw std::runtime_error("missing command");
  Options o;
  o.command = args[0];
  if (o.command != "sample" && o.command != "export" && o.command != "compare" && o.command != "encode-link" &&
      o.command != "decode-link" && o.command != "check" && o.command != "import")
    throw std::runtime_error("unknown command '" + o.command + "'");
  for (size_t i = 1; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&]() -> const std::string& {
      if (i + 1 >= args.size()) throw std::runtime_error(a + " needs a value");
      return args[++i];
    };
    if (a == "--patch") o.patch = value();
    else if (a == "--grid") parseGrid(value(), o), o.gridGiven = true;
    else if (a == "--method") o.method = value();
    else if (a == "--json") o.json = true;
    else if (a == "--control-net") o.controlNet = true;
    else if (a == "--patches") o.loosePatches = true;
    else if (a == "-o" || a == "--output") o.output = value();
    else if (a == "--format") {
      o.format = value();
      if (o.format != "step" && o.format != "stp" && o.format != "iges" && o.format != "igs") parseMeshFormat(o.format);  // refused here, before any work
    } else if (a == "--tol") {
      const std::string& t = value();
      // Decimal only, as numbers in scenes (docs/limits.md): strtod alone also reads "0x1p-10",
      // " 1e-3", "inf" and "nan".
      const bool decimal = !t.empty() && t.find_first_not_of("0123456789.eE+-") == std::string::npos && std::isdigit(static_cast<unsigned char>(t[0]));
      char* end = nullptr;
      o.tolerance = decimal ? std::strtod(t.c_str(), &end) : 0.0;
      if (!decimal || *end != '\0' || !(o.tolerance > 0) || !std::isfinite(o.tolerance))
        throw std::runtime_error("--tol expects a positive finite decimal number, got '" + t.substr(0, 40) + "'");
    } else if (a == "--degree") {
      const std::string& d = value();
      if (d != "3" && d != "5") throw std::runtime_error("--degree expects 3 or 5, got '" + d.substr(0, 40) + "'");
      o.degree = d[0] - '0';
    } else if (a == "--jobs") {
      const std::string& j = value();
      char* end = nullptr;
      const long n = std::strtol(j.c_str(), &end, 10);
      if (j.empty() || *end != '\0' || n < 1 || n > 64) throw std::runtime_error("--jobs expects a whole number from 1 to 64, got '" + j.substr(0, 40) + "'");
      o.jobs = int(n);
    }
    else if (!a.empty() && a[0] == '-' && o.command != "decode-link") throw std::runtime_error("unknown option '" + a + "'");
    else if (o.scenePath.empty()) o.scenePath = a;
    else throw std::runtime_error("unexpected argument '" + a + "'");
  }
  if (o.scenePath.empty())
    throw std::runtime_error(o.command == "decode-link" ? "missing the link" : o.command == "import" ? "missing FILE.step or FILE.igs" : "missing SCENE.json");
  if (o.command == "import" && (o.gridGiven || o.json || o.controlNet || !o.method.empty() || !o.patch.empty()))
    throw std::runtime_error("import takes FILE and -o SCENE.json only");
  if (o.command == "export" && o.output.empty()) throw std::runtime_error("export needs -o FILE (.obj, .stl, .ply, .glb, .3mf, .step, .stp, .igs or .iges)");
  if (o.command != "export" && !o.format.empty()) throw std::runtime_error("--format applies to export only");
  if (o.command != "export" && o.loosePatches) throw std::runtime_error("--patches applies to export only");
  if (o.command != "export" && (o.tolerance > 0 || o.degree != 5 || o.jobs > 0))
    throw std::runtime_error("--tol, --degree and --jobs apply to export only");
  return o;
}

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read '" + path + "'");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace pdesurf::cli
