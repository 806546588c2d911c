// derivative, substitute and nodeCount on the DAG: one pass over the distinct nodes in
// topological order, each node's result kept for its parents (memoised per call).
#include "expr/graph.hpp"

#include "expr/spline.hpp"

#include <unordered_map>
#include <unordered_set>

namespace pdesurf {

using Op = ExprNode::Op;

std::vector<const Expr*> topologicalOrder(const std::vector<const Expr*>& roots, int onlyVar) {
  auto keep = [&](const Expr& x) { return x && (onlyVar < 0 || dependsOn(x, static_cast<ExprVar>(onlyVar))); };
  std::vector<const Expr*> order;
  std::unordered_set<const ExprNode*> seen;
  std::vector<std::pair<const Expr*, bool>> stack;  // (node, its children are done)
  for (const Expr* r : roots)
    if (keep(*r)) stack.push_back({r, false});
  while (!stack.empty()) {
    const auto [x, done] = stack.back();
    stack.pop_back();
    if (done) {
      order.push_back(x);
      continue;
    }
    if (!seen.insert(x->get()).second) continue;
    stack.push_back({x, true});
    const ExprNode& n = **x;
    if (keep(n.b) && !seen.count(n.b.get())) stack.push_back({&n.b, false});
    if (keep(n.a) && !seen.count(n.a.get())) stack.push_back({&n.a, false});
  }
  return order;
}

size_t nodeCount(const Expr& e) { return e ? topologicalOrder({&e}).size() : 0; }

Expr substitute(const Expr& e, ExprVar var, const Expr& by) {
  if (!dependsOn(e, var)) return e;
  std::unordered_map<const ExprNode*, Expr> done;
  auto sub = [&](const Expr& x) -> Expr { return dependsOn(x, var) ? done.at(x.get()) : x; };
  for (const Expr* p : topologicalOrder({&e}, static_cast<int>(var))) {
    const Expr& x = *p;
    Expr r;
    switch (x->op) {
      case Op::Var: r = by; break;
      case Op::Neg: r = negate(sub(x->a)); break;
      case Op::Add: r = add(sub(x->a), sub(x->b)); break;
      case Op::Sub: r = subtract(sub(x->a), sub(x->b)); break;
      case Op::Mul: r = multiply(sub(x->a), sub(x->b)); break;
      case Op::Div: r = divide(sub(x->a), sub(x->b)); break;
      case Op::Pow: r = power(sub(x->a), sub(x->b)); break;
      case Op::Call: r = call(x->fn, sub(x->a)); break;
      case Op::Spline: r = spline(x->spline, sub(x->a)); break;
      case Op::Const: r = x; break;
    }
    done.emplace(x.get(), std::move(r));
  }
  return done.at(e.get());
}

Expr substitute(const Expr& e, ExprVar var, double value) { return substitute(e, var, constant(value)); }

namespace {

// d e / d var from the derivatives of its operands (da, db; zero where they do not depend on var).
Expr rule(const Expr& e, const Expr& da, const Expr& db, ExprVar var) {
  const Expr& a = e->a;
  const Expr& b = e->b;
  switch (e->op) {
    case Op::Const: return constant(0.0);
    case Op::Var: return constant(1.0);
    case Op::Neg: return negate(da);
    case Op::Add: return add(da, db);
    case Op::Sub: return subtract(da, db);
    case Op::Mul: return add(multiply(da, b), multiply(a, db));
    case Op::Div: return divide(subtract(multiply(da, b), multiply(a, db)), multiply(b, b));
    case Op::Pow:
      if (!dependsOn(b, var))  // a^c: c a^{c-1} a'
        return multiply(multiply(b, power(a, subtract(b, constant(1.0)))), da);
      // a^b = exp(b log a)
      return multiply(e, add(multiply(db, call(ExprFn::Log, a)), divide(multiply(b, da), a)));
    case Op::Call: {
      Expr outer;
      switch (e->fn) {
        case ExprFn::Sqrt: outer = divide(constant(0.5), e); break;
        case ExprFn::Exp: outer = e; break;
        case ExprFn::Log: outer = divide(constant(1.0), a); break;
        case ExprFn::Sin: outer = call(ExprFn::Cos, a); break;
        case ExprFn::Cos: outer = negate(call(ExprFn::Sin, a)); break;
        case ExprFn::Tan: outer = add(constant(1.0), multiply(e, e)); break;
        case ExprFn::Asin: outer = divide(constant(1.0), call(ExprFn::Sqrt, subtract(constant(1.0), multiply(a, a)))); break;
        case ExprFn::Acos: outer = divide(constant(-1.0), call(ExprFn::Sqrt, subtract(constant(1.0), multiply(a, a)))); break;
        case ExprFn::Atan: outer = divide(constant(1.0), add(constant(1.0), multiply(a, a))); break;
        case ExprFn::Sinh: outer = call(ExprFn::Cosh, a); break;
        case ExprFn::Cosh: outer = call(ExprFn::Sinh, a); break;
        case ExprFn::Tanh: outer = subtract(constant(1.0), multiply(e, e)); break;
        case ExprFn::Abs: outer = call(ExprFn::Sign, a); break;  // 0 at the kink: the one-sided derivatives' mean
        case ExprFn::Sign: return constant(0.0);
        case ExprFn::General: return da;
      }
      return multiply(outer, da);
    }
    case Op::Spline:  // a piecewise constant's derivative is 0 (as sign's, between its jumps)
      return e->spline->derivative() ? multiply(spline(e->spline->derivative(), a), da) : constant(0.0);
  }
  return constant(0.0);
}

}  // namespace

Expr derivative(const Expr& e, ExprVar var) {
  if (!dependsOn(e, var)) return constant(0.0);
  const Expr zero = constant(0.0);
  std::unordered_map<const ExprNode*, Expr> done;
  auto d = [&](const Expr& x) -> const Expr& { return dependsOn(x, var) ? done.at(x.get()) : zero; };
  for (const Expr* p : topologicalOrder({&e}, static_cast<int>(var))) {
    const Expr& x = *p;
    Expr r = rule(x, x->a ? d(x->a) : zero, x->b ? d(x->b) : zero, var);
    done.emplace(x.get(), std::move(r));
  }
  return done.at(e.get());
}

std::vector<Expr> partialDerivatives(const Expr& e, bool second) {
  const Expr eu = derivative(e, ExprVar::U), ev = derivative(e, ExprVar::V);
  if (!second) return {e, eu, ev};
  return {e, eu, ev, derivative(eu, ExprVar::U), derivative(eu, ExprVar::V), derivative(ev, ExprVar::V)};
}

}  // namespace pdesurf
