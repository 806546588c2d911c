// The STEP and IGES writers' structure, checked without a CAD kernel (tests/occt reads the
// same files back with Open CASCADE): entity and record counts, IGES's fixed columns and
// section counts, escaped names, numbers that parse back to the very doubles written.
#include <doctest.h>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <algorithm>
#include <map>
#include <random>
#include <stdexcept>

#include "cad/iges_writer.hpp"
#include "common/errors.hpp"
#include "cad/step_writer.hpp"
#include "iges_records.hpp"

using namespace pdesurf;
using namespace pdesurf::testing;

namespace {

std::vector<double> clampedKnots(int count, int degree, double a, double b) {
  std::vector<double> k(size_t(degree) + 1, a);
  for (int i = 1; i < count - degree; ++i) k.push_back(a + (b - a) * i / (count - degree));
  k.insert(k.end(), size_t(degree) + 1, b);
  return k;
}

// countU x countV poles on a bumpy grid, or wrapped round a tube when closedV (first column
// == last column); radius(i) 0 collapses row i to a point.
BSplineSurface surface(const std::string& name, int countU, int countV, bool closedV, double topRadius = 1.0) {
  BSplineSurface s;
  s.name = name;
  s.countU = countU, s.countV = countV, s.closedV = closedV;
  s.knotsU = clampedKnots(countU, 3, 0.25, 1.75);
  s.knotsV = clampedKnots(countV, 3, 0.0, 2.0 / 3.0);
  for (int i = 0; i < countU; ++i)
    for (int j = 0; j < countV; ++j) {
      if (!closedV) {
        s.poles.emplace_back(0.7 * i, 0.3 * j + 0.01 * i * j, std::sin(0.9 * i + 0.4 * j) / 3.0);
        continue;
      }
      const double a = 2 * M_PI * (j % (countV - 1)) / (countV - 1);
      const double r = 1.0 + (topRadius - 1.0) * i / (countU - 1);
      s.poles.emplace_back(r * std::cos(a), r * std::sin(a), 0.5 * i);
    }
  return s;
}

std::vector<BSplineSurface> fixtures() {
  BSplineSurface open = surface("open", 5, 6, false);
  BSplineSurface tube = surface("tube", 4, 7, true);
  BSplineSurface cap = surface("cap", 4, 7, true, 0.0);
  cap.degenerate[1] = true;
  BSplineSurface tri = surface("it's a \\ \"tri\"\tangle \xC3\xA9\xF0\x9F\x98\x80", 4, 5, false);
  for (int j = 0; j < tri.countV; ++j) tri.pole(0, j) = tri.pole(0, 0);
  tri.degenerate[0] = true;
  return {open, tube, cap, tri};
}

const CadFileInfo kInfo{"scene 'one'", 1e-6, "2026-03-04T05:06:07"};


// ---- STEP: the DATA section as id -> body, line breaks the writer added removed ----

std::map<int, std::string> stepEntities(const std::string& text) {
  const size_t data = text.find("\nDATA;\n"), end = text.find("\nENDSEC;\nEND-ISO-10303-21;\n");
  REQUIRE(data != std::string::npos);
  REQUIRE(end != std::string::npos);
  std::string body = text.substr(data + 7, end - data - 6);
  for (size_t at; (at = body.find("\n  ")) != std::string::npos;) body.erase(at, 3);  // continuation lines
  std::map<int, std::string> out;
  size_t start = 0;
  bool inString = false;
  for (size_t i = 0; i < body.size(); ++i) {
    if (body[i] == '\'') inString = !inString;
    if (body[i] != ';' || inString) continue;
    std::string e = body.substr(start, i - start);
    if (e.front() == '\n') e.erase(0, 1);
    const size_t eq = e.find('=');
    REQUIRE(e.front() == '#');
    REQUIRE(eq != std::string::npos);
    const int id = std::stoi(e.substr(1, eq - 1));
    CHECK(out.count(id) == 0);
    out[id] = e.substr(eq + 1);
    start = i + 1;
  }
  return out;
}

int countType(const std::map<int, std::string>& es, const std::string& type) {
  int n = 0;
  for (const auto& [id, body] : es) n += body.compare(0, type.size() + 1, type + "(") == 0;
  return n;
}

std::vector<std::string> splitNumbers(const std::string& list) {  // "a,b,c" -> {a, b, c}
  std::vector<std::string> out;
  size_t start = 0;
  for (size_t i = 0; i <= list.size(); ++i)
    if (i == list.size() || list[i] == ',') out.push_back(list.substr(start, i - start)), start = i + 1;
  return out;
}

}  // namespace

