// Fills side by side with Open CASCADE's BRepOffsetAPI_MakeFilling (issue 35, docs/chains-and-fills.md
// "Side by side with Open CASCADE"). The same holes for both: an irregular convex N-gon (N = 3..8)
// cut in the sheet z = a x² + b y² + c xy + d x³ and ringed by strips of it. Each strip is exactly
// a bicubic Bézier patch (its x, y are linear in (t, v), so z is cubic), which is what OCCT gets,
// with the strip's t0 edge as a G1 (or G2) constraint; pdesurf gets the same strips as typed
// surfaces and a "fill". Both results are measured by the same code, from outside: along every
// side the largest gap and normal angle to the strip (256 points, OCCT's face found by projection),
// and the crease measure 2a(h/2) - a(h) inside (128² and 256²; OCCT's spline over its face's
// parameter box), with the time of the fill alone. Output: a Markdown table per setting.
//   occt_filling_compare [HOLES] [--g2] [--no-tight]   (--no-tight: OCCT's defaults only; its tight
//   setting takes minutes per hole at G2)
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepOffsetAPI_MakeFilling.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <GeomLProp_SLProps.hxx>
#include <Geom_BezierSurface.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <vector>

#include "analysis/edge_samples.hpp"
#include "analysis/interior_creases.hpp"
#include "analysis/join_certificate.hpp"
#include "scene/scene.hpp"

using json = nlohmann::json;
using Clock = std::chrono::steady_clock;

namespace {

struct Sheet {
  double a, b, c, d;
  double z(double x, double y) const { return a * x * x + b * y * y + c * x * y + d * x * x * x; }
  Eigen::Vector3d normal(double x, double y) const {
    return Eigen::Vector3d(-(2 * a * x + c * y + 3 * d * x * x), -(2 * b * y + c * x), 1).normalized();
  }
};

struct Strip {
  Eigen::Vector2d p0, e, o;  // (x, y) = p0 + v e + t o
};

struct Hole {
  Sheet sheet;
  std::vector<Strip> strips;
};

Hole makeHole(int n, std::mt19937& rng) {
  std::uniform_real_distribution<double> coef(-0.4, 0.4), cubic(-0.1, 0.1), jitter(-0.5, 0.5);
  Hole h;
  h.sheet = {coef(rng), coef(rng), coef(rng), cubic(rng)};
  const double turn = 2 * M_PI * (jitter(rng) + 0.5);
  std::vector<Eigen::Vector2d> corner(n);
  for (int k = 0; k < n; ++k) {
    const double angle = turn + 2 * M_PI * (k + 0.4 * jitter(rng)) / n, radius = 1 + 0.15 * jitter(rng);
    corner[k] = {radius * std::cos(angle), radius * std::sin(angle)};
  }
  for (int k = 0; k < n; ++k) {
    const Eigen::Vector2d e = corner[(k + 1) % n] - corner[k];
    h.strips.push_back({corner[k], e, 0.5 * Eigen::Vector2d(e.y(), -e.x()) / e.norm()});
  }
  return h;
}

Eigen::Vector3d stripPoint(const Sheet& s, const Strip& st, double t, double v) {
  const Eigen::Vector2d p = st.p0 + v * st.e + t * st.o;
  return {p.x(), p.y(), s.z(p.x(), p.y())};
}

std::string num(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "(%.17g)", x);
  return buf;
}

json sceneOf(const Hole& h, bool g2) {
  json patches = json::array(), borders = json::array();
  for (size_t k = 0; k < h.strips.size(); ++k) {
    const Strip& st = h.strips[k];
    const std::string X = num(st.p0.x()) + " + " + num(st.e.x()) + "*v + " + num(st.o.x()) + "*t";
    const std::string Y = num(st.p0.y()) + " + " + num(st.e.y()) + "*v + " + num(st.o.y()) + "*t";
    const std::string Z = num(h.sheet.a) + "*(" + X + ")^2 + " + num(h.sheet.b) + "*(" + Y + ")^2 + " + num(h.sheet.c) + "*(" + X + ")*(" + Y + ") + " +
                          num(h.sheet.d) + "*(" + X + ")^3";
    const std::string name = "strip" + std::to_string(k);
    patches.push_back({{"name", name}, {"kind", "surface"}, {"t_range", {0, 1}}, {"v_range", {0, 1}}, {"x", X}, {"y", Y}, {"z", Z}});
    borders.push_back({{"patch", name}, {"at", "t0"}});
  }
  patches.push_back({{"name", "fill"}, {"kind", "fill"}, {"borders", borders}, {"continuity", g2 ? "curvature" : "tangency"}});
  return {{"format", "pdesurf-scene"}, {"version", 4}, {"patches", patches}};
}

