#include "cad/brep_3dm.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "cad/face_loops.hpp"
#include "cad/on_archive.hpp"

namespace pdesurf {

namespace {

// openNURBS enums (opennurbs_brep.h, opennurbs_surface.h).
enum TrimType { kBoundary = 1, kMated = 2, kSeam = 3, kSingular = 4 };
enum Iso { kNotIso = 0, kXIso = 1, kYIso = 2, kWest = 3, kSouth = 4, kEast = 5, kNorth = 6 };
constexpr int kOuterLoop = 1;
constexpr const char* kNurbsCurveUuid = "4ED7D4DD-E947-11d3-BFE5-0010830122F0";
constexpr const char* kNurbsSurfaceUuid = "4ED7D4DE-E947-11d3-BFE5-0010830122F0";
constexpr const char* kBrepUuid = "60B5DBC5-E660-11d3-BFE4-0010830122F0";

struct Trim {
  int curve = 0, edge = -1, v0 = 0, v1 = 0, loop = 0;
  bool rev3d = false;
  int type = kBoundary, iso = kNotIso;
};

struct Edge {
  int global = 0, v0 = 0, v1 = 0;
  std::vector<int> trims;
  double tolerance = 0;
};

// A curve run the other way over the same parameter interval.
BrepPcurve reversed(BrepPcurve c) {
  const double a = c.knots.front(), b = c.knots.back();
  std::reverse(c.poles.begin(), c.poles.end());
  std::reverse(c.knots.begin(), c.knots.end());
  for (double& k : c.knots) k = a + b - k;
  return c;
}

BrepPcurve line(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  BrepPcurve c;  // degree 1
  c.knots = {0, 0, 1, 1};
  c.poles = {a, b};
  return c;
}

// Where a curve in (u, v) lies on the surface's box: a side, an iso-line inside, or neither.
int isoOf(const BrepPcurve& c, const BSplineSurface& s) {
  const auto all = [&](int axis, double x) {
    return std::all_of(c.poles.begin(), c.poles.end(), [&](const Eigen::Vector2d& p) { return p[axis] == x; });
  };
  if (all(0, s.u0())) return kWest;
  if (all(0, s.u1())) return kEast;
  if (all(1, s.v0())) return kSouth;
  if (all(1, s.v1())) return kNorth;
  if (all(0, c.poles.front().x())) return kXIso;
  if (all(1, c.poles.front().y())) return kYIso;
  return kNotIso;
}

// The side of the box both points lie on (a collapsed border), or -1.
int commonSide(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const BSplineSurface& s) {
  if (a.x() == s.u0() && b.x() == s.u0() && s.degenerate[0]) return kWest;
  if (a.x() == s.u1() && b.x() == s.u1() && s.degenerate[1]) return kEast;
  if (a.y() == s.v0() && b.y() == s.v0() && s.degenerate[2]) return kSouth;
  if (a.y() == s.v1() && b.y() == s.v1() && s.degenerate[3]) return kNorth;
  return -1;
}

void writeCurve(OnArchive& a, int dim, int degree, const std::vector<double>& knots, const double* poles, size_t count) {
  a.object(kNurbsCurveUuid, [&](OnArchive& w) {
    w.version(1, 1);
    w.i32(dim), w.i32(0), w.i32(degree + 1), w.i32(int32_t(count)), w.i32(0), w.i32(0);
    w.point({1, 0, 0}), w.point({-1, 0, 0});  // "no box", as openNURBS writes it
    w.i32(int32_t(knots.size() - 2));          // openNURBS keeps no end knot twice over
    for (size_t k = 1; k + 1 < knots.size(); ++k) w.f64(knots[k]);
    w.i32(int32_t(count));
    for (size_t k = 0; k < count * size_t(dim); ++k) w.f64(poles[k]);
    w.boolean(false);  // SubD-friendly tag
  });
}

void writeSurface(OnArchive& a, const BSplineSurface& s) {
  a.object(kNurbsSurfaceUuid, [&](OnArchive& w) {
    w.version(1, 0);
    w.i32(3), w.i32(0), w.i32(s.degreeU + 1), w.i32(s.degreeV + 1), w.i32(s.countU), w.i32(s.countV), w.i32(0), w.i32(0);
    w.point({1, 0, 0}), w.point({-1, 0, 0});
    for (const std::vector<double>* knots : {&s.knotsU, &s.knotsV}) {
      w.i32(int32_t(knots->size() - 2));
      for (size_t k = 1; k + 1 < knots->size(); ++k) w.f64((*knots)[k]);
    }
    w.i32(s.countU * s.countV);
    for (const Eigen::Vector3d& p : s.poles) w.point(p);  // i along u outside, j along v inside: openNURBS's order
  });
}

// An array of objects (ON_CurveArray / ON_SurfaceArray::Write), each flagged present.
template <class Each>
void writeObjects(OnArchive& a, size_t count, Each each) {
  a.beginChunk(kOnTcodeAnonymous);
  a.version(1, 0);
  a.i32(int32_t(count));
  for (size_t k = 0; k < count; ++k) {
    a.i32(1);
    each(k);
  }
  a.endChunk();
}

// A table of topology records (ON_BrepVertexArray::Write and the like); `after` adds what
// a later chunk version appended.
template <class Each, class After>
void writeRecords(OnArchive& a, int minor, size_t count, Each each, After after) {
  a.beginChunk(kOnTcodeAnonymous);
  a.version(1, minor);
  a.i32(int32_t(count));
  for (size_t k = 0; k < count; ++k) each(int(k));
  after();
  a.endChunk();
}
const auto nothing = [] {};

class BodyWriter {
 public:
  BodyWriter(const std::vector<BSplineSurface>& faces, const BrepTopology& t, const BrepShell& shell)
      : faces_(faces), t_(t), shell_(shell) {}

