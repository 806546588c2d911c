#include "analysis/watertight_mesh.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "analysis/bodies.hpp"
#include "common/errors.hpp"
#include "surface/mesh.hpp"

namespace pdesurf {

namespace {

// A point of a ring around a face's grid: its place along the ring (counter-clockwise in
// (u, v), one unit a side) and its vertex.
struct RingPoint {
  double pos;
  uint32_t vertex;
};

// The (u, v) of parameter t along border b (kBezierEdge's order: u0, u1 run along v; v0, v1 along u).
Eigen::Vector2d borderUv(const TopologyFace& f, int b, double t) {
  switch (b) {
    case 0: return {f.u0, t};
    case 1: return {f.u1, t};
    case 2: return {t, f.v0};
    default: return {t, f.v1};
  }
}

class MeshBuilder {
 public:
  MeshBuilder(const std::vector<SolvedPatch>& solved, const SolvedTopology& st, int nu, int nv)
      : solved_(solved), faces_(st.faces), joins_(st.joins), topo_(st.topology), nu_(nu), nv_(nv), samples_(faces_.size() * 4) {}

  ModelMesh run() {
    for (const Eigen::Vector3d& p : topo_.vertices) addVertex(p);
    for (const BrepEdge& e : topo_.edges) sampleEdge(e);
    std::vector<int> bodyOf(faces_.size(), 0);
    for (size_t b = 0; b < topo_.shells.size(); ++b)
      for (int f : topo_.shells[b].faces) bodyOf[size_t(f)] = int(b);
    for (size_t f = 0; f < faces_.size(); ++f) {
      ModelMesh::Part part;
      part.name = faces_[f].name, part.body = bodyOf[f];
      meshFace(int(f), &part.indices);
      out_.parts.push_back(std::move(part));
    }
    finishNormals();
    return std::move(out_);
  }

 private:
  uint32_t addVertex(const Eigen::Vector3d& p) {
    for (int d = 0; d < 3; ++d) out_.positions.push_back(float(p[d]));
    normalSum_.push_back(Eigen::Vector3d::Zero());
    return uint32_t(normalSum_.size() - 1);
  }

  // The face's unit normal at (u, v), outward when the face is flipped to be; 0 at a pole.
  Eigen::Vector3d normalAt(int f, const Eigen::Vector2d& uv) const {
    const TopologyFace& s = faces_[size_t(f)];
    const Eigen::Vector3d n = s.eval(uv[0], uv[1], 1, 0).cross(s.eval(uv[0], uv[1], 0, 1));
    const double len = n.norm();
    if (!(len > 0) || !std::isfinite(len)) return Eigen::Vector3d::Zero();
    return (topo_.faces[size_t(f)].flipped ? -1 : 1) * n / len;
  }

  int cells(int f, int b, double a, double c) const {
    const TopologyFace& s = faces_[size_t(f)];
    const double range = b < 2 ? s.v1 - s.v0 : s.u1 - s.u0;
    const int n = b < 2 ? nv_ : nu_;
    return std::max(1, int(std::ceil(n * std::abs(c - a) / range - 1e-9)));
  }

  // A seam is the face's wrap, not a ring: closed faces are zipped along u0 and u1 only.
  bool isSeam(const BrepEdge& e) const { return e.otherFace < 0 && faces_[size_t(e.face)].closedV && e.border >= 2; }

  // One set of points per edge, at the finer of its two sides' grid spacings; each side
  // records them at its own border parameter.
  void sampleEdge(const BrepEdge& e) {
    if (isSeam(e)) return;
    const BorderJoin* j = e.join >= 0 ? &joins_[size_t(e.join)] : nullptr;
    int m = cells(e.face, e.border, e.t0, e.t1);
    if (j) m = std::max(m, cells(e.otherFace, e.otherBorder, mapBtoA(*j, e.t0), mapBtoA(*j, e.t1)));
    const TopologyFace& owner = faces_[size_t(e.face)];
    for (int k = 0; k <= m; ++k) {
      const double t = k == m ? e.t1 : e.t0 + (e.t1 - e.t0) * k / m;
      const Eigen::Vector2d uv = borderUv(owner, e.border, t);
      const uint32_t v = k == 0 ? uint32_t(e.start) : k == m ? uint32_t(e.end) : addVertex(owner.eval(uv[0], uv[1], 0, 0));
      samples_[size_t(e.face) * 4 + e.border].push_back({t, v});
      normalSum_[v] += normalAt(e.face, uv);
      if (!j) continue;
      const double s = mapBtoA(*j, t);
      samples_[size_t(e.otherFace) * 4 + e.otherBorder].push_back({s, v});
      normalSum_[v] += normalAt(e.otherFace, borderUv(faces_[size_t(e.otherFace)], e.otherBorder, s));
    }
  }

  // Border b's points by increasing parameter (here `pos` holds the parameter).
  std::vector<RingPoint> borderPoints(int f, int b) const {
    std::vector<RingPoint> p = samples_[size_t(f) * 4 + b];
    std::stable_sort(p.begin(), p.end(), [](const RingPoint& x, const RingPoint& y) { return x.pos < y.pos; });
    return p;
  }

