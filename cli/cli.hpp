// The pdesurf command-line tool: the same core as the page, with file I/O.
#pragma once
#include <iosfwd>
#include <string>
#include <vector>

namespace pdesurf::cli {

struct Options {
  std::string command, scenePath, patch, output, method, format;
  int nu = 16, nv = 16;
  double tolerance = 0.0;  // export to CAD: 0 is the default (1e-6 of the scene's diagonal)
  int degree = 5;
  int jobs = 0;  // export to CAD: threads fitting patches; 0 is the default (the machine's, at most 8)
  bool gridGiven = false, json = false, controlNet = false;
  bool loosePatches = false;  // export: each patch its own grid mesh (with texture coordinates), not joined
};

// Throws std::runtime_error with a usage message.
Options parseArgs(const std::vector<std::string>& args);
std::string readFile(const std::string& path);

int runSample(const Options& o, std::ostream& out);
int runExport(const Options& o);
enum class CadFormat { None, Step, Iges };
CadFormat cadFormatOf(const Options& o);  // by --format or the output's extension
int runCadExport(const Options& o, CadFormat format, std::ostream& out);
int runCompare(const Options& o, std::ostream& out);
int runEncodeLink(const Options& o, std::ostream& out);
int runDecodeLink(const Options& o, std::ostream& out);
int runCheck(const Options& o, std::ostream& out);
int runImport(const Options& o, std::ostream& out);  // cli/import_command.cpp  // exit code 1 when a join fails or a patch crosses

extern const char* kUsage;

}  // namespace pdesurf::cli