  std::string write() {
    for (size_t k = 0; k < shell_.faces.size(); ++k) addFace(int(k), shell_.faces[k]);
    OnArchive a;
    a.object(kBrepUuid, [&](OnArchive& w) { writeBrep(w); });
    return a.bytes();
  }

 private:
  int vertexOf(int global) {
    const auto [it, added] = vertex_.emplace(global, int(vertices_.size()));
    if (added) vertices_.push_back({global, {}});
    return it->second;
  }

  int edgeOf(int global) {
    const auto [it, added] = edge_.emplace(global, int(edges_.size()));
    if (added) {
      const BrepEdge& e = t_.edges[size_t(global)];
      Edge out;
      out.global = global, out.v0 = vertexOf(e.start), out.v1 = vertexOf(e.end);
      out.tolerance = e.gap;
      edges_.push_back(out);
      vertices_[size_t(out.v0)].edges.push_back(it->second);
      vertices_[size_t(out.v1)].edges.push_back(it->second);  // a closed edge twice, as openNURBS keeps it
    }
    return it->second;
  }

  void addFace(int loop, int f) {
    const BSplineSurface& s = faces_[size_t(f)];
    std::vector<Trim> trims;
    std::vector<BrepPcurve> curves;
    for (const BrepEdgeUse& use : surfaceLoop(t_, size_t(f))) {
      BrepPcurve c = usePcurve(s, t_, f, use);  // runs with the edge's curve; a trim runs with the loop
      if (!use.forward) c = reversed(c);
      Trim tr;
      tr.edge = edgeOf(use.edge);
      const Edge& e = edges_[size_t(tr.edge)];
      tr.rev3d = !use.forward;
      tr.v0 = use.forward ? e.v0 : e.v1, tr.v1 = use.forward ? e.v1 : e.v0;
      tr.iso = isoOf(c, s);
      tr.loop = loop;
      trims.push_back(tr);
      curves.push_back(c);
    }
    // A piece of border shorter than the tolerance is a vertex in the topology: the trim before
    // it reaches over it in (u, v), and its edge's tolerance covers the piece's length.
    for (size_t k = 0; k < trims.size(); ++k) {
      const size_t next = (k + 1) % trims.size();
      const Eigen::Vector2d a = curves[k].poles.back(), b = curves[next].poles.front();
      if (a == b || commonSide(a, b, s) >= 0 || trims[k].v1 != trims[next].v0) continue;
      curves[k].poles.back() = b;
      trims[k].iso = isoOf(curves[k], s);
      Edge& e = edges_[size_t(trims[k].edge)];
      e.tolerance = std::max(e.tolerance, (evaluate(s, a.x(), a.y()) - evaluate(s, b.x(), b.y())).norm());
    }
    // A collapsed border has no edge: a singular trim along it, at the vertex there.
    std::vector<Trim> closedTrims;
    std::vector<BrepPcurve> closedCurves;
    for (size_t k = 0; k < trims.size(); ++k) {
      closedTrims.push_back(trims[k]);
      closedCurves.push_back(curves[k]);
      const Eigen::Vector2d a = curves[k].poles.back(), b = curves[(k + 1) % trims.size()].poles.front();
      const int side = a == b ? -1 : commonSide(a, b, s);
      if (side < 0) continue;
      Trim sing;
      sing.type = kSingular, sing.iso = side, sing.loop = loop, sing.v0 = sing.v1 = trims[k].v1;
      closedTrims.push_back(sing);
      closedCurves.push_back(line(a, b));
    }
    std::vector<int> ids;
    for (size_t k = 0; k < closedTrims.size(); ++k) {
      Trim tr = closedTrims[k];
      tr.curve = int(curves2_.size());
      curves2_.push_back(closedCurves[k]);
      const int id = int(trims_.size());
      if (tr.edge >= 0) edges_[size_t(tr.edge)].trims.push_back(id);
      trims_.push_back(tr);
      ids.push_back(id);
    }
    loops_.push_back(ids);
  }

  // Trim types once every face is in: an edge's two trims are mated, or a seam in one loop.
  void typeTrims() {
    for (Trim& tr : trims_) {
      if (tr.type == kSingular) continue;
      const Edge& e = edges_[size_t(tr.edge)];
      if (e.trims.size() < 2) tr.type = kBoundary;
      else tr.type = trims_[size_t(e.trims[0])].loop == trims_[size_t(e.trims[1])].loop ? kSeam : kMated;
    }
  }

