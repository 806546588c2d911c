#include "expr/program.hpp"

#include "expr/spline.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace pdesurf {

using Op = ExprNode::Op;

ExprProgram::ExprProgram(const std::vector<Expr>& roots) {
  std::vector<const ExprNode*> r;
  for (const Expr& e : roots) r.push_back(e.get());
  compile(r);
}

ExprProgram::ExprProgram(const std::vector<const ExprNode*>& roots) { compile(roots); }

void ExprProgram::compile(const std::vector<const ExprNode*>& roots) {
  // Topological order (children first), without recursion.
  std::vector<const ExprNode*> order;
  std::unordered_map<const ExprNode*, uint32_t> index;  // node -> position in order
  {
    std::unordered_map<const ExprNode*, bool> seen;
    std::vector<std::pair<const ExprNode*, bool>> stack;
    for (const ExprNode* r : roots) stack.push_back({r, false});
    while (!stack.empty()) {
      const auto [n, done] = stack.back();
      stack.pop_back();
      if (done) {
        index[n] = static_cast<uint32_t>(order.size());
        order.push_back(n);
        continue;
      }
      if (!seen.emplace(n, true).second) continue;
      stack.push_back({n, true});
      if (n->b && !seen.count(n->b.get())) stack.push_back({n->b.get(), false});
      if (n->a && !seen.count(n->a.get())) stack.push_back({n->a.get(), false});
    }
  }
  // Readers left per node; roots are read at the end, so they are never freed.
  std::vector<uint32_t> readers(order.size(), 0);
  for (const ExprNode* n : order) {
    if (n->a) ++readers[index[n->a.get()]];
    if (n->b) ++readers[index[n->b.get()]];
  }
  for (const ExprNode* r : roots) readers[index[r]] += 1u << 30;
  // Basis groups: (argument node, degree, knots); the first member in program order computes.
  std::vector<std::pair<const ExprNode*, const SplineFn*>> groupKey;
  std::vector<uint32_t> reg(order.size());
  std::vector<uint32_t> freeRegs;
  code_.reserve(order.size());
  for (size_t k = 0; k < order.size(); ++k) {
    const ExprNode& n = *order[k];
    Instruction ins{n.op, n.fn, n.var, false, n.value, n.spline.get(), 0, 0, 0, -1, false};
    if (n.spline) {
      splines_.push_back(n.spline);
      for (size_t g = 0; g < groupKey.size() && ins.group < 0; ++g)
        if (groupKey[g].first == n.a.get() && groupKey[g].second->sameBasis(*n.spline)) ins.group = int(g);
      if (ins.group < 0) {
        ins.group = int(groups_.size()), ins.computesBasis = true;
        groupKey.push_back({n.a.get(), n.spline.get()});
        groups_.push_back({n.spline->degree(), basisUnits_});
        basisUnits_ += size_t(n.spline->degree()) + 2;
      }
    }
    if (n.a) ins.a = reg[index[n.a.get()]];
    if (n.b) ins.b = reg[index[n.b.get()]];
    if (n.op == Op::Pow && n.b->op == Op::Const && (n.b->value == 2 || n.b->value == 3)) ins.smallPower = true, ins.value = n.b->value;
    if (freeRegs.empty()) {
      reg[k] = registers_++;
    } else {
      reg[k] = freeRegs.back();
      freeRegs.pop_back();
    }
    ins.out = reg[k];
    code_.push_back(ins);
    for (const Expr* c : {&n.a, &n.b}) {  // a*a reads its operand twice, and frees it once
      if (!*c) continue;
      const uint32_t ci = index[c->get()];
      if (--readers[ci] == 0) freeRegs.push_back(reg[ci]);
    }
  }
  for (const ExprNode* r : roots) rootRegister_.push_back(reg[index[r]]);
}