// A strip as the bicubic Bézier patch it is (U = t, V = v): interpolation at 4 × 4 points.
Handle(Geom_BezierSurface) stripSurface(const Sheet& s, const Strip& st) {
  Eigen::Matrix4d B;  // Bernstein values at 0, 1/3, 2/3, 1
  for (int i = 0; i < 4; ++i) {
    const double x = i / 3.0;
    B.row(i) << std::pow(1 - x, 3), 3 * x * std::pow(1 - x, 2), 3 * x * x * (1 - x), std::pow(x, 3);
  }
  const Eigen::Matrix4d Bi = B.inverse();
  TColgp_Array2OfPnt poles(1, 4, 1, 4);
  for (int c = 0; c < 3; ++c) {
    Eigen::Matrix4d P;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) P(i, j) = stripPoint(s, st, i / 3.0, j / 3.0)(c);
    const Eigen::Matrix4d C = Bi * P * Bi.transpose();
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) {
        gp_Pnt q = poles(i + 1, j + 1);
        q.SetCoord(c + 1, C(i, j));
        poles.SetValue(i + 1, j + 1, q);
      }
  }
  return new Geom_BezierSurface(poles);
}

struct Figures {
  bool built = false;
  std::string error;
  double gap = 0, angleDeg = 0, curvature = 0;  // along the sides (curvature: relative, G2 only)
  double crease = 0, fromSheet = 0, ms = 0;
};

// Along every side: the filling surface S (found by projection) against the sheet there.
template <class Eval>
void measureSides(const Hole& h, const Eval& fillAt, Figures* f) {
  for (const Strip& st : h.strips)
    for (int k = 0; k < 256; ++k) {
      const double v = (k + 0.5) / 256;
      const Eigen::Vector3d p = stripPoint(h.sheet, st, 0, v);
      Eigen::Vector3d q, n;
      if (!fillAt(p, &q, &n)) continue;
      f->gap = std::max(f->gap, (q - p).norm());
      const Eigen::Vector3d m = h.sheet.normal(p.x(), p.y());
      f->angleDeg = std::max(f->angleDeg, std::atan2(m.cross(n).norm(), std::abs(m.dot(n))) * 180 / M_PI);
    }
}

