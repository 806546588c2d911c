#include "cad/brep_topology.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <queue>

namespace pdesurf {

namespace {

// One piece of a face's border between two breakpoints, in the border's own parameter.
struct Segment {
  int face = 0, border = 0;
  double t0 = 0, t1 = 0;
  Eigen::Vector3d p0, p1;
  bool zero = false;    // shorter than the tolerance: a vertex, not an edge (a rim's dwell)
  int partner = -1;     // the segment of the other face it is one edge with
  bool met = false;     // the join's met side (b): its border is the shared edge's curve
  int join = -1;        // the join that paired it
  double gap = 0;       // met side: the largest distance to the partner's border
  bool sameWay = true;  // partner's parameter increases with this one's
  int edge = -1;
  bool edgeForward = true;  // the edge's curve runs with this segment's parameter
};

struct BorderKey {
  int face, border;
};

class Builder {
 public:
  Builder(const std::vector<TopologyFace>& faces, const std::vector<BorderJoin>& joins, double tolerance)
      : faces_(faces), joins_(joins), tol_(tolerance), breaks_(faces.size() * 4) {}

  BrepTopology run() {
    for (size_t f = 0; f < faces_.size(); ++f)
      for (int b = 0; b < 4; ++b)
        if (usable(int(f), b)) breaks_[f * 4 + b] = {range(int(f), b)[0], range(int(f), b)[1]};
    for (const BorderJoin& j : joins_) {
      if (!usable(int(j.a.face), j.a.border) || !usable(int(j.b.face), j.b.border)) continue;
      for (double t : {j.a.from, j.a.to}) addBreak(int(j.a.face), j.a.border, t);
      for (double t : {j.b.from, j.b.to}) addBreak(int(j.b.face), j.b.border, t);
    }
    propagate();
    makeSegments();
    for (const BorderJoin& j : joins_) pair(j);
    makeVertices();
    makeEdges();
    makeLoops();
    orient();
    return std::move(out_);
  }

 private:
  // A border that gets edges: not collapsed, and not a closed face's v1 (its seam is v0).
  bool usable(int f, int b) const {
    const TopologyFace& s = faces_[size_t(f)];
    return !s.degenerate[b] && !(s.closedV && b == 3);
  }
  std::array<double, 2> range(int f, int b) const {
    const TopologyFace& s = faces_[size_t(f)];
    return b < 2 ? std::array<double, 2>{s.v0, s.v1} : std::array<double, 2>{s.u0, s.u1};
  }
  std::vector<double>& breaks(int f, int b) { return breaks_[size_t(f) * 4 + b]; }
  bool addBreak(int f, int b, double t) {
    const auto r = range(f, b);
    if (!(t >= r[0] - 1e-12 * (r[1] - r[0]) && t <= r[1] + 1e-12 * (r[1] - r[0]))) return false;
    t = std::clamp(t, r[0], r[1]);
    std::vector<double>& list = breaks(f, b);
    const double eps = 1e-9 * (r[1] - r[0]);
    for (double x : list)
      if (std::abs(x - t) <= eps) return false;
    list.insert(std::upper_bound(list.begin(), list.end(), t), t);
    return true;
  }

  // A breakpoint inside one side of a join is one inside the other (a vertex of either face).
  void propagate() {
    for (int pass = 0; pass < 8; ++pass) {
      bool more = false;
      for (const BorderJoin& j : joins_) {
        if (!usable(int(j.a.face), j.a.border) || !usable(int(j.b.face), j.b.border)) continue;
        const auto inside = [](double t, double x, double y) { return t > std::min(x, y) && t < std::max(x, y); };
        for (double t : std::vector<double>(breaks(int(j.a.face), j.a.border)))
          if (inside(t, j.a.from, j.a.to)) more |= addBreak(int(j.b.face), j.b.border, mapAtoB(j, t));
        for (double t : std::vector<double>(breaks(int(j.b.face), j.b.border)))
          if (inside(t, j.b.from, j.b.to)) more |= addBreak(int(j.a.face), j.a.border, mapBtoA(j, t));
      }
      if (!more) break;
    }
  }

