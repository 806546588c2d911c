// Scalar expressions in scene fields ("2*a^2", "-30*pi/180"): the expression grammar of
// expr/parse.hpp without variables, folded to one number.
#pragma once
#include <string>

#include "expr/parse.hpp"

namespace pdesurf {

// Throws Error(ParseError | UnknownName | NonFinite).
double evaluateExpression(const std::string& text, const ParameterValues& parameters);

}  // namespace pdesurf