TEST_CASE("cad writers: reals are written with a decimal point and read back exactly") {
  std::vector<double> xs = {0.0, -0.0, 3.0, -17.0, 1e-7, 1.1, 0.1 + 0.2, 1e300, -2.5e-310, M_PI, 123456789012345678.0};
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-30, 30);
  for (int k = 0; k < 2000; ++k) xs.push_back(std::ldexp(mantissa(rng), exponent(rng)));
  for (double x : xs) {
    const std::string s = formatReal(x);
    CHECK_MESSAGE(s.find('.') != std::string::npos, s);
    CHECK(s.find_first_not_of("0123456789.+-E") == std::string::npos);
    CHECK(parseReal(s) == x);
    CHECK(std::signbit(parseReal(s)) == std::signbit(x));
  }
  CHECK(formatReal(3.0) == "3.");
  CHECK(formatReal(1e-7) == "1.E-07");
  CHECK(formatReal(1.1) == "1.1");
}

TEST_CASE("cad writers: names are escaped for STEP and reduced to ASCII for IGES") {
  CHECK(stepString("it's") == "'it''s'");
  CHECK(stepString("a\\b") == "'a\\\\b'");
  CHECK(stepString("tab\there\n") == "'tab here '");
  CHECK(stepString("Na\xC3\xAFve \xCE\xA9\xCE\xB1") == "'Na\\X2\\00EF\\X0\\ve \\X2\\03A903B1\\X0\\'");
  CHECK(stepString("\xF0\x9F\x98\x80!") == "'\\X4\\0001F600\\X0\\!'");
  CHECK(stepString("bad \xFF byte") == "'bad \\X2\\FFFD\\X0\\ byte'");
  CHECK(stepString("\xC0\xAF") == "'\\X2\\FFFDFFFD\\X0\\'");  // an overlong '/' is two bad bytes
  CHECK(igesText("caf\xC3\xA9\tx;y,z") == "caf? x;y,z");
}

TEST_CASE("cad writers: STEP has one named advanced face per surface, edges by topology, the tolerance") {
  const std::vector<BSplineSurface> faces = fixtures();
  const std::string text = writeStep(faces, kInfo);
  CHECK(text.rfind("ISO-10303-21;\nHEADER;\n", 0) == 0);
  CHECK(text.find("FILE_SCHEMA(('AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }'));") != std::string::npos);
  CHECK(text.find("FILE_NAME('scene ''one''','2026-03-04T05:06:07',") != std::string::npos);
  const std::map<int, std::string> es = stepEntities(text);
  // Ids run 1..n and every reference is defined.
  CHECK(es.begin()->first == 1);
  CHECK(es.rbegin()->first == int(es.size()));
  for (const auto& [id, body] : es)
    for (size_t at = body.find('#'); at != std::string::npos; at = body.find('#', at + 1))
      CHECK(es.count(std::atoi(body.c_str() + at + 1)) == 1);

  CHECK(countType(es, "ADVANCED_FACE") == 4);
  CHECK(countType(es, "B_SPLINE_SURFACE_WITH_KNOTS") == 4);
  CHECK(countType(es, "OPEN_SHELL") == 4);
  CHECK(countType(es, "SHELL_BASED_SURFACE_MODEL") == 1);
  CHECK(countType(es, "MANIFOLD_SURFACE_SHAPE_REPRESENTATION") == 1);
  CHECK(countType(es, "PRODUCT") == 1);
  // open 4 edges; tube a seam and two circles; cap a seam and one circle; triangle 3.
  CHECK(countType(es, "EDGE_CURVE") == 4 + 3 + 2 + 3);
  CHECK(countType(es, "B_SPLINE_CURVE_WITH_KNOTS") == 4 + 3 + 2 + 3);
  CHECK(countType(es, "ORIENTED_EDGE") == 4 + 4 + 3 + 3);  // the seam twice
  CHECK(countType(es, "VERTEX_POINT") == 4 + 2 + 2 + 3);
  CHECK(countType(es, "EDGE_LOOP") == 4);
  CHECK(text.find("UNCERTAINTY_MEASURE_WITH_UNIT(LENGTH_MEASURE(1.E-06),") != std::string::npos);
  CHECK(text.find("SI_UNIT(.MILLI.,.METRE.)") != std::string::npos);

  std::vector<std::string> names;
  for (const auto& [id, body] : es)
    if (body.rfind("ADVANCED_FACE(", 0) == 0) names.push_back(body.substr(14, body.find("',(") - 13));
  CHECK(names == std::vector<std::string>{"'open'", "'tube'", "'cap'",
                                          "'it''s a \\\\ \"tri\" angle \\X2\\00E9\\X0\\\\X4\\0001F600\\X0\\'"});
  // closedV flags the surface v-closed.
  int closedSurfaces = 0;
  for (const auto& [id, body] : es)
    if (body.rfind("B_SPLINE_SURFACE_WITH_KNOTS(", 0) == 0)
      closedSurfaces += body.find(".UNSPECIFIED.,.F.,.T.,") != std::string::npos;
  CHECK(closedSurfaces == 2);

  // The points, in order, begin with every face's poles, exactly (then the vertices, the edges'
  // curves and the placement's origin).
  std::vector<Eigen::Vector3d> points;
  for (const auto& [id, body] : es)
    if (body.rfind("CARTESIAN_POINT('',(", 0) == 0) {
      const auto xyz = splitNumbers(body.substr(20, body.size() - 22));
      REQUIRE(xyz.size() == 3);
      points.emplace_back(parseReal(xyz[0]), parseReal(xyz[1]), parseReal(xyz[2]));
    }
  std::vector<Eigen::Vector3d> poles;
  for (const BSplineSurface& s : faces) poles.insert(poles.end(), s.poles.begin(), s.poles.end());
  REQUIRE(points.size() > poles.size() + 1);
  for (size_t k = 0; k < poles.size(); ++k) CHECK(points[k] == poles[k]);
  CHECK(writeStep(faces, kInfo) == text);  // no clock, no hidden state
}

