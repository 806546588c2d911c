// The join report as JSON (issue 39: one serialiser, one key style): what `pdesurf check
// --json` prints and what the wasm module hands the page (docs/wasm-api.md, docs/analysis.md).
// Keys are snake_case; a figure that is not finite (an angle at a degenerate point, an
// unbounded ratio) is null, as JSON has no NaN or infinity.
#pragma once
#include <nlohmann/json.hpp>
#include <vector>

#include "analysis/bodies.hpp"
#include "analysis/join_certificate.hpp"

namespace pdesurf {

// { ok, scene_size, joins, seams, crossings, centres, bodies }.
nlohmann::json reportJson(const SceneReport& r, const std::vector<Body>& bodies);
// { patches, closed, area, volume (null when open), free_edges }: a body in the report and in
// the module's model mesh.
nlohmann::json bodyJson(const Body& b);

}  // namespace pdesurf