  Eigen::Vector3d at(int f, int b, double t) const {
    const TopologyFace& s = faces_[size_t(f)];
    const double u = b == 0 ? s.u0 : b == 1 ? s.u1 : t, v = b == 2 ? s.v0 : b == 3 ? s.v1 : t;
    return s.eval(u, v, 0, 0);
  }

  // The points of border b at ts: at once where the face can, else one by one.
  std::vector<Eigen::Vector3d> atMany(int f, int b, const std::vector<double>& ts) const {
    const TopologyFace& s = faces_[size_t(f)];
    if (s.borderPoints) return s.borderPoints(b, ts);
    std::vector<Eigen::Vector3d> out;
    for (double t : ts) out.push_back(at(f, b, t));
    return out;
  }

  void makeSegments() {
    first_.assign(faces_.size() * 4, -1);
    count_.assign(faces_.size() * 4, 0);
    for (size_t f = 0; f < faces_.size(); ++f)
      for (int b = 0; b < 4; ++b) {
        if (!usable(int(f), b)) continue;
        const std::vector<double>& list = breaks(int(f), b);
        first_[f * 4 + b] = int(segments_.size());
        // The breaks and the pieces' middles, [t0, mid, t1, mid, …, t_last].
        std::vector<double> ts;
        for (size_t k = 0; k < list.size(); ++k) {
          ts.push_back(list[k]);
          if (k + 1 < list.size()) ts.push_back((list[k] + list[k + 1]) / 2);
        }
        const std::vector<Eigen::Vector3d> x = atMany(int(f), b, ts);
        for (size_t k = 0; k + 1 < list.size(); ++k) {
          Segment s;
          s.face = int(f), s.border = b, s.t0 = list[k], s.t1 = list[k + 1];
          s.p0 = x[2 * k], s.p1 = x[2 * k + 2];
          const Eigen::Vector3d& mid = x[2 * k + 1];
          s.zero = (mid - s.p0).norm() + (s.p1 - mid).norm() <= tol_;
          segments_.push_back(s);
          ++count_[f * 4 + b];
        }
      }
  }

  // The non-zero segments of a border within [x, y] (either order), in the direction x -> y.
  std::vector<int> piecesOf(int f, int b, double x, double y) const {
    std::vector<int> out;
    const int first = first_[size_t(f) * 4 + b];
    for (int k = 0; k < count_[size_t(f) * 4 + b]; ++k) {
      const Segment& s = segments_[size_t(first + k)];
      const double mid = (s.t0 + s.t1) / 2;
      if (!s.zero && mid > std::min(x, y) && mid < std::max(x, y)) out.push_back(first + k);
    }
    if (x > y) std::reverse(out.begin(), out.end());
    return out;
  }

  void refuse(const BorderJoin& j, const std::string& why) { out_.unshared.push_back(j.label + ": " + why); }

  void pair(const BorderJoin& j) {
    const int joinIndex = int(&j - joins_.data());
    if (!usable(int(j.a.face), j.a.border) || !usable(int(j.b.face), j.b.border)) return;
    const std::vector<int> A = piecesOf(int(j.a.face), j.a.border, j.a.from, j.a.to);
    const std::vector<int> B = piecesOf(int(j.b.face), j.b.border, j.b.from, j.b.to);
    if (A.size() != B.size()) return refuse(j, "its two sides split into different pieces (" + std::to_string(A.size()) + " and " + std::to_string(B.size()) + ")");
    const bool sameWay = (j.a.to > j.a.from) == (j.b.to > j.b.from);
    for (size_t k = 0; k < A.size(); ++k) {
      Segment &a = segments_[size_t(A[k])], &b = segments_[size_t(B[k])];
      if (a.partner >= 0 || b.partner >= 0) return refuse(j, "a border met by more than one face there (not a manifold)");
      double gap = 0;
      std::vector<double> ta, tb;
      for (int q = 0; q <= 8; ++q) ta.push_back(a.t0 + (a.t1 - a.t0) * q / 8), tb.push_back(mapAtoB(j, ta.back()));
      const std::vector<Eigen::Vector3d> xa = atMany(a.face, a.border, ta), xb = atMany(b.face, b.border, tb);
      for (int q = 0; q <= 8; ++q) gap = std::max(gap, (xa[size_t(q)] - xb[size_t(q)]).norm());
      if (!(gap <= 2 * tol_)) {
        char why[160];
        std::snprintf(why, sizeof why, "the two faces' borders are %.3g apart, beyond twice the tolerance %.3g", gap, tol_);
        return refuse(j, why);
      }
      a.partner = B[k], b.partner = A[k];
      a.sameWay = b.sameWay = sameWay;
      a.join = b.join = joinIndex;
      b.met = true, b.gap = gap;
    }
  }