Figures occtFill(const Hole& h, bool g2, bool best) {
  Figures f;
  try {
    const auto start = Clock::now();
    // Defaults: degree 3, 15 points per curve, 2 iterations, tolerances 1e-5 / 1e-4 / 0.01 rad / 0.1.
    BRepOffsetAPI_MakeFilling fill = best ? BRepOffsetAPI_MakeFilling(3, 40, 4, Standard_False, 1e-7, 1e-6, 1e-4, 1e-3, 12, 16)
                                          : BRepOffsetAPI_MakeFilling();
    for (const Strip& st : h.strips) {
      const TopoDS_Face face = BRepBuilderAPI_MakeFace(stripSurface(h.sheet, st), 0, 1, 0, 1, 1e-9);
      // The face's edge U = 0 (t = 0), with its pcurve: the one whose middle is the side's.
      const Eigen::Vector3d middle = stripPoint(h.sheet, st, 0, 0.5);
      TopoDS_Edge side;
      double nearest = HUGE_VAL;
      for (TopExp_Explorer e(face, TopAbs_EDGE); e.More(); e.Next()) {
        Standard_Real a, b;
        const Handle(Geom_Curve) c = BRep_Tool::Curve(TopoDS::Edge(e.Current()), a, b);
        const gp_Pnt m = c->Value((a + b) / 2);
        const double d = (Eigen::Vector3d(m.X(), m.Y(), m.Z()) - middle).norm();
        if (d < nearest) nearest = d, side = TopoDS::Edge(e.Current());
      }
      fill.Add(side, face, g2 ? GeomAbs_G2 : GeomAbs_G1, Standard_True);
    }
    fill.Build();
    if (!fill.IsDone()) {
      f.error = "not done";
      return f;
    }
    f.ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    const TopoDS_Face result = TopoDS::Face(fill.Shape());
    const Handle(Geom_Surface) S = BRep_Tool::Surface(result);
    GeomAPI_ProjectPointOnSurf project;
    const auto at = [&](const Eigen::Vector3d& p, Eigen::Vector3d* q, Eigen::Vector3d* n) {
      project.Init(gp_Pnt(p.x(), p.y(), p.z()), S);
      if (!project.IsDone() || project.NbPoints() == 0) return false;
      Standard_Real u, v;
      project.LowerDistanceParameters(u, v);
      GeomLProp_SLProps props(S, u, v, 1, 1e-12);
      if (!props.IsNormalDefined()) return false;
      const gp_Pnt x = props.Value();
      const gp_Dir d = props.Normal();
      *q = {x.X(), x.Y(), x.Z()}, *n = {d.X(), d.Y(), d.Z()};
      return true;
    };
    measureSides(h, at, &f);
    // Inside: the crease measure over the face's parameter box, and the distance to the sheet.
    Standard_Real u0, u1, v0, v1;
    BRepTools::UVBounds(result, u0, u1, v0, v1);
    double turn[2] = {0, 0};
    for (int level = 0; level < 2; ++level) {
      const int m = 128 << level;
      std::vector<Eigen::Vector3d> normal((m + 1) * (m + 1));
      for (int j = 0; j <= m; ++j)
        for (int i = 0; i <= m; ++i) {
          GeomLProp_SLProps props(S, u0 + (u1 - u0) * i / m, v0 + (v1 - v0) * j / m, 1, 1e-12);
          const gp_Dir d = props.IsNormalDefined() ? props.Normal() : gp_Dir(0, 0, 1);
          normal[size_t(j) * (m + 1) + i] = {d.X(), d.Y(), d.Z()};
        }
      const auto angle = [&](size_t a, size_t b) { return std::atan2(normal[a].cross(normal[b]).norm(), normal[a].dot(normal[b])) * 180 / M_PI; };
      for (int j = 0; j <= m; ++j)
        for (int i = 0; i <= m; ++i) {
          const size_t k = size_t(j) * (m + 1) + i;
          if (i < m) turn[level] = std::max(turn[level], angle(k, k + 1));
          if (j < m) turn[level] = std::max(turn[level], angle(k, k + m + 1));
        }
    }
    f.crease = std::max(0.0, 2 * turn[1] - turn[0]);
    // Off the sheet: the sheet's points over the hole (its corners drawn 2 % towards their
    // centroid) projected on the filling surface.
    Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
    for (const Strip& st : h.strips) centroid += st.p0 / double(h.strips.size());
    for (const Strip& st : h.strips)
      for (int i = 0; i <= 16; ++i)
        for (int j = 0; j <= 16 - i; ++j) {  // a triangle fan: centroid, corner k, corner k + 1
          const Eigen::Vector2d a = st.p0 - centroid, b = st.p0 + st.e - centroid;
          const Eigen::Vector2d xy = centroid + 0.98 * (a * i + b * j) / 16.0;
          project.Init(gp_Pnt(xy.x(), xy.y(), h.sheet.z(xy.x(), xy.y())), S);
          if (project.IsDone() && project.NbPoints() > 0) f.fromSheet = std::max(f.fromSheet, project.LowerDistance());
        }
    f.built = true;
  } catch (const Standard_Failure& e) {
    f.error = e.GetMessageString();
  }
  return f;
}

