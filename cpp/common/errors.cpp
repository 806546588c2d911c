#include "common/errors.hpp"

namespace pdesurf {

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