  int find(int x) {
    while (parent_[size_t(x)] != x) x = parent_[size_t(x)] = parent_[size_t(parent_[size_t(x)])];
    return x;
  }
  void unite(int a, int b) {
    if (a >= 0 && b >= 0) parent_[size_t(find(a))] = find(b);
  }
  // Endpoint ids: 2 s (start) and 2 s + 1 (end) of segment s.
  int endOf(int f, int b, bool last) const {
    const int n = count_[size_t(f) * 4 + b];
    if (n == 0) return -1;
    return last ? 2 * (first_[size_t(f) * 4 + b] + n - 1) + 1 : 2 * first_[size_t(f) * 4 + b];
  }

  void makeVertices() {
    parent_.resize(segments_.size() * 2);
    std::iota(parent_.begin(), parent_.end(), 0);
    for (size_t f = 0; f < faces_.size(); ++f) {
      const TopologyFace& s = faces_[f];
      const int F = int(f);
      for (int b = 0; b < 4; ++b) {
        const int n = count_[f * 4 + b], first = first_[f * 4 + b];
        for (int k = 0; k + 1 < n; ++k) unite(2 * (first + k) + 1, 2 * (first + k + 1));
        if (s.closedV && b < 2 && n > 0) unite(endOf(F, b, true), endOf(F, b, false));
      }
      // The corners (u0,v0), (u1,v0), (u0,v1), (u1,v1): the two borders meeting there; a
      // closed face's v1 is its v0; a collapsed border makes its two corners one.
      const int v1 = s.closedV ? 2 : 3;
      const int corner[4][2] = {{endOf(F, 0, false), endOf(F, 2, false)},
                                {endOf(F, 1, false), endOf(F, 2, true)},
                                {endOf(F, 0, true), endOf(F, v1, false)},
                                {endOf(F, 1, true), endOf(F, v1, true)}};
      int rep[4];
      for (int c = 0; c < 4; ++c) {
        unite(corner[c][0], corner[c][1]);
        rep[c] = corner[c][0] >= 0 ? corner[c][0] : corner[c][1];
      }
      if (s.degenerate[0]) unite(rep[0], rep[2]);
      if (s.degenerate[1]) unite(rep[1], rep[3]);
      if (s.degenerate[2]) unite(rep[0], rep[1]);
      if (s.degenerate[3]) unite(rep[2], rep[3]);
    }
    for (size_t k = 0; k < segments_.size(); ++k) {
      const Segment& s = segments_[k];
      if (s.zero) unite(int(2 * k), int(2 * k + 1));
      if (s.partner < 0 || s.partner < int(k)) continue;
      const int p = s.partner;
      unite(int(2 * k), s.sameWay ? 2 * p : 2 * p + 1);
      unite(int(2 * k + 1), s.sameWay ? 2 * p + 1 : 2 * p);
    }
    // One vertex per class, at the mean of its points.
    vertexOf_.assign(parent_.size(), -1);
    std::vector<int> members;
    for (size_t e = 0; e < parent_.size(); ++e) {
      const int r = find(int(e));
      if (vertexOf_[size_t(r)] < 0) {
        vertexOf_[size_t(r)] = int(out_.vertices.size());
        out_.vertices.push_back(Eigen::Vector3d::Zero());
        members.push_back(0);
      }
      const int v = vertexOf_[size_t(r)];
      const Segment& s = segments_[e / 2];
      out_.vertices[size_t(v)] += e % 2 ? s.p1 : s.p0;
      ++members[size_t(v)];
    }
    for (size_t v = 0; v < out_.vertices.size(); ++v) out_.vertices[v] /= members[v];
    for (size_t e = 0; e < parent_.size(); ++e) {
      const Segment& s = segments_[e / 2];
      out_.vertexSpread = std::max(out_.vertexSpread, ((e % 2 ? s.p1 : s.p0) - out_.vertices[size_t(vertex(int(e)))]).norm());
    }
  }
  int vertex(int endpoint) { return vertexOf_[size_t(find(endpoint))]; }

