// Error model of the core: every failure is a pdesurf::Error with a code and a message that
// names the offending field. Numeric kernels never throw; parsing and solving set-up do.
#pragma once
#include <stdexcept>
#include <string>

namespace pdesurf {

enum class ErrorCode {
  ParseError,          // malformed JSON or expression text
  InvalidField,        // a field has the wrong type, range, or is unknown/missing
  UnknownName,         // a parameter or function name that does not exist
  NonFinite,           // a number or a sampled value is NaN or infinite
  DegenerateOperator,  // the PDE loses its order in u (leading coefficient zero)
  GridSize,            // grid outside 1..2048 per direction
  TooLarge,            // input or work over a limit of common/limits.hpp (docs/limits.md)
  Singular,            // the boundary-value problem has no unique solution (resonance)
  Internal,            // a bug: please report
};

const char* errorCodeName(ErrorCode code);

class Error : public std::runtime_error {
 public:
  // The message is clipped to kErrorMessageChars (common/text.hpp): it may embed user text.
  Error(ErrorCode code, const std::string& message);
  ErrorCode code() const { return code_; }

 private:
  ErrorCode code_;
};

// An error at a field of the scene: "patches[2].ends.u0: why".
[[noreturn]] inline void fail(ErrorCode code, const std::string& path, const std::string& why) { throw Error(code, path + ": " + why); }

// f(), with an Error it throws named by the patch it concerns: "patch 'blend': why".
template <class F>
auto inPatch(const std::string& name, F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const Error& e) {
    throw Error(e.code(), "patch '" + name + "': " + e.what());
  }
}

}  // namespace pdesurf