  static void append(std::vector<RingPoint>* ring, double pos, uint32_t v) {
    if (!ring->empty() && ring->back().vertex == v && std::abs(ring->back().pos - pos) < 1e-9) return;
    ring->push_back({pos, v});
  }

  void triangle(std::vector<uint32_t>* out, uint32_t a, uint32_t b, uint32_t c, bool reversed) const {
    if (a == b || b == c || a == c) return;  // at a pole
    if (reversed) std::swap(b, c);
    out->insert(out->end(), {a, b, c});
  }

  // Triangles between two cyclic rings running the same way (pos increasing, period
  // `period`), the outer one on the right of that direction (reversed: on the left).
  void zip(const std::vector<RingPoint>& outer, const std::vector<RingPoint>& inner, double period, bool reversed, std::vector<uint32_t>* out) const {
    const size_t P = outer.size(), Q = inner.size();
    const auto pos = [period](const std::vector<RingPoint>& r, size_t i) { return i < r.size() ? r[i].pos : r[i - r.size()].pos + period; };
    size_t i = 0, j = 0;
    while (i < P || j < Q) {
      const uint32_t a = outer[i % P].vertex, b = inner[j % Q].vertex;
      if (j == Q || (i < P && pos(outer, i + 1) <= pos(inner, j + 1))) {
        triangle(out, a, outer[(i + 1) % P].vertex, b, reversed);
        ++i;
      } else {
        triangle(out, a, inner[(j + 1) % Q].vertex, b, reversed);
        ++j;
      }
    }
  }

  // The pole of a closed face's collapsed u-border: the seam's vertex there.
  uint32_t poleOf(int f, int b) {
    for (const BrepEdge& e : topo_.edges)
      if (e.face == f && isSeam(e)) return uint32_t(b == 0 ? e.start : e.end);
    const TopologyFace& s = faces_[size_t(f)];
    return addVertex(s.eval(b == 0 ? s.u0 : s.u1, s.v0, 0, 0));
  }

  void meshFace(int f, std::vector<uint32_t>* out) {
    const TopologyFace& s = faces_[size_t(f)];
    const bool flip = topo_.faces[size_t(f)].flipped;
    const Mesh grid = tessellatePatch(solved_[size_t(f)], nu_, nv_);
    const int W = nu_ + 1;
    std::vector<uint32_t> id(size_t(W) * (nv_ + 1), 0);
    const int jFirst = s.closedV ? 0 : 1, jLast = s.closedV ? nv_ - 1 : nv_ - 1;
    for (int j = jFirst; j <= jLast; ++j)
      for (int i = 1; i < nu_; ++i) {
        const size_t k = size_t(j) * W + i;
        const uint32_t v = addVertex(Eigen::Vector3d(grid.positions[3 * k], grid.positions[3 * k + 1], grid.positions[3 * k + 2]));
        normalSum_[v] = (flip ? -1 : 1) * Eigen::Vector3d(grid.normals[3 * k], grid.normals[3 * k + 1], grid.normals[3 * k + 2]);
        id[k] = v;
      }
    const auto at = [&](int i, int j) { return id[size_t(s.closedV ? j % nv_ : j) * W + i]; };
    // The grid's cells inside the ring: counter-clockwise in (u, v), as tessellate's.
    const int jCells = s.closedV ? nv_ : nv_ - 2;
    for (int j = jFirst; j < jFirst + jCells; ++j)
      for (int i = 1; i + 1 < nu_; ++i) {
        triangle(out, at(i, j), at(i + 1, j), at(i + 1, j + 1), flip);
        triangle(out, at(i, j), at(i + 1, j + 1), at(i, j + 1), flip);
      }
    const double U = s.u1 - s.u0, V = s.v1 - s.v0;
    if (s.closedV) {
      for (int b = 0; b < 2; ++b) {
        std::vector<RingPoint> outer, inner;
        if (s.degenerate[b]) {
          outer.push_back({0, poleOf(f, b)});
        } else {
          for (const RingPoint& p : borderPoints(f, b)) append(&outer, (p.pos - s.v0) / V, p.vertex);
          if (outer.size() > 1 && outer.back().vertex == outer.front().vertex) outer.pop_back();
        }
        const int i = b == 0 ? 1 : nu_ - 1;
        for (int j = 0; j < nv_; ++j) inner.push_back({double(j) / nv_, at(i, j)});
        zip(outer, inner, 1, (b == 0) != flip, out);
      }
      return;
    }
    // An open face: the ring of its borders v0, u1, v1 (backwards), u0 (backwards).
    std::vector<RingPoint> outer, inner;
    for (const RingPoint& p : borderPoints(f, 2)) append(&outer, (p.pos - s.u0) / U, p.vertex);
    for (const RingPoint& p : borderPoints(f, 1)) append(&outer, 1 + (p.pos - s.v0) / V, p.vertex);
    std::vector<RingPoint> top = borderPoints(f, 3), left = borderPoints(f, 0);
    for (auto p = top.rbegin(); p != top.rend(); ++p) append(&outer, 2 + (s.u1 - p->pos) / U, p->vertex);
    for (auto p = left.rbegin(); p != left.rend(); ++p) append(&outer, 3 + (s.v1 - p->pos) / V, p->vertex);
    if (outer.size() > 1 && outer.back().vertex == outer.front().vertex && outer.back().pos > 4 - 1e-9) outer.pop_back();
    if (outer.empty()) throw Error(ErrorCode::Internal, "patch '" + s.name + "': no border points to mesh");
    const double a = nu_ - 2, c = nv_ - 2;
    for (int i = 1; i < nu_; ++i) inner.push_back({(i - 1) / a, at(i, 1)});
    for (int j = 2; j < nv_; ++j) inner.push_back({1 + (j - 1) / c, at(nu_ - 1, j)});
    for (int i = nu_ - 2; i >= 1; --i) inner.push_back({2 + (nu_ - 1 - i) / a, at(i, nv_ - 1)});
    for (int j = nv_ - 2; j >= 2; --j) inner.push_back({3 + (nv_ - 1 - j) / c, at(1, j)});
    zip(outer, inner, 4, flip, out);
  }

