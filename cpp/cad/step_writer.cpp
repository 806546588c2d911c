#include "cad/step_writer.hpp"

#include <algorithm>
#include <cstdio>

#include "cad/brep_topology.hpp"

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

// A face's surface: the B-spline with its own control points.
int writeSurface(Data& d, const BSplineSurface& s) {
  std::vector<int> pts(s.poles.size());
  for (size_t k = 0; k < s.poles.size(); ++k) pts[k] = writePoint(d, s.poles[k]);
  std::vector<double> ku, kv;
  std::vector<int> mu, mv;
  knotsWithMultiplicities(s.knotsU, &ku, &mu);
  knotsWithMultiplicities(s.knotsV, &kv, &mv);
  std::string rows = "(";
  for (int i = 0; i < s.countU; ++i) {
    std::vector<int> row(pts.begin() + i * s.countV, pts.begin() + (i + 1) * s.countV);
    rows += (i ? "," : "") + refs(row);
  }
  rows += ")";
  return d.add("B_SPLINE_SURFACE_WITH_KNOTS(''," + std::to_string(s.degreeU) + "," + std::to_string(s.degreeV) + "," + rows +
               ",.UNSPECIFIED.,.F.," + logical(s.closedV) + ",.F.," + ints(mu) + "," + ints(mv) + "," + reals(ku) + "," + reals(kv) +
               ",.UNSPECIFIED.)");
}

// A pcurve's 2D B-spline in the parametric context.
int writePcurve(Data& d, const BrepPcurve& p, int surface, int context2d) {
  std::vector<int> poles;
  for (const Eigen::Vector2d& q : p.poles) poles.push_back(d.add("CARTESIAN_POINT('',(" + formatReal(q.x()) + "," + formatReal(q.y()) + "))"));
  const int curve = writeCurve(d, p.degree, poles, p.knots, false);
  const int rep = d.add("DEFINITIONAL_REPRESENTATION(''," + refs({curve}) + "," + ref(context2d) + ")");
  return d.add("PCURVE(''," + ref(surface) + "," + ref(rep) + ")");
}

