// Reading IGES text back in the tests (tests/native/cad_writers_test.cpp, iges_brep_test.cpp):
// its sections of 80-column records, free-format parameters with Hollerith strings, numbers
// parsed whole.
#pragma once
#include <doctest.h>

#include <cctype>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

namespace pdesurf::testing {

inline double parseReal(const std::string& s) {
  char* end = nullptr;
  const double x = std::strtod(s.c_str(), &end);
  REQUIRE(end == s.c_str() + s.size());
  return x;
}

// Sections of 80-column records, parameters with Hollerith strings.

struct Iges {
  std::map<char, std::vector<std::string>> sections;  // columns 1-72 of each record
};

inline Iges igesRecords(const std::string& text) {
  Iges f;
  size_t at = 0;
  std::string order;
  while (at < text.size()) {
    const size_t nl = text.find('\n', at);
    REQUIRE(nl != std::string::npos);
    const std::string line = text.substr(at, nl - at);
    CHECK(line.size() == 80);
    const char section = line[72];
    if (order.empty() || order.back() != section) order += section;
    auto& records = f.sections[section];
    records.push_back(line.substr(0, 72));
    CHECK(std::stoi(line.substr(73)) == int(records.size()));  // sequence numbers 1, 2, ... per section
    at = nl + 1;
  }
  CHECK(order == "SGDPT");
  return f;
}

// Parameters of free-format text: Hollerith strings (nH...) taken whole, others split at ','
// (an empty one is a null parameter), up to the ';'.
inline std::vector<std::string> igesParams(const std::string& text) {
  std::vector<std::string> out;
  for (size_t i = 0;;) {
    while (i < text.size() && text[i] == ' ') ++i;  // a record's padding before the next parameter
    size_t j = i;
    while (j < text.size() && std::isdigit((unsigned char)text[j])) ++j;
    if (j > i && j < text.size() && text[j] == 'H') {
      const size_t n = std::stoul(text.substr(i, j - i));
      out.push_back(text.substr(j + 1, n));
      i = j + 1 + n;
    } else {
      j = text.find_first_of(",;", i);
      REQUIRE(j != std::string::npos);
      out.push_back(text.substr(i, j - i));
      i = j;
    }
    REQUIRE(i < text.size());
    REQUIRE((text[i] == ',' || text[i] == ';'));
    if (text[i++] == ';') return out;
  }
}

}  // namespace pdesurf::testing
