// Shared by the scene parsers: field-path errors, strict objects, and the resolver that turns
// numbers-or-expressions and term lists into values.
#pragma once
#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <initializer_list>
#include <string>

#include "common/errors.hpp"
#include "common/text.hpp"
#include "pde/pde_problem.hpp"
#include "basis/general_function.hpp"
#include "scene/expression.hpp"

namespace pdesurf::scene_json {

// The work of a scene's Bézier patches so far (limits::kBezierAssembly, limits::kFieldSampling).
struct BezierWork {
  size_t assembly = 0;  // assembly and factorisation units (bezierAssemblyWork)
  size_t sampling = 0;  // normal-field samples × the operations of their expressions
};

using json = nlohmann::json;
constexpr int kMaxTerms = 256;
constexpr int kMaxPower = 24;
inline const char* const kAxis[3] = {"x", "y", "z"};

using ::pdesurf::fail;

inline void allowOnly(const json& obj, const std::string& path, std::initializer_list<const char*> keys) {
  if (!obj.is_object()) fail(ErrorCode::InvalidField, path, "expected an object");
  for (auto it = obj.begin(); it != obj.end(); ++it) {
    bool known = false;
    for (const char* k : keys) known = known || it.key() == k;
    if (!known) fail(ErrorCode::InvalidField, path + "." + it.key(), "unknown field");
  }
}

inline const json& require(const json& obj, const char* key, const std::string& path) {
  const auto it = obj.find(key);
  if (it == obj.end()) fail(ErrorCode::InvalidField, path + "." + key, "missing");
  return *it;
}

// One line of text: control characters are refused, C1 (NEL U+0085) and U+2028, U+2029
// included (common/text.hpp: a reader that splits lines there would see a name in an OBJ file
// start a line of its own); multiLine allows newlines and tabs (descriptions, notes). Over
// maxLen is a size limit: TooLarge.
inline std::string stringField(const json& j, const std::string& path, size_t maxLen = 200, bool multiLine = false) {
  if (!j.is_string()) fail(ErrorCode::InvalidField, path, "expected a string");
  const std::string s = j.get<std::string>();
  if (s.size() > maxLen) fail(ErrorCode::TooLarge, path, "longer than " + std::to_string(maxLen) + " characters");
  for (size_t i = 0; i < s.size(); ++i)
    if (controlCharacterAt(s, i) && !(multiLine && (s[i] == '\n' || s[i] == '\t')))
      fail(ErrorCode::InvalidField, path,
           "a control character " + codePointName(s, i) + (multiLine ? " (only newline and tab are allowed)" : " (names and titles are one line)"));
  return s;
}

// An integer in lo..hi, read without wrapping (get<int> would read 4294967297 as 1). A number
// written with a fraction or an exponent whose value is a whole number (4.0, 4e0) is that
// integer: JSON does not tell them apart, nor does the page, which writes 4.0 as 4.
inline int integerField(const json& j, const std::string& path, long long lo, long long hi) {
  bool ok = false;
  long long v = 0;
  if (j.is_number_unsigned()) {
    const auto u = j.get<unsigned long long>();
    ok = u <= static_cast<unsigned long long>(hi);
    v = ok ? static_cast<long long>(u) : 0;
  } else if (j.is_number_integer()) {
    v = j.get<long long>();
    ok = true;
  } else if (j.is_number_float()) {
    const double d = j.get<double>();
    ok = d >= static_cast<double>(lo) && d <= static_cast<double>(hi) && d == static_cast<double>(static_cast<long long>(d));
    v = ok ? static_cast<long long>(d) : 0;
  }
  if (!ok || v < lo || v > hi)
    fail(ErrorCode::InvalidField, path, "expected an integer in " + std::to_string(lo) + ".." + std::to_string(hi));
  return static_cast<int>(v);
}

class Resolver {
 public:
  ParameterValues values;

