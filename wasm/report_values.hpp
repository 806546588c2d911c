// The join certificate as plain data for JS (docs/wasm-api.md: the report), from a whole
// report or its failure; shared by the solve's all-at-once report and the part-by-part one.
#pragma once
#include <emscripten/val.h>

#include <vector>

#include "analysis/bodies.hpp"
#include "analysis/join_certificate.hpp"
#include "common/errors.hpp"

namespace pdesurf::wasm {

emscripten::val reportValue(const SceneReport& r, const std::vector<Body>& bodies, bool crossingsChecked);
// A scene whose declared join is wrong still draws; the report says why it cannot certify.
emscripten::val reportFailure(const Error& e, bool crossingsChecked);

}  // namespace pdesurf::wasm
