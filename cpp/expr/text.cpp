// Expression text. A DAG written out as a tree can be exponentially long, so printing stops
// at a character limit and marks the cut (kElided).
#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include "expr/expr.hpp"

namespace pdesurf {

const char* const kElided = "\xE2\x80\xA6 (elided)";

namespace {

using Op = ExprNode::Op;

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

struct Full {};
constexpr size_t kMaxPrintDepth = 4000;  // parsed text (1000 characters) is far shallower  // thrown when the text reaches the limit

class Printer {
 public:
  Printer(size_t maxChars, const char* v, const char* u) : max_(maxChars), v_(v), u_(u) {}
  std::string out;

  void put(const std::string& s) {
    out += s;
    if (out.size() > max_) throw Full{};
  }

  void node(const ExprNode& e) {
    // Every operator prints at least one character, so a node deeper than the room left
    // cannot fit: stop before recursing that deep.
    // (and never recurse deeper than kMaxPrintDepth).
    if (e.depth > std::min(kMaxPrintDepth, max_ - std::min(max_, out.size()))) throw Full{};
    switch (e.op) {
      case Op::Const: return put(number(e.value));
      case Op::Var: return put(e.var == ExprVar::V ? v_ : u_);
      case Op::Neg: return put("-"), sub(*e.a, 4);
      case Op::Add: return sub(*e.a, 1), put(" + "), sub(*e.b, 2);
      case Op::Sub: return sub(*e.a, 1), put(" - "), sub(*e.b, 2);
      case Op::Mul: return sub(*e.a, 2), put("*"), sub(*e.b, 3);
      case Op::Div: return sub(*e.a, 2), put("/"), sub(*e.b, 4);
      case Op::Pow: return sub(*e.a, 5), put("^"), sub(*e.b, 4);
      case Op::Call: return put(std::string(exprFnName(e.fn)) + "("), node(*e.a), put(")");
      // Shown, not typed: a B-spline function's coefficients live in the scene's surface.
      case Op::Spline: return put("bspline("), node(*e.a), put(")");
    }
  }

 private:
  void sub(const ExprNode& x, int minPrec) {
    const bool parens = precedence(x) < minPrec;
    if (parens) put("(");
    node(x);
    if (parens) put(")");
  }
  size_t max_;
  const char *v_, *u_;
};

}  // namespace

std::string toTextLimited(const Expr& e, size_t maxChars, const char* vName, const char* uName) {
  Printer p(maxChars, vName, uName);
  try {
    p.node(*e);
  } catch (const Full&) {
    p.out.resize(std::min(p.out.size(), maxChars));
    p.out += kElided;
  }
  return p.out;
}

std::string toText(const Expr& e, const char* vName, const char* uName) { return toTextLimited(e, size_t{1} << 20, vName, uName); }

}  // namespace pdesurf
