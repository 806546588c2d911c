// Text -> expression tree. Grammar (precedence low to high): sum (+ -), product (* /),
// unary (+ -), power (^, right associative, binds tighter than unary minus: -a^2 = -(a^2)),
// primary (number, name, name(expr), (expr)). Names are the given parameters (folded in as
// constants), pi, e, and the allowed variables v and u. Errors carry the 1-based column:
// "col 7: unknown function 'cso'".
#pragma once
#include <map>
#include <string>

#include "expr/expr.hpp"

namespace pdesurf {

using ParameterValues = std::map<std::string, double>;

constexpr size_t kMaxExpressionLength = 1000;
constexpr int kMaxExpressionDepth = 64;

struct AllowedVariables {
  bool v = false, u = false;
  const char* uName = "u";  // the second variable's name: u in forces, t in primary surfaces
};

// Throws Error(ParseError | UnknownName | NonFinite).
Expr parseExpression(const std::string& text, const ParameterValues& parameters, AllowedVariables allowed);

}  // namespace pdesurf
