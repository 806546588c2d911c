// JSON -> Scene. Every error names its field path; unknown fields are rejected because they
// are nearly always typos that would otherwise be silently ignored.
#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include "bezier/bezier_solver.hpp"
#include "expr/budget.hpp"
#include "common/text.hpp"
#include "scene/bezier_borders.hpp"
#include "scene/derived_ends.hpp"
#include "scene/expression_fields.hpp"
#include "scene/patch_graph.hpp"
#include "scene/patch_kinds.hpp"
#include "scene/placement.hpp"
#include "common/limits.hpp"
#include "scene/json_fields.hpp"
#include "scene/json_read.hpp"
#include "scene/scene.hpp"

namespace pdesurf {

using namespace scene_json;

namespace {

void parseParameters(const json& j, Scene& scene, Resolver& r, int version) {
  if (!j.is_object()) fail(ErrorCode::InvalidField, "parameters", "expected an object of named parameters");
  // Values first so that ranges may refer to none but numbers; parameters are plain numbers.
  for (auto it = j.begin(); it != j.end(); ++it) {
    const std::string path = "parameters." + it.key();
    const std::string& name = it.key();
    bool ident = !name.empty() && name.size() <= 32 && (std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_');
    for (char c : name) ident = ident && (std::isalnum(static_cast<unsigned char>(c)) || c == '_');
    if (!ident) fail(ErrorCode::InvalidField, path, "a parameter name is a letter or '_' followed by letters, digits or '_'");
    if (name == "pi" || name == "e" || name == "v" || name == "u" || (version >= 2 && name == "t"))
      fail(ErrorCode::InvalidField, path, "'" + name + "' is reserved");
    allowOnly(it.value(), path, {"value", "min", "max", "step", "label"});
    Parameter p;
    p.name = name;
    auto num = [&](const char* key) {
      const json& v = require(it.value(), key, path);
      if (!v.is_number()) fail(ErrorCode::InvalidField, path + "." + key, "expected a number");
      const double x = v.get<double>();
      if (!std::isfinite(x)) fail(ErrorCode::NonFinite, path + "." + key, "not finite");
      return x;
    };
    p.value = num("value");
    p.min = num("min");
    p.max = num("max");
    if (!(p.min < p.max)) fail(ErrorCode::InvalidField, path, "min must be less than max");
    if (p.value < p.min || p.value > p.max)
      fail(ErrorCode::InvalidField, path + ".value", "outside [min, max] = [" + numberText(p.min) + ", " + numberText(p.max) + "]");
    if (it.value().contains("label")) p.label = stringField(it.value()["label"], path + ".label");
    if (it.value().contains("step")) {
      p.step = num("step");
      if (!(p.step > 0)) fail(ErrorCode::InvalidField, path + ".step", "must be positive");
    }
    r.values[name] = p.value;
    scene.parameters.push_back(p);
  }
}

// The primary's v-interval a join covers (meets.v_range, else a PDE blend's own v_range, else
// the primary's) must lie inside the primary's v_range: outside it the primary's expressions
// are evaluated where the surface is not drawn, so the certificate would pass a border that
// hangs free. A part of the border (seed 002 Fig. 4's middle third) is allowed.
void checkJoinInterval(const Patch& primary, const Meets& m, const Patch& target, const std::string& mp) {
  const PrimarySurface& S = primary.primary();
  const bool given = !std::isnan(m.v0);
  if (!given && !target.solvedAsPde()) return;
  const double a = given ? m.v0 : target.pde().v0, b = given ? m.v1 : target.pde().v1;
  const double slack = 1e-12 * std::max({1.0, std::abs(S.v0), std::abs(S.v1)});
  if (a < S.v0 - slack || b > S.v1 + slack) {
    const auto num = [](double x) { std::ostringstream o; o << x; return o.str(); };
    const std::string what = given ? "[" : "the v_range [";
    fail(ErrorCode::InvalidField, given ? mp + ".v_range" : mp,
         what + num(a) + ", " + num(b) + "]" + (given ? "" : " of pde patch '" + target.name + "'") + " is not inside the v_range [" + num(S.v0) +
             ", " + num(S.v1) + "] of '" + primary.name + "': the join would hang past the surface's border");
  }
}

}  // namespace

static Scene parseSceneUnchecked(const std::string& text);

Scene parseScene(const std::string& text) {
  try {
    return parseSceneUnchecked(text);
  } catch (const json::exception& e) {
    // nlohmann reports number overflow ("1e999") and similar as its own exceptions.
    throw Error(ErrorCode::ParseError, std::string("malformed JSON: ") + e.what());
  }
}

static Scene parseSceneUnchecked(const std::string& text) {
  const json doc = readJson(text);
  if (!doc.is_object()) fail(ErrorCode::InvalidField, "scene", "expected an object");
  const json& format = require(doc, "format", "scene");
  if (!format.is_string() || format.get<std::string>() != "pdesurf-scene")
    fail(ErrorCode::InvalidField, "format", "expected \"pdesurf-scene\"");
  const json& version = require(doc, "version", "scene");
  const bool known = version.is_number() && version.get<double>() >= 1 && version.get<double>() <= 4 &&
                     version.get<double>() == static_cast<double>(static_cast<int>(version.get<double>()));
  if (!known) fail(ErrorCode::InvalidField, "version", "this build reads scene versions 1 to 4");
  allowOnly(doc, "scene", {"format", "version", "id", "title", "description", "source", "parameters", "patches"});
  Scene scene;
  scene.version = static_cast<int>(version.get<double>());  // 4.0 and 4e0 are 4, as the page reads them
  if (doc.contains("title")) scene.title = stringField(doc["title"], "title");
  if (doc.contains("id")) stringField(doc["id"], "id", 64);
  if (doc.contains("description")) stringField(doc["description"], "description", 2000, true);
  if (doc.contains("source")) {
    allowOnly(doc["source"], "source", {"paper", "figure", "equation", "note"});
    for (auto it = doc["source"].begin(); it != doc["source"].end(); ++it) stringField(it.value(), "source." + it.key(), 500, true);
  }
  Resolver r;
  if (doc.contains("parameters")) parseParameters(doc["parameters"], scene, r, scene.version);
  const json& patches = require(doc, "patches", "scene");
  // Version 4 is what the page builds from nothing: its first scene has no patch yet.
  if (!patches.is_array()) fail(ErrorCode::InvalidField, "patches", "expected an array");
  if (patches.empty() && scene.version < 4) fail(ErrorCode::InvalidField, "patches", "expected a non-empty array (an empty scene needs version 4)");
  if (patches.size() > limits::kPatches) fail(ErrorCode::TooLarge, "patches", "more than " + std::to_string(limits::kPatches) + " patches");
  std::set<std::string> names;
  BezierWork bezierWork;  // over the Bezier patches so far
  for (size_t i = 0; i < patches.size(); ++i) {
    const std::string path = "patches[" + std::to_string(i) + "]";
    const json& pj = patches[i];
    if (!pj.is_object()) fail(ErrorCode::InvalidField, path, "expected an object");
    Patch patch;
    patch.name = stringField(require(pj, "name", path), path + ".name", 64);
    if (patch.name.empty()) fail(ErrorCode::InvalidField, path + ".name", "empty");
    if (!names.insert(patch.name).second) fail(ErrorCode::InvalidField, path + ".name", "duplicate patch name '" + patch.name + "'");
    const std::string kind = stringField(require(pj, "kind", path), path + ".kind");
    patch.kindName = kind;
    const PatchKindEntry* entry = findPatchKind(kind, scene.version);
    if (!entry) fail(ErrorCode::InvalidField, path + ".kind", "unknown kind '" + kind + "' (" + patchKindNames(scene.version) + ")");
    patch.setKind(entry->solvedAs);
    entry->parse({pj, path, r, scene.version, bezierWork}, patch);
    scene.patches.push_back(std::move(patch));
  }
  {
    // One budget for every node derived for the scene: its ends and its Bezier borders.
    ExprBudget budget(limits::kDerivedNodes, "the derived conditions of the scene's ends and Bezier borders and the surfaces they trim");
    deriveEnds(scene, budget);     // version 3: ends by reference, once every surface is known
    deriveBorders(scene, budget);  // version 4: Bezier borders by reference (after the trims: it refuses a trimmed surface)
  }
  linkPatches(scene);  // version 4: chained ends and fills (their conditions are derived when solved)
  for (size_t i = 0; i < scene.patches.size(); ++i)
    for (const Meets& m : scene.patches[i].meets) {
      if (!m.by.empty()) continue;  // derived from an end: its patch is that end's blend
      const Patch* target = scene.find(m.patch);
      const std::string mp = "patches[" + std::to_string(i) + "].meets";
      if (!target || (!target->solvedAsPde() && target->kind != PatchKind::Bezier))
        fail(ErrorCode::UnknownName, mp + ".patch", "no pde or bezier patch named '" + m.patch + "'");
      if (m.alongU && target->kind != PatchKind::Bezier)
        fail(ErrorCode::InvalidField, mp + ".end", "pde patch '" + m.patch + "' has ends u0 and u1 only");
      checkJoinInterval(scene.patches[i], m, *target, mp);
    }
  checkEdgesMetOnce(scene);
  return scene;
}

}  // namespace pdesurf
