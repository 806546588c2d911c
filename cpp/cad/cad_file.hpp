// What the CAD writers (STEP, IGES) share: the file-level information a caller gives, the
// checks a surface must pass before it is written, and exact number and text helpers.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "cad/bspline_surface.hpp"

namespace pdesurf {

struct CadFileInfo {
  std::string title;        // product / file name shown by CAD systems (UTF-8)
  double tolerance = 1e-6;  // scene units, written as mm (one scene unit = one millimetre)
  // ISO 8601 "YYYY-MM-DDThh:mm:ss" for the file headers. The core reads no clock: empty means a
  // fixed stamp, so the same scene always gives the same bytes.
  std::string timestamp;
};

// Throws Error(InvalidField) naming the face unless every face is wellFormed, closedV faces
// close (first and last pole columns within tolerance), degenerate borders are points (all
// their poles within tolerance) and at least one border is left to bound the face.
void checkFacesForCad(const std::vector<BSplineSurface>& faces, const CadFileInfo& info);

// The timestamp to write (info.timestamp or the fixed stamp), as its six numbers.
struct CadStamp {
  int year, month, day, hour, minute, second;
};
CadStamp cadStamp(const CadFileInfo& info);

// The shortest form that reads back exactly (std::to_chars),
// with the decimal point STEP and IGES reals require: 3 -> "3.", 1e-07 -> "1.E-07".
std::string formatReal(double x);

// UTF-8 to code points; a malformed byte becomes U+FFFD.
std::vector<char32_t> decodeUtf8(const std::string& s);

// Distinct knot values and their multiplicities (exact comparison: knots are written as given).
void knotsWithMultiplicities(const std::vector<double>& full, std::vector<double>* knots, std::vector<int>* mults);

}  // namespace pdesurf
