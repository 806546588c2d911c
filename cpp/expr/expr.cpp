#include "expr/expr.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace pdesurf {

namespace {

using Op = ExprNode::Op;

Expr make(Op op, const Expr& a, const Expr& b = nullptr) {
  auto n = std::make_shared<ExprNode>();
  n->op = op;
  n->a = a;
  n->b = b;
  return n;
}

bool isValue(const Expr& e, double c) { return e->op == Op::Const && e->value == c; }

}  // namespace

Expr constant(double c) {
  auto n = std::make_shared<ExprNode>();
  n->value = c;
  return n;
}

Expr variable(ExprVar v) {
  auto n = std::make_shared<ExprNode>();
  n->op = Op::Var;
  n->var = v;
  return n;
}

Expr negate(const Expr& a) {
  if (a->op == Op::Const) return constant(-a->value);
  if (a->op == Op::Neg) return a->a;
  return make(Op::Neg, a);
}

Expr add(const Expr& a, const Expr& b) {
  if (a->op == Op::Const && b->op == Op::Const) return constant(a->value + b->value);
  if (isValue(a, 0)) return b;
  if (isValue(b, 0)) return a;
  return make(Op::Add, a, b);
}

Expr subtract(const Expr& a, const Expr& b) {
  if (a->op == Op::Const && b->op == Op::Const) return constant(a->value - b->value);
  if (isValue(b, 0)) return a;
  if (isValue(a, 0)) return negate(b);
  return make(Op::Sub, a, b);
}

Expr multiply(const Expr& a, const Expr& b) {
  if (a->op == Op::Const && b->op == Op::Const) return constant(a->value * b->value);
  if (isValue(a, 0) || isValue(b, 0)) return constant(0.0);
  if (isValue(a, 1)) return b;
  if (isValue(b, 1)) return a;
  if (isValue(a, -1)) return negate(b);
  if (isValue(b, -1)) return negate(a);
  return make(Op::Mul, a, b);
}

Expr divide(const Expr& a, const Expr& b) {
  if (a->op == Op::Const && b->op == Op::Const) return constant(a->value / b->value);
  if (isValue(a, 0)) return constant(0.0);
  if (isValue(b, 1)) return a;
  return make(Op::Div, a, b);
}

Expr power(const Expr& a, const Expr& b) {
  if (a->op == Op::Const && b->op == Op::Const) return constant(std::pow(a->value, b->value));
  if (isValue(b, 0)) return constant(1.0);
  if (isValue(b, 1)) return a;
  return make(Op::Pow, a, b);
}

Expr call(ExprFn f, const Expr& a) {
  if (a->op == Op::Const) return constant(applyFn(f, a->value));
  auto n = std::make_shared<ExprNode>();
  n->op = Op::Call;
  n->fn = f;
  n->a = a;
  return n;
}

const char* exprFnName(ExprFn f) {
  static const char* names[] = {"sqrt", "exp", "log", "sin", "cos", "tan", "asin", "acos", "atan", "sinh", "cosh", "tanh", "abs", "sign", "general"};
  return names[static_cast<int>(f)];
}

bool exprFnFromName(const std::string& name, ExprFn* out) {
  for (int k = 0; k <= static_cast<int>(ExprFn::General); ++k)
    if (name == exprFnName(static_cast<ExprFn>(k))) {
      *out = static_cast<ExprFn>(k);
      return true;
    }
  return false;
}

double applyFn(ExprFn f, double x) {
  switch (f) {
    case ExprFn::Sqrt: return std::sqrt(x);
    case ExprFn::Exp: return std::exp(x);
    case ExprFn::Log: return std::log(x);
    case ExprFn::Sin: return std::sin(x);
    case ExprFn::Cos: return std::cos(x);
    case ExprFn::Tan: return std::tan(x);
    case ExprFn::Asin: return std::asin(x);
    case ExprFn::Acos: return std::acos(x);
    case ExprFn::Atan: return std::atan(x);
    case ExprFn::Sinh: return std::sinh(x);
    case ExprFn::Cosh: return std::cosh(x);
    case ExprFn::Tanh: return std::tanh(x);
    case ExprFn::Abs: return std::abs(x);
    case ExprFn::Sign: return std::isnan(x) ? x : (x > 0) - (x < 0);
    case ExprFn::General: return x;
  }
  return NAN;
}

double evaluate(const ExprNode& e, const double* vars) {
  switch (e.op) {
    case Op::Const: return e.value;
    case Op::Var: return vars[static_cast<int>(e.var)];
    case Op::Neg: return -evaluate(*e.a, vars);
    case Op::Add: return evaluate(*e.a, vars) + evaluate(*e.b, vars);
    case Op::Sub: return evaluate(*e.a, vars) - evaluate(*e.b, vars);
    case Op::Mul: return evaluate(*e.a, vars) * evaluate(*e.b, vars);
    case Op::Div: return evaluate(*e.a, vars) / evaluate(*e.b, vars);
    case Op::Pow: {
      const double base = evaluate(*e.a, vars);
      if (e.b->op == Op::Const) {  // integer powers by multiplication: exact for negative bases
        const double p = e.b->value;
        if (p == 2) return base * base;
        if (p == 3) return base * base * base;
      }
      return std::pow(base, evaluate(*e.b, vars));
    }
    case Op::Call: return applyFn(e.fn, evaluate(*e.a, vars));
  }
  return NAN;
}

