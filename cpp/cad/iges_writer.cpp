#include "cad/iges_writer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "cad/brep_topology.hpp"
#include "cad/face_loops.hpp"

namespace pdesurf {

namespace {

std::string hollerith(const std::string& ascii) {
  return ascii.empty() ? std::string() : std::to_string(ascii.size()) + "H" + ascii;  // empty: a null parameter
}

// Directory entry status (field 9): blank, subordinate switch, entity use, hierarchy. A root
// is independent (00); a B-rep's parts are physically dependent (01) on what uses them.
constexpr const char* kIndependent = "00000000";
constexpr const char* kDependent = "00010000";
constexpr const char* kParametric = "00010500";  // a dependent curve in a surface's (u, v)

struct Entity {
  int type, form;
  std::string label;                // directory entry field 18, at most 8 characters
  std::vector<std::string> params;  // parameter data, the type number first
  std::string status = kIndependent;
};

// Entities in the order written, each pointing only at earlier ones: entity k is at directory
// sequence number 2k + 1.
class Entities {
 public:
  int add(Entity e) {
    list_.push_back(std::move(e));
    return 2 * int(list_.size()) - 1;
  }
  int next() const { return 2 * int(list_.size()) + 1; }  // the directory entry of the next add
  const std::vector<Entity>& list() const { return list_; }

