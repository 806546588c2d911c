// Every limit on input and work, in one place (docs/limits.md). Each is checked before the
// allocation or the work it bounds, and each failure is a named Error (or, for links, a named
// refusal). The page's link codec (web/link/) holds the same numbers; tests/hostile/ feeds one
// corpus to both and expects the same verdicts.
#pragma once
#include <cstddef>

namespace pdesurf::limits {

// Text.
constexpr size_t kSceneBytes = 1 << 20;        // a scene file, or a link's inflated content
constexpr int kJsonDepth = 32;                 // nesting of arrays and objects, outermost = 1
constexpr size_t kLinkChars = 2 << 20;         // a link's text, before any decoding
constexpr size_t kInflatedBytes = kSceneBytes;  // what a link may inflate to
constexpr size_t kExpressionChars = 1000;      // one expression string
constexpr size_t kNameChars = 64;              // a patch name or id

// Geometry and work.
constexpr int kPatches = 64;
constexpr int kGrid = 2048;  // grid cells per direction, per patch
// Vertices over all patches of one solve (patches × (nu+1)(nv+1)): about one 2048² patch,
// ~240 MB of mesh. The caps above alone would allow 64 × 2048².
constexpr size_t kSceneVertices = size_t{2049} * 2049;
constexpr int kBezierDegree = 16;
// A discrete guiding-normal field's samples (np+1)(mp+1) times the square of the number of
// control points: the normal term's assembly is about 13 such products (Gram matrices), so
// this bounds a solve from scratch to about a second natively.
constexpr size_t kBezierAssembly = size_t{1} << 28;

}  // namespace pdesurf::limits