  void writeBrep(OnArchive& w) {
    typeTrims();
    w.version(3, 3);
    writeObjects(w, curves2_.size(), [&](size_t k) {
      const BrepPcurve& c = curves2_[k];
      std::vector<double> xy;
      for (const Eigen::Vector2d& p : c.poles) xy.insert(xy.end(), {p.x(), p.y()});
      writeCurve(w, 2, c.degree, c.knots, xy.data(), c.poles.size());
    });
    writeObjects(w, edges_.size(), [&](size_t k) {
      const BSplineCurve& c = t_.edges[size_t(edges_[k].global)].curve;
      std::vector<double> xyz;
      for (const Eigen::Vector3d& p : c.poles) xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
      writeCurve(w, 3, c.degree, c.knots, xyz.data(), c.poles.size());
    });
    writeObjects(w, shell_.faces.size(), [&](size_t k) { writeSurface(w, faces_[size_t(shell_.faces[k])]); });

    writeRecords(w, 0, vertices_.size(), [&](int k) {
      w.i32(k);
      w.point(t_.vertices[size_t(vertices_[size_t(k)].global)]);
      w.ints(vertices_[size_t(k)].edges);
      w.f64(t_.vertexSpread);
    }, nothing);
    writeRecords(w, 0, edges_.size(), [&](int k) {
      const Edge& e = edges_[size_t(k)];
      const BSplineCurve& c = t_.edges[size_t(e.global)].curve;
      w.i32(k), w.i32(k), w.i32(0);  // index, its 3D curve, not reversed
      w.interval(c.knots.front(), c.knots.back());
      w.i32(e.v0), w.i32(e.v1);
      w.ints(e.trims);
      w.f64(e.tolerance);
      w.interval(c.knots.front(), c.knots.back());
    }, nothing);
    writeRecords(w, 0, trims_.size(), [&](int k) {
      const Trim& tr = trims_[size_t(k)];
      const BrepPcurve& c = curves2_[size_t(tr.curve)];
      w.i32(k), w.i32(tr.curve);
      w.interval(c.knots.front(), c.knots.back());
      w.i32(tr.edge), w.i32(tr.v0), w.i32(tr.v1), w.i32(tr.rev3d ? 1 : 0), w.i32(tr.type), w.i32(tr.iso), w.i32(tr.loop);
      w.f64(0), w.f64(0);  // 2D tolerances
      w.interval(c.knots.front(), c.knots.back());
      w.zeros(8 + 24);     // the 2D curve not reversed; reserved
      w.f64(0), w.f64(0);  // legacy tolerances
    }, nothing);
    writeRecords(w, 0, loops_.size(), [&](int k) {
      w.i32(k);
      w.ints(loops_[size_t(k)]);
      w.i32(kOuterLoop);
      w.i32(k);  // loop k bounds face k
    }, nothing);
    writeRecords(w, 1, shell_.faces.size(), [&](int k) {
      w.i32(k);
      w.ints({k});
      w.i32(k);
      w.i32(t_.faces[size_t(shell_.faces[size_t(k)])].flipped ? 1 : 0);
      w.i32(0);  // material channel
    }, [&] { w.zeros(16 * shell_.faces.size()); });  // version 1.1: face ids, nil (the reader makes them)

    Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = -lo;
    for (int f : shell_.faces)
      for (const Eigen::Vector3d& p : faces_[size_t(f)].poles) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    w.point(lo), w.point(hi);
    for (int meshes = 0; meshes < 2; ++meshes) {  // render and analysis meshes: none
      w.beginChunk(kOnTcodeAnonymous);
      w.zeros(shell_.faces.size());
      w.endChunk();
    }
    w.i32(0);  // solid or not: left for the reader to find
    w.beginChunk(kOnTcodeAnonymous);  // region topology (version 1.1): none
    w.i32(1), w.i32(1);
    w.boolean(false);
    w.endChunk();
  }

  struct Vertex {
    int global;
    std::vector<int> edges;
  };
  const std::vector<BSplineSurface>& faces_;
  const BrepTopology& t_;
  const BrepShell& shell_;
  std::map<int, int> vertex_, edge_;  // the topology's index -> this body's
  std::vector<Vertex> vertices_;
  std::vector<Edge> edges_;
  std::vector<Trim> trims_;
  std::vector<BrepPcurve> curves2_;
  std::vector<std::vector<int>> loops_;
};

}  // namespace

std::vector<OnBrepBody> onBreps(const std::vector<BSplineSurface>& faces, const BrepTopology& t) {
  std::vector<OnBrepBody> out;
  for (const BrepShell& shell : t.shells) {
    OnBrepBody body;
    body.faces = shell.faces;
    body.closed = shell.closed;
    body.bytes = BodyWriter(faces, t, shell).write();
    out.push_back(std::move(body));
  }
  return out;
}

}  // namespace pdesurf
