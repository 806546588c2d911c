// The "pde" patch: operators (one for x, y, z or one each, so mixed order is a scene choice),
// boundary conditions by derivative order, and forces.
#include <algorithm>
#include <cmath>

#include "scene/ends_json.hpp"
#include "scene/expression_fields.hpp"
#include "scene/json_fields.hpp"
#include "scene/patch_parsers.hpp"
#include "scene/scene.hpp"

namespace pdesurf {

using namespace scene_json;

namespace {

constexpr int kMaxForceDegree = 8;

// The names each order accepts, in operator order (alpha[0] first).
const std::vector<std::string>& namesFor(int order) {
  static const std::vector<std::string> second{"s", "t"}, fourth{"b", "c", "d"}, sixth{"a"};
  return order == 2 ? second : order == 4 ? fourth : sixth;
}

// The papers' standard operator of an order (web/state/operator-edit.js has the same):
// what a blend with ends by reference gets when it names no coefficients.
json defaultOperator(int order) {
  if (order == 2) return {{"order", 2}, {"s", 1}, {"t", 1}};
  if (order == 4) return {{"order", 4}, {"b", 1}, {"c", 2}, {"d", 1}};
  return {{"order", 6}, {"a", 1}};
}

// alpha from the named values: order 6 by "a" means (∂²u + a²∂²v)³ (seed 003 Eq. 1).
std::vector<double> alphaOf(const ComponentOperator& op) {
  if (op.names.size() == 1 && op.names[0] == "a") {
    const double a2 = op.values[0] * op.values[0];
    return {1.0, 3 * a2, 3 * a2 * a2, a2 * a2 * a2};
  }
  return op.values;
}

// Parses one operator object; `component` selects x, y or z from 3-arrays (single form).
ComponentOperator parseOperator(const json& o, const std::string& path, const Resolver& r, int component) {
  const json& order = require(o, "order", path);
  const double given = order.is_number() ? order.get<double>() : 0.0;  // 4.0 is 4 (JSON does not tell them apart)
  if (given != 2 && given != 4 && given != 6) fail(ErrorCode::InvalidField, path + ".order", "order must be 2, 4 or 6");
  ComponentOperator op;
  op.order = static_cast<int>(given);
  auto value = [&](const json& j, const std::string& p) {
    return component < 0 || !j.is_array() ? r.number(j, p) : r.perComponent(j, p)[component];
  };
  if (o.contains("coefficients")) {
    allowOnly(o, path, {"order", "coefficients"});
    const json& c = o["coefficients"];
    if (!c.is_array() || static_cast<int>(c.size()) != op.order / 2 + 1)
      fail(ErrorCode::InvalidField, path + ".coefficients",
           "order " + std::to_string(op.order) + " needs " + std::to_string(op.order / 2 + 1) + " coefficients");
    for (size_t k = 0; k < c.size(); ++k) {
      const std::string p = path + ".coefficients[" + std::to_string(k) + "]";
      op.names.push_back("coefficients[" + std::to_string(k) + "]");
      op.values.push_back(value(c[k], p));
    }
  } else {
    const auto& names = namesFor(op.order);
    if (op.order == 2) allowOnly(o, path, {"order", "s", "t"});
    else if (op.order == 4) allowOnly(o, path, {"order", "b", "c", "d"});
    else allowOnly(o, path, {"order", "a"});
    for (const std::string& n : names) {
      op.names.push_back(n);
      op.values.push_back(value(require(o, n.c_str(), path), path + "." + n));
    }
  }
  return op;
}

// `o` is the operator object, `single` whether it serves x, y and z (3-arrays allowed).
void checkLeading(const ComponentOperator& op, const json& o, const std::string& path, int component, bool single) {
  if (alphaOf(op)[0] != 0.0) return;
  const std::string name = op.names[0];
  const json& field = name == "coefficients[0]" ? o["coefficients"][0] : o[name];
  const std::string where = path + "." + name + (single && field.is_array() ? "[" + std::to_string(component) + "]" : "");
  fail(ErrorCode::DegenerateOperator, where,
       name + "_" + kAxis[component] + " = 0 removes the " + std::to_string(op.order) +
           "th u-derivative: the PDE loses its order");
}

// Family terms with an optional polynomial "u" become ForceTerms; "expr" terms (in u and v)
// become GeneralForces.
void parseForce(const json& j, const std::string& path, const Resolver& r, ComponentProblem& cp) {
  if (!j.is_array()) fail(ErrorCode::InvalidField, path, "expected an array of force terms");
  if (j.size() > kMaxTerms) fail(ErrorCode::InvalidField, path, "more than " + std::to_string(kMaxTerms) + " terms");
  for (size_t k = 0; k < j.size(); ++k) {
    const std::string p = path + "[" + std::to_string(k) + "]";
    if (!j[k].is_object()) fail(ErrorCode::InvalidField, p, "expected an object");
    json t = j[k];
    if (t.contains("fn") && t["fn"] == "expr") {
      allowOnly(t, p, {"fn", "expr", "coef"});
      const std::string text = stringField(require(t, "expr", p), p + ".expr", kMaxExpressionLength);
      const double coef = t.contains("coef") ? r.number(t["coef"], p + ".coef") : 1.0;
      Expr e;
      try {
        e = parseExpression(text, r.values, AllowedVariables{true, true});
      } catch (const Error& err) {
        fail(err.code(), p + ".expr", err.what());
      }
      cp.generalForce.push_back({text, multiply(constant(coef), e)});
      continue;
    }
    std::vector<double> poly{1.0};
    if (t.contains("u")) {
      const json& u = t["u"];
      if (!u.is_array() || u.empty() || u.size() > kMaxForceDegree + 1)
        fail(ErrorCode::InvalidField, p + ".u", "expected 1 to " + std::to_string(kMaxForceDegree + 1) + " polynomial coefficients in u");
      poly.clear();
      for (size_t d = 0; d < u.size(); ++d) poly.push_back(r.number(u[d], p + ".u[" + std::to_string(d) + "]"));
      t.erase("u");
    }
    const VTerm term = r.term(t, p, false);
    for (double& c : poly) c *= term.coef;
    cp.force.push_back({term.g, poly});
  }
}

}  // namespace

void parsePdePatch(const json& j, const std::string& path, const Resolver& r, int version, Patch& patch) {
  allowOnly(j, path, {"name", "kind", "v_range", "operator", "boundary", "force", "method", "ends"});
  // Version 3: ends by reference set the order the operator needs (and may leave it out).
  int needed = 0;
  if (j.contains("ends")) {
    if (version < 3) fail(ErrorCode::InvalidField, path + ".ends", "ends by reference need scene version 3");
    needed = parseEnds(j["ends"], path + ".ends", r, version, patch);
  }
  if (j.contains("method")) {
    try {
      patch.method() = parseMethod(stringField(j["method"], path + ".method", 64));
    } catch (const Error& e) {
      fail(e.code(), path + ".method", e.what());
    }
  }
  const auto vr = r.range(j, "v_range", path, 0.0, 2 * M_PI);
  patch.pde().v0 = vr[0];
  patch.pde().v1 = vr[1];

  const std::string op = path + ".operator";
  json withOrder;  // the operator object, given its order when the ends decide it
  if (needed && !j.contains("operator")) withOrder = defaultOperator(needed);
  else withOrder = require(j, "operator", path);
  if (!withOrder.is_object()) fail(ErrorCode::InvalidField, op, "expected an object");
  if (needed && !withOrder.contains("order") && !withOrder.contains("x") && !withOrder.contains("y") && !withOrder.contains("z")) {
    if (withOrder.empty()) withOrder = defaultOperator(needed);
    else withOrder["order"] = needed;
    // Coefficients named for another order (b, c, d kept while an end now asks for curvature).
    for (auto it = withOrder.begin(); it != withOrder.end(); ++it) {
      const auto& names = namesFor(needed);
      if (it.key() == "order" || it.key() == "coefficients" || std::find(names.begin(), names.end(), it.key()) != names.end()) continue;
      std::string list;
      for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
      fail(ErrorCode::InvalidField, op + "." + it.key(),
           "the ends ask for an order-" + std::to_string(needed) + " operator, whose coefficients are " + list +
               " (or coefficients[k]); leave the operator out for the default");
    }
  }
  const json& o = withOrder;
  const bool perComponent = !o.contains("order");
  if (perComponent) allowOnly(o, op, {"x", "y", "z"});
  for (int c = 0; c < 3; ++c) {
    if (perComponent) {
      const std::string cp = op + "." + kAxis[c];
      patch.op()[c] = parseOperator(require(o, kAxis[c], op), cp, r, -1);
      checkLeading(patch.op()[c], o[kAxis[c]], cp, c, false);
    } else {
      patch.op()[c] = parseOperator(o, op, r, c);
      checkLeading(patch.op()[c], o, op, c, true);
    }
    patch.pde().component[c].alpha = alphaOf(patch.op()[c]);
    if (patch.op()[c].order < needed) {
      const int end = static_cast<int>(patch.ends()[1].continuity) > static_cast<int>(patch.ends()[0].continuity) && patch.ends()[1].given ? 1 : 0;
      static const char* level[3] = {"position", "tangency", "curvature"};
      fail(ErrorCode::InvalidField, (perComponent ? op + "." + kAxis[c] : op) + ".order",
           std::string(level[static_cast<int>(patch.ends()[end].continuity)]) + " continuity at " + (end ? "u1" : "u0") +
               " needs an order-" + std::to_string(needed) + " operator; " + kAxis[c] + " has order " + std::to_string(patch.op()[c].order));
    }
  }

  const std::string bp = path + ".boundary";
  static const json kNone = json::object();
  const bool allByReference = patch.ends()[0].given && patch.ends()[1].given;
  const json& bnd = allByReference && !j.contains("boundary") ? kNone : require(j, "boundary", path);
  allowOnly(bnd, bp, {"x", "y", "z"});
  for (int k = 0; k < 3; ++k) {
    const int n = patch.op()[k].order / 2;
    ComponentProblem& cp = patch.pde().component[k];
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
      if (patch.ends()[end].given)
        fail(ErrorCode::InvalidField, lp, std::string("end ") + key + " is given by reference (" + path + ".ends." + key + "): its conditions are derived, not typed");
      static const char* kinds[3] = {"X", "dX/du", "d2X/du2"};
      std::string expect = kinds[0];
      for (int i = 1; i < n; ++i) expect += std::string(", ") + kinds[i];
      if (!list.is_array() || list.size() > static_cast<size_t>(n))
        fail(ErrorCode::InvalidField, lp,
             "an order-" + std::to_string(2 * n) + " operator takes at most " + std::to_string(n) + " conditions [" + expect + "]");
      for (size_t i = 0; i < list.size(); ++i) {
        const std::string sp = lp + "[" + std::to_string(i) + "]";
        VExpansion& slot = (end == 0 ? cp.left : cp.right)[i];
        if (version >= 2) slot = slotExpression(list[i], sp, r, i == 0 ? &patch.typedPosition()[end][k] : nullptr);
        else slot = r.terms(list[i], sp);
      }
    }
  }

  if (j.contains("force")) {
    const std::string fp = path + ".force";
    allowOnly(j["force"], fp, {"x", "y", "z"});
    for (int k = 0; k < 3; ++k) {
      if (!j["force"].contains(kAxis[k])) continue;
      const std::string cp = fp + "." + kAxis[k];
      if (version >= 2) forceExpression(j["force"][kAxis[k]], cp, r, patch.pde().component[k]);
      else parseForce(j["force"][kAxis[k]], cp, r, patch.pde().component[k]);
    }
  }
}

}  // namespace pdesurf
