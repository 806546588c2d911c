#include "cad/iges_writer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace pdesurf {

namespace {

std::string hollerith(const std::string& ascii) {
  return ascii.empty() ? std::string() : std::to_string(ascii.size()) + "H" + ascii;  // empty: a null parameter
}

struct Entity {
  int type, form;
  std::string label;                // directory entry field 18, at most 8 characters
  std::vector<std::string> params;  // parameter data, the type number first
};

// Parameters packed into records of `width` columns, delimiter after each and the record
// delimiter after the last. Only a string longer than a whole record is split (IGES lets a
// string continue on the next record; a number must not).
std::vector<std::string> pack(const std::vector<std::string>& tokens, size_t width) {
  std::vector<std::string> lines;
  std::string cur;
  for (size_t k = 0; k < tokens.size(); ++k) {
    const std::string t = tokens[k] + (k + 1 == tokens.size() ? ';' : ',');
    if (cur.size() + t.size() <= width) {
      cur += t;
    } else if (t.size() <= width) {
      lines.push_back(cur);
      cur = t;
    } else {
      for (char c : t) {
        if (cur.size() == width) {
          lines.push_back(cur);
          cur.clear();
        }
        cur += c;
      }
    }
  }
  if (!cur.empty()) lines.push_back(cur);
  return lines;
}

// One 80-column record: `data` padded to 72 columns, the section letter, the sequence number.
std::string record(const std::string& data, char section, int sequence) {
  char tail[16];
  std::snprintf(tail, sizeof tail, "%c%07d\n", section, sequence);
  std::string line = data;
  line.resize(72, ' ');
  return line + tail;
}

std::string field(int x) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%8d", x);
  return buf;
}

std::string rightJustified(const std::string& s, size_t width) {
  return s.size() >= width ? s.substr(0, width) : std::string(width - s.size(), ' ') + s;
}

// Type 128 parameters: indices K1 K2, degrees M1 M2, PROP1..5 (closed u, closed v,
// polynomial, periodic u, periodic v), full knot vectors, weights and poles with u varying
// fastest, the parameter ranges; then no associativities and one property, the name
// (nameEntity 0: none).
std::vector<std::string> surfaceParams(const BSplineSurface& s, int nameEntity) {
  std::vector<std::string> p = {"128",
                                std::to_string(s.countU - 1),
                                std::to_string(s.countV - 1),
                                std::to_string(s.degreeU),
                                std::to_string(s.degreeV),
                                "0",
                                s.closedV ? "1" : "0",
                                "1",
                                "0",
                                "0"};
  for (double k : s.knotsU) p.push_back(formatReal(k));
  for (double k : s.knotsV) p.push_back(formatReal(k));
  p.insert(p.end(), s.poles.size(), "1.");
  for (int j = 0; j < s.countV; ++j)
    for (int i = 0; i < s.countU; ++i)
      for (int c = 0; c < 3; ++c) p.push_back(formatReal(s.pole(i, j)[c]));
  for (double x : {s.u0(), s.u1(), s.v0(), s.v1()}) p.push_back(formatReal(x));
  if (nameEntity) p.insert(p.end(), {"0", "1", std::to_string(nameEntity)});
  return p;
}

}  // namespace

std::string igesText(const std::string& utf8) {
  std::string out;
  for (char32_t c : decodeUtf8(utf8)) out += c < 0x20 ? ' ' : c < 0x7F ? char(c) : '?';
  return out;
}

std::string writeIges(const std::vector<BSplineSurface>& faces, const CadFileInfo& info) {
  checkFacesForCad(faces, info);
  const CadStamp t = cadStamp(info);
  char stamp[24];
  std::snprintf(stamp, sizeof stamp, "%04d%02d%02d.%02d%02d%02d", t.year, t.month, t.day, t.hour, t.minute, t.second);
  const std::string title = igesText(info.title);
  // Global fields 3, 4 and 12 (product ids, file name) have no default in IGES: never null.
  const std::string product = hollerith(title.empty() ? "pdesurf" : title);

  // Entity k sits at directory sequence 2k+1; a named face's surface is followed by its name
  // (OCCT reads a name property with no name as a null string, so an unnamed face has none).
  std::vector<Entity> entities;
  for (const BSplineSurface& s : faces) {
    const std::string name = igesText(s.name);
    const int nameDe = name.empty() ? 0 : 2 * int(entities.size() + 1) + 1;
    entities.push_back({128, 0, name.substr(0, 8), surfaceParams(s, nameDe)});
    if (nameDe) entities.push_back({406, 15, "", {"406", "1", hollerith(name)}});
  }

  double maxCoordinate = 0.0;
  for (const BSplineSurface& s : faces)
    for (const auto& p : s.poles) maxCoordinate = std::max(maxCoordinate, p.cwiseAbs().maxCoeff());

  std::string start, global, directory, parameters;
  int nS = 0, nG = 0, nD = 0, nP = 0;
  const std::string about = "pdesurf B-spline surfaces" + (title.empty() ? std::string() : ": " + title);
  for (size_t at = 0; at < about.size(); at += 72) start += record(about.substr(at, 72), 'S', ++nS);

  // Global section (IGES 5.3 table 3), as numbered there.
  const std::string date = hollerith(stamp);
  // clang-format off
  const std::vector<std::string> g = {
      "1H,", "1H;",                          // 1-2 parameter and record delimiters
      product, product,                      // 3-4 sender's product id, file name
      "7Hpdesurf", "7Hpdesurf",              // 5-6 native system, preprocessor version
      "32", "38", "6", "308", "15",          // 7-11 integer bits, single and double precision
      product, "1.", "2", "2HMM",            // 12-15 receiver's product id, scale, units mm
      "1", "1.", date,                       // 16-18 line weights, file date
      formatReal(info.tolerance),            // 19 minimum user-intended resolution
      formatReal(maxCoordinate), "", "",     // 20-22 largest coordinate, author, organisation
      "11", "0", date, ""};                  // 23-26 IGES 5.3, drafting standard, model date, protocol
  // clang-format on
  for (const std::string& line : pack(g, 72)) global += record(line, 'G', ++nG);

  for (const Entity& e : entities) {
    const int de = nD + 1;
    const std::vector<std::string> lines = pack(e.params, 64);
    char pointer[16];
    std::snprintf(pointer, sizeof pointer, " %7d", de);
    for (const std::string& line : lines) {
      std::string data = line;
      data.resize(64, ' ');
      parameters += record(data + pointer, 'P', ++nP);
    }
    const int firstP = nP - int(lines.size()) + 1;
    directory += record(
        field(e.type) + field(firstP) + field(0) + field(0) + field(0) + field(0) + field(0) + field(0) + "00000000",
        'D', ++nD);
    directory += record(field(e.type) + field(0) + field(0) + field(int(lines.size())) + field(e.form) +
                            std::string(16, ' ') + rightJustified(e.label, 8) + field(0),
                        'D', ++nD);
  }

  char terminate[64];
  std::snprintf(terminate, sizeof terminate, "S%7dG%7dD%7dP%7d", nS, nG, nD, nP);
  return start + global + directory + parameters + record(terminate, 'T', 1);
}

}  // namespace pdesurf
