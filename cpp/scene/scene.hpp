// A scene: named parameters and patches, resolved to numbers (docs/scene-format.md).
// parseScene validates everything and names the offending field in its errors; solveScene
// turns each patch into a separable surface.
#pragma once
#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "bezier/bezier_solver_cache.hpp"
#include "methods/method.hpp"
#include "ode/basis_cache.hpp"
#include "pde/pde_problem.hpp"
#include "surface/mesh.hpp"
#include "surface/separable_surface.hpp"

namespace pdesurf {

struct Parameter {
  std::string name, label;
  double value = 0, min = 0, max = 0, step = 0;  // step 0: not given
};

// How a patch is made: a PDE solved (a blend, a chain; a fill closing a loop), a primary surface
// typed by the scene, a Bézier patch minimising an energy (scene/patch_kinds.hpp).
enum class PatchKind { Pde, Fill, Primary, Bezier };

// coef · T(t) · g(v): one term of a primary surface; T and g are basis functions.
struct PrimaryTerm {
  VFunction t, v;
  double coef = 1.0;
};

// A primary surface, separable in (t, v): each coordinate Σ coef T(t) g(v), t in [t0, t1].
// "ruled" scenes (C(v) + t D(v): cylinders, cones, planes) and "separable" scenes (spheres
// R sin t cos v, ellipsoids, hyperboloids a cosh t cos v, explicit surfaces) both become one.
struct PrimarySurface {
  double t0 = 0, t1 = 1, v0 = 0, v1 = 0;
  std::array<std::vector<PrimaryTerm>, 3> terms;
  std::array<Expr, 3> pointwise;  // what does not separate (version-2 "surface" expressions)
  // Each coordinate's whole expression in t (ExprVar::U) and v: "surface" patches only
  // (null otherwise); blend ends by reference are derived from it (scene/derived_ends.hpp).
  std::array<Expr, 3> full;
  bool trimmed = false;  // reparametrised by a curve trimline: t0 = 0 is the trimline
  bool trimReplacesT1 = false;  // trimmed: the border the curve replaces (t1, else t0)
  // A trimmed surface's pointwise expression with its partial derivatives (X, X_t, X_v, X_tt,
  // X_tv, X_vv), built under the scene's budget when it is trimmed; empty otherwise.
  std::array<std::vector<Expr>, 3> pointwisePartials;
};

// Version 3: how smoothly a blend's end meets the surface it names (G0, G1, G2).
enum class Continuity { Position = 0, Tangency = 1, Curvature = 2 };

// Version 3: a pde patch end given by reference, {"surface", "at", "continuity", "power",
// "flip"} (docs/blends-by-reference.md). Its conditions are derived from the surface.
struct EndReference {
  bool given = false;
  std::string surface;  // the name of a "surface" patch (empty for an end on a patch, below)
  // Version 4, a chain: the end continues another pde patch's end (edge 0 u0, 1 u1) or a
  // Bézier patch's border (kBezierEdge's order) instead of a surface; its conditions come from
  // that patch once it is solved (scene/chain_conditions.hpp). power must then be constant.
  std::string patch;
  int patchEdge = 0;
  bool reverse = false;  // a Bézier border's parameter runs backwards along this end's v
  bool curve = false;   // the trimline is t = tau(v); else the iso-line t = t0 or t1
  bool atT1 = false;    // iso-line: t1 (else t0); curve: it replaces the border t1 (else t0)
  Expr tau;             // curve only: an expression in v
  Continuity continuity = Continuity::Tangency;
  Expr power;           // in v (parameters folded in); 1 when not given
  bool surfaceScale = false;  // "scale": "surface": power times S_t itself; else ("gap") normalised
  bool flip = false;
  std::string path;     // "patches[0].ends.u0", for errors
  // Filled by deriveEnds: per coordinate, the conditions X, X_u (, X_uu) as text in v, with
  // the parameters' current values (what the page shows and can detach into typed ends).
  std::array<std::vector<std::string>, 3> derived;
};

// Where a primary surface meets a PDE or Bézier patch: its t = t0 (or t1) curve is that
// patch's boundary at u = end (or, for a Bézier patch, v = end). The join certificate
// (analysis/join_certificate.hpp) checks the continuity the patch promises along it.
struct Meets {
  std::string patch;
  int end = 0;          // 0: u (or v) = 0, 1: u (or v) = 1
  bool alongU = false;  // Bézier only: the border v = end, running along u
  bool atT1 = false;    // the primary's edge: false t = t0, true t = t1
  // Scene version 3, an end along a curve t = tau(v): the trimmed surface starts at the curve
  // (atT1 false); replacesT1 says which border the curve replaces (for the certificate's label).
  bool curve = false, replacesT1 = false;
  // A border of a surface trimmed along a curve, as the scene names it (0: t0, 1: t1): the
  // trimmed surface's t runs from the curve, so atT1 is its far border whatever its name.
  // -1: atT1 is the name.
  int namedT = -1;
  // The primary's v-interval that the patch's border parameter maps onto linearly; unset
  // (NaN): a PDE blend shares v with the primary, a Bézier border maps [0, 1] onto v_range.
  double v0 = NAN, v1 = NAN;
  // Version 3: the end that made this join ("patches[2].ends.u0", for errors); empty: the
  // scene's own `meets`. Version 4: also a Bézier border ("patches[4].borders.v1").
  std::string by;
  // Version 4, a Bézier border with "reverse": the border parameter 0..1 runs over the
  // primary's v-range backwards (v1 to v0).
  bool reversed = false;
  // Version 4, the met patch is a pde patch (its end u0/u1 by atT1) or a Bézier patch (its
  // border sourceEdge in kBezierEdge's order); -1: atT1 names the edge t0/t1 (u0/u1).
  int sourceEdge = -1;
  // Version 4, a fill (PatchKind::Fill): the part [from, to] of the fill's border
  // u = 0 (its v) that meets this edge; NaN: the target's whole border.
  double targetFrom = NAN, targetTo = NAN;
  // A fill's side: its part maps onto [v0, v1] through σ(w) = w - kFillEase sin(2πw)/2π, not
  // linearly (scene/fill_conditions.cpp).
  bool eased = false;
  // Version 4, a Bézier border by reference (a fit of the edge): 0 when its distance from the
  // edge is proven within the G0 tolerance everywhere, the distance found beyond it, or +inf
  // when neither could be shown (analysis/curve_gap_bound.hpp); at borderGapV (the surface's
  // v). NaN: not such a border. The certificate's G0 takes it with its samples.
  double borderGap = NAN, borderGapV = NAN;
};

// The part of a fill's v (its loop u = 0) that border k of n runs over. With n > 1 the loop
// starts halfway along border 0, [2π(k - ½)/n, 2π(k + ½)/n]: its corners are never at v = 0,
// so the fill's seam v = 0 ≡ 2π runs from a smooth point of its data and is G1 to rounding
// (border 0's part wraps: [-π/n, π/n], its expression valid on both sides of 0).
inline std::array<double, 2> fillSideRange(size_t k, size_t n) {
  if (n == 1) return {0.0, 2 * M_PI};
  return {2 * M_PI * (k - 0.5) / n, 2 * M_PI * (k + 0.5) / n};
}

// How much a fill's sides slow down at the loop's corners: their speed there is 1 - kFillEase
// of the mean (scene/fill_conditions.cpp). Fully (1): the loop's data are then C2 in v at the
// corners and no kink runs inward along a corner's ray (half way, 0.5, until issue 35: creases
// of 0.3° to 7° along the rays).
constexpr double kFillEase = 0.75;

// Version 4: one border of a fill's loop, or the edge a chained end continues: an edge of
// another patch (a surface's t0/t1, a pde patch's u0/u1, a Bézier border), optionally a part
// [from, to] of its parameter, optionally run backwards.
struct LoopBorder {
  std::string patch;
  int edge = 0;          // surface, pde: 0 t0/u0, 1 t1/u1; Bézier: kBezierEdge's order
  double from = NAN, to = NAN;  // NaN: the edge's whole parameter range
  bool reverse = false;
  Expr power;            // a number (parameters folded in); 1 when not given
  std::string path;      // "patches[3].borders[1]", for errors
  // A surface's trimline curve, `"at": {"t": tau(v), "replaces": "t0" | "t1"}` (curve.given):
  // deriveEnds checks it and trims the surface along it as for a blend's end, and edge becomes
  // 0, the curve in the drawn parametrisation. A surface's t0/t1 always name its own borders:
  // on a trimmed surface, the one not replaced is its drawn edge 1.
  EndReference curve;
};

// Version 4, kind "fill" (docs/chains-and-fills.md): a pde patch that closes a loop of N borders of other
// patches. u = 0 is the loop (v in [0, 2π], border k on [2πk/N, 2π(k+1)/N]); u = 1 collapses to
// a centre point with a tangent plane. Order 2 (position) or 4 (tangency along every side).
struct FillLoop {
  std::vector<LoopBorder> borders;
  Continuity continuity = Continuity::Tangency;
  bool centreGiven = false, normalGiven = false;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero(), normal = Eigen::Vector3d::Zero();
  double height = 1.0;  // the derived centre's lift along the normal, in units of the loop's rise
  std::string path;     // "patches[3]"
};

// Version 4: a Bézier patch's border given by reference, {"surface", "at", "reverse"}
// (docs/bezier.md, "Borders by reference"): its two outer rings of control points are derived
// from the surface's border t = t0 or t1 (scene/bezier_borders.hpp).
struct BorderReference {
  bool given = false;
  std::string surface;   // the name of a "surface" patch
  bool atT1 = false;     // the surface's border t = t1 (else t0)
  bool reverse = false;  // the surface's v runs backwards along the edge
  std::string path;      // "patches[4].borders.u0", for errors
};

// The Bézier patch's edges in the order of Patch::borders: u = 0, u = 1 (running along v),
// v = 0, v = 1 (running along u); the names `meets.end` uses for a Bézier patch.
inline const char* const kBezierEdge[4] = {"u0", "u1", "v0", "v1"};

// The operator of one coordinate as the scene names it, resolved to numbers: order 2 {s, t},
// order 4 {b, c, d}, order 6 {a} (= (∂²u + a²∂²v)³) or, for any order, coefficients[k].
struct ComponentOperator {
  int order = 4;
  std::vector<std::string> names;
  std::vector<double> values;
};

// What a pde patch carries (kind "pde", and "fill", which closes a loop of borders).
struct PdeData {
  std::array<ComponentOperator, 3> op;
  PdeProblem pde;
  Method method;  // "method" in the scene, default auto
  // Version 3: the ends given by reference ([0] u0, [1] u1), and the typed ends' position
  // expressions per coordinate (null: not typed), for the extra conditions of an end that
  // asks less than the operator carries.
  std::array<EndReference, 2> ends;
  std::array<std::array<Expr, 3>, 2> typedPosition;
  FillLoop fill;  // a fill's loop (version 4); its conditions are derived at solve time
};

// What a Bézier patch carries (seed 002).
struct BezierData {
  BezierProblem bezier;
  // Version 4: the borders given by reference, in kBezierEdge's order. A patch whose four
  // borders are given may omit its control_net (bezier.initial is then empty until
  // deriveBorders builds it).
  std::array<BorderReference, 4> borders;
};

struct Patch {
  std::string name;
  std::string kindName;  // as the scene says: "pde", "fill", "surface", "ruled", "separable", "bezier"
  // Primary only: its joins, one per edge and patch end: the scene's own `meets` first (when
  // given), then those of the version-3 ends that name it (scene/derived_ends.hpp), in the
  // drawn parametrisation (a surface trimmed along a curve has the curve at t = t0 = 0).
  std::vector<Meets> meets;
  PatchKind kind = PatchKind::Pde;  // set with setKind, which gives the patch that kind's data
  // The patches whose solved surfaces this one's conditions come from (chained ends, a fill's
  // borders): solveScene solves them first.
  std::vector<std::string> dependsOn;
  // One payload, the kind's (scene/patch_kinds.hpp): PdeData for pde patches and fills.
  std::variant<PdeData, PrimarySurface, BezierData> data;

