// JSON -> Scene. Every error names its field path; unknown fields are rejected because they
// are nearly always typos that would otherwise be silently ignored.
#include <nlohmann/json.hpp>

#include <cmath>
#include <initializer_list>
#include <set>

#include "common/errors.hpp"
#include "scene/expression.hpp"
#include "scene/scene.hpp"

namespace pdesurf {

namespace {

using json = nlohmann::json;
constexpr int kMaxJsonDepth = 32;
constexpr int kMaxPatches = 64;
constexpr int kMaxTerms = 256;
constexpr int kMaxPower = 24;
const char* kAxis[3] = {"x", "y", "z"};

[[noreturn]] void fail(ErrorCode code, const std::string& path, const std::string& why) {
  throw Error(code, path + ": " + why);
}

// nlohmann's parser recurses per nesting level; bound the depth before it runs.
void checkNesting(const std::string& text) {
  int depth = 0;
  bool inString = false;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (inString) {
      if (c == '\\') ++i;
      else if (c == '"') inString = false;
    } else if (c == '"') {
      inString = true;
    } else if (c == '{' || c == '[') {
      if (++depth > kMaxJsonDepth) throw Error(ErrorCode::ParseError, "JSON nested deeper than " + std::to_string(kMaxJsonDepth));
    } else if (c == '}' || c == ']') {
      --depth;
    }
  }
}

void allowOnly(const json& obj, const std::string& path, std::initializer_list<const char*> keys) {
  if (!obj.is_object()) fail(ErrorCode::InvalidField, path, "expected an object");
  for (auto it = obj.begin(); it != obj.end(); ++it) {
    bool known = false;
    for (const char* k : keys) known = known || it.key() == k;
    if (!known) fail(ErrorCode::InvalidField, path + "." + it.key(), "unknown field");
  }
}

const json& require(const json& obj, const char* key, const std::string& path) {
  const auto it = obj.find(key);
  if (it == obj.end()) fail(ErrorCode::InvalidField, path + "." + key, "missing");
  return *it;
}

std::string stringField(const json& j, const std::string& path, size_t maxLen = 200) {
  if (!j.is_string()) fail(ErrorCode::InvalidField, path, "expected a string");
  const std::string s = j.get<std::string>();
  if (s.size() > maxLen) fail(ErrorCode::InvalidField, path, "longer than " + std::to_string(maxLen) + " characters");
  return s;
}

class Resolver {
 public:
  ParameterValues values;

  double number(const json& j, const std::string& path) const {
    double v = 0;
    if (j.is_number()) {
      v = j.get<double>();
    } else if (j.is_string()) {
      try {
        v = evaluateExpression(j.get<std::string>(), values);
      } catch (const Error& e) {
        fail(e.code(), path, e.what());
      }
    } else {
      fail(ErrorCode::InvalidField, path, "expected a number or an expression string");
    }
    if (!std::isfinite(v)) fail(ErrorCode::NonFinite, path, "not a finite number");
    return v;
  }

  std::array<double, 2> range(const json& obj, const char* key, const std::string& path, double a, double b) const {
    const auto it = obj.find(key);
    if (it == obj.end()) return {a, b};
    const std::string p = path + "." + key;
    if (!it->is_array() || it->size() != 2) fail(ErrorCode::InvalidField, p, "expected [start, end]");
    const double lo = number((*it)[0], p + "[0]"), hi = number((*it)[1], p + "[1]");
    if (!(hi > lo)) fail(ErrorCode::InvalidField, p, "end must be greater than start");
    return {lo, hi};
  }

  VExpansion terms(const json& j, const std::string& path) const {
    if (!j.is_array()) fail(ErrorCode::InvalidField, path, "expected an array of terms");
    if (j.size() > kMaxTerms) fail(ErrorCode::InvalidField, path, "more than " + std::to_string(kMaxTerms) + " terms");
    VExpansion out;
    for (size_t k = 0; k < j.size(); ++k) {
      const std::string p = path + "[" + std::to_string(k) + "]";
      const json& t = j[k];
      allowOnly(t, p, {"fn", "coef", "w", "n"});
      VTerm term;
      const std::string fn = stringField(require(t, "fn", p), p + ".fn");
      if (!familyFromName(fn, &term.g.family))
        fail(ErrorCode::UnknownName, p + ".fn", "unknown basis function '" + fn + "' (poly, cos, sin, exp, cosh, sinh)");
      if (t.contains("coef")) term.coef = number(t["coef"], p + ".coef");
      if (term.g.isPoly()) {
        if (t.contains("w")) fail(ErrorCode::InvalidField, p + ".w", "a polynomial term has a power n, not a frequency w");
        if (t.contains("n")) {
          const json& n = t["n"];
          if (!n.is_number_integer() || n.get<long long>() < 0 || n.get<long long>() > kMaxPower)
            fail(ErrorCode::InvalidField, p + ".n", "expected an integer power 0.." + std::to_string(kMaxPower));
          term.g.n = n.get<int>();
        }
      } else {
        if (t.contains("n")) fail(ErrorCode::InvalidField, p + ".n", "only poly terms have a power n");
        if (t.contains("w")) term.g.w = number(t["w"], p + ".w");
      }
      out.push_back(term);
    }
    return out;
  }

