// A scene: named parameters and patches, resolved to numbers (docs/scene-format.md).
// parseScene validates everything and names the offending field in its errors; solveScene
// turns each patch into a separable surface.
#pragma once
#include <string>
#include <vector>

#include "pde/pde_problem.hpp"
#include "surface/separable_surface.hpp"

namespace pdesurf {

struct Parameter {
  std::string name, label;
  double value = 0, min = 0, max = 0;
};

enum class PatchKind { Pde, Ruled };
const char* patchKindName(PatchKind kind);

// P(t, v) = C(v) + t·D(v), t in [t0, t1]: cylinders, cones and planes through a trimline.
struct RuledSurface {
  double t0 = 0, t1 = 1, v0 = 0, v1 = 0;
  std::array<VExpansion, 3> curve, direction;
};

// Where a primary surface meets a PDE patch: its t = t0 curve is that patch's boundary at
// u = end. Used to check (and later report) continuity along the trimline.
struct Meets {
  std::string patch;
  int end = 0;  // 0: u = 0, 1: u = 1
};

// The operator of one coordinate as the scene names it, resolved to numbers: order 2 {s, t},
// order 4 {b, c, d}, order 6 {a} (= (∂²u + a²∂²v)³) or, for any order, coefficients[k].
struct ComponentOperator {
  int order = 4;
  std::vector<std::string> names;
  std::vector<double> values;
};

struct Patch {
  std::string name;
  Meets meets;          // Ruled only; meets.patch empty when not given
  PatchKind kind = PatchKind::Pde;
  std::array<ComponentOperator, 3> op;  // Pde only
  PdeProblem pde;                       // Pde only
  RuledSurface ruled;   // Ruled only
};

struct Scene {
  std::string title;
  std::vector<Parameter> parameters;
  std::vector<Patch> patches;
  const Patch* find(const std::string& name) const;
  const Patch* firstPde() const;
};

struct SolvedPatch {
  const Patch* patch;
  SeparableSurface surface;
};

constexpr size_t kMaxSceneBytes = 1 << 20;

// Throws Error(ParseError | InvalidField | UnknownName | NonFinite) with a field path such as
// "patches[0].boundary.x.u0[1][0].coef: col 3: unknown parameter 'r9'".
Scene parseScene(const std::string& jsonText);

SeparableSurface solvePatch(const Patch& patch);  // throws, message prefixed with the patch name
std::vector<SolvedPatch> solveScene(const Scene& scene);

}  // namespace pdesurf
