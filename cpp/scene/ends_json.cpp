// Version 3's "ends" of a pde patch: each of u0 and u1 given by reference to a primary
// surface, {"surface", "at", "continuity", "power", "flip"}. Only read here; the conditions
// are derived once every patch is known (scene/derived_ends.cpp).
#include "scene/ends_json.hpp"

#include <algorithm>

#include "common/limits.hpp"

namespace pdesurf::scene_json {

Continuity continuityOf(const json& j, const std::string& path) {
  const std::string c = stringField(j, path);
  if (c == "position") return Continuity::Position;
  if (c == "tangency") return Continuity::Tangency;
  if (c == "curvature") return Continuity::Curvature;
  fail(ErrorCode::InvalidField, path, "expected \"position\", \"tangency\" or \"curvature\"");
}

int edgeIndex(const std::string& at, const std::string& path, bool surfaceNames) {
  for (int k = 0; k < 4; ++k)
    if (at == kBezierEdge[k]) return k;
  if (surfaceNames && (at == "t0" || at == "t1")) return at == "t1" ? 1 : 0;
  fail(ErrorCode::InvalidField, path,
       std::string("expected ") + (surfaceNames ? "\"t0\", \"t1\" (a surface), " : "") + "\"u0\", \"u1\" (a pde patch) or \"v0\", \"v1\" (a bezier patch)");
}

namespace {

Expr expressionInV(const json& j, const std::string& path, const Resolver& r) {
  if (j.is_number()) {
    const double x = j.get<double>();
    if (!std::isfinite(x)) fail(ErrorCode::NonFinite, path, "not a finite number");
    return constant(x);
  }
  const std::string text = stringField(j, path, kMaxExpressionLength);
  if (text.empty()) fail(ErrorCode::InvalidField, path, "empty expression");
  try {
    return parseExpression(text, r.values, AllowedVariables{true, false});
  } catch (const Error& e) {
    fail(e.code(), path, e.what());
  }
}

// Version 4, a chain: {"patch", "at": "u0" | "u1" | "v0" | "v1", "continuity", "power",
// "reverse"}; whether the edge exists is checked once every patch is known (scene/patch_graph).
EndReference parseChainEnd(const json& j, const std::string& path, const Resolver& r, int version) {
  if (version < 4) fail(ErrorCode::InvalidField, path + ".patch", "an end on another patch needs scene version 4");
  allowOnly(j, path, {"patch", "at", "continuity", "power", "reverse"});
  EndReference e;
  e.given = true;
  e.path = path;
  e.patch = stringField(require(j, "patch", path), path + ".patch", 64);
  e.patchEdge = edgeIndex(stringField(require(j, "at", path), path + ".at"), path + ".at", false);
  if (j.contains("reverse")) {
    if (!j["reverse"].is_boolean()) fail(ErrorCode::InvalidField, path + ".reverse", "expected true or false");
    e.reverse = j["reverse"].get<bool>();
  }
  e.power = constant(j.contains("power") ? r.number(j["power"], path + ".power") : 1.0);
  if (!(e.power->value > 0)) fail(ErrorCode::InvalidField, path + ".power", "must be positive");
  if (!(e.power->value <= limits::kEndScale)) fail(ErrorCode::InvalidField, path + ".power", "at most 100 (past it a spike, not a blend)");
  e.surfaceScale = true;
  return e;
}

}  // namespace

void parseTrimCurve(const json& at, const std::string& path, const Resolver& r, EndReference& e) {
  allowOnly(at, path, {"t", "replaces"});
  e.curve = true;
  e.tau = expressionInV(require(at, "t", path), path + ".t", r);
  if (at.contains("replaces")) {
    const std::string s = stringField(at["replaces"], path + ".replaces");
    if (s != "t0" && s != "t1") fail(ErrorCode::InvalidField, path + ".replaces", "expected \"t0\" or \"t1\"");
    e.atT1 = s == "t1";
  }
}

namespace {

EndReference parseEnd(const json& j, const std::string& path, const Resolver& r, int version) {
  if (j.is_object() && j.contains("patch")) {
    EndReference e = parseChainEnd(j, path, r, version);
    if (j.contains("continuity")) e.continuity = continuityOf(j["continuity"], path + ".continuity");
    return e;
  }
  allowOnly(j, path, {"surface", "at", "continuity", "power", "scale", "flip"});
  EndReference e;
  e.given = true;
  e.path = path;
  e.surface = stringField(require(j, "surface", path), path + ".surface", 64);
  const json& at = require(j, "at", path);
  if (at.is_string()) {
    const std::string s = at.get<std::string>();
    if (s != "t0" && s != "t1") fail(ErrorCode::InvalidField, path + ".at", "expected \"t0\", \"t1\" or {\"t\": \"<expression in v>\"}");
    e.atT1 = s == "t1";
  } else if (at.is_object()) {
    parseTrimCurve(at, path + ".at", r, e);
  } else {
    fail(ErrorCode::InvalidField, path + ".at", "expected \"t0\", \"t1\" or {\"t\": \"<expression in v>\"}");
  }
  if (j.contains("continuity")) e.continuity = continuityOf(j["continuity"], path + ".continuity");
  e.power = j.contains("power") ? expressionInV(j["power"], path + ".power", r) : constant(1.0);
  if (j.contains("scale")) {
    const std::string sc = stringField(j["scale"], path + ".scale");
    if (sc != "gap" && sc != "surface") fail(ErrorCode::InvalidField, path + ".scale", "expected \"gap\" or \"surface\"");
    e.surfaceScale = sc == "surface";
  }
  if (j.contains("flip")) {
    if (!j["flip"].is_boolean()) fail(ErrorCode::InvalidField, path + ".flip", "expected true or false");
    e.flip = j["flip"].get<bool>();
  }
  return e;
}

}  // namespace

int parseEnds(const json& j, const std::string& path, const Resolver& r, int version, Patch& patch) {
  allowOnly(j, path, {"u0", "u1"});
  int order = 0;
  for (int end = 0; end < 2; ++end) {
    const char* key = end == 0 ? "u0" : "u1";
    if (!j.contains(key)) continue;
    patch.ends()[end] = parseEnd(j[key], path + "." + key, r, version);
    order = std::max(order, 2 * (static_cast<int>(patch.ends()[end].continuity) + 1));
  }
  if (order == 0) fail(ErrorCode::InvalidField, path, "expected u0, u1 or both");
  return order;
}

}  // namespace pdesurf::scene_json