TEST_CASE("cad writers: IGES records are 80 columns, sections counted, surfaces and names exact") {
  const std::vector<BSplineSurface> faces = fixtures();
  const std::string text = writeIges(faces, kInfo);
  Iges f = igesRecords(text);
  const auto& S = f.sections['S'];
  const auto& G = f.sections['G'];
  const auto& D = f.sections['D'];
  const auto& P = f.sections['P'];
  REQUIRE(f.sections['T'].size() == 1);
  char want[40];
  std::snprintf(want, sizeof want, "S%7zuG%7zuD%7zuP%7zu", S.size(), G.size(), D.size(), P.size());
  CHECK(f.sections['T'][0].substr(0, 32) == want);

  std::string global;
  for (const auto& r : G) global += r;
  const std::vector<std::string> g = igesParams(global);
  REQUIRE(g.size() == 26);
  CHECK(g[0] == ",");
  CHECK(g[1] == ";");
  CHECK(g[2] == "scene 'one'");
  CHECK(g[13] == "2");  // units flag: millimetres
  CHECK(g[14] == "MM");
  CHECK(g[17] == "20260304.050607");
  CHECK(parseReal(g[18]) == kInfo.tolerance);  // minimum resolution
  CHECK(g[22] == "11");                        // IGES 5.3

  // Directory: two records an entity, a surface and its name property per face.
  REQUIRE(D.size() == 4 * faces.size());
  for (size_t k = 0; k < faces.size(); ++k) {
    const BSplineSurface& s = faces[k];
    const std::string& d1 = D[4 * k];
    const std::string& d2 = D[4 * k + 1];
    CHECK(std::stoi(d1.substr(0, 8)) == 128);
    CHECK(d1.substr(64, 8) == "00000000");  // visible, independent: a root for readers
    CHECK(std::stoi(D[4 * k + 2].substr(0, 8)) == 406);
    CHECK(std::stoi(D[4 * k + 3].substr(32, 8)) == 15);
    const std::string label = igesText(s.name).substr(0, 8);
    CHECK(d2.substr(56, 8) == std::string(8 - label.size(), ' ') + label);

    // Parameter records of each entity: the range its directory entry gives, pointing back.
    auto params = [&](size_t entry) {
      const int first = std::stoi(D[2 * entry].substr(8, 8)), count = std::stoi(D[2 * entry + 1].substr(24, 8));
      std::string t;
      for (int r = first; r < first + count; ++r) {
        CHECK(std::stoi(P[r - 1].substr(64, 8)) == int(2 * entry + 1));
        t += P[r - 1].substr(0, 64);
      }
      return igesParams(t);
    };
    const std::vector<std::string> p = params(2 * k);
    const std::vector<std::string> name = params(2 * k + 1);
    REQUIRE(name.size() == 3);
    CHECK(name[2] == igesText(s.name));
    // 128: K1 K2 M1 M2 PROP1..5, knots, weights, poles u fastest, ranges, 0 associativities, 1 property.
    const size_t nk = s.knotsU.size() + s.knotsV.size(), np = s.poles.size();
    REQUIRE(p.size() == 10 + nk + 4 * np + 4 + 3);
    CHECK(p[0] == "128");
    CHECK(std::stoi(p[1]) == s.countU - 1);
    CHECK(std::stoi(p[2]) == s.countV - 1);
    CHECK(std::stoi(p[3]) == s.degreeU);
    CHECK(std::stoi(p[6]) == int(s.closedV));
    CHECK(p[7] == "1");  // polynomial
    for (size_t i = 0; i < s.knotsU.size(); ++i) CHECK(parseReal(p[10 + i]) == s.knotsU[i]);
    for (size_t i = 0; i < s.knotsV.size(); ++i) CHECK(parseReal(p[10 + s.knotsU.size() + i]) == s.knotsV[i]);
    size_t at = 10 + nk + np;
    for (int j = 0; j < s.countV; ++j)
      for (int i = 0; i < s.countU; ++i, at += 3)
        CHECK(Eigen::Vector3d(parseReal(p[at]), parseReal(p[at + 1]), parseReal(p[at + 2])) == s.pole(i, j));
    CHECK(parseReal(p[at + 1]) == s.u1());
    CHECK(parseReal(p[at + 3]) == s.v1());
    CHECK(std::stoi(p[at + 6]) == int(4 * k + 3));  // the name property's directory entry
  }
  CHECK(writeIges(faces, kInfo) == text);
}

