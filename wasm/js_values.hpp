// Plain-data helpers shared by the binding files: copies of core arrays for JS, and the
// {ok: false, error: {code, message}} result every call returns instead of throwing.
#pragma once
#include <emscripten/val.h>

#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <cmath>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/errors.hpp"

namespace pdesurf::wasm {

// A copy, not a view: views into the wasm heap go stale when the heap grows.
template <class T>
emscripten::val copyOut(const std::vector<T>& v) {
  return emscripten::val(emscripten::typed_memory_view(v.size(), v.data())).call<emscripten::val>("slice");
}

// Points as x, y, z, x, y, z, … in doubles (a copy for JS keeps them exact).
inline std::vector<double> flattenExact(const std::vector<Eigen::Vector3d>& pts) {
  std::vector<double> out;
  out.reserve(pts.size() * 3);
  for (const Eigen::Vector3d& p : pts) out.insert(out.end(), {p.x(), p.y(), p.z()});
  return out;
}

// JSON as a JS value (objects, arrays, strings, numbers, booleans, null), as JSON.parse of its
// text would give: the core's report serialiser feeds the CLI and the module alike.
inline emscripten::val jsonValue(const nlohmann::json& j) {
  using emscripten::val;
  switch (j.type()) {
    case nlohmann::json::value_t::object: {
      val o = val::object();
      for (auto it = j.begin(); it != j.end(); ++it) o.set(it.key(), jsonValue(it.value()));
      return o;
    }
    case nlohmann::json::value_t::array: {
      val a = val::array();
      for (const auto& x : j) a.call<void>("push", jsonValue(x));
      return a;
    }
    case nlohmann::json::value_t::string: return val(j.get<std::string>());
    case nlohmann::json::value_t::boolean: return val(j.get<bool>());
    case nlohmann::json::value_t::number_integer: return val(double(j.get<int64_t>()));
    case nlohmann::json::value_t::number_unsigned: return val(double(j.get<uint64_t>()));
    case nlohmann::json::value_t::number_float: {
      const double x = j.get<double>();
      return std::isfinite(x) ? val(x) : val::null();
    }
    default: return val::null();
  }
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

// body()'s result, or its exception as a failure: a core error keeps its code; out of memory
// says what to try (`hint`), since the module's heap, not the machine, ran out.
template <class Body>
emscripten::val guarded(const char* hint, Body&& body) {
  try {
    return body();
  } catch (const Error& e) {
    return failure(errorCodeName(e.code()), e.what());
  } catch (const std::bad_alloc&) {
    return failure("Internal", std::string("out of memory: ") + hint);
  } catch (const std::exception& e) {
    return failure("Internal", e.what());
  }
}

// A grid size from JS: a number that is an integer (1.5 or "64" are refused, not truncated or
// converted).
inline int gridArg(const emscripten::val& v, const char* name) {
  const std::string type = v.typeOf().as<std::string>();
  if (type != "number") throw Error(ErrorCode::GridSize, std::string("grid ") + name + " must be an integer number, not a " + type);
  const double x = v.as<double>();
  if (!(x == std::floor(x)) || std::fabs(x) > 1e9)
    throw Error(ErrorCode::GridSize, std::string("grid ") + name + " must be an integer number, not " + std::to_string(x));
  return static_cast<int>(x);  // the range: checkGrid
}

}  // namespace pdesurf::wasm
