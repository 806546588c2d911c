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

void splitSurface(const Expr& e, std::vector<PrimaryTerm>& terms, Expr* pointwise) {
  const Split sp = splitExpression(e);
  for (const SplitTerm& t : sp.terms) terms.push_back({t.s, t.v, t.coef});
  *pointwise = sp.remainder;
}

}  // namespace pdesurf::scene_json
