// Scalar arithmetic expressions over named parameters, e.g. "sqrt(2)/2*a", "-30*pi/180".
// Grammar (precedence low to high): sum (+ -), product (* /), unary (+ -), power (^, right
// associative, binds tighter than unary minus), primary (number, name, name(expr), (expr)).
// Errors carry the 1-based column: "col 7: unknown function 'cso'".
#pragma once
#include <map>
#include <string>

namespace pdesurf {

using ParameterValues = std::map<std::string, double>;

constexpr size_t kMaxExpressionLength = 1000;
constexpr int kMaxExpressionDepth = 64;

// Throws Error(ParseError | UnknownName | NonFinite).
double evaluateExpression(const std::string& text, const ParameterValues& parameters);

}  // namespace pdesurf
