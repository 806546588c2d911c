// openNURBS's binary archive, the bytes inside a .3dm file (opennurbs_archive.cpp): just what
// writing one object needs. Little-endian numbers; chunks of a typecode and an 8-byte length
// (archive version 50 and later); a chunk whose typecode has the CRC bit ends with the CRC-32
// of its own bytes (not those of the chunks inside it); a short chunk is its typecode and value.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace pdesurf {

// Typecodes (opennurbs_3dm.h).
constexpr uint32_t kOnTcodeCrc = 0x8000;
constexpr uint32_t kOnTcodeAnonymous = 0x40000000 | kOnTcodeCrc;
constexpr uint32_t kOnTcodeClass = 0x00020000 | 0x7FFA;
constexpr uint32_t kOnTcodeClassUuid = 0x00020000 | kOnTcodeCrc | 0x7FFB;
constexpr uint32_t kOnTcodeClassData = 0x00020000 | kOnTcodeCrc | 0x7FFC;
constexpr uint32_t kOnTcodeClassEnd = 0x00020000 | 0x80000000 | 0x7FFF;

// CRC-32 as zlib computes it (openNURBS's ON_CRC32), continuing from `crc`.
uint32_t crc32(uint32_t crc, const unsigned char* p, size_t n);

class OnArchive {
 public:
  void beginChunk(uint32_t typecode);
  void endChunk();
  void shortChunk(uint32_t typecode, int64_t value);  // a whole short chunk
  // An object as ON_BinaryArchive::WriteObject writes it: class uuid, then what `data` writes.
  template <class Data>
  void object(const char* classUuid, Data data) {
    beginChunk(kOnTcodeClass);
    beginChunk(kOnTcodeClassUuid);
    uuid(classUuid);
    endChunk();
    beginChunk(kOnTcodeClassData);
    data(*this);
    endChunk();
    shortChunk(kOnTcodeClassEnd, 0);
    endChunk();
  }

  void version(int major, int minor) { byte(uint8_t(major * 16 + minor)); }
  void byte(uint8_t b) { put(&b, 1); }
  void boolean(bool b) { byte(b ? 1 : 0); }
  void i16(int16_t x) { put(&x, 2); }
  void i32(int32_t x) { put(&x, 4); }
  void i64(int64_t x) { put(&x, 8); }
  void f64(double x) { put(&x, 8); }
  void ints(const std::vector<int>& a);  // count, then the values (WriteArray)
  void point(const Eigen::Vector3d& p) { f64(p.x()), f64(p.y()), f64(p.z()); }
  void interval(double a, double b) { f64(a), f64(b); }
  void uuid(const char* text);  // "4ED7D4DD-E947-11d3-BFE5-0010830122F0"
  void zeros(size_t n);

  const std::string& bytes() const { return bytes_; }

 private:
  struct Open {
    size_t start;  // first byte after the length
    bool crc;
    uint32_t sum;
  };
  void put(const void* p, size_t n);  // little-endian hosts (x86-64, wasm32)
  std::string bytes_;
  std::vector<Open> open_;
};

}  // namespace pdesurf
