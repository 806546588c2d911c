// Expression trees over the variables v and u: parsed once (scene/expression.hpp's grammar,
// parameters folded in as constants), evaluated at many sample points, and differentiated
// symbolically, so a boundary function typed as text has exact v-derivatives for normals and
// for the residuals of the general methods.
#pragma once
#include <memory>
#include <string>

namespace pdesurf {

// V is v; U is the other variable: u in forces, t in primary surfaces.
enum class ExprVar { V = 0, U = 1 };
// General is the identity that keeps its argument out of the closed form (general(exp(v))).
// Sign is abs's derivative: sign(0) = 0, the mean of abs's one-sided derivatives at its kink.
enum class ExprFn { Sqrt, Exp, Log, Sin, Cos, Tan, Asin, Acos, Atan, Sinh, Cosh, Tanh, Abs, Sign, General };

struct ExprNode;
using Expr = std::shared_ptr<const ExprNode>;

struct ExprNode {
  enum class Op { Const, Var, Neg, Add, Sub, Mul, Div, Pow, Call } op = Op::Const;
  double value = 0.0;       // Const
  ExprVar var = ExprVar::V; // Var
  ExprFn fn = ExprFn::Sqrt; // Call
  Expr a, b;                // operands
};

// Builders fold constants and drop neutral elements (0 + x, 1 * x, x ^ 1, …).
Expr constant(double c);
Expr variable(ExprVar v);
Expr negate(const Expr& a);
Expr add(const Expr& a, const Expr& b);
Expr subtract(const Expr& a, const Expr& b);
Expr multiply(const Expr& a, const Expr& b);
Expr divide(const Expr& a, const Expr& b);
Expr power(const Expr& a, const Expr& b);
Expr call(ExprFn f, const Expr& a);

const char* exprFnName(ExprFn f);
bool exprFnFromName(const std::string& name, ExprFn* out);
double applyFn(ExprFn f, double x);

// vars[0] = v, vars[1] = u. May return NaN or inf; callers check.
double evaluate(const ExprNode& e, const double* vars);
bool isConstant(const Expr& e);
bool dependsOn(const Expr& e, ExprVar v);
// d e / d var, simplified by the builders.
Expr derivative(const Expr& e, ExprVar var);
size_t nodeCount(const Expr& e);
// Readable text with the fewest parentheses; varNames[0] for v, varNames[1] for the other.
std::string toText(const Expr& e, const char* vName = "v", const char* uName = "u");
// e with the variable replaced by a number (folded by the builders).
Expr substitute(const Expr& e, ExprVar var, double value);
// e with the variable replaced by an expression (a trimline t = τ(v) put into S(t, v)).
Expr substitute(const Expr& e, ExprVar var, const Expr& by);

}  // namespace pdesurf
