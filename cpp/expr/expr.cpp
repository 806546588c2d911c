#include "expr/expr.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <unordered_map>
#include <vector>

#include "expr/budget.hpp"
#include "expr/program.hpp"
#include "expr/spline.hpp"

namespace pdesurf {

namespace {

using Op = ExprNode::Op;

// The interning table: one entry per distinct live node, keyed on what makes it distinct
// (op, value bits, variable or function, the children's identities). Entries are weak, so the
// table never keeps a node alive; dead entries are swept when the table has doubled.
struct Key {
  uint8_t op, sub;  // sub: the variable or the function
  uint64_t bits;    // the constant's bit pattern (0.0 and -0.0 stay distinct)
  const ExprNode *a, *b;
  bool operator==(const Key& o) const { return op == o.op && sub == o.sub && bits == o.bits && a == o.a && b == o.b; }
};

struct KeyHash {
  size_t operator()(const Key& k) const {
    uint64_t h = k.bits * 0x9E3779B97F4A7C15ull;
    h ^= (reinterpret_cast<uintptr_t>(k.a) + 0x632BE59BD9B4E019ull + (h << 6) + (h >> 2));
    h ^= (reinterpret_cast<uintptr_t>(k.b) + 0x85EBCA77C2B2AE63ull + (h << 6) + (h >> 2));
    h ^= (uint64_t{k.op} << 8 | k.sub) * 0xC2B2AE3D27D4EB4Full;
    return static_cast<size_t>(h ^ (h >> 29));
  }
};

struct Table {
  std::unordered_map<Key, std::weak_ptr<const ExprNode>, KeyHash> map;
  size_t sweepAt = 4096;
};

Table& table() {
  thread_local Table t;
  return t;
}

constexpr uint64_t kTreeSaturated = uint64_t{1} << 62;

Expr intern(Op op, uint8_t sub, double value, const Expr& a, const Expr& b, std::shared_ptr<const SplineFn> fn = nullptr) {
  ExprBudget::charge();
  uint64_t bits = 0;
  std::memcpy(&bits, &value, sizeof bits);
  // A spline node is its function's: the node keeps the function alive, so while an entry's
  // node lives no other function can take its address.
  if (op == Op::Spline) bits = reinterpret_cast<uintptr_t>(fn.get());
  Table& t = table();
  std::weak_ptr<const ExprNode>& slot = t.map[Key{static_cast<uint8_t>(op), sub, bits, a.get(), b.get()}];
  if (Expr live = slot.lock()) return live;
  auto n = std::make_shared<ExprNode>();
  n->op = op;
  n->value = value;
  if (op == Op::Var) n->var = static_cast<ExprVar>(sub), n->vars = static_cast<uint8_t>(1u << sub);
  if (op == Op::Call) n->fn = static_cast<ExprFn>(sub);
  n->spline = std::move(fn);
  n->a = a;
  n->b = b;
  for (const Expr& c : {a, b})
    if (c) {
      n->vars |= c->vars;
      n->depth = std::max(n->depth, c->depth + 1);
      n->treeSize = std::min(kTreeSaturated, n->treeSize + c->treeSize);
    }
  slot = n;
  if (t.map.size() > t.sweepAt) {
    for (auto it = t.map.begin(); it != t.map.end();) it = it->second.expired() ? t.map.erase(it) : std::next(it);
    t.sweepAt = std::max<size_t>(4096, 2 * t.map.size());
  }
  return n;
}

Expr make(Op op, const Expr& a, const Expr& b = nullptr) { return intern(op, 0, 0.0, a, b); }

bool isValue(const Expr& e, double c) { return e->op == Op::Const && e->value == c; }

// Set while a node's children are being released: nodes that die meanwhile hand their own
// children to it instead of recursing. A plain pointer, so thread exit has nothing to order.
thread_local std::vector<Expr>* releasing = nullptr;

}  // namespace

ExprNode::~ExprNode() {
  if (!a && !b) return;
  if (releasing) {
    if (a) releasing->push_back(std::move(a));
    if (b) releasing->push_back(std::move(b));
    return;
  }
  std::vector<Expr> pending;
  releasing = &pending;
  if (a) pending.push_back(std::move(a));
  if (b) pending.push_back(std::move(b));
  while (!pending.empty()) {
    Expr x = std::move(pending.back());
    pending.pop_back();
    x.reset();  // may push its children
  }
  releasing = nullptr;
}

Expr constant(double c) { return intern(Op::Const, 0, c, nullptr, nullptr); }

Expr variable(ExprVar v) { return intern(Op::Var, static_cast<uint8_t>(v), 0.0, nullptr, nullptr); }

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
  return intern(Op::Call, static_cast<uint8_t>(f), 0.0, a, nullptr);
}

Expr spline(std::shared_ptr<const SplineFn> f, const Expr& a) {
  if (a->op == Op::Const) return constant(f->eval(a->value));
  return intern(Op::Spline, 0, 0.0, a, nullptr, std::move(f));
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

namespace {

double walk(const ExprNode& e, const double* vars) {
  switch (e.op) {
    case Op::Const: return e.value;
    case Op::Var: return vars[static_cast<int>(e.var)];
    case Op::Neg: return -walk(*e.a, vars);
    case Op::Add: return walk(*e.a, vars) + walk(*e.b, vars);
    case Op::Sub: return walk(*e.a, vars) - walk(*e.b, vars);
    case Op::Mul: return walk(*e.a, vars) * walk(*e.b, vars);
    case Op::Div: return walk(*e.a, vars) / walk(*e.b, vars);
    case Op::Pow: return powerValue(walk(*e.a, vars), *e.b, e.b->op == Op::Const ? e.b->value : walk(*e.b, vars));
    case Op::Call: return applyFn(e.fn, walk(*e.a, vars));
    case Op::Spline: return e.spline->eval(walk(*e.a, vars));
  }
  return NAN;
}

}  // namespace

double powerValue(double base, const ExprNode& exponent, double p) {
  if (exponent.op == Op::Const) {  // integer powers by multiplication: exact for negative bases
    if (p == 2) return base * base;
    if (p == 3) return base * base * base;
  }
  return std::pow(base, p);
}

double evaluate(const ExprNode& e, const double* vars) {
  if (e.treeSize <= kTreeWalkMax) return walk(e, vars);
  if (!e.program) e.program = std::make_shared<const ExprProgram>(std::vector<const ExprNode*>{&e});
  double out;
  e.program->run(&vars[0], &vars[1], 1, &out);
  return out;
}

bool isConstant(const Expr& e) { return e->op == Op::Const; }

bool dependsOn(const Expr& e, ExprVar v) { return e && (e->vars >> static_cast<int>(v) & 1u); }

}  // namespace pdesurf
