// Reads a STEP or IGES file with Open CASCADE and checks it against expected faces: shape
// valid (BRepCheck_Analyzer), face count, each expected face found by name, its surface
// within tolerance of the expected points, its parameter bounds those of the samples.
// Shared by occt_readback (a file and a JSON expectation) and occt_writers_selftest.
#pragma once
#include <array>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace pdesurf_occt {

struct ExpectedFace {
  std::string name;
  // (u, v, x, y, z). The samples' u and v ranges are taken as the face's domain: include the
  // corners.
  std::vector<std::array<double, 5>> samples;
};

struct Expectation {
  double tolerance = 0.0;
  std::vector<ExpectedFace> faces;
  // Optional: {"solids", "closedShells", "freeEdges", "edgesOnMoreThanTwoFaces": counts,
  // "volume": v, "volumeRelTol": r (default 1e-4)}, each judged when given.
  nlohmann::json topology = nlohmann::json::object();
};

// {"tolerance": t, "faces": [{"name": ..., "samples": [[u, v, x, y, z], ...]}], "topology": {...}}; throws
// std::runtime_error on anything else.
Expectation parseExpectation(const nlohmann::json& j);
nlohmann::json toJson(const Expectation& e);  // parseExpectation's inverse

struct CheckResult {
  bool ok = false;        // valid, every face found by name, every deviation <= tolerance, bounds agree
  nlohmann::json report;  // {"valid", "faceCount", "fileTolerance", "faces": [...], "errors": [...], "messages": [...]}
};

// path ends in .step/.stp or .igs/.iges (any case). OCCT's own messages go to stderr.
CheckResult checkCadFile(const std::string& path, const Expectation& expect);

}  // namespace pdesurf_occt
