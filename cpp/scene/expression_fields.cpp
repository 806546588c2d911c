#include "scene/expression_fields.hpp"

#include "expr/split.hpp"

namespace pdesurf::scene_json {

namespace {

Expr parseField(const json& j, const std::string& path, const Resolver& r, AllowedVariables vars, std::string* text) {
  if (j.is_number()) {
    *text = j.dump();
    const double x = j.get<double>();
    if (!std::isfinite(x)) fail(ErrorCode::NonFinite, path, "not a finite number");
    return constant(x);
  }
  *text = stringField(j, path, kMaxExpressionLength);
  if (text->empty()) return constant(0.0);
  try {
    return parseExpression(*text, r.values, vars);
  } catch (const Error& e) {
    fail(e.code(), path, e.what());
  }
}

// c·general(f) (or general(f)) with f a single family function of v: (c·k, f).
bool generalOfFamily(const Expr& part, double* coef, VFunction* f) {
  double c = 1.0;
  Expr call = part;
  if (part->op == ExprNode::Op::Mul && isConstant(part->a)) c = part->a->value, call = part->b;
  if (call->op != ExprNode::Op::Call || call->fn != ExprFn::General) return false;
  const Split inner = splitExpression(call->a);
  if (inner.remainder || inner.terms.size() != 1) return false;
  const SplitTerm& t = inner.terms.front();
  if (!(t.s.isPoly() && t.s.n == 0)) return false;
  *coef = c * t.coef;
  *f = t.v;
  return true;
}

}  // namespace

VExpansion slotExpression(const json& j, const std::string& path, const Resolver& r, Expr* parsed) {
  std::string text;
  const Expr e = parseField(j, path, r, AllowedVariables{true, false}, &text);
  if (parsed) *parsed = e;
  return slotFromExpr(e, text);
}

VExpansion slotFromExpr(const Expr& e, const std::string& text) {
  const Split sp = splitExpression(e);
  VExpansion out;
  for (const SplitTerm& t : sp.terms) out.push_back({t.v, t.coef});
  Expr rest;
  for (const Expr& part : sp.remainderParts) {
    double coef;
    VFunction f;
    if (generalOfFamily(part, &coef, &f)) {
      out.push_back({Resolver::asGeneral(f), coef});
      continue;
    }
    rest = rest ? add(rest, part) : part;
  }
  if (rest) {
    VFunction g;
    g.family = Family::General;
    g.general = std::make_shared<GeneralFunction>(text, rest);
    out.push_back({g, 1.0});
  }
  return out;
}

void forceExpression(const json& j, const std::string& path, const Resolver& r, ComponentProblem& cp) {
  std::string text;
  const Split sp = splitExpression(parseField(j, path, r, AllowedVariables{true, true}, &text), true);
  for (const SplitTerm& t : sp.terms) {
    std::vector<double> poly(t.s.n + 1, 0.0);
    poly[t.s.n] = t.coef;
    cp.force.push_back({t.v, poly});
  }
  if (sp.remainder) cp.generalForce.push_back({text, sp.remainder});
}

Expr surfaceField(const json& j, const std::string& path, const Resolver& r) {
  std::string text;
  AllowedVariables vars{true, true};
  vars.uName = "t";
  return parseField(j, path, r, vars, &text);
}

namespace {

constexpr uint8_t kV = 1u << static_cast<int>(ExprVar::V), kT = 1u << static_cast<int>(ExprVar::U);

void factorsOf(const Expr& e, std::vector<Expr>& out) {
  if (e->op == ExprNode::Op::Mul) {
    factorsOf(e->a, out);
    factorsOf(e->b, out);
    return;
  }
  out.push_back(e);
}

// e as ± its additive parts.
void summandsOf(const Expr& e, double sign, std::vector<std::pair<double, Expr>>& out) {
  if (e->op == ExprNode::Op::Add) return summandsOf(e->a, sign, out), summandsOf(e->b, sign, out);
  if (e->op == ExprNode::Op::Sub) return summandsOf(e->a, sign, out), summandsOf(e->b, -sign, out);
  if (e->op == ExprNode::Op::Neg) return summandsOf(e->a, -sign, out);
  out.push_back({sign, e});
}

// sign·c·T(t)·g(v), T made of family functions of t and g anything of v (a wing's profile
// curve, a product the split gave up on): separable still, with g a general function of v
// (families when it splits), so drawing evaluates g once per grid line instead of the whole
// part at every point. False (nothing added) when it is not of that form.
bool separateOverV(double sign, const Expr& part, std::vector<PrimaryTerm>& terms) {
  std::vector<Expr> factors;
  factorsOf(part, factors);
  Expr vPart = constant(1.0), tPart = constant(sign);
  for (const Expr& f : factors) {
    if ((f->vars & kV) && (f->vars & kT)) return false;
    if (f->vars & kT) tPart = multiply(tPart, f);
    else vPart = multiply(vPart, f);
  }
  const Split ts = splitExpression(tPart);  // t is the split's second variable
  if (ts.remainder) return false;
  for (const SplitTerm& s : ts.terms)
    if (!(s.v.isPoly() && s.v.n == 0)) return false;
  const Split vs = splitExpression(vPart);
  bool vFamilies = !vs.remainder;
  for (const SplitTerm& s : vs.terms) vFamilies = vFamilies && s.s.isPoly() && s.s.n == 0;
  std::vector<PrimaryTerm> added;
  if (vFamilies) {
    for (const SplitTerm& a : ts.terms)
      for (const SplitTerm& b : vs.terms) added.push_back({a.s, b.v, a.coef * b.coef});
  } else {
    VFunction g;
    g.family = Family::General;
    g.general = std::make_shared<GeneralFunction>(toTextLimited(vPart, 200), vPart);
    for (const SplitTerm& a : ts.terms) added.push_back({a.s, g, a.coef});
  }
  terms.insert(terms.end(), added.begin(), added.end());
  return true;
}

}  // namespace

void splitSurface(const Expr& e, std::vector<PrimaryTerm>& terms, Expr* pointwise) {
  const Split sp = splitExpression(e);
  for (const SplitTerm& t : sp.terms) terms.push_back({t.s, t.v, t.coef});
  if (!sp.remainder) return void(*pointwise = nullptr);
  // What did not split, summand by summand: separable over v where it can be, else pointwise.
  std::vector<std::pair<double, Expr>> summands;
  for (const Expr& part : sp.remainderParts) summandsOf(part, 1.0, summands);
  std::vector<PrimaryTerm> separated;
  Expr rest;
  for (const auto& [sign, part] : summands) {
    if (separateOverV(sign, part, separated)) continue;
    const Expr signed_ = sign > 0 ? part : negate(part);
    rest = rest ? add(rest, signed_) : signed_;
  }
  // Nothing separated: the remainder as the split made it (the same node, the same drawing).
  if (separated.empty()) return void(*pointwise = sp.remainder);
  terms.insert(terms.end(), separated.begin(), separated.end());
  *pointwise = rest;
}

}  // namespace pdesurf::scene_json
