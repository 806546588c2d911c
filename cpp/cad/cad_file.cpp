#include "cad/cad_file.hpp"
#include "common/errors.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace pdesurf {

namespace {

bool allNear(const std::vector<Eigen::Vector3d>& pts, double tol) {
  for (const auto& p : pts)
    if ((p - pts.front()).norm() > tol) return false;
  return true;
}

// Poles of a border in kBezierEdge order u0 u1 v0 v1 (a row i = 0 or last, a column j = 0 or last).
std::vector<Eigen::Vector3d> borderPoles(const BSplineSurface& s, int border) {
  std::vector<Eigen::Vector3d> out;
  if (border < 2) {
    const int i = border == 0 ? 0 : s.countU - 1;
    for (int j = 0; j < s.countV; ++j) out.push_back(s.pole(i, j));
  } else {
    const int j = border == 2 ? 0 : s.countV - 1;
    for (int i = 0; i < s.countU; ++i) out.push_back(s.pole(i, j));
  }
  return out;
}

}  // namespace

void checkFacesForCad(const std::vector<BSplineSurface>& faces, const CadFileInfo& info) {
  if (!(info.tolerance > 0.0) || !std::isfinite(info.tolerance))
    throw Error(ErrorCode::InvalidField, "CAD export: the tolerance must be a positive number");
  if (faces.empty()) throw Error(ErrorCode::InvalidField, "CAD export: no faces to write");
  for (const BSplineSurface& s : faces) {
    auto fail = [&](const std::string& why) {
      throw Error(ErrorCode::InvalidField, "CAD export: face '" + s.name + "': " + why);
    };
    std::string why;
    if (!wellFormed(s, &why)) fail(why);
    if (s.closedV) {
      for (int i = 0; i < s.countU; ++i)
        if ((s.pole(i, 0) - s.pole(i, s.countV - 1)).norm() > info.tolerance)
          fail("closed in v but its first and last pole columns differ");
    }
    int bounding = 0;
    for (int b = 0; b < 4; ++b) {
      if (s.degenerate[b] && !allNear(borderPoles(s, b), info.tolerance))
        fail("a border marked degenerate is not a point");
      if (!s.degenerate[b]) ++bounding;
    }
    if (bounding == 0) fail("every border is degenerate");
    if (s.closedV && (s.degenerate[2] || s.degenerate[3])) fail("closed in v with a degenerate seam");
  }
}

CadStamp cadStamp(const CadFileInfo& info) {
  CadStamp t{2000, 1, 1, 0, 0, 0};
  if (info.timestamp.empty()) return t;
  CadStamp r{};
  if (std::sscanf(info.timestamp.c_str(), "%4d-%2d-%2dT%2d:%2d:%2d", &r.year, &r.month, &r.day, &r.hour, &r.minute,
                  &r.second) != 6 ||
      r.year < 1000 || r.year > 9999 || r.month < 1 || r.month > 12 || r.day < 1 || r.day > 31 || r.hour < 0 ||
      r.hour > 23 || r.minute < 0 || r.minute > 59 || r.second < 0 || r.second > 60)
    throw Error(ErrorCode::InvalidField, "CAD export: timestamp is not YYYY-MM-DDThh:mm:ss");
  return r;
}

std::string formatReal(double x) {
  // The shortest form that reads back as x: 1.1, not 1.1000000000000001.
  char buf[40];
#if defined(__cpp_lib_to_chars)
  // std::to_chars (Ryu): locale-independent, about twenty times quicker than the loop below.
  const std::to_chars_result r = std::to_chars(buf, buf + sizeof buf, x);
  std::string s(buf, r.ptr);
#else
  // Emscripten's libc++ has no floating-point to_chars: the shortest of 15, 16 and 17
  // significant digits that reads back (17 always does), a decimal comma made a point.
  for (int digits = 15; digits <= 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*G", digits, x);
    if (std::strtod(buf, nullptr) == x) break;
  }
  std::string s(buf);
  for (char& c : s)
    if (c == ',') c = '.';
#endif
  for (char& c : s) c = char(std::toupper(static_cast<unsigned char>(c)));
  const size_t e = s.find('E');
  if (s.find('.') == std::string::npos) s.insert(e == std::string::npos ? s.size() : e, ".");
  return s;
}

std::vector<char32_t> decodeUtf8(const std::string& s) {
  std::vector<char32_t> out;
  for (size_t i = 0; i < s.size();) {
    const unsigned char c = s[i];
    int len = c < 0x80 ? 1 : (c >> 5) == 6 ? 2 : (c >> 4) == 14 ? 3 : (c >> 3) == 30 ? 4 : 0;
    char32_t cp = len == 1 ? c : len == 2 ? (c & 0x1F) : len == 3 ? (c & 0x0F) : (c & 0x07);
    bool ok = len > 0 && i + len <= s.size();
    for (int k = 1; ok && k < len; ++k) {
      const unsigned char d = s[i + k];
      ok = (d >> 6) == 2;
      cp = (cp << 6) | (d & 0x3F);
    }
    // Overlong forms, surrogates and values past U+10FFFF are malformed too.
    static const char32_t kMin[5] = {0, 0, 0x80, 0x800, 0x10000};
    if (ok && (cp < kMin[len] || (cp >= 0xD800 && cp <= 0xDFFF) || cp > 0x10FFFF)) ok = false;
    if (!ok) {
      out.push_back(0xFFFD);
      ++i;
    } else {
      out.push_back(cp);
      i += len;
    }
  }
  return out;
}

void knotsWithMultiplicities(const std::vector<double>& full, std::vector<double>* knots, std::vector<int>* mults) {
  knots->clear();
  mults->clear();
  for (double k : full) {
    if (!knots->empty() && knots->back() == k) {
      ++mults->back();
    } else {
      knots->push_back(k);
      mults->push_back(1);
    }
  }
}

}  // namespace pdesurf
