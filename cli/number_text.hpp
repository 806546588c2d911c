// Output assembled in one large buffer and handed to the stream about once per MiB: no
// iostream formatting and no snprintf per number. Numbers are written with std::to_chars in
// their shortest round-trip form (a double parses back to the same double, a float to the same
// float); binary values are written byte by byte in little-endian order, whatever the host.
#pragma once
#include <algorithm>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <ostream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace pdesurf::cli {

// The longest shortest-form double is 24 characters ("-2.2250738585072014e-308").
constexpr size_t kMaxNumberChars = 32;

inline char* putNumber(char* p, double v) { return std::to_chars(p, p + kMaxNumberChars, v).ptr; }
inline char* putNumber(char* p, float v) { return std::to_chars(p, p + kMaxNumberChars, v).ptr; }
inline char* putNumber(char* p, uint64_t v) { return std::to_chars(p, p + kMaxNumberChars, v).ptr; }
inline char* putNumber(char* p, int v) { return std::to_chars(p, p + kMaxNumberChars, v).ptr; }

inline char* putU8(char* p, uint8_t v) {
  *p = static_cast<char>(v);
  return p + 1;
}
inline char* putU16(char* p, uint16_t v) {
  p[0] = static_cast<char>(v & 0xff);
  p[1] = static_cast<char>(v >> 8);
  return p + 2;
}
// The compiler merges these byte stores into one store on a little-endian host.
inline char* putU32(char* p, uint32_t v) {
  p[0] = static_cast<char>(v & 0xff);
  p[1] = static_cast<char>((v >> 8) & 0xff);
  p[2] = static_cast<char>((v >> 16) & 0xff);
  p[3] = static_cast<char>(v >> 24);
  return p + 4;
}
inline char* putF32(char* p, float v) {
  uint32_t bits;
  std::memcpy(&bits, &v, 4);
  return putU32(p, bits);
}

// A number's text kept for reuse (values that repeat along a grid row or column).
struct NumberText {
  char text[kMaxNumberChars];
  uint8_t size = 0;
  template <class T>
  void set(T v) { size = static_cast<uint8_t>(putNumber(text, v) - text); }
  char* put(char* p) const {
    std::memcpy(p, text, kMaxNumberChars);  // fixed size: one copy; the buffer has slack
    return p + size;
  }
};

class OutBuffer {
 public:
  // `what` names the destination in errors ("cannot write 'x.stl'").
  OutBuffer(std::ostream& out, std::string what, size_t capacity = size_t(1) << 20)
      : out_(out), what_(std::move(what)), buf_(capacity + kSlack), capacity_(capacity) {}
  OutBuffer(const OutBuffer&) = delete;
  OutBuffer& operator=(const OutBuffer&) = delete;

  // Room for up to kSlack bytes from the returned pointer; hand back the end with commit().
  char* reserve() {
    if (used_ > capacity_) flush();
    return buf_.data() + used_;
  }
  void commit(char* end) { used_ = static_cast<size_t>(end - buf_.data()); }

  void put(std::string_view s) {
    while (!s.empty()) {
      const size_t n = std::min(s.size(), kSlack);
      char* p = reserve();
      std::memcpy(p, s.data(), n);
      commit(p + n);
      s.remove_prefix(n);
    }
  }

  // Writes out what is buffered; throws when the stream refuses it (disk full, closed pipe).
  void flush() {
    if (used_ > 0) out_.write(buf_.data(), static_cast<std::streamsize>(used_));
    used_ = 0;
    if (!out_) throw std::runtime_error("writing " + what_ + " failed");
  }

  static constexpr size_t kSlack = 4096;

 private:
  std::ostream& out_;
  std::string what_;
  std::vector<char> buf_;
  size_t capacity_, used_ = 0;
};

}  // namespace pdesurf::cli