Figures pdesurfFill(const Hole& h, bool g2) {
  Figures f;
  try {
    const pdesurf::Scene scene = pdesurf::parseScene(sceneOf(h, g2).dump());
    const auto start = Clock::now();
    const auto solved = pdesurf::solveScene(scene);
    f.ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    const pdesurf::SeparableSurface* fill = nullptr;
    for (const auto& sp : solved)
      if (sp.patch->name == "fill") fill = &sp.surface;
    // Along the sides: the fill's own border points and normals are what a CAD reader sees;
    // found here, like OCCT's, by the nearest of a fine sampling of its border u = 0 (exact:
    // the side is the fill's border) and measured against the sheet.
    const std::vector<pdesurf::EdgePoint> border = pdesurf::edgeSamples(*fill, false, 0, fill->v0, fill->v1, 2049);
    const auto at = [&](const Eigen::Vector3d& p, Eigen::Vector3d* q, Eigen::Vector3d* n) {
      double best = HUGE_VAL, bestV = 0;
      for (size_t k = 0; k < border.size(); ++k) {
        const double d = (border[k].X - p).norm();
        if (d < best) best = d, bestV = fill->v0 + (fill->v1 - fill->v0) * double(k) / double(border.size() - 1);
      }
      // Refine by Newton on |X(0, v) - p|² along the border.
      for (int it = 0; it < 6; ++it) {
        const Eigen::Vector3d X = pdesurf::evalPoint(*fill, 0, bestV), Xv = pdesurf::evalPoint(*fill, 0, bestV, 0, 1),
                              Xvv = pdesurf::evalPoint(*fill, 0, bestV, 0, 2);
        const double g = (X - p).dot(Xv), H = Xv.dot(Xv) + (X - p).dot(Xvv);
        if (!(H > 0)) break;
        bestV -= g / H;
      }
      *q = pdesurf::evalPoint(*fill, 0, bestV);
      *n = pdesurf::evalPoint(*fill, 0, bestV, 1, 0).cross(pdesurf::evalPoint(*fill, 0, bestV, 0, 1)).normalized();
      return n->allFinite();
    };
    measureSides(h, at, &f);
    f.crease = pdesurf::measureCreases("fill", *fill).creaseDeg;
    for (int i = 0; i <= 64; ++i)
      for (int j = 0; j < 128; ++j) {
        const Eigen::Vector3d x = pdesurf::evalPoint(*fill, i / 64.0, 2 * M_PI * j / 128);
        f.fromSheet = std::max(f.fromSheet, std::abs(x.z() - h.sheet.z(x.x(), x.y())));
      }
    f.built = true;
  } catch (const std::exception& e) {
    f.error = e.what();
  }
  return f;
}

}  // namespace

int main(int argc, char** argv) {
  int holes = 12;
  bool g2 = false, tight = true;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--g2") g2 = true;
    else if (a == "--no-tight") tight = false;
    else holes = std::max(1, std::atoi(argv[i]));
  }
  std::mt19937 rng(2035);
  struct Row {
    std::string name;
    std::vector<Figures> f;
  };
  std::vector<Row> rows{{"pdesurf fill", {}}, {"OCCT MakeFilling, defaults", {}}};
  if (tight) rows.push_back({"OCCT MakeFilling, tight (40 pts/curve, 4 iterations, tight tolerances)", {}});
  for (int k = 0; k < holes; ++k) {
    const Hole h = makeHole(3 + k % 6, rng);
    rows[0].f.push_back(pdesurfFill(h, g2));
    rows[1].f.push_back(occtFill(h, g2, false));
    if (tight) rows[2].f.push_back(occtFill(h, g2, true));
  }
  std::printf("%d holes (N = 3..8, irregular, convex) in z = a x² + b y² + c xy + d x³, %s to every side; largest over the holes "
              "(median time)\n\n",
              holes, g2 ? "G2" : "G1");
  std::printf("| fill | built | gap on sides | normal angle on sides (°) | crease inside (°) | off the sheet | time (ms) |\n|---|---|---|---|---|---|---|\n");
  for (const Row& r : rows) {
    int built = 0;
    Figures worst;
    std::vector<double> ms;
    std::string error;
    for (const Figures& f : r.f) {
      if (!f.built) {
        if (error.empty()) error = f.error;
        continue;
      }
      ++built;
      worst.gap = std::max(worst.gap, f.gap), worst.angleDeg = std::max(worst.angleDeg, f.angleDeg);
      worst.crease = std::max(worst.crease, f.crease), worst.fromSheet = std::max(worst.fromSheet, f.fromSheet);
      ms.push_back(f.ms);
    }
    std::sort(ms.begin(), ms.end());
    std::printf("| %s | %d of %zu%s | %.1e | %.1e | %.3g | %.1e | %.1f |\n", r.name.c_str(), built, r.f.size(), error.empty() ? "" : (" (" + error + ")").c_str(),
                worst.gap, worst.angleDeg, worst.crease, worst.fromSheet, ms.empty() ? 0.0 : ms[ms.size() / 2]);
  }
  return 0;
}
