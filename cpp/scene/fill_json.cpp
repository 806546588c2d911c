// Version 4's "fill" patch (docs/chains-and-fills.md): a pde patch closing a loop of borders of other
// patches. Read here; its conditions come from the solved borders (scene/fill_conditions.cpp).
#include <cmath>

#include "common/limits.hpp"
#include "scene/ends_json.hpp"
#include "scene/json_fields.hpp"
#include "scene/patch_parsers.hpp"
#include "scene/scene.hpp"

namespace pdesurf {

using namespace scene_json;

namespace {

constexpr int kMinSides = 1, kMaxSides = 8;

LoopBorder parseBorder(const json& j, const std::string& path, const Resolver& r) {
  allowOnly(j, path, {"patch", "at", "range", "reverse", "power"});
  LoopBorder b;
  b.path = path;
  b.patch = stringField(require(j, "patch", path), path + ".patch", 64);
  const json& at = require(j, "at", path);
  if (at.is_object()) {
    // A surface's trimline curve: checked and trimmed with the blends' ends (deriveEnds).
    b.curve.given = true;
    b.curve.surface = b.patch;
    b.curve.path = path;
    parseTrimCurve(at, path + ".at", r, b.curve);
    b.curve.power = constant(1.0);
  } else {
    b.edge = edgeIndex(stringField(at, path + ".at"), path + ".at", true);
  }
  if (j.contains("range")) {
    const auto range = r.range(j, "range", path, 0.0, 1.0);
    b.from = range[0], b.to = range[1];
  }
  if (j.contains("reverse")) {
    if (!j["reverse"].is_boolean()) fail(ErrorCode::InvalidField, path + ".reverse", "expected true or false");
    b.reverse = j["reverse"].get<bool>();
  }
  const double power = j.contains("power") ? r.number(j["power"], path + ".power") : 1.0;
  if (!(power > 0)) fail(ErrorCode::InvalidField, path + ".power", "must be positive");
  if (!(power <= limits::kEndScale)) fail(ErrorCode::InvalidField, path + ".power", "at most 100 (past it a spike, not a fill)");
  b.power = constant(power);
  return b;
}

Eigen::Vector3d vectorField(const json& j, const std::string& path, const Resolver& r) {
  if (!j.is_array() || j.size() != 3) fail(ErrorCode::InvalidField, path, "expected [x, y, z]");
  const auto v = r.perComponent(j, path);
  return {v[0], v[1], v[2]};
}

}  // namespace

void parseFillPatch(const json& j, const std::string& path, const Resolver& r, int version, Patch& patch) {
  if (version < 4) fail(ErrorCode::InvalidField, path + ".kind", "a fill needs scene version 4");
  allowOnly(j, path, {"name", "kind", "borders", "continuity", "centre", "normal", "height", "operator", "force", "method"});
  FillLoop& fill = patch.fill();
  fill.path = path;
  const json& borders = require(j, "borders", path);
  if (!borders.is_array()) fail(ErrorCode::InvalidField, path + ".borders", "expected an array of borders");
  if (borders.size() < kMinSides || borders.size() > kMaxSides)
    fail(ErrorCode::InvalidField, path + ".borders",
         "a fill closes 1 (a closed border) to " + std::to_string(kMaxSides) + " borders; this one has " + std::to_string(borders.size()));
  for (size_t k = 0; k < borders.size(); ++k) fill.borders.push_back(parseBorder(borders[k], path + ".borders[" + std::to_string(k) + "]", r));
  if (j.contains("continuity")) fill.continuity = continuityOf(j["continuity"], path + ".continuity");
  for (LoopBorder& b : fill.borders) b.curve.continuity = fill.continuity;  // what the trimline's checks ask
  if (j.contains("centre")) fill.centreGiven = true, fill.centre = vectorField(j["centre"], path + ".centre", r);
  if (j.contains("normal")) {
    fill.normalGiven = true;
    fill.normal = vectorField(j["normal"], path + ".normal", r);
    // Scaled by its largest coordinate first: [1e200, 0, 1e200] has a direction though its
    // norm overflows, and [0, 0, 1e-200] one though its square underflows.
    const double largest = fill.normal.cwiseAbs().maxCoeff();
    if (!(largest > 0)) fail(ErrorCode::InvalidField, path + ".normal", "the zero vector has no direction");
    fill.normal = (fill.normal / largest).normalized();
  }
  if (j.contains("height")) {
    fill.height = r.number(j["height"], path + ".height");
    if (!(std::abs(fill.height) <= limits::kEndScale)) fail(ErrorCode::InvalidField, path + ".height", "outside [-100, 100]");
  }
  // The rest is an ordinary pde patch over v in [0, 2π] whose conditions are all derived.
  const int order = fill.continuity == Continuity::Position ? 2 : fill.continuity == Continuity::Tangency ? 4 : 6;
  json pde = {{"name", patch.name}, {"kind", "pde"}, {"v_range", json::array({0.0, 2 * M_PI})}, {"boundary", json::object()}};
  pde["operator"] = j.contains("operator") ? j["operator"]
                    : order == 2           ? json{{"order", 2}, {"s", 1}, {"t", 1}}
                    : order == 4           ? json{{"order", 4}, {"b", 1}, {"c", 2}, {"d", 1}}
                                           : json{{"order", 6}, {"a", 1}};
  if (j.contains("force")) pde["force"] = j["force"];
  // The loop's data are piecewise (their cross derivatives jump at the corners): a fixed modal
  // series with the exact boundary lift, rather than auto's refinement, which would not settle.
  // 32 modes for position and tangency (the corners' remainder decays with the lift: creases
  // no larger than with 64 on the examples and random holes, a third of the time); curvature's
  // X_uu data need 64 (32 left 0.9° creases on random G2 holes).
  pde["method"] = j.contains("method") ? j["method"] : json(order == 6 ? "modal:64" : "modal:32");
  parsePdePatch(pde, path, r, version, patch);
  patch.kindName = "fill";
  for (int c = 0; c < 3; ++c)
    if (patch.op()[c].order != order)
      fail(ErrorCode::InvalidField, path + ".operator",
           std::string(order == 2 ? "position" : order == 4 ? "tangency" : "curvature") + " continuity needs an order-" + std::to_string(order) + " operator; " + kAxis[c] +
               " has order " + std::to_string(patch.op()[c].order));
}

}  // namespace pdesurf