  std::array<VExpansion, 3> vectorTerms(const json& obj, const char* key, const std::string& path) const {
    std::array<VExpansion, 3> out;
    const auto it = obj.find(key);
    if (it == obj.end()) return out;
    const std::string p = path + "." + key;
    allowOnly(*it, p, {"x", "y", "z"});
    for (int c = 0; c < 3; ++c)
      if (it->contains(kAxis[c])) out[c] = terms((*it)[kAxis[c]], p + "." + kAxis[c]);
    return out;
  }

  // One number for x, y, z, or an array of three.
  std::array<double, 3> perComponent(const json& j, const std::string& path) const {
    if (j.is_array()) {
      if (j.size() != 3) fail(ErrorCode::InvalidField, path, "expected one value or three (x, y, z)");
      return {number(j[0], path + "[0]"), number(j[1], path + "[1]"), number(j[2], path + "[2]")};
    }
    const double v = number(j, path);
    return {v, v, v};
  }
};

void parseParameters(const json& j, Scene& scene, Resolver& r) {
  if (!j.is_object()) fail(ErrorCode::InvalidField, "parameters", "expected an object of named parameters");
  // Values first so that ranges may refer to none but numbers; parameters are plain numbers.
  for (auto it = j.begin(); it != j.end(); ++it) {
    const std::string path = "parameters." + it.key();
    const std::string& name = it.key();
    bool ident = !name.empty() && name.size() <= 32 && (std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_');
    for (char c : name) ident = ident && (std::isalnum(static_cast<unsigned char>(c)) || c == '_');
    if (!ident) fail(ErrorCode::InvalidField, path, "a parameter name is a letter or '_' followed by letters, digits or '_'");
    if (name == "pi" || name == "e" || name == "v" || name == "u")
      fail(ErrorCode::InvalidField, path, "'" + name + "' is reserved");
    allowOnly(it.value(), path, {"value", "min", "max", "label"});
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
      fail(ErrorCode::InvalidField, path + ".value", "outside [min, max] = [" + std::to_string(p.min) + ", " + std::to_string(p.max) + "]");
    if (it.value().contains("label")) p.label = stringField(it.value()["label"], path + ".label");
    r.values[name] = p.value;
    scene.parameters.push_back(p);
  }
}

void parsePde(const json& j, const std::string& path, const Resolver& r, Patch& patch) {
  allowOnly(j, path, {"name", "kind", "v_range", "operator", "boundary"});
  const auto vr = r.range(j, "v_range", path, 0.0, 2 * M_PI);
  patch.pde.v0 = vr[0];
  patch.pde.v1 = vr[1];
  const std::string op = path + ".operator";
  const json& o = require(j, "operator", path);
  allowOnly(o, op, {"order", "b", "c", "d"});
  const json& order = require(o, "order", op);
  if (!order.is_number_integer() || order.get<long long>() != 4) fail(ErrorCode::InvalidField, op + ".order", "order must be 4");
  patch.order = 4;
  const auto b = r.perComponent(require(o, "b", op), op + ".b");
  const auto c = r.perComponent(require(o, "c", op), op + ".c");
  const auto d = r.perComponent(require(o, "d", op), op + ".d");
  for (int k = 0; k < 3; ++k) {
    if (b[k] == 0.0)
      fail(ErrorCode::DegenerateOperator, op + ".b[" + std::to_string(k) + "]",
           std::string("b_") + kAxis[k] + " = 0 removes the fourth u-derivative: the PDE loses its order");
    patch.pde.component[k].alpha = {b[k], c[k], d[k]};
  }
  const int n = patch.order / 2;
  const std::string bp = path + ".boundary";
  const json& bnd = require(j, "boundary", path);
  allowOnly(bnd, bp, {"x", "y", "z"});
  for (int k = 0; k < 3; ++k) {
    ComponentProblem& cp = patch.pde.component[k];
    cp.left.assign(n, {});
    cp.right.assign(n, {});
    if (!bnd.contains(kAxis[k])) continue;
    const std::string cpath = bp + "." + kAxis[k];
    const json& comp = bnd[kAxis[k]];
    allowOnly(comp, cpath, {"u0", "u1"});
    for (int end = 0; end < 2; ++end) {
      const char* key = end == 0 ? "u0" : "u1";
      if (!comp.contains(key)) continue;
      const json& list = comp[key];
      const std::string lp = cpath + "." + key;
      if (!list.is_array() || list.size() > static_cast<size_t>(n))
        fail(ErrorCode::InvalidField, lp, "expected at most " + std::to_string(n) + " conditions [X, dX/du]");
      for (size_t i = 0; i < list.size(); ++i)
        (end == 0 ? cp.left : cp.right)[i] = r.terms(list[i], lp + "[" + std::to_string(i) + "]");
    }
  }
}

void parseRuled(const json& j, const std::string& path, const Resolver& r, Patch& patch) {
  allowOnly(j, path, {"name", "kind", "v_range", "t_range", "curve", "direction", "meets"});
  if (j.contains("meets")) {
    const std::string mp = path + ".meets";
    allowOnly(j["meets"], mp, {"patch", "end"});
    patch.meets.patch = stringField(require(j["meets"], "patch", mp), mp + ".patch", 64);
    const std::string end = stringField(require(j["meets"], "end", mp), mp + ".end");
    if (end != "u0" && end != "u1") fail(ErrorCode::InvalidField, mp + ".end", "expected \"u0\" or \"u1\"");
    patch.meets.end = end == "u0" ? 0 : 1;
  }
  const auto vr = r.range(j, "v_range", path, 0.0, 2 * M_PI);
  const auto tr = r.range(j, "t_range", path, 0.0, 1.0);
  patch.ruled.v0 = vr[0];
  patch.ruled.v1 = vr[1];
  patch.ruled.t0 = tr[0];
  patch.ruled.t1 = tr[1];
  require(j, "curve", path);
  require(j, "direction", path);
  patch.ruled.curve = r.vectorTerms(j, "curve", path);
  patch.ruled.direction = r.vectorTerms(j, "direction", path);
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
  if (text.size() > kMaxSceneBytes) throw Error(ErrorCode::ParseError, "scene larger than 1 MiB");
  checkNesting(text);
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::parse_error& e) {
    throw Error(ErrorCode::ParseError, std::string("malformed JSON at byte ") + std::to_string(e.byte));
  }
  if (!doc.is_object()) fail(ErrorCode::InvalidField, "scene", "expected an object");
  const json& format = require(doc, "format", "scene");
  if (!format.is_string() || format.get<std::string>() != "pdesurf-scene")
    fail(ErrorCode::InvalidField, "format", "expected \"pdesurf-scene\"");
  const json& version = require(doc, "version", "scene");
  if (!version.is_number_integer() || version.get<long long>() != 1)
    fail(ErrorCode::InvalidField, "version", "this build reads scene version 1");
  allowOnly(doc, "scene", {"format", "version", "id", "title", "description", "source", "parameters", "patches"});
  Scene scene;
  if (doc.contains("title")) scene.title = stringField(doc["title"], "title");
  if (doc.contains("id")) stringField(doc["id"], "id", 64);
  if (doc.contains("description")) stringField(doc["description"], "description", 2000);
  if (doc.contains("source")) {
    allowOnly(doc["source"], "source", {"paper", "figure", "equation", "note"});
    for (auto it = doc["source"].begin(); it != doc["source"].end(); ++it) stringField(it.value(), "source." + it.key(), 500);
  }
  Resolver r;
  if (doc.contains("parameters")) parseParameters(doc["parameters"], scene, r);
  const json& patches = require(doc, "patches", "scene");
  if (!patches.is_array() || patches.empty()) fail(ErrorCode::InvalidField, "patches", "expected a non-empty array");
  if (patches.size() > kMaxPatches) fail(ErrorCode::InvalidField, "patches", "more than " + std::to_string(kMaxPatches) + " patches");
  std::set<std::string> names;
  for (size_t i = 0; i < patches.size(); ++i) {
    const std::string path = "patches[" + std::to_string(i) + "]";
    const json& pj = patches[i];
    if (!pj.is_object()) fail(ErrorCode::InvalidField, path, "expected an object");
    Patch patch;
    patch.name = stringField(require(pj, "name", path), path + ".name", 64);
    if (patch.name.empty()) fail(ErrorCode::InvalidField, path + ".name", "empty");
    if (!names.insert(patch.name).second) fail(ErrorCode::InvalidField, path + ".name", "duplicate patch name '" + patch.name + "'");
    const std::string kind = stringField(require(pj, "kind", path), path + ".kind");
    if (kind == "pde") {
      patch.kind = PatchKind::Pde;
      parsePde(pj, path, r, patch);
    } else if (kind == "ruled") {
      patch.kind = PatchKind::Ruled;
      parseRuled(pj, path, r, patch);
    } else {
      fail(ErrorCode::InvalidField, path + ".kind", "unknown kind '" + kind + "' (pde, ruled)");
    }
    scene.patches.push_back(std::move(patch));
  }
  for (size_t i = 0; i < scene.patches.size(); ++i) {
    const Meets& m = scene.patches[i].meets;
    if (m.patch.empty()) continue;
    const Patch* target = scene.find(m.patch);
    if (!target || target->kind != PatchKind::Pde)
      fail(ErrorCode::UnknownName, "patches[" + std::to_string(i) + "].meets.patch", "no PDE patch named '" + m.patch + "'");
  }
  return scene;
}

}  // namespace pdesurf