TEST_CASE("cad writers: a long name continues over parameter records") {
  std::vector<BSplineSurface> faces = {surface(std::string(150, 'n') + ",;H", 4, 4, false)};
  const std::string text = writeIges(faces, kInfo);
  Iges f = igesRecords(text);
  std::string t;
  for (size_t r = f.sections['P'].size() - 3; r < f.sections['P'].size(); ++r) t += f.sections['P'][r].substr(0, 64);
  const std::vector<std::string> p = igesParams(t);
  CHECK(p.back() == std::string(150, 'n') + ",;H");
}

TEST_CASE("cad writers: faces that cannot be written are refused by name") {
  auto refuses = [](std::vector<BSplineSurface> faces, CadFileInfo info = kInfo) {
    CHECK_THROWS_AS(writeStep(faces, info), Error);
    CHECK_THROWS_AS(writeIges(faces, info), Error);
  };
  refuses({});
  BSplineSurface s = surface("bad", 4, 5, false);
  s.knotsU.pop_back();
  refuses({s});
  s = surface("open", 4, 5, false);
  s.closedV = true;  // the v borders differ
  refuses({s});
  s = surface("tri", 4, 5, false);
  s.degenerate[0] = true;  // row 0 is not a point
  refuses({s});
  s = surface("tube", 4, 7, true);
  s.degenerate[2] = true;  // a degenerate seam
  refuses({s});
  refuses({surface("ok", 4, 5, false)}, CadFileInfo{"t", 0.0, ""});
  refuses({surface("ok", 4, 5, false)}, CadFileInfo{"t", 1e-6, "yesterday"});
  try {
    writeStep({surface("fine", 4, 5, false), s}, kInfo);
    FAIL("a degenerate seam was written");
  } catch (const Error& e) {
    CHECK(std::string(e.what()).find("'tube'") != std::string::npos);
  }
  // An empty timestamp is a fixed one: the same bytes every time. An empty title leaves no
  // IGES product id null.
  const std::string iges = writeIges({surface("ok", 4, 5, false)}, CadFileInfo{"", 1e-6, ""});
  CHECK(iges.find("15H20000101.000000") != std::string::npos);
  CHECK(iges.find("1H,,1H;,7Hpdesurf,7Hpdesurf,7Hpdesurf,7Hpdesurf,") != std::string::npos);
}
