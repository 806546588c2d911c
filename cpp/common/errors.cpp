#include "common/errors.hpp"

#include "common/text.hpp"

namespace pdesurf {

Error::Error(ErrorCode code, const std::string& message) : std::runtime_error(clipMiddle(message, kErrorMessageChars)), code_(code) {}

const char* errorCodeName(ErrorCode code) {
  switch (code) {
    case ErrorCode::ParseError: return "ParseError";
    case ErrorCode::InvalidField: return "InvalidField";
    case ErrorCode::UnknownName: return "UnknownName";
    case ErrorCode::NonFinite: return "NonFinite";
    case ErrorCode::DegenerateOperator: return "DegenerateOperator";
    case ErrorCode::GridSize: return "GridSize";
    case ErrorCode::TooLarge: return "TooLarge";
    case ErrorCode::Singular: return "Singular";
    case ErrorCode::Internal: return "Internal";
  }
  return "Internal";
}

}  // namespace pdesurf
