// Expressions over the variables v and u: parsed once (scene/expression.hpp's grammar,
// parameters folded in as constants), evaluated at many sample points, and differentiated
// symbolically, so a boundary function typed as text has exact v-derivatives for normals and
// for the residuals of the general methods.
//
// Expressions are a shared graph (a DAG): every node is interned (hash-consed), so two
// structurally equal subexpressions are the same pointer, and derivative() / substitute()
// visit each distinct node once. Symbolic work is therefore O(distinct nodes), while the same
// expression written out as a tree (toText) can be exponentially longer; see expr/budget.hpp
// for the bound on work and expr/program.hpp for evaluation over many points.
#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace pdesurf {

// V is v; U is the other variable: u in forces, t in primary surfaces.
enum class ExprVar { V = 0, U = 1 };
// General is the identity that keeps its argument out of the closed form (general(exp(v))).
// Sign is abs's derivative: sign(0) = 0, the mean of abs's one-sided derivatives at its kink.
enum class ExprFn { Sqrt, Exp, Log, Sin, Cos, Tan, Asin, Acos, Atan, Sinh, Cosh, Tanh, Abs, Sign, General };

struct ExprNode;
class SplineFn;
using Expr = std::shared_ptr<const ExprNode>;
class ExprProgram;

// Made only by the builders below (interned); read-only once made.
struct ExprNode {
  // Spline: spline(a), a piecewise polynomial in B-spline form (expr/spline.hpp).
  enum class Op { Const, Var, Neg, Add, Sub, Mul, Div, Pow, Call, Spline } op = Op::Const;
  double value = 0.0;       // Const
  ExprVar var = ExprVar::V; // Var
  ExprFn fn = ExprFn::Sqrt; // Call
  Expr a, b;                // operands
  std::shared_ptr<const SplineFn> spline;  // Spline
  // Facts of the graph below this node, set when it is made.
  uint8_t vars = 0;         // bit 0: depends on v, bit 1: on u
  uint32_t depth = 1;       // longest path to a leaf, in nodes
  uint64_t treeSize = 1;    // nodes of the expression written out as a tree (saturates at 2^62)
  // evaluate() on a node whose tree is large runs this program, compiled on first use.
  mutable std::shared_ptr<const ExprProgram> program;
  // Releases long chains without recursion (a derived DAG can be thousands of nodes deep).
  ~ExprNode();
};

// Builders fold constants and drop neutral elements (0 + x, 1 * x, x ^ 1, …), then intern.
// Each node they make is charged to the thread's current ExprBudget, if any (expr/budget.hpp).
Expr constant(double c);
Expr variable(ExprVar v);
Expr negate(const Expr& a);
Expr add(const Expr& a, const Expr& b);
Expr subtract(const Expr& a, const Expr& b);
Expr multiply(const Expr& a, const Expr& b);
Expr divide(const Expr& a, const Expr& b);
Expr power(const Expr& a, const Expr& b);
Expr call(ExprFn f, const Expr& a);
// f(a) for a B-spline function f: nodes are interned on f's identity.
Expr spline(std::shared_ptr<const SplineFn> f, const Expr& a);

const char* exprFnName(ExprFn f);
bool exprFnFromName(const std::string& name, ExprFn* out);
double applyFn(ExprFn f, double x);

// vars[0] = v, vars[1] = u. May return NaN or inf; callers check. A small tree is walked;
// a large DAG runs its compiled program (one pass over its distinct nodes).
// A tree walk costs its tree size; past kTreeWalkMax, a shared DAG runs a compiled program.
constexpr uint64_t kTreeWalkMax = 4096;
double evaluate(const ExprNode& e, const double* vars);
bool isConstant(const Expr& e);
bool dependsOn(const Expr& e, ExprVar v);
// d e / d var, simplified by the builders; each distinct node is differentiated once.
Expr derivative(const Expr& e, ExprVar var);
// Distinct nodes (shared subexpressions counted once).
size_t nodeCount(const Expr& e);
// Readable text with the fewest parentheses; vName for v, uName for the other.
std::string toText(const Expr& e, const char* vName = "v", const char* uName = "u");
// The same, elided past maxChars: the text is cut and ends in kElided ("… (elided)"), which
// does not parse. A DAG's text can be exponentially longer than the DAG.
extern const char* const kElided;
std::string toTextLimited(const Expr& e, size_t maxChars, const char* vName = "v", const char* uName = "u");
// e and its partial derivatives X, X_u, X_v and, with `second`, X_uu, X_uv, X_vv: the orders
// (in u, in v) of kPartialOrders.
constexpr int kPartialOrders[6][2] = {{0, 0}, {1, 0}, {0, 1}, {2, 0}, {1, 1}, {0, 2}};
std::vector<Expr> partialDerivatives(const Expr& e, bool second);
// e with the variable replaced by a number (folded by the builders).
Expr substitute(const Expr& e, ExprVar var, double value);
// e with the variable replaced by an expression (a trimline t = τ(v) put into S(t, v)).
Expr substitute(const Expr& e, ExprVar var, const Expr& by);

}  // namespace pdesurf
