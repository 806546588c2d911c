// Interval arithmetic over expressions: an enclosure of every value an expression takes on a
// box of (v, u), for the certified bounds of the B-spline fit (cad/derivative_bounds.hpp).
// Each operation widens its result outward by one ulp per bound (libm is not correctly
// rounded), so the enclosure holds in floating point. An expression that may be undefined on
// the box (a pole, log or sqrt of a range reaching below 0, asin outside [-1, 1]) gives the
// whole line, [-inf, inf]: callers then subdivide or give up.
#pragma once
#include <vector>

#include "expr/expr.hpp"

namespace pdesurf {

struct Interval {
  double lo = 0.0, hi = 0.0;
  bool bounded() const;  // both ends finite
  double magnitude() const;  // max |x| over the interval (inf when unbounded)
};

// An expression compiled for enclosures: its distinct nodes in an order where operands come
// first, so each enclosure is one pass over an array (no recursion, no hashing).
class IntervalProgram {
 public:
  explicit IntervalProgram(const Expr& e);
  // vars[0] = v's interval, vars[1] = u's.
  Interval run(const Interval* vars) const;
  size_t steps() const { return steps_.size(); }

 private:
  struct Step {
    const ExprNode* node;
    int a = -1, b = -1;  // operands' steps
  };
  std::vector<Step> steps_;
  mutable std::vector<Interval> values_;
};

// One enclosure (compiles, runs once).
Interval enclose(const Expr& e, const Interval* vars);

}  // namespace pdesurf
