#include "scene/expression.hpp"

namespace pdesurf {

double evaluateExpression(const std::string& text, const ParameterValues& parameters) {
  return parseExpression(text, parameters, AllowedVariables{})->value;  // no variables: a constant
}

}  // namespace pdesurf
