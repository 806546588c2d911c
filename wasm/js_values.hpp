// Plain-data helpers shared by the binding files: copies of core arrays for JS, and the
// {ok: false, error: {code, message}} result every call returns instead of throwing.
#pragma once
#include <emscripten/val.h>

#include <string>
#include <vector>

namespace pdesurf::wasm {

// A copy, not a view: views into the wasm heap go stale when the heap grows.
template <class T>
emscripten::val copyOut(const std::vector<T>& v) {
  return emscripten::val(emscripten::typed_memory_view(v.size(), v.data())).call<emscripten::val>("slice");
}

inline emscripten::val failure(const char* code, const std::string& message) {
  emscripten::val err = emscripten::val::object();
  err.set("code", std::string(code));
  err.set("message", message);
  emscripten::val r = emscripten::val::object();
  r.set("ok", false);
  r.set("error", err);
  return r;
}

}  // namespace pdesurf::wasm
