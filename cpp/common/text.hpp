// Text rules shared by the scene reader, the error messages and the CLI's line-based writers.
#pragma once
#include <cstddef>
#include <string>

namespace pdesurf {

// The longest message an Error carries (docs/limits.md): user text embedded in it is clipped.
constexpr size_t kErrorMessageChars = 600;

// The byte length of a control character starting at s[i], 0 if there is none. Control
// characters: C0 (U+0000-U+001F), DEL, C1 (U+0080-U+009F, NEL U+0085 among them) and the line
// and paragraph separators U+2028, U+2029 — everything some reader takes as a line break or
// that no one-line text should hold. s is UTF-8.
size_t controlCharacterAt(const std::string& s, size_t i);

// "U+0085" for the control character at s[i] (controlCharacterAt(s, i) > 0).
std::string codePointName(const std::string& s, size_t i);

// s with every control character replaced by one space (defence in depth for OBJ and PLY lines).
std::string oneLineText(const std::string& s);

// s cut to at most maxBytes bytes, ending in "…" when cut (never inside a UTF-8 sequence).
std::string clipText(const std::string& s, size_t maxBytes);

// s cut to at most maxBytes bytes by dropping its middle ("head … tail"): a message keeps the
// field path it starts with and the reason it ends with.
std::string clipMiddle(const std::string& s, size_t maxBytes);

// A number for a message: 6 significant digits ("0.5", "1e+300"), never %f's hundreds.
std::string numberText(double x);

}  // namespace pdesurf