  // Unit normals: the faces' analytic ones summed; where they vanish (a pole), the triangles'.
  void finishNormals() {
    std::vector<Eigen::Vector3d> fallback(normalSum_.size(), Eigen::Vector3d::Zero());
    const auto P = [&](uint32_t v) { return Eigen::Vector3d(out_.positions[3 * v], out_.positions[3 * v + 1], out_.positions[3 * v + 2]); };
    for (const ModelMesh::Part& part : out_.parts)
      for (size_t t = 0; t < part.indices.size(); t += 3) {
        const uint32_t a = part.indices[t], b = part.indices[t + 1], c = part.indices[t + 2];
        const Eigen::Vector3d n = (P(b) - P(a)).cross(P(c) - P(a));
        for (uint32_t v : {a, b, c})
          if (!(normalSum_[v].norm() > 1e-12)) fallback[v] += n;
      }
    out_.normals.resize(out_.positions.size());
    for (size_t v = 0; v < normalSum_.size(); ++v) {
      Eigen::Vector3d n = normalSum_[v].norm() > 1e-12 ? normalSum_[v] : fallback[v];
      n = n.norm() > 0 ? n.normalized() : Eigen::Vector3d::Zero();
      for (int d = 0; d < 3; ++d) out_.normals[3 * v + d] = float(n[d]);
    }
  }

  const std::vector<SolvedPatch>& solved_;
  const std::vector<TopologyFace>& faces_;
  const std::vector<BorderJoin>& joins_;
  const BrepTopology& topo_;
  const int nu_, nv_;
  std::vector<std::vector<RingPoint>> samples_;  // per face and border: (parameter, vertex)
  std::vector<Eigen::Vector3d> normalSum_;
  ModelMesh out_;
};

}  // namespace

ModelMesh watertightMesh(const std::vector<SolvedPatch>& solved, double sceneSize, int nu, int nv) {
  if (nu < 3 || nv < 3)
    throw Error(ErrorCode::GridSize, "a watertight mesh needs at least 3x3 cells a patch (the grid " + std::to_string(nu) + "x" + std::to_string(nv) + " has no row inside its border)");
  const SolvedTopology st = solvedTopology(solved, sceneSize);
  return MeshBuilder(solved, st, nu, nv).run();
}

std::vector<BodyMesh> bodyMeshes(const ModelMesh& mesh) {
  int bodies = 0;
  for (const ModelMesh::Part& p : mesh.parts) bodies = std::max(bodies, p.body + 1);
  std::vector<BodyMesh> out(static_cast<size_t>(bodies));
  std::vector<int> patches(static_cast<size_t>(bodies), 0);
  // A vertex's number in the body being numbered (two bodies may touch at a point): bodies
  // one after the other, so a tag from another body is never taken for this one's.
  std::vector<std::pair<int, uint32_t>> local(mesh.vertexCount(), {-1, 0});
  for (int body = 0; body < bodies; ++body) {
    BodyMesh& b = out[size_t(body)];
    for (const ModelMesh::Part& p : mesh.parts) {
      if (p.body != body) continue;
      if (patches[size_t(body)]++ == 0) b.name = p.name;
      for (uint32_t v : p.indices) {
        if (local[v].first != body) {
          local[v] = {body, uint32_t(b.positions.size() / 3)};
          b.positions.insert(b.positions.end(), {mesh.positions[3 * size_t(v)], mesh.positions[3 * size_t(v) + 1], mesh.positions[3 * size_t(v) + 2]});
        }
        b.indices.push_back(local[v].second);
      }
    }
  }
  for (size_t k = 0; k < out.size(); ++k)
    if (patches[k] != 1) out[k].name = "body " + std::to_string(k + 1);
  return out;
}

}  // namespace pdesurf