  void makeEdges() {
    for (Segment& s : segments_) {
      if (s.zero || s.edge >= 0) continue;
      // A shared edge takes the met border's curve (the join's b side).
      Segment& owner = s.partner >= 0 && !s.met ? segments_[size_t(s.partner)] : s;
      const int id = int(&owner - segments_.data());
      BrepEdge e;
      if (const BSplineSurface* spline = faces_[size_t(owner.face)].spline) e.curve = subCurve(borderCurve(*spline, owner.border), owner.t0, owner.t1);
      e.start = vertex(2 * id), e.end = vertex(2 * id + 1);
      const bool seam = faces_[size_t(owner.face)].closedV && owner.border == 2;
      e.uses = owner.partner >= 0 || seam ? 2 : 1;
      e.face = owner.face, e.border = owner.border, e.t0 = owner.t0, e.t1 = owner.t1;
      e.gap = owner.gap;
      out_.edgeGap = std::max(out_.edgeGap, e.gap);
      owner.edge = int(out_.edges.size()), owner.edgeForward = true;
      if (owner.partner >= 0) {
        Segment& other = segments_[size_t(owner.partner)];
        other.edge = owner.edge, other.edgeForward = owner.sameWay;
        e.otherFace = other.face, e.otherBorder = other.border, e.join = owner.join;
        if (faces_[size_t(owner.face)].spline) {
          e.pcurves.push_back(pcurveOf(owner, nullptr));
          e.pcurves.push_back(pcurveOf(other, &joins_[size_t(owner.join)]));
        }
      }
      out_.edges.push_back(std::move(e));
    }
  }

  // The (u, v) of a point of segment s's border at its own parameter x.
  Eigen::Vector2d uvOf(const Segment& s, double x) const {
    const TopologyFace& f = faces_[size_t(s.face)];
    switch (s.border) {
      case 0: return {f.u0, x};
      case 1: return {f.u1, x};
      case 2: return {x, f.v0};
      default: return {x, f.v1};
    }
  }

  // The edge curve's parameter t runs over the met segment's [t0, t1]. On the met face the
  // pcurve is that border itself; on the other (join given) its parameter is the join's map of t.
  BrepPcurve pcurveOf(const Segment& s, const BorderJoin* j) const {
    const Segment& met = j ? segments_[size_t(s.partner)] : s;
    BrepPcurve p;
    p.face = s.face;
    const double t0 = met.t0, t1 = met.t1;
    if (!j || !j->eased) {
      p.degree = 1;
      p.knots = {t0, t0, t1, t1};
      p.poles = {uvOf(s, j ? mapBtoA(*j, t0) : t0), uvOf(s, j ? mapBtoA(*j, t1) : t1)};
      return p;
    }
    // A fill side's easing: cubic Hermite pieces of its exact map and slope, as Bézier spans.
    constexpr int pieces = 32;
    p.degree = 3;
    p.knots = {t0, t0, t0, t0};
    const Eigen::Vector2d axis = uvOf(s, 1) - uvOf(s, 0);  // the border's running direction in (u, v)
    for (int k = 0; k < pieces; ++k) {
      const double a = t0 + (t1 - t0) * k / pieces, b = t0 + (t1 - t0) * (k + 1) / pieces, h = b - a;
      const double sa = mapBtoA(*j, a), sb = mapBtoA(*j, b), da = mapBtoADerivative(*j, a), db = mapBtoADerivative(*j, b);
      if (k == 0) p.poles.push_back(uvOf(s, sa));
      p.poles.push_back(uvOf(s, sa) + axis * (h / 3 * da));
      p.poles.push_back(uvOf(s, sb) - axis * (h / 3 * db));
      p.poles.push_back(uvOf(s, sb));
      for (int r = 0; r < (k + 1 < pieces ? 3 : 4); ++r) p.knots.push_back(b);
    }
    return p;
  }

