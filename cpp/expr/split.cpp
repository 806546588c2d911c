#include "expr/split.hpp"

#include <cmath>
#include <list>
#include <map>

namespace pdesurf {

namespace {

using Op = ExprNode::Op;
constexpr size_t kMaxProducts = 512;  // past this, give up expanding and keep the expression
// The expansion walks the expression as a tree, and a shared DAG (a derived condition) can be
// exponentially larger as a tree: past this much work (nodes visited, products and factors
// copied), or this deep, the whole expression is kept as the remainder (solved by the general
// methods) instead.
constexpr size_t kMaxWork = 200000;
constexpr uint32_t kMaxDepth = 2000;
struct GiveUp {};
thread_local size_t work = 0;
void visit(size_t units = 1) {
  work += units;
  if (work > kMaxWork) throw GiveUp{};
}

// A factor of a product, in one variable: v^n, or trig/exp of (w x + φ), or opaque.
enum class Kind { Cos, Sin, Exp };
struct Wave {
  Kind kind;
  double w, phi;  // argument w x + phi
};
struct Product {
  double coef = 1.0;
  int power[2] = {0, 0};        // powers of v and s
  std::vector<Wave> waves[2];   // per variable
  std::vector<Expr> opaque;     // anything else, kept as expressions
};
using Sum = std::vector<Product>;

struct Linear {
  bool ok;
  double w, phi;
};

// e = w x + phi for one variable x (and no other variable)?
Linear linearIn(const Expr& e, ExprVar x) {
  visit();
  const ExprVar other = x == ExprVar::V ? ExprVar::U : ExprVar::V;
  if (dependsOn(e, other)) return {false, 0, 0};
  switch (e->op) {
    case Op::Const: return {true, 0, e->value};
    case Op::Var: return {true, 1, 0};
    case Op::Neg: {
      const Linear a = linearIn(e->a, x);
      return {a.ok, -a.w, -a.phi};
    }
    case Op::Add:
    case Op::Sub: {
      const Linear a = linearIn(e->a, x), b = linearIn(e->b, x);
      const double s = e->op == Op::Add ? 1 : -1;
      return {a.ok && b.ok, a.w + s * b.w, a.phi + s * b.phi};
    }
    case Op::Mul: {
      if (isConstant(e->a)) {
        const Linear b = linearIn(e->b, x);
        return {b.ok, e->a->value * b.w, e->a->value * b.phi};
      }
      if (isConstant(e->b)) {
        const Linear a = linearIn(e->a, x);
        return {a.ok, e->b->value * a.w, e->b->value * a.phi};
      }
      return {false, 0, 0};
    }
    case Op::Div:
      if (isConstant(e->b)) {
        const Linear a = linearIn(e->a, x);
        return {a.ok, a.w / e->b->value, a.phi / e->b->value};
      }
      return {false, 0, 0};
    default: return {false, 0, 0};
  }
}

Sum single(const Product& p) { return Sum{p}; }

Sum opaque(const Expr& e) {
  Product p;
  p.opaque.push_back(e);
  return single(p);
}

Sum multiplySums(const Sum& a, const Sum& b, bool* tooBig) {
  if (a.size() * b.size() > kMaxProducts) {
    *tooBig = true;
    return {};
  }
  Sum out;
  for (const Product& x : a)
    for (const Product& y : b) {
      visit(1 + x.opaque.size() + y.opaque.size());
      Product p = x;
      p.coef *= y.coef;
      for (int k = 0; k < 2; ++k) {
        p.power[k] += y.power[k];
        p.waves[k].insert(p.waves[k].end(), y.waves[k].begin(), y.waves[k].end());
      }
      p.opaque.insert(p.opaque.end(), y.opaque.begin(), y.opaque.end());
      out.push_back(p);
    }
  return out;
}

Sum toSum(const Expr& e) {
  visit();
  switch (e->op) {
    case Op::Const: {
      Product p;
      p.coef = e->value;
      return single(p);
    }
    case Op::Var: {
      Product p;
      p.power[static_cast<int>(e->var)] = 1;
      return single(p);
    }
    case Op::Neg: {
      Sum s = toSum(e->a);
      for (Product& p : s) p.coef = -p.coef;
      return s;
    }
    case Op::Add:
    case Op::Sub: {
      Sum a = toSum(e->a), b = toSum(e->b);
      if (a.size() + b.size() > kMaxProducts) return opaque(e);
      for (Product& p : b)
        if (e->op == Op::Sub) p.coef = -p.coef;
      a.insert(a.end(), b.begin(), b.end());
      return a;
    }
    case Op::Mul: {
      bool tooBig = false;
      Sum s = multiplySums(toSum(e->a), toSum(e->b), &tooBig);
      return tooBig ? opaque(e) : s;
    }
    case Op::Div: {
      if (!isConstant(e->b)) return opaque(e);
      Sum s = toSum(e->a);
      for (Product& p : s) p.coef /= e->b->value;
      return s;
    }
    case Op::Pow: {
      const double k = isConstant(e->b) ? e->b->value : -1;
      if (k < 0 || k > 12 || k != std::floor(k)) return opaque(e);
      const Sum base = toSum(e->a);
      Sum out = single(Product{});
      bool tooBig = false;
      for (int i = 0; i < static_cast<int>(k) && !tooBig; ++i) out = multiplySums(out, base, &tooBig);
      return tooBig ? opaque(e) : out;
    }
    case Op::Spline: return opaque(e);  // a B-spline function of v is a general function
    case Op::Call: {
      if (e->fn == ExprFn::General) return opaque(e);  // kept whole: callers look for it
      const bool wave = e->fn == ExprFn::Cos || e->fn == ExprFn::Sin || e->fn == ExprFn::Exp || e->fn == ExprFn::Cosh || e->fn == ExprFn::Sinh;
      if (!wave) return opaque(e);
      for (ExprVar x : {ExprVar::V, ExprVar::U}) {
        const Linear l = linearIn(e->a, x);
        if (!l.ok || l.w == 0) continue;
        const int k = static_cast<int>(x);
        Product p;
        if (e->fn == ExprFn::Cos || e->fn == ExprFn::Sin || e->fn == ExprFn::Exp) {
          p.waves[k].push_back({e->fn == ExprFn::Cos ? Kind::Cos : e->fn == ExprFn::Sin ? Kind::Sin : Kind::Exp, l.w, l.phi});
          return single(p);
        }
        // cosh, sinh as half sums of exponentials
        Product q = p;
        p.coef = 0.5;
        p.waves[k].push_back({Kind::Exp, l.w, l.phi});
        q.coef = e->fn == ExprFn::Cosh ? 0.5 : -0.5;
        q.waves[k].push_back({Kind::Exp, -l.w, -l.phi});
        return Sum{p, q};
      }
      return opaque(e);
    }
  }
  return opaque(e);
}

// The waves of one variable reduced to a sum of single waves (coef, wave); exponentials
// multiply, sines and cosines by the product-to-sum rules. Mixed exp × trig fails.
struct Reduced {
  bool ok = true;
  std::vector<std::pair<double, Wave>> parts;  // Σ coef · wave; an empty wave list means 1
};

Reduced reduceWaves(const std::vector<Wave>& waves) {
  Reduced r;
  bool hasExp = false, hasTrig = false;
  Wave exp{Kind::Exp, 0, 0};
  std::vector<std::pair<double, Wave>> trig{{1.0, Wave{Kind::Cos, 0, 0}}};  // cos(0) = 1
  for (const Wave& w : waves) {
    if (w.kind == Kind::Exp) {
      hasExp = true;
      exp.w += w.w, exp.phi += w.phi;
      continue;
    }
    hasTrig = true;
    std::vector<std::pair<double, Wave>> next;
    for (const auto& [c, t] : trig) {
      const Wave sum{Kind::Cos, t.w + w.w, t.phi + w.phi}, diff{Kind::Cos, t.w - w.w, t.phi - w.phi};
      if (t.kind == Kind::Cos && w.kind == Kind::Cos) {
        next.push_back({c / 2, diff}), next.push_back({c / 2, sum});
      } else if (t.kind == Kind::Sin && w.kind == Kind::Sin) {
        next.push_back({c / 2, diff}), next.push_back({-c / 2, sum});
      } else if (t.kind == Kind::Sin && w.kind == Kind::Cos) {  // sin a cos b = (sin(a+b) + sin(a-b))/2
        next.push_back({c / 2, Wave{Kind::Sin, sum.w, sum.phi}}), next.push_back({c / 2, Wave{Kind::Sin, diff.w, diff.phi}});
      } else {  // cos a sin b = (sin(a+b) - sin(a-b))/2
        next.push_back({c / 2, Wave{Kind::Sin, sum.w, sum.phi}}), next.push_back({-c / 2, Wave{Kind::Sin, diff.w, diff.phi}});
      }
    }
    trig.swap(next);
    if (trig.size() > 1024) {  // a pathological power of sums: leave it to the general methods
      r.ok = false;
      return r;
    }
  }
  if (hasExp && hasTrig) {
    r.ok = false;
    return r;
  }
  if (hasExp) r.parts.push_back({1.0, exp});
  else r.parts = trig;
  return r;
}

// One wave as constant × family function: shifts expanded, cos/sin made even/odd in w.
std::vector<std::pair<double, VFunction>> familyOf(const Wave& w) {
  if (w.kind == Kind::Exp) {
    if (w.w == 0) return {{std::exp(w.phi), VFunction{Family::Poly, 1.0, 0}}};
    return {{std::exp(w.phi), VFunction{Family::Exp, w.w, 0}}};
  }
  const double c = std::cos(w.phi), s = std::sin(w.phi);
  if (w.w == 0) return {{w.kind == Kind::Cos ? c : s, VFunction{Family::Poly, 1.0, 0}}};
  const double sign = w.w < 0 ? -1.0 : 1.0, a = std::abs(w.w);
  const VFunction cw{Family::Cos, a, 0}, sw{Family::Sin, a, 0};
  // cos(wx + φ) = cos φ cos(wx) - sin φ sin(wx); sin(wx + φ) = sin φ cos(wx) + cos φ sin(wx); w < 0 flips sin(wx).
  if (w.kind == Kind::Cos) return {{c, cw}, {-s * sign, sw}};
  return {{s, cw}, {c * sign, sw}};
}

Expr waveExpr(const Wave& w, ExprVar x) {
  const Expr arg = add(multiply(constant(w.w), variable(x)), constant(w.phi));
  return call(w.kind == Kind::Cos ? ExprFn::Cos : w.kind == Kind::Sin ? ExprFn::Sin : ExprFn::Exp, arg);
}

Expr productExpr(const Product& p) {
  Expr e = constant(p.coef);
  for (int k = 0; k < 2; ++k) {
    const ExprVar x = static_cast<ExprVar>(k);
    if (p.power[k] > 0) e = multiply(e, power(variable(x), constant(p.power[k])));
    for (const Wave& w : p.waves[k]) e = multiply(e, waveExpr(w, x));
  }
  for (const Expr& o : p.opaque) e = multiply(e, o);
  return e;
}

}  // namespace

namespace {

Split splitUncached(const Expr& e, bool secondPolynomialOnly);

// Splits made before, by expression (interned: an unchanged field of an edited scene is the
// same node while the last solve holds it); per thread, the most recent kSplitsKept, each
// holding its expression alive so that no other node takes its address.
struct KeptSplit {
  Expr e;
  bool secondPolynomialOnly;
  Split split;
};
constexpr size_t kSplitsKept = 256;

}  // namespace

Split splitExpression(const Expr& e, bool secondPolynomialOnly) {
  thread_local std::list<KeptSplit> kept;  // most recent first
  for (auto it = kept.begin(); it != kept.end(); ++it)
    if (it->e == e && it->secondPolynomialOnly == secondPolynomialOnly) {
      kept.splice(kept.begin(), kept, it);
      return it->split;
    }
  Split out = splitUncached(e, secondPolynomialOnly);
  kept.push_front({e, secondPolynomialOnly, out});
  if (kept.size() > kSplitsKept) kept.pop_back();
  return out;
}

namespace {

Split splitUncached(const Expr& e, bool secondPolynomialOnly) {
  Split out;
  std::map<std::tuple<int, double, int, int, double, int>, size_t> index;  // merge equal terms
  auto addTerm = [&](double coef, const VFunction& fv, const VFunction& fs) {
    if (coef == 0.0) return;
    const auto key = std::make_tuple(static_cast<int>(fv.family), fv.w, fv.n, static_cast<int>(fs.family), fs.w, fs.n);
    const auto it = index.find(key);
    if (it != index.end()) {
      out.terms[it->second].coef += coef;
      return;
    }
    index[key] = out.terms.size();
    out.terms.push_back({coef, fv, fs});
  };
  auto addRemainder = [&](const Product& p) {
    const Expr part = productExpr(p);
    out.remainderParts.push_back(part);
    out.remainder = out.remainder ? add(out.remainder, part) : part;
  };

  Sum sum;
  try {
    work = 0;
    if (e->depth > kMaxDepth || e->treeSize > kMaxWork) throw GiveUp{};  // the walk alone would pass the cap
    sum = toSum(e);
  } catch (const GiveUp&) {
    sum = opaque(e);
  }
  for (const Product& p : sum) {
    if (p.coef == 0.0) continue;
    if (!p.opaque.empty() || (secondPolynomialOnly && !p.waves[1].empty())) {
      addRemainder(p);
      continue;
    }
    const Reduced rv = reduceWaves(p.waves[0]), rs = reduceWaves(p.waves[1]);
    // Each variable: either a power or waves, not both (v cos v is not a family member).
    const bool fits = rv.ok && rs.ok && !(p.power[0] > 0 && !p.waves[0].empty()) && !(p.power[1] > 0 && !p.waves[1].empty());
    if (!fits) {
      addRemainder(p);
      continue;
    }
    auto partsOf = [](const Reduced& r, int powerN, bool hasWaves) {
      std::vector<std::pair<double, VFunction>> parts;
      if (!hasWaves) return std::vector<std::pair<double, VFunction>>{{1.0, VFunction{Family::Poly, 1.0, powerN}}};
      for (const auto& [c, w] : r.parts)
        for (const auto& [k, f] : familyOf(w)) parts.push_back({c * k, f});
      return parts;
    };
    for (const auto& [cv, fv] : partsOf(rv, p.power[0], !p.waves[0].empty()))
      for (const auto& [cs, fs] : partsOf(rs, p.power[1], !p.waves[1].empty())) addTerm(p.coef * cv * cs, fv, fs);
  }
  std::vector<SplitTerm> kept;
  for (const SplitTerm& t : out.terms)
    if (t.coef != 0.0) kept.push_back(t);
  out.terms.swap(kept);
  return out;
}

}  // namespace

}  // namespace pdesurf