  void setKind(PatchKind k);
  bool isFill() const { return kind == PatchKind::Fill; }
  bool solvedAsPde() const { return kind == PatchKind::Pde || kind == PatchKind::Fill; }  // a fill is a pde patch too
  // The kind's data by the names the fields had; asking for another kind's is an Internal error.
  PdeData& pdeData();
  const PdeData& pdeData() const;
  BezierData& bezierData();
  const BezierData& bezierData() const;
  PrimarySurface& primary();
  const PrimarySurface& primary() const;
  std::array<ComponentOperator, 3>& op() { return pdeData().op; }
  const std::array<ComponentOperator, 3>& op() const { return pdeData().op; }
  PdeProblem& pde() { return pdeData().pde; }
  const PdeProblem& pde() const { return pdeData().pde; }
  Method& method() { return pdeData().method; }
  const Method& method() const { return pdeData().method; }
  std::array<EndReference, 2>& ends() { return pdeData().ends; }
  const std::array<EndReference, 2>& ends() const { return pdeData().ends; }
  std::array<std::array<Expr, 3>, 2>& typedPosition() { return pdeData().typedPosition; }
  const std::array<std::array<Expr, 3>, 2>& typedPosition() const { return pdeData().typedPosition; }
  FillLoop& fill() { return pdeData().fill; }
  const FillLoop& fill() const { return pdeData().fill; }
  BezierProblem& bezier() { return bezierData().bezier; }
  const BezierProblem& bezier() const { return bezierData().bezier; }
  std::array<BorderReference, 4>& borders() { return bezierData().borders; }
  const std::array<BorderReference, 4>& borders() const { return bezierData().borders; }
};

struct Scene {
  int version = 2;  // of the file it was read from (1 to 4)
  std::string title;
  std::vector<Parameter> parameters;
  std::vector<Patch> patches;
  // Indices into patches, every patch after the ones it depends on (parseScene refuses a cycle).
  std::vector<size_t> solveOrder;
  const Patch* find(const std::string& name) const;
  const Patch* firstPde() const;
  const Patch* firstSolved() const;  // the first pde patch, else the first bezier patch
  const Patch* firstBezier() const;
};

struct SolvedPatch {
  const Patch* patch;
  SeparableSurface surface;
  Method used;  // Pde only: the method that produced it (auto resolved)
  // Bezier only: the solved control net, its energy and normal misfit.
  std::vector<Eigen::Vector3d> controlNet;
  double energy = 0.0, normalMisfit = 0.0;
  // Pde only: the problem solved, with the conditions derived from other patches filled in
  // (null: the patch's own pde).
  std::shared_ptr<const PdeProblem> problem;
  bool reused = false;  // the same problem as the cache's last solve of this patch: not re-solved
  uint64_t solveId = 0;  // with a cache, pde only: which solve made `surface` (a mesh made from it stays valid)
  const PdeProblem& pde() const { return problem ? *problem : patch->pde(); }
};

// Throws Error(ParseError | InvalidField | UnknownName | NonFinite | TooLarge) with a field
// path such as
// "patches[0].boundary.x.u0[1][0].coef: col 3: unknown parameter 'r9'".
Scene parseScene(const std::string& jsonText);

// What repeated solves can reuse: the closed form's ODE bases and the Bézier factorisations.
// The page keeps one between calls; one-off solves pass none.
// Its last solve of every pde patch, by name: a patch whose derived problem is unchanged (same
// operator, conditions, forces, method) is not solved again, so an edit re-solves only the
// patches downstream of it.
struct SolveMemo {
  PdeProblem problem;
  Method method;
  SeparableSurface surface;
  Method used;
  uint64_t id = 0;
};
struct SolveCache {
  BasisCache bases;
  BezierSolverCache bezier;
  std::map<std::string, SolveMemo> solved;
  uint64_t solves = 0;  // ids for SolveMemo::id
};

// A solved patch drawn on an nu×nv grid (surface/mesh.hpp), its errors (NonFinite beyond a
// float, GridSize) naming the patch, the same wherever it is drawn (page, export, check).
void tessellatePatchInto(const SolvedPatch& patch, int nu, int nv, Mesh& out, bool curvature = false);
Mesh tessellatePatch(const SolvedPatch& patch, int nu, int nv, bool curvature = false);

// Throws, message prefixed with the patch name. `method` overrides the patch's own. A patch
// that depends on others (Patch::dependsOn) needs them: solveScene, or solvePatchIn.
SolvedPatch solvePatch(const Patch& patch, const Method* method = nullptr, SolveCache* cache = nullptr);
// Every patch, in solveOrder, returned in the scene's order.
std::vector<SolvedPatch> solveScene(const Scene& scene, SolveCache* cache = nullptr);
// One patch of the scene with what it depends on solved first; `method` overrides its own.
SolvedPatch solvePatchIn(const Scene& scene, const Patch& patch, const Method* method = nullptr);

// Before drawing every patch of `scene` on an nu×nv grid: throws Error(GridSize) outside
// 1..limits::kGrid per direction and Error(TooLarge) when all patches together would exceed
// limits::kSceneVertices. Call it before solving, so refused work costs nothing.
void checkSceneGrid(const Scene& scene, int nu, int nv);

}  // namespace pdesurf
