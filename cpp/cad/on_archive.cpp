#include "cad/on_archive.hpp"

#include <array>
#include <cstring>
#include <stdexcept>

namespace pdesurf {

uint32_t crc32(uint32_t crc, const unsigned char* p, size_t n) {
  static const std::array<uint32_t, 256> table = [] {
    std::array<uint32_t, 256> t{};
    for (uint32_t i = 0; i < 256; ++i) {
      uint32_t c = i;
      for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      t[i] = c;
    }
    return t;
  }();
  crc = ~crc;
  for (size_t i = 0; i < n; ++i) crc = table[(crc ^ p[i]) & 0xFF] ^ (crc >> 8);
  return ~crc;
}

void OnArchive::put(const void* p, size_t n) {
  static_assert(sizeof(double) == 8, "IEEE doubles");
  const auto* b = static_cast<const unsigned char*>(p);
  bytes_.append(reinterpret_cast<const char*>(b), n);
  if (!open_.empty() && open_.back().crc) open_.back().sum = crc32(open_.back().sum, b, n);
}

void OnArchive::beginChunk(uint32_t typecode) {
  // The header is outside every chunk's CRC: openNURBS writes its length twice.
  bytes_.append(reinterpret_cast<const char*>(&typecode), 4);
  bytes_.append(8, '\0');  // the length, filled in by endChunk
  open_.push_back({bytes_.size(), (typecode & kOnTcodeCrc) != 0, 0});
}

void OnArchive::endChunk() {
  if (open_.empty()) throw std::logic_error("OnArchive::endChunk: no chunk open");
  const Open c = open_.back();
  if (c.crc) {
    const uint32_t sum = c.sum;
    bytes_.append(reinterpret_cast<const char*>(&sum), 4);
  }
  const int64_t length = int64_t(bytes_.size() - c.start);
  std::memcpy(&bytes_[c.start - 8], &length, 8);
  open_.pop_back();
}

void OnArchive::shortChunk(uint32_t typecode, int64_t value) {
  bytes_.append(reinterpret_cast<const char*>(&typecode), 4);
  bytes_.append(reinterpret_cast<const char*>(&value), 8);
}

void OnArchive::ints(const std::vector<int>& a) {
  i32(int32_t(a.size()));
  for (int x : a) i32(x);
}

void OnArchive::zeros(size_t n) {
  for (size_t i = 0; i < n; ++i) byte(0);
}

void OnArchive::uuid(const char* text) {
  // 8-4-4-4-12 hex digits: Data1 (32 bits), Data2, Data3 (16 bits each), then 8 bytes as read.
  const auto hex = [&](size_t at, size_t n) { return uint32_t(std::stoul(std::string(text + at, n), nullptr, 16)); };
  if (std::strlen(text) != 36) throw std::logic_error("OnArchive::uuid: 36 characters expected");
  i32(int32_t(hex(0, 8)));
  i16(int16_t(hex(9, 4)));
  i16(int16_t(hex(14, 4)));
  for (size_t at : {19u, 21u, 24u, 26u, 28u, 30u, 32u, 34u}) byte(uint8_t(hex(at, 2)));
}

}  // namespace pdesurf
