// Every limit on input and work, in one place (docs/limits.md). Each is checked before the
// allocation or the work it bounds, and each failure is a named Error (or, for links, a named
// refusal). The page's link codec (web/link/) holds the same numbers; tests/hostile/ feeds one
// corpus to both and expects the same verdicts.
#pragma once
#include <cstddef>

namespace pdesurf::limits {

// Text.
// A scene's text (a file, the module's argument): 16 MiB, as imported CAD faces need it (the
// aeroplane's 22 certified faces through STEP are 4.4 MB of compact JSON; a scene of 64 faces
// of a few hundred control points each is several MB). A link stays at 1 MiB: a larger scene
// is shared as a file.
constexpr size_t kSceneBytes = 16 << 20;
constexpr int kJsonDepth = 32;                 // nesting of arrays and objects, outermost = 1
constexpr size_t kLinkChars = 2 << 20;         // a link's text, before any decoding
constexpr size_t kInflatedBytes = 1 << 20;     // what a link may inflate to
constexpr size_t kExpressionChars = 1000;      // one expression string
constexpr size_t kNameChars = 64;              // a patch name or id

// Geometry and work.
constexpr int kPatches = 64;
constexpr int kGrid = 2048;  // grid cells per direction, per patch
// Vertices over all patches of one solve (patches × (nu+1)(nv+1)): about one 2048² patch,
// ~240 MB of mesh. The caps above alone would allow 64 × 2048².
constexpr size_t kSceneVertices = size_t{2049} * 2049;
constexpr int kBezierDegree = 16;
// Bezier assembly work over all Bezier patches of a scene. Per patch, on the Nu×Nv nodes of the
// normal and data terms (a discrete field's (np+1)(mp+1) samples, or a continuous field's
// (n+n1)(m+m1) Gauss points) with K = (n+1)(m+1) control points: Nu·Nv·(m+1)² + Nu·K², the
// cost of one tensor-product Gram matrix (bezier/tensor_gram.hpp; the assembly makes ~13).
// The degree (16) and grid (256²) caps alone keep one patch at or below 40.5 M units (degree
// 16 with a 256² field: ~0.1 s natively from scratch); the total stops 64 such patches. At the
// cap, 13 of them: ~1-2 s natively.
constexpr size_t kBezierAssembly = size_t{1} << 29;
// Normal fields typed as expressions, summed over a scene's Bezier patches: samples × the
// operations of each compiled expression (x, y, z and the weights), charged before it runs.
// 2^27 ≈ 1.3·10^8: e.g. a 256² field of five 200-operation expressions (~0.2 s natively).
constexpr size_t kFieldSampling = size_t{1} << 27;
// Expression nodes built to derive the ends given by reference of one scene (version 3),
// summed over its blends, with the pointwise expressions and partial derivatives of the
// surfaces they trim along a curve. Counted while the graph is built (expr/budget.hpp): the
// first node over it stops the derivation with TooLarge. Measured figures: docs/limits.md.
constexpr size_t kDerivedNodes = 200000;
// A chain's or a fill border's power (the cross derivative's scale) and a fill's height are
// within ±kEndScale, and a fill's given centre within kEndScale loop radii of the loop: past
// them the shape is a spike, not a design, and p² overflowed (issue 38: a power of 1e300 was
// reported as a 0.8 gap by check and as NonFinite by export).
constexpr double kEndScale = 100;
// Expression nodes built deriving the chained ends and fills' loops of one solve, summed over
// its patches (each also within kDerivedNodes): a chain whose every patch carries its
// predecessors' terms grows quadratically, and 64 patches each under the per-patch budget
// took minutes (issue 38). Counted while building, as kDerivedNodes.
constexpr size_t kSceneDerivedNodes = size_t{1} << 20;
// A "surface" given as NURBS (scene/nurbs_json.hpp): its degree in each direction (Open
// CASCADE's own maximum) and its control points. Each point costs one B-spline evaluation per
// sample of the surface only along its rows (below); 16 384 points are ~1 MB of scene text.
constexpr int kNurbsDegree = 25;
constexpr size_t kNurbsPoints = 16384;  // 128²: pdesurf's own CAD faces reach 28 × 153
// And the work of one evaluation of it, counted before it is built: the de Boor steps of its
// spline nodes, Σ (degree + 1)² (a basis function per row of the direction summed over, a
// curve per coordinate and the weights along the other). A 64 × 64 bicubic costs 5 120; the
// heaviest typed expression (1 000 characters) ~500 operations. With it, one surface on the
// largest grid (2048²) stays within minutes natively, where degree 25 over 64 rows (216 000)
// would take hours.
constexpr size_t kNurbsEvaluation = 8192;
// A derived condition's text (shown in the page, typed by detach) is elided past this.
constexpr size_t kDerivedTextChars = 2000;

}  // namespace pdesurf::limits