  double number(const json& j, const std::string& path) const {
    double v = 0;
    if (j.is_number()) {
      v = j.get<double>();
    } else if (j.is_string()) {
      if (j.get_ref<const std::string&>().size() > kMaxExpressionLength)  // a size limit, before the parser sees it
        fail(ErrorCode::TooLarge, path, "longer than " + std::to_string(kMaxExpressionLength) + " characters");
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

  // allowGeneral: whether "expr" terms and the "general" flag are accepted (not for factors of t).
  VExpansion terms(const json& j, const std::string& path, bool allowGeneral = true) const {
    if (!j.is_array()) fail(ErrorCode::InvalidField, path, "expected an array of terms");
    if (j.size() > kMaxTerms) fail(ErrorCode::InvalidField, path, "more than " + std::to_string(kMaxTerms) + " terms");
    VExpansion out;
    for (size_t k = 0; k < j.size(); ++k) out.push_back(term(j[k], path + "[" + std::to_string(k) + "]", allowGeneral));
    return out;
  }

  VTerm term(const json& t, const std::string& p, bool allowGeneral) const {
    allowOnly(t, p, {"fn", "coef", "w", "n", "expr", "general"});
    VTerm term;
    const std::string fn = stringField(require(t, "fn", p), p + ".fn");
    if (!familyFromName(fn, &term.g.family))
      fail(ErrorCode::UnknownName, p + ".fn", "unknown basis function '" + fn + "' (poly, cos, sin, exp, cosh, sinh, expr)");
    if (t.contains("coef")) term.coef = number(t["coef"], p + ".coef");
    if (term.g.isGeneral()) {
      if (!allowGeneral) fail(ErrorCode::InvalidField, p + ".fn", "an expression is not allowed here");
      for (const char* k : {"w", "n", "general"})
        if (t.contains(k)) fail(ErrorCode::InvalidField, p + "." + k, "an expr term takes only \"expr\" and \"coef\"");
      const std::string text = stringField(require(t, "expr", p), p + ".expr", kMaxExpressionLength);
      Expr e;
      try {
        e = parseExpression(text, values, AllowedVariables{true, false});
      } catch (const Error& err) {
        fail(err.code(), p + ".expr", err.what());
      }
      term.g.general = std::make_shared<GeneralFunction>(text, e);
      return term;
    }
    if (t.contains("expr")) fail(ErrorCode::InvalidField, p + ".expr", "only fn \"expr\" terms take an expression");
    if (term.g.isPoly()) {
      if (t.contains("w")) fail(ErrorCode::InvalidField, p + ".w", "a polynomial term has a power n, not a frequency w");
      if (t.contains("n")) {
        term.g.n = integerField(t["n"], p + ".n", 0, kMaxPower);
      }
    } else {
      if (t.contains("n")) fail(ErrorCode::InvalidField, p + ".n", "only poly terms have a power n");
      if (t.contains("w")) term.g.w = number(t["w"], p + ".w");
    }
    if (t.contains("general")) {
      // Solve this family term as if it had no closed form (seed 000 Section 3 treats e^v so).
      if (!allowGeneral) fail(ErrorCode::InvalidField, p + ".general", "not allowed here");
      if (!t["general"].is_boolean()) fail(ErrorCode::InvalidField, p + ".general", "expected true or false");
      if (t["general"].get<bool>()) term.g = asGeneral(term.g);
    }
    return term;
  }

  // The same function as a general (expression) one.
  static VFunction asGeneral(const VFunction& f) {
    Expr e;
    const Expr v = variable(ExprVar::V);
    if (f.isPoly()) {
      e = power(v, constant(f.n));
    } else {
      const Expr wv = multiply(constant(f.w), v);
      static const ExprFn fns[] = {ExprFn::Cos, ExprFn::Cos, ExprFn::Sin, ExprFn::Exp, ExprFn::Cosh, ExprFn::Sinh};
      e = call(fns[static_cast<int>(f.family)], wv);
    }
    VFunction g;
    g.family = Family::General;
    auto general = std::make_shared<GeneralFunction>(
        f.isPoly() ? "v^" + std::to_string(f.n) : std::string(familyName(f.family)) + "(" + std::to_string(f.w) + "*v)", e);
    general->hasOrigin = true;
    general->origin = f;
    g.general = general;
    return g;
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

}  // namespace pdesurf::scene_json
