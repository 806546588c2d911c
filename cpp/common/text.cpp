#include "common/text.hpp"

#include <cstdio>

namespace pdesurf {

size_t controlCharacterAt(const std::string& s, size_t i) {
  const auto at = [&](size_t k) { return k < s.size() ? static_cast<unsigned char>(s[k]) : 0u; };
  const unsigned c = at(i);
  if (c < 0x20 || c == 0x7f) return 1;
  if (c == 0xc2 && at(i + 1) >= 0x80 && at(i + 1) <= 0x9f) return 2;                      // C1
  if (c == 0xe2 && at(i + 1) == 0x80 && (at(i + 2) == 0xa8 || at(i + 2) == 0xa9)) return 3;  // U+2028, U+2029
  return 0;
}

std::string codePointName(const std::string& s, size_t i) {
  const size_t n = controlCharacterAt(s, i);
  unsigned cp = static_cast<unsigned char>(s[i]);
  if (n == 2) cp = ((cp & 0x1f) << 6) | (static_cast<unsigned char>(s[i + 1]) & 0x3f);
  if (n == 3) cp = ((cp & 0x0f) << 12) | ((static_cast<unsigned char>(s[i + 1]) & 0x3f) << 6) | (static_cast<unsigned char>(s[i + 2]) & 0x3f);
  char out[16];
  std::snprintf(out, sizeof out, "U+%04X", cp);
  return out;
}

std::string oneLineText(const std::string& s) {
  std::string out;
  out.reserve(s.size());
  for (size_t i = 0; i < s.size();) {
    const size_t n = controlCharacterAt(s, i);
    if (n) {
      out += ' ';
      i += n;
    } else {
      out += s[i++];
    }
  }
  return out;
}

namespace {
const std::string kEllipsis = "\xe2\x80\xa6";  // U+2026
bool continuationByte(const std::string& s, size_t i) { return i < s.size() && (static_cast<unsigned char>(s[i]) & 0xc0) == 0x80; }
}  // namespace

std::string clipText(const std::string& s, size_t maxBytes) {
  if (s.size() <= maxBytes) return s;
  size_t cut = maxBytes > kEllipsis.size() ? maxBytes - kEllipsis.size() : 0;
  while (cut > 0 && continuationByte(s, cut)) --cut;  // not inside a UTF-8 sequence
  return s.substr(0, cut) + kEllipsis;
}

std::string clipMiddle(const std::string& s, size_t maxBytes) {
  if (s.size() <= maxBytes) return s;
  const size_t keep = maxBytes > kEllipsis.size() ? maxBytes - kEllipsis.size() : 0;
  size_t head = keep * 2 / 3, tail = s.size() - (keep - head);
  while (head > 0 && continuationByte(s, head)) --head;
  while (continuationByte(s, tail)) ++tail;
  return s.substr(0, head) + kEllipsis + s.substr(tail);
}

std::string numberText(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}

}  // namespace pdesurf