// The topology's vertices, edges and faces (cad/brep_topology.hpp): a shared edge is one
// EDGE_CURVE that both faces' loops name, each in its own direction, its SURFACE_CURVE carrying
// its curve in both faces' parameters; a flipped face has same_sense .F. and its loop already
// runs the other way. Returns the ADVANCED_FACE ids.
std::vector<int> writeFaces(Data& d, const std::vector<BSplineSurface>& faces, const BrepTopology& t) {
  std::vector<int> surface;
  for (const BSplineSurface& f : faces) surface.push_back(writeSurface(d, f));
  const int context2d =
      d.add("(GEOMETRIC_REPRESENTATION_CONTEXT(2)PARAMETRIC_REPRESENTATION_CONTEXT()REPRESENTATION_CONTEXT('2D SPACE',''))");
  std::vector<int> vertex;
  for (const Eigen::Vector3d& p : t.vertices) vertex.push_back(d.add("VERTEX_POINT(''," + ref(writePoint(d, p)) + ")"));
  std::vector<int> edge;
  for (const BrepEdge& e : t.edges) {
    std::vector<int> poles;
    for (const Eigen::Vector3d& p : e.curve.poles) poles.push_back(writePoint(d, p));
    int curve = writeCurve(d, e.curve.degree, poles, e.curve.knots, e.start == e.end);
    if (!e.pcurves.empty()) {
      std::vector<int> pcurves;
      for (const BrepPcurve& p : e.pcurves) pcurves.push_back(writePcurve(d, p, surface[size_t(p.face)], context2d));
      curve = d.add("SURFACE_CURVE(''," + ref(curve) + "," + refs(pcurves) + ",.CURVE_3D.)");
    }
    edge.push_back(d.add("EDGE_CURVE(''," + ref(vertex[size_t(e.start)]) + "," + ref(vertex[size_t(e.end)]) + "," + ref(curve) + ",.T.)"));
  }
  std::vector<int> out;
  for (size_t f = 0; f < faces.size(); ++f) {
    std::vector<int> oriented;
    for (const BrepEdgeUse& u : t.faces[f].loop)
      oriented.push_back(d.add("ORIENTED_EDGE('',*,*," + ref(edge[size_t(u.edge)]) + "," + logical(u.forward) + ")"));
    const int loop = d.add("EDGE_LOOP(''," + refs(oriented) + ")");
    const int bound = d.add("FACE_OUTER_BOUND(''," + ref(loop) + ",.T.)");
    out.push_back(d.add("ADVANCED_FACE(" + stepString(faces[f].name) + ",(" + ref(bound) + ")," + ref(surface[f]) + "," +
                        logical(!t.faces[f].flipped) + ")"));
  }
  return out;
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

std::string writeStep(const std::vector<BSplineSurface>& faces, const CadFileInfo& info, const BrepTopology* topology) {
  checkFacesForCad(faces, info);
  const BrepTopology own = topology ? BrepTopology{} : buildTopology(faces, {}, info.tolerance);
  const BrepTopology& t = topology ? *topology : own;
  const CadStamp stampOf = cadStamp(info);
  char stamp[32];
  std::snprintf(stamp, sizeof stamp, "%04d-%02d-%02dT%02d:%02d:%02d", stampOf.year, stampOf.month, stampOf.day, stampOf.hour,
                stampOf.minute, stampOf.second);
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
  // The distance accuracy: the fit's tolerance, or the largest gap the topology closed if larger.
  const double accuracy = std::max({info.tolerance, t.edgeGap, t.vertexSpread});
  const int uncertainty = d.add("UNCERTAINTY_MEASURE_WITH_UNIT(LENGTH_MEASURE(" + formatReal(accuracy) + ")," +
                                ref(mm) + ",'distance_accuracy_value','pdesurf export tolerance')");
  const int geometricContext =
      d.add("(GEOMETRIC_REPRESENTATION_CONTEXT(3)GLOBAL_UNCERTAINTY_ASSIGNED_CONTEXT((" + ref(uncertainty) +
            "))GLOBAL_UNIT_ASSIGNED_CONTEXT((" + ref(mm) + "," + ref(rad) + "," + ref(sr) +
            "))REPRESENTATION_CONTEXT('3D','3D context with units and uncertainty'))");

  // Each connected set of faces is a shell: closed, the boundary of a solid; else open.
  const std::vector<int> faceIds = writeFaces(d, faces, t);
  std::vector<int> solids, openShells;
  for (const BrepShell& sh : t.shells) {
    std::vector<int> members;
    for (int f : sh.faces) members.push_back(faceIds[size_t(f)]);
    const int shell = d.add(std::string(sh.closed ? "CLOSED_SHELL" : "OPEN_SHELL") + "(''," + refs(members) + ")");
    if (sh.closed) solids.push_back(d.add("MANIFOLD_SOLID_BREP(" + title + "," + ref(shell) + ")"));
    else openShells.push_back(shell);
  }
  const int origin = d.add("AXIS2_PLACEMENT_3D(''," + ref(d.add("CARTESIAN_POINT('',(0.,0.,0.))")) + "," +
                           ref(d.add("DIRECTION('',(0.,0.,1.))")) + "," + ref(d.add("DIRECTION('',(1.,0.,0.))")) + ")");
  std::vector<int> items = solids;
  if (!openShells.empty()) items.push_back(d.add("SHELL_BASED_SURFACE_MODEL(''," + refs(openShells) + ")"));
  items.push_back(origin);
  // Every body closed: an advanced B-rep of solids (several bodies stay several); every body
  // open: a manifold surface model; both: a plain shape representation holds the solids and
  // the surface model side by side (the advanced and surface representations each admit only
  // their own kind).
  const char* representationType = openShells.empty() ? "ADVANCED_BREP_SHAPE_REPRESENTATION"
                                   : solids.empty()   ? "MANIFOLD_SURFACE_SHAPE_REPRESENTATION"
                                                      : "SHAPE_REPRESENTATION";
  d.set(representation, std::string(representationType) + "(" + title + "," + refs(items) + "," + ref(geometricContext) + ")");

  std::string out = "ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION(('pdesurf B-spline surfaces'),'2;1');\n";
  out += "FILE_NAME(" + title + ",'" + stamp + "',(''),(''),'pdesurf','pdesurf','');\n";
  out += "FILE_SCHEMA(('AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }'));\nENDSEC;\nDATA;\n";
  d.appendTo(&out);
  out += "ENDSEC;\nEND-ISO-10303-21;\n";
  return out;
}

}  // namespace pdesurf
