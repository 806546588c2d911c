#include "cad/step_writer.hpp"

#include <cstdio>

namespace pdesurf {

namespace {

std::string ref(int id) { return "#" + std::to_string(id); }
const char* logical(bool b) { return b ? ".T." : ".F."; }

template <class T, class F>
std::string list(const std::vector<T>& v, F item) {
  std::string s = "(";
  for (size_t i = 0; i < v.size(); ++i) s += (i ? "," : "") + item(v[i]);
  return s + ")";
}
std::string refs(const std::vector<int>& ids) { return list(ids, ref); }
std::string reals(const std::vector<double>& xs) { return list(xs, formatReal); }
std::string ints(const std::vector<int>& xs) {
  return list(xs, [](int x) { return std::to_string(x); });
}

// The DATA section: entity bodies numbered from 1; an id may be reserved before its body is
// known (the product entities point at the shell written after the faces).
class Data {
 public:
  int add(std::string body) {
    bodies_.push_back(std::move(body));
    return int(bodies_.size());
  }
  int reserve() { return add(""); }
  void set(int id, std::string body) { bodies_[size_t(id) - 1] = std::move(body); }
  void appendTo(std::string* out) const {
    for (size_t i = 0; i < bodies_.size(); ++i)
      appendWrapped(out, "#" + std::to_string(i + 1) + "=" + bodies_[i] + ";");
  }

