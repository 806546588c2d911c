// An expression DAG compiled to a flat program: one instruction per distinct node, in
// topological order, each writing a register that is reused once its last reader has run.
// run() executes each instruction once over a block of points (a contiguous loop per
// instruction, which the compiler can vectorise), instead of walking the graph per point.
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include "expr/expr.hpp"

namespace pdesurf {

class ExprProgram {
 public:
  explicit ExprProgram(const std::vector<Expr>& roots);
  explicit ExprProgram(const std::vector<const ExprNode*>& roots);

  size_t outputs() const { return rootRegister_.size(); }
  size_t instructions() const { return code_.size(); }
  size_t registers() const { return registers_; }

  // outs[r][i] = root r at (v[i], u[i]), i < n; u may be null (u = 0). NaN and inf pass through.
  void runAll(const double* v, const double* u, size_t n, double* const* outs) const;
  // The single-root form: out[i].
  void run(const double* v, const double* u, size_t n, double* out) const { runAll(v, u, n, &out); }

 private:
  struct Instruction {
    ExprNode::Op op;
    ExprFn fn;
    ExprVar var;
    bool smallPower;  // Pow by the constant 2 or 3: multiplied out, as evaluate() does
    double value;     // Const; the exponent of a small power
    const SplineFn* spline;  // Spline: its function (kept alive by splines_)
    uint32_t out, a, b;
    int group;           // Spline: its basis group (below)
    bool computesBasis;  // Spline: the group's first member, which computes the basis
  };
  // Spline instructions on one knot vector and degree reading one argument share the piece
  // and the p + 1 non-zero basis functions at each point: a NURBS surface is tens of basis
  // and coefficient splines on two knot vectors, so the basis is computed once per point for
  // all of them, and each adds only its p + 1 products (SplineFn::basis / combine).
  struct SplineGroup {
    int degree;
    size_t basisOffset;  // in units of the block: the group's spans, then (p + 1) basis rows
  };
  void compile(const std::vector<const ExprNode*>& roots);
  std::vector<Instruction> code_;
  std::vector<std::shared_ptr<const SplineFn>> splines_;  // the Spline instructions' functions, kept alive
  std::vector<SplineGroup> groups_;
  size_t basisUnits_ = 0;  // Σ over groups of p + 2 (one row of spans, p + 1 of basis values)
  std::vector<uint32_t> rootRegister_;
  uint32_t registers_ = 0;
};

// a^p as evaluate() computes it: exact products for the constant exponents 2 and 3.
double powerValue(double base, const ExprNode& exponent, double p);

}  // namespace pdesurf
