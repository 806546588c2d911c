// openNURBS's archive bytes (cad/on_archive.hpp), the layer under the .3dm Breps: the CRC is
// zlib's, a chunk's length counts its data and CRC, its CRC covers its own bytes and not those
// of the chunks inside it, and an object is the class-uuid, data and end chunks openNURBS's
// ReadObject expects (rhino3dm reads whole Breps back in tests/js/write-3dm-breps.test.mjs).
#include <doctest.h>

#include <cstring>

#include "cad/on_archive.hpp"

using namespace pdesurf;

namespace {

template <class T>
T at(const std::string& b, size_t offset) {
  T x;
  std::memcpy(&x, b.data() + offset, sizeof x);
  return x;
}

uint32_t crcOf(const std::string& b, size_t from, size_t n) {
  return crc32(0, reinterpret_cast<const unsigned char*>(b.data()) + from, n);
}

}  // namespace

TEST_CASE("CRC-32 is zlib's: the standard check value, and continuing a sum") {
  const std::string s = "123456789";
  CHECK(crcOf(s, 0, 9) == 0xCBF43926u);
  CHECK(crc32(crcOf(s, 0, 4), reinterpret_cast<const unsigned char*>(s.data()) + 4, 5) == 0xCBF43926u);
}

TEST_CASE("a chunk: typecode, 8-byte length of data and CRC, CRC of its own bytes only") {
  OnArchive a;
  a.beginChunk(kOnTcodeAnonymous);
  a.i32(7);
  a.beginChunk(kOnTcodeAnonymous);  // inside: its bytes are not the outer chunk's CRC
  a.f64(1.5);
  a.endChunk();
  a.byte(3);
  a.endChunk();
  const std::string& b = a.bytes();
  REQUIRE(b.size() == 12 + 4 + (12 + 8 + 4) + 1 + 4);
  CHECK(at<uint32_t>(b, 0) == kOnTcodeAnonymous);
  CHECK(at<int64_t>(b, 4) == int64_t(b.size() - 12));
  CHECK(at<int32_t>(b, 12) == 7);
  CHECK(at<int64_t>(b, 20) == 12);
  CHECK(at<double>(b, 28) == 1.5);
  CHECK(at<uint32_t>(b, 36) == crcOf(b, 28, 8));
  const std::string own = b.substr(12, 4) + b.substr(40, 1);
  CHECK(at<uint32_t>(b, 41) == crcOf(own, 0, own.size()));
}

TEST_CASE("an object: class uuid (20 bytes with its CRC), data, a short end chunk") {
  OnArchive a;
  a.object("60B5DBC5-E660-11d3-BFE4-0010830122F0", [](OnArchive& w) { w.i32(42); });
  const std::string& b = a.bytes();
  CHECK(at<uint32_t>(b, 0) == kOnTcodeClass);
  CHECK(at<int64_t>(b, 4) == int64_t(b.size() - 12));
  CHECK(at<uint32_t>(b, 12) == kOnTcodeClassUuid);
  CHECK(at<int64_t>(b, 16) == 20);
  CHECK(at<uint32_t>(b, 24) == 0x60B5DBC5u);  // Data1, little-endian
  CHECK(at<uint16_t>(b, 28) == 0xE660);
  CHECK(at<uint16_t>(b, 30) == 0x11d3);
  CHECK(uint8_t(b[32]) == 0xBF);
  CHECK(uint8_t(b[39]) == 0xF0);
  CHECK(at<uint32_t>(b, 44) == kOnTcodeClassData);
  CHECK(at<int64_t>(b, 48) == 8);
  CHECK(at<int32_t>(b, 56) == 42);
  CHECK(at<uint32_t>(b, 64) == kOnTcodeClassEnd);
  CHECK(at<int64_t>(b, 68) == 0);
  CHECK(b.size() == 76);
  OnArchive unclosed;
  CHECK_THROWS(unclosed.endChunk());
}