 private:
  // Lines broken after a comma or a closing parenthesis outside strings once past 72 columns:
  // long pole lists stay readable and no reader meets a line of megabytes.
  static void appendWrapped(std::string* out, const std::string& entity) {
    size_t column = 0;
    bool inString = false;
    for (size_t i = 0; i < entity.size(); ++i) {
      const char c = entity[i];
      out->push_back(c);
      ++column;
      if (c == '\'') inString = !inString;  // '' inside a string toggles twice
      const char next = i + 1 < entity.size() ? entity[i + 1] : ';';
      if ((c == ',' || c == ')') && !inString && column >= 72 && next != ';' && next != ',' && next != ')') {
        out->append("\n  ");
        column = 2;
      }
    }
    out->push_back('\n');
  }
  std::vector<std::string> bodies_;
};

int writePoint(Data& d, const Eigen::Vector3d& p) {
  return d.add("CARTESIAN_POINT('',(" + formatReal(p.x()) + "," + formatReal(p.y()) + "," + formatReal(p.z()) + "))");
}

int writeCurve(Data& d, int degree, const std::vector<int>& poles, const std::vector<double>& fullKnots, bool closed) {
  std::vector<double> knots;
  std::vector<int> mults;
  knotsWithMultiplicities(fullKnots, &knots, &mults);
  return d.add("B_SPLINE_CURVE_WITH_KNOTS(''," + std::to_string(degree) + "," + refs(poles) + ",.UNSPECIFIED.," +
               logical(closed) + ",.F.," + ints(mults) + "," + reals(knots) + ",.UNSPECIFIED.)");
}

// One ADVANCED_FACE with its own vertices and edges. A border is a pole row or column
// (clamped knots), so each edge curve reuses the surface's own points. The loop runs
// counter-clockwise in (u, v): v0 forward, u1 forward, v1 backward, u0 backward. A closed-v
// face uses its v0 edge again, reversed, as v1 (the seam); a degenerate border gets no edge
// and its two corners one vertex (readers add the degenerate edge, as for a cone's apex).
int writeFace(Data& d, const BSplineSurface& s) {
  std::vector<int> pts(s.poles.size());
  for (size_t k = 0; k < s.poles.size(); ++k) pts[k] = writePoint(d, s.poles[k]);
  auto pt = [&](int i, int j) { return pts[size_t(i) * s.countV + j]; };

  std::vector<double> ku, kv;
  std::vector<int> mu, mv;
  knotsWithMultiplicities(s.knotsU, &ku, &mu);
  knotsWithMultiplicities(s.knotsV, &kv, &mv);
  std::string rows = "(";
  for (int i = 0; i < s.countU; ++i) {
    std::vector<int> row;
    for (int j = 0; j < s.countV; ++j) row.push_back(pt(i, j));
    rows += (i ? "," : "") + refs(row);
  }
  rows += ")";
  const int surface =
      d.add("B_SPLINE_SURFACE_WITH_KNOTS(''," + std::to_string(s.degreeU) + "," + std::to_string(s.degreeV) + "," +
            rows + ",.UNSPECIFIED.,.F.," + logical(s.closedV) + ",.F.," + ints(mu) + "," + ints(mv) + "," + reals(ku) +
            "," + reals(kv) + ",.UNSPECIFIED.)");

  // Corners 0 (u0,v0), 1 (u1,v0), 2 (u0,v1), 3 (u1,v1); a degenerate border or the seam
  // makes two corners one vertex.
  int parent[4] = {0, 1, 2, 3};
  auto root = [&](int c) {
    while (parent[c] != c) c = parent[c];
    return c;
  };
  auto join = [&](int a, int b) { parent[root(a)] = root(b); };
  if (s.degenerate[0] || s.closedV) join(0, 2);
  if (s.degenerate[1] || s.closedV) join(1, 3);
  if (s.degenerate[2]) join(0, 1);
  if (s.degenerate[3]) join(2, 3);
  const int lastI = s.countU - 1, lastJ = s.countV - 1;
  const int cornerPoint[4] = {pt(0, 0), pt(lastI, 0), pt(0, lastJ), pt(lastI, lastJ)};
  int vertex[4] = {0, 0, 0, 0};
  auto vertexOf = [&](int c) {
    const int r = root(c);
    if (!vertex[r]) vertex[r] = d.add("VERTEX_POINT(''," + ref(cornerPoint[r]) + ")");
    return vertex[r];
  };

  struct Border {
    int which;     // kBezierEdge order u0 u1 v0 v1
    int from, to;  // corners, in the curve's parameter direction
    bool sense;    // as the loop runs
    bool alongU;   // a pole column (v fixed) runs along u
    int index;     // the fixed row or column
  };
  const Border loopOrder[4] = {{2, 0, 1, true, true, 0},
                               {1, 1, 3, true, false, lastI},
                               {3, 2, 3, false, true, lastJ},
                               {0, 0, 2, false, false, 0}};
  std::vector<int> oriented;
  int seamEdge = 0;
  for (const Border& b : loopOrder) {
    if (s.degenerate[b.which]) continue;
    int edge = seamEdge;
    if (!(s.closedV && b.which == 3)) {
      std::vector<int> poles;
      for (int k = 0; k < (b.alongU ? s.countU : s.countV); ++k)
        poles.push_back(b.alongU ? pt(k, b.index) : pt(b.index, k));
      const int from = vertexOf(b.from), to = vertexOf(b.to);
      const int curve =
          writeCurve(d, b.alongU ? s.degreeU : s.degreeV, poles, b.alongU ? s.knotsU : s.knotsV, from == to);
      edge = d.add("EDGE_CURVE(''," + ref(from) + "," + ref(to) + "," + ref(curve) + ",.T.)");
      if (b.which == 2) seamEdge = edge;
    }
    oriented.push_back(d.add("ORIENTED_EDGE('',*,*," + ref(edge) + "," + logical(b.sense) + ")"));
  }
  const int loop = d.add("EDGE_LOOP(''," + refs(oriented) + ")");
  const int bound = d.add("FACE_OUTER_BOUND(''," + ref(loop) + ",.T.)");
  return d.add("ADVANCED_FACE(" + stepString(s.name) + ",(" + ref(bound) + ")," + ref(surface) + ",.T.)");
}

void appendHex(std::string* out, char32_t c, int digits) {
  char buf[12];
  std::snprintf(buf, sizeof buf, "%0*X", digits, unsigned(c));
  out->append(buf);
}

}  // namespace

std::string stepString(const std::string& utf8) {
  const std::vector<char32_t> cps = decodeUtf8(utf8);
  std::string out = "'";
  for (size_t i = 0; i < cps.size();) {
    const char32_t c = cps[i];
    if (c < 0x20 || (c >= 0x7F && c < 0xA0)) {  // C0 and C1 controls and DEL
      out += ' ';
      ++i;
    } else if (c < 0x7F) {
      out += c == '\'' ? "''" : c == '\\' ? "\\\\" : std::string(1, char(c));
      ++i;
    } else {
      // A run of printable non-ASCII characters in one directive: \X2\ holds 4 hex digits a
      // character (the BMP), \X4\ 8 (beyond it).
      const bool wide = c > 0xFFFF;
      out += wide ? "\\X4\\" : "\\X2\\";
      for (; i < cps.size() && cps[i] >= 0xA0 && (cps[i] > 0xFFFF) == wide; ++i) appendHex(&out, cps[i], wide ? 8 : 4);
      out += "\\X0\\";
    }
  }
  return out + "'";
}

std::string writeStep(const std::vector<BSplineSurface>& faces, const CadFileInfo& info) {
  checkFacesForCad(faces, info);
  const CadStamp t = cadStamp(info);
  char stamp[32];
  std::snprintf(stamp, sizeof stamp, "%04d-%02d-%02dT%02d:%02d:%02d", t.year, t.month, t.day, t.hour, t.minute,
                t.second);
  const std::string title = stepString(info.title);

  Data d;
  const int context = d.add("APPLICATION_CONTEXT('core data for automotive mechanical design processes')");
  d.add("APPLICATION_PROTOCOL_DEFINITION('international standard','automotive_design',2000," + ref(context) + ")");
  const int product = d.add("PRODUCT(" + title + "," + title + ",''," + "(" +
                            ref(d.add("PRODUCT_CONTEXT(''," + ref(context) + ",'mechanical')")) + "))");
  d.add("PRODUCT_RELATED_PRODUCT_CATEGORY('part',$,(" + ref(product) + "))");
  const int formation = d.add("PRODUCT_DEFINITION_FORMATION('',''," + ref(product) + ")");
  const int pdContext = d.add("PRODUCT_DEFINITION_CONTEXT('part definition'," + ref(context) + ",'design')");
  const int definition = d.add("PRODUCT_DEFINITION('design',''," + ref(formation) + "," + ref(pdContext) + ")");
  const int pdShape = d.add("PRODUCT_DEFINITION_SHAPE('',''," + ref(definition) + ")");
  const int representation = d.reserve();
  d.add("SHAPE_DEFINITION_REPRESENTATION(" + ref(pdShape) + "," + ref(representation) + ")");

  // Millimetres, radians, steradians; the tolerance as the distance accuracy of the context.
  const int mm = d.add("(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT(.MILLI.,.METRE.))");
  const int rad = d.add("(NAMED_UNIT(*)PLANE_ANGLE_UNIT()SI_UNIT($,.RADIAN.))");
  const int sr = d.add("(NAMED_UNIT(*)SI_UNIT($,.STERADIAN.)SOLID_ANGLE_UNIT())");
  const int uncertainty = d.add("UNCERTAINTY_MEASURE_WITH_UNIT(LENGTH_MEASURE(" + formatReal(info.tolerance) + ")," +
                                ref(mm) + ",'distance_accuracy_value','pdesurf export tolerance')");
  const int geometricContext =
      d.add("(GEOMETRIC_REPRESENTATION_CONTEXT(3)GLOBAL_UNCERTAINTY_ASSIGNED_CONTEXT((" + ref(uncertainty) +
            "))GLOBAL_UNIT_ASSIGNED_CONTEXT((" + ref(mm) + "," + ref(rad) + "," + ref(sr) +
            "))REPRESENTATION_CONTEXT('3D','3D context with units and uncertainty'))");

  // An open shell is a connected face set and the faces share no edges: one shell a face.
  std::vector<int> shells;
  for (const BSplineSurface& s : faces) shells.push_back(d.add("OPEN_SHELL('',(" + ref(writeFace(d, s)) + "))"));
  const int model = d.add("SHELL_BASED_SURFACE_MODEL(''," + refs(shells) + ")");
  const int origin = d.add("AXIS2_PLACEMENT_3D(''," + ref(d.add("CARTESIAN_POINT('',(0.,0.,0.))")) + "," +
                           ref(d.add("DIRECTION('',(0.,0.,1.))")) + "," + ref(d.add("DIRECTION('',(1.,0.,0.))")) + ")");
  d.set(representation, "MANIFOLD_SURFACE_SHAPE_REPRESENTATION(" + title + ",(" + ref(origin) + "," + ref(model) +
                            ")," + ref(geometricContext) + ")");

  std::string out = "ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION(('pdesurf B-spline surfaces'),'2;1');\n";
  out += "FILE_NAME(" + title + ",'" + stamp + "',(''),(''),'pdesurf','pdesurf','');\n";
  out += "FILE_SCHEMA(('AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }'));\nENDSEC;\nDATA;\n";
  d.appendTo(&out);
  out += "ENDSEC;\nEND-ISO-10303-21;\n";
  return out;
}

}  // namespace pdesurf