bool isConstant(const Expr& e) { return e->op == Op::Const; }

bool dependsOn(const Expr& e, ExprVar v) {
  if (!e) return false;
  if (e->op == Op::Var) return e->var == v;
  return dependsOn(e->a, v) || dependsOn(e->b, v);
}

size_t nodeCount(const Expr& e) { return e ? 1 + nodeCount(e->a) + nodeCount(e->b) : 0; }

namespace {

// Precedence for printing: sum 1, product 2, unary minus 3, power 4, atoms 5.
int precedence(const ExprNode& e) {
  switch (e.op) {
    case Op::Add:
    case Op::Sub: return 1;
    case Op::Mul:
    case Op::Div: return 2;
    case Op::Neg: return 3;
    case Op::Pow: return 4;
    case Op::Const: return e.value < 0 ? 3 : 5;
    default: return 5;
  }
}

std::string number(double x) {
  if (x == 0) return "0";  // -0 (a negated zero condition) reads as 0
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  // Prefer the shortest text that reads back to the same double.
  for (int digits = 1; digits < 17; ++digits) {
    char shorter[32];
    std::snprintf(shorter, sizeof shorter, "%.*g", digits, x);
    if (std::strtod(shorter, nullptr) == x) return shorter;
  }
  return buf;
}

}  // namespace

std::string toText(const Expr& e, const char* vName, const char* uName) {
  auto sub = [&](const Expr& x, int minPrec) {
    const std::string t = toText(x, vName, uName);
    return precedence(*x) < minPrec ? "(" + t + ")" : t;
  };
  switch (e->op) {
    case Op::Const: return number(e->value);
    case Op::Var: return e->var == ExprVar::V ? vName : uName;
    case Op::Neg: return "-" + sub(e->a, 4);
    case Op::Add: return sub(e->a, 1) + " + " + sub(e->b, 2);
    case Op::Sub: return sub(e->a, 1) + " - " + sub(e->b, 2);
    case Op::Mul: return sub(e->a, 2) + "*" + sub(e->b, 3);
    case Op::Div: return sub(e->a, 2) + "/" + sub(e->b, 4);
    case Op::Pow: return sub(e->a, 5) + "^" + sub(e->b, 4);
    case Op::Call: return std::string(exprFnName(e->fn)) + "(" + toText(e->a, vName, uName) + ")";
  }
  return "?";
}

Expr substitute(const Expr& e, ExprVar var, const Expr& by) {
  if (!dependsOn(e, var)) return e;
  switch (e->op) {
    case Op::Var: return by;
    case Op::Neg: return negate(substitute(e->a, var, by));
    case Op::Add: return add(substitute(e->a, var, by), substitute(e->b, var, by));
    case Op::Sub: return subtract(substitute(e->a, var, by), substitute(e->b, var, by));
    case Op::Mul: return multiply(substitute(e->a, var, by), substitute(e->b, var, by));
    case Op::Div: return divide(substitute(e->a, var, by), substitute(e->b, var, by));
    case Op::Pow: return power(substitute(e->a, var, by), substitute(e->b, var, by));
    case Op::Call: return call(e->fn, substitute(e->a, var, by));
    case Op::Const: break;
  }
  return e;
}

Expr substitute(const Expr& e, ExprVar var, double value) { return substitute(e, var, constant(value)); }

Expr derivative(const Expr& e, ExprVar var) {
  if (!dependsOn(e, var)) return constant(0.0);
  const Expr& a = e->a;
  const Expr& b = e->b;
  switch (e->op) {
    case Op::Const: return constant(0.0);
    case Op::Var: return constant(1.0);
    case Op::Neg: return negate(derivative(a, var));
    case Op::Add: return add(derivative(a, var), derivative(b, var));
    case Op::Sub: return subtract(derivative(a, var), derivative(b, var));
    case Op::Mul: return add(multiply(derivative(a, var), b), multiply(a, derivative(b, var)));
    case Op::Div:
      return divide(subtract(multiply(derivative(a, var), b), multiply(a, derivative(b, var))), multiply(b, b));
    case Op::Pow:
      if (!dependsOn(b, var))  // a^c: c a^{c-1} a'
        return multiply(multiply(b, power(a, subtract(b, constant(1.0)))), derivative(a, var));
      // a^b = exp(b log a)
      return multiply(e, add(multiply(derivative(b, var), call(ExprFn::Log, a)), divide(multiply(b, derivative(a, var)), a)));
    case Op::Call: {
      const Expr da = derivative(a, var);
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
  }
  return constant(0.0);
}

}  // namespace pdesurf