 private:
  std::vector<Entity> list_;
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

// Type 126, a polynomial B-spline curve: K, M, PROP1..4 (planar, closed, polynomial,
// periodic), knots, weights, poles, its parameter range and the plane's normal (a parameter
// space curve lies in z = 0).
std::vector<std::string> curveParams(int degree, const std::vector<double>& knots, const std::vector<Eigen::Vector3d>& poles, bool planar) {
  const int count = int(poles.size());
  const bool closed = (poles.front() - poles.back()).norm() == 0;
  std::vector<std::string> p = {"126", std::to_string(count - 1), std::to_string(degree), planar ? "1" : "0", closed ? "1" : "0", "1", "0"};
  for (double k : knots) p.push_back(formatReal(k));
  p.insert(p.end(), size_t(count), "1.");
  for (const Eigen::Vector3d& q : poles)
    for (int d = 0; d < 3; ++d) p.push_back(formatReal(q[d]));
  p.insert(p.end(), {formatReal(knots[size_t(degree)]), formatReal(knots[size_t(count)]), "0.", "0.", planar ? "1." : "0."});
  return p;
}

// The faces as a B-rep (IGES 5.3 section 4.7 types 186, 514, 510, 508, 504, 502): one vertex
// list; each edge its 3D curve (the shared border's exact part) in one edge list; a face per
// surface with one outer loop of its edges, each used in its direction; a shell per body,
// closed (form 1) or open (form 2), each face flagged when its normal is the surface's
// reverse; a closed shell the boundary of a manifold solid (186). Solids and open shells are
// the roots; everything else is dependent. Each use of an edge in a loop carries its curve in
// the face's (u, v) (a 126 in z = 0, entity use 05): readers need not project the 3D edges,
// which near a surface's own border can land on the wrong side.
void addBrep(Entities& out, const std::vector<BSplineSurface>& faces, const BrepTopology& t) {
  std::vector<int> surface;
  for (const BSplineSurface& f : faces) surface.push_back(out.add({128, 0, "", surfaceParams(f, 0), kDependent}));
  std::vector<std::string> vp = {"502", std::to_string(t.vertices.size())};
  for (const Eigen::Vector3d& v : t.vertices)
    for (int d = 0; d < 3; ++d) vp.push_back(formatReal(v[d]));
  const int vertices = out.add({502, 1, "", vp, kDependent});
  std::vector<int> curve;
  for (const BrepEdge& e : t.edges) curve.push_back(out.add({126, 0, "", curveParams(e.curve.degree, e.curve.knots, e.curve.poles, false), kDependent}));
  std::vector<std::string> ep = {"504", std::to_string(t.edges.size())};
  for (size_t k = 0; k < t.edges.size(); ++k)
    for (int x : {curve[k], vertices, t.edges[k].start + 1, vertices, t.edges[k].end + 1}) ep.push_back(std::to_string(x));
  const int edges = out.add({504, 1, "", ep, kDependent});
  std::vector<int> face;
  for (size_t f = 0; f < faces.size(); ++f) {
    const std::vector<BrepEdgeUse> loopUses = surfaceLoop(t, f);
    std::vector<std::string> lp = {"508", std::to_string(loopUses.size())};
    for (const BrepEdgeUse& u : loopUses) {
      // A ring (a closed border met whole) on a face closed in v goes without: Open CASCADE's
      // reader projects the 3D ring onto the periodic face well, while given the ring's curve
      // in (u, v) it rebuilt some rings from it, dropped their 3D curves and took them for
      // degenerate (zhang-pot-case2's open rim) or widened them to 0.75 (the bottle's neck).
      // On a face open in v the projection of a closed curve is ambiguous (it collapsed to a
      // point on you2004-fig1's blend): there the curve is given.
      const BrepEdge& e = t.edges[size_t(u.edge)];
      if (e.start == e.end && faces[f].closedV) {
        for (int x : {0, edges, u.edge + 1, u.forward ? 1 : 0, 0}) lp.push_back(std::to_string(x));
        continue;
      }
      const BrepPcurve pc = usePcurve(faces[f], t, int(f), u);
      std::vector<Eigen::Vector3d> poles;
      for (const Eigen::Vector2d& q : pc.poles) poles.emplace_back(q.x(), q.y(), 0.0);
      const int pcurve = out.add({126, 0, "", curveParams(pc.degree, pc.knots, poles, true), kParametric});
      for (int x : {0, edges, u.edge + 1, u.forward ? 1 : 0, 1, 0, pcurve}) lp.push_back(std::to_string(x));
    }
    const int loop = out.add({508, 1, "", lp, kDependent});
    const std::string name = igesText(faces[f].name);
    std::vector<std::string> fp = {"510", std::to_string(surface[f]), "1", "1", std::to_string(loop)};
    if (!name.empty()) fp.insert(fp.end(), {"0", "1", std::to_string(out.next() + 2)});  // the name property, next after the face
    face.push_back(out.add({510, 1, name.substr(0, 8), fp, kDependent}));
    if (!name.empty()) out.add({406, 15, "", {"406", "1", hollerith(name)}, kDependent});
  }
  for (const BrepShell& sh : t.shells) {
    std::vector<std::string> sp = {"514", std::to_string(sh.faces.size())};
    for (int f : sh.faces) sp.insert(sp.end(), {std::to_string(face[size_t(f)]), t.faces[size_t(f)].flipped ? "0" : "1"});
    const int shell = out.add({514, sh.closed ? 1 : 2, "", sp, sh.closed ? kDependent : kIndependent});
    if (sh.closed) out.add({186, 0, "", {"186", std::to_string(shell), "1", "0"}, kIndependent});
  }
}

}  // namespace

std::string igesText(const std::string& utf8) {
  std::string out;
  for (char32_t c : decodeUtf8(utf8)) out += c < 0x20 ? ' ' : c < 0x7F ? char(c) : '?';
  return out;
}

std::string writeIges(const std::vector<BSplineSurface>& faces, const CadFileInfo& info, const BrepTopology* topology) {
  checkFacesForCad(faces, info);
  const CadStamp t = cadStamp(info);
  char stamp[24];
  std::snprintf(stamp, sizeof stamp, "%04d%02d%02d.%02d%02d%02d", t.year, t.month, t.day, t.hour, t.minute, t.second);
  const std::string title = igesText(info.title);
  // Global fields 3, 4 and 12 (product ids, file name) have no default in IGES: never null.
  const std::string product = hollerith(title.empty() ? "pdesurf" : title);

  // Entity k sits at directory sequence 2k+1; a named face's surface is followed by its name
  // (OCCT reads a name property with no name as a null string, so an unnamed face has none).
  Entities list;
  if (topology) {
    addBrep(list, faces, *topology);
  } else {
    for (const BSplineSurface& s : faces) {
      const std::string name = igesText(s.name);
      const int nameDe = name.empty() ? 0 : list.next() + 2;
      list.add({128, 0, name.substr(0, 8), surfaceParams(s, nameDe)});
      if (nameDe) list.add({406, 15, "", {"406", "1", hollerith(name)}});
    }
  }
  const std::vector<Entity>& entities = list.list();

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
        field(e.type) + field(firstP) + field(0) + field(0) + field(0) + field(0) + field(0) + field(0) + e.status,
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