  // Counter-clockwise in (u, v): v0 forward, u1 forward, v1 backward, u0 backward.
  void makeLoops() {
    out_.faces.resize(faces_.size());
    for (size_t f = 0; f < faces_.size(); ++f) {
      const TopologyFace& s = faces_[f];
      const int order[4][2] = {{2, 1}, {1, 1}, {s.closedV ? 2 : 3, 0}, {0, 0}};
      for (const auto& [b, forward] : order) {
        if (s.degenerate[b]) continue;
        const int n = count_[f * 4 + b], first = first_[f * 4 + b];
        for (int q = 0; q < n; ++q) {
          const Segment& seg = segments_[size_t(first + (forward ? q : n - 1 - q))];
          if (seg.zero) continue;
          out_.faces[f].loop.push_back({seg.edge, seg.edgeForward == bool(forward)});
        }
      }
    }
  }

  // Neighbours traverse a shared edge in opposite directions; a closed shell's normals point out.
  void orient() {
    const size_t n = faces_.size();
    std::vector<std::vector<std::pair<int, bool>>> usesOf(out_.edges.size());  // (face, forward)
    for (size_t f = 0; f < n; ++f)
      for (const BrepEdgeUse& u : out_.faces[f].loop) usesOf[size_t(u.edge)].push_back({int(f), u.forward});
    std::vector<int> shellOf(n, -1);
    std::vector<bool> flip(n, false);
    for (size_t start = 0; start < n; ++start) {
      if (shellOf[start] >= 0) continue;
      BrepShell shell;
      const int id = int(out_.shells.size());
      std::queue<int> todo;
      todo.push(int(start));
      shellOf[start] = id;
      bool consistent = true;
      while (!todo.empty()) {
        const int f = todo.front();
        todo.pop();
        shell.faces.push_back(f);
        for (const BrepEdgeUse& u : out_.faces[size_t(f)].loop)
          for (const auto& [g, forward] : usesOf[size_t(u.edge)]) {
            if (g == f) continue;
            const bool wantFlip = flip[size_t(f)] != (forward == u.forward);
            if (shellOf[size_t(g)] < 0) {
              shellOf[size_t(g)] = id, flip[size_t(g)] = wantFlip;
              todo.push(g);
            } else if (flip[size_t(g)] != wantFlip) {
              consistent = false;
            }
          }
      }
      std::sort(shell.faces.begin(), shell.faces.end());
      shell.closed = consistent;
      for (int f : shell.faces)
        for (const BrepEdgeUse& u : out_.faces[size_t(f)].loop) shell.closed = shell.closed && out_.edges[size_t(u.edge)].uses == 2;
      if (!consistent) out_.unshared.push_back("the faces around '" + faces_[start].name + "' cannot be oriented consistently");
      if (shell.closed) {
        double v = 0;
        for (int f : shell.faces) v += (flip[size_t(f)] ? -1 : 1) * faceSignedVolume(faces_[size_t(f)]);
        if (v < 0)
          for (int f : shell.faces) flip[size_t(f)] = !flip[size_t(f)];
        shell.volume = std::abs(v);
      }
      for (int f : shell.faces) shell.area += faceArea(faces_[size_t(f)]);
      out_.shells.push_back(std::move(shell));
    }
    for (size_t f = 0; f < n; ++f) {
      BrepFace& face = out_.faces[f];
      face.flipped = flip[f];
      if (!flip[f]) continue;
      std::reverse(face.loop.begin(), face.loop.end());
      for (BrepEdgeUse& u : face.loop) u.forward = !u.forward;
    }
  }

  const std::vector<TopologyFace>& faces_;
  const std::vector<BorderJoin>& joins_;
  const double tol_;
  std::vector<std::vector<double>> breaks_;
  std::vector<Segment> segments_;
  std::vector<int> first_, count_;
  std::vector<int> parent_, vertexOf_;
  BrepTopology out_;
};

}  // namespace

BrepTopology buildTopology(const std::vector<TopologyFace>& faces, const std::vector<BorderJoin>& joins, double tolerance) {
  return Builder(faces, joins, tolerance).run();
}

BrepTopology buildTopology(const std::vector<BSplineSurface>& faces, const std::vector<BorderJoin>& joins, double tolerance) {
  std::vector<TopologyFace> described;
  for (const BSplineSurface& s : faces) described.push_back(topologyFace(s));
  return buildTopology(described, joins, tolerance);
}

}  // namespace pdesurf