namespace {

template <class F>
void map1(double* o, const double* a, size_t m, F f) {
  for (size_t k = 0; k < m; ++k) o[k] = f(a[k]);
}

template <class F>
void map2(double* o, const double* a, const double* b, size_t m, F f) {
  for (size_t k = 0; k < m; ++k) o[k] = f(a[k], b[k]);
}

void callFn(ExprFn fn, double* o, const double* a, size_t m) {
  switch (fn) {
    case ExprFn::Sqrt: return map1(o, a, m, [](double x) { return std::sqrt(x); });
    case ExprFn::Exp: return map1(o, a, m, [](double x) { return std::exp(x); });
    case ExprFn::Log: return map1(o, a, m, [](double x) { return std::log(x); });
    case ExprFn::Sin: return map1(o, a, m, [](double x) { return std::sin(x); });
    case ExprFn::Cos: return map1(o, a, m, [](double x) { return std::cos(x); });
    case ExprFn::Tan: return map1(o, a, m, [](double x) { return std::tan(x); });
    case ExprFn::Asin: return map1(o, a, m, [](double x) { return std::asin(x); });
    case ExprFn::Acos: return map1(o, a, m, [](double x) { return std::acos(x); });
    case ExprFn::Atan: return map1(o, a, m, [](double x) { return std::atan(x); });
    case ExprFn::Sinh: return map1(o, a, m, [](double x) { return std::sinh(x); });
    case ExprFn::Cosh: return map1(o, a, m, [](double x) { return std::cosh(x); });
    case ExprFn::Tanh: return map1(o, a, m, [](double x) { return std::tanh(x); });
    case ExprFn::Abs: return map1(o, a, m, [](double x) { return std::abs(x); });
    case ExprFn::Sign: return map1(o, a, m, [](double x) { return std::isnan(x) ? x : static_cast<double>((x > 0) - (x < 0)); });
    case ExprFn::General: return map1(o, a, m, [](double x) { return x; });
  }
}

}  // namespace

void ExprProgram::runAll(const double* v, const double* u, size_t n, double* const* outs) const {
  // Points per block: the registers of one block stay within ~8 MB whatever the program's width.
  const size_t block = std::max<size_t>(1, std::min({n, size_t{256}, (size_t{1} << 20) / std::max<uint32_t>(1, registers_)}));
  // Every register is written before it is read: the scratch is kept per thread and reused
  // as it is (clearing and allocating it on each call cost as much as a wide program's run).
  thread_local std::vector<double> scratch, bases;
  if (scratch.size() < static_cast<size_t>(registers_) * block) scratch.resize(static_cast<size_t>(registers_) * block);
  if (bases.size() < basisUnits_ * block) bases.resize(basisUnits_ * block);
  for (size_t start = 0; start < n; start += block) {
    const size_t m = std::min(block, n - start);
    for (const Instruction& ins : code_) {
      double* o = scratch.data() + ins.out * block;
      const double* a = scratch.data() + ins.a * block;
      const double* b = scratch.data() + ins.b * block;
      switch (ins.op) {
        case Op::Const: std::fill(o, o + m, ins.value); break;
        case Op::Var: {
          const double* x = ins.var == ExprVar::V ? v : u;
          if (x) std::copy(x + start, x + start + m, o);
          else std::fill(o, o + m, 0.0);
          break;
        }
        case Op::Neg: map1(o, a, m, [](double x) { return -x; }); break;
        case Op::Add: map2(o, a, b, m, [](double x, double y) { return x + y; }); break;
        case Op::Sub: map2(o, a, b, m, [](double x, double y) { return x - y; }); break;
        case Op::Mul: map2(o, a, b, m, [](double x, double y) { return x * y; }); break;
        case Op::Div: map2(o, a, b, m, [](double x, double y) { return x / y; }); break;
        case Op::Pow:
          if (ins.smallPower && ins.value == 2) map1(o, a, m, [](double x) { return x * x; });
          else if (ins.smallPower) map1(o, a, m, [](double x) { return x * x * x; });
          else map2(o, a, b, m, [](double x, double y) { return std::pow(x, y); });
          break;
        case Op::Call: callFn(ins.fn, o, a, m); break;
        case Op::Spline: {
          const SplineGroup& g = groups_[size_t(ins.group)];
          const size_t stride = size_t(g.degree) + 1;
          double* spans = bases.data() + g.basisOffset * block;  // the pieces, as doubles
          double* N = spans + block;                               // stride values per point
          if (ins.computesBasis)
            for (size_t k = 0; k < m; ++k) {
              if (k && a[k] == a[k - 1]) continue;  // a grid line along the other variable: the members copy their last value
              const int piece = ins.spline->span(a[k]);
              spans[k] = piece;
              ins.spline->basis(piece, a[k], N + k * stride);
            }
          for (size_t k = 0; k < m; ++k)
            o[k] = k && a[k] == a[k - 1] ? o[k - 1] : std::isnan(a[k]) ? a[k] : ins.spline->combine(int(spans[k]), N + k * stride);
          break;
        }
      }
    }
    for (size_t r = 0; r < rootRegister_.size(); ++r) {
      const double* x = scratch.data() + rootRegister_[r] * block;
      std::copy(x, x + m, outs[r] + start);
    }
  }
}

}  // namespace pdesurf
