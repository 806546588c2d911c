#include "analysis/join_certificate.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "analysis/edge_samples.hpp"
#include "common/errors.hpp"
#include "common/text.hpp"
#include "surface/mesh.hpp"

namespace pdesurf {

namespace {

// What a patch promises at a join: the lowest continuity any coordinate's order gives
// (2nd G0, 4th G1, 6th G2); a membrane Bézier fixes one ring (G0), a thin plate two (G1).
// An end given by reference (scene version 3) promises the continuity it asks for.
int promisedLevel(const Patch& p, int end) {
  if (p.kind == PatchKind::Bezier) return p.bezier().energy == BezierEnergy::ThinPlate ? 1 : 0;
  if (p.isFill()) return static_cast<int>(p.fill().continuity);
  if (p.ends()[end].given) return static_cast<int>(p.ends()[end].continuity);
  int order = 6;
  for (const ComponentOperator& op : p.op()) order = std::min(order, op.order);
  return order / 2 - 1;
}

// The tangent plane at an edge point from the first non-vanishing derivative across the edge.
struct Side {
  bool regular = false;      // the tangent plane exists here
  bool firstOrder = false;   // ... and the speed across does not vanish (curvature measurable)
  Eigen::Vector3d n, inward; // unit normal; the direction into the patch, across the edge
};

Side sideAt(const EdgePoint& p, double floor) {
  Side side;
  if (p.s.norm() <= floor) return side;  // the edge's own parametrisation stops (a pole)
  side.firstOrder = p.w.norm() > floor;
  const Eigen::Vector3d w = side.firstOrder ? p.w : p.ww;  // w = 0: X ≈ X0 + ½ X_ww w², inward along X_ww
  const Eigen::Vector3d n = p.s.cross(w);
  if (!(n.norm() > 1e-12 * p.s.norm() * w.norm())) return side;
  side.regular = true;
  side.n = n.normalized();
  const Eigen::Vector3d sh = p.s.normalized();
  side.inward = w - w.dot(sh) * sh;
  return side;
}

// Normal curvature in the unit direction m of the tangent plane, the normal oriented as n.
double normalCurvature(const EdgePoint& p, const Eigen::Vector3d& n, const Eigen::Vector3d& m) {
  Eigen::Matrix2d I;
  I << p.s.dot(p.s), p.s.dot(p.w), p.s.dot(p.w), p.w.dot(p.w);
  const Eigen::Vector2d ab = I.ldlt().solve(Eigen::Vector2d(p.s.dot(m), p.w.dot(m)));
  const double a = ab(0), b = ab(1);
  const double II = a * a * p.ss.dot(n) + 2 * a * b * p.sw.dot(n) + b * b * p.ww.dot(n);
  return II / (a * a * I(0, 0) + 2 * a * b * I(0, 1) + b * b * I(1, 1));
}

// The met patch's edge (Meets::sourceEdge): a primary's t0/t1 or a pde patch's u0/u1 (along v),
// or a Bézier border (v0/v1 run along u); its name for the report.
struct SourceEdge {
  bool alongU = false;
  int end = 0;
  std::string name;
};

SourceEdge sourceEdgeOf(const Patch& p, const Meets& m) {
  if (m.sourceEdge < 0) return {false, m.atT1 ? 1 : 0, m.atT1 ? "t1" : "t0"};
  return {m.sourceEdge >= 2, m.sourceEdge % 2, p.kind == PatchKind::Primary ? (m.sourceEdge ? "t1" : "t0") : kBezierEdge[m.sourceEdge]};
}

// Samples at the middles of `count` equal parts of [a0, a1]: a fill's side is measured on its
// open interval (its corners are the model's vertices, where the sides' tangent planes differ).
std::vector<EdgePoint> openEdgeSamples(const SeparableSurface& s, bool alongU, int end, double a0, double a1, int count) {
  const double h = (a1 - a0) / count / 2;
  return edgeSamples(s, alongU, end, a0 + h, a1 - h, count);
}

// The parameters edgeSamples (open: openEdgeSamples) takes along [a0, a1], for another reader.
std::vector<double> sampleParameters(double a0, double a1, int count, bool open) {
  const double h = open ? (a1 - a0) / count / 2 : 0.0;
  std::vector<double> at(static_cast<size_t>(count));
  for (int k = 0; k < count; ++k) at[size_t(k)] = (a0 + h) + ((a1 - h) - (a0 + h)) * k / (count - 1);
  return at;
}

// Compares the two sides of a join point by point (B the patch that promises, P what it meets,
// at the same points; the met edge's parameter runs p0..p1): the gap, the tangent-plane angle,
// the normal-curvature mismatch across (level 2), folds; r->level set, the figures filled in.
// Returns how many points measured the promised figure.
int compareEdges(const std::vector<EdgePoint>& B, const std::vector<EdgePoint>& P, double p0, double p1, double size, JoinResult* out) {
  JoinResult& r = *out;
  const int samples = static_cast<int>(B.size());
  const double floor = 1e-9 * size;
  int measured = 0;
  double worstFigure = -1.0;
  for (int k = 0; k < samples; ++k) {
    const double v = p0 + (p1 - p0) * k / (samples - 1);
    const double gap = (B[k].X - P[k].X).norm() / size;
    r.g0 = std::max(r.g0, gap);
    double figure = gap;
    const Side b = sideAt(B[k], floor), p = sideAt(P[k], floor);
    if (b.regular && p.regular) {
      // Both leave the shared edge: on opposite sides of it, or the join folds.
      if (b.inward.dot(p.inward) > 0) r.fold = true;
      const double deg = std::atan2(b.n.cross(p.n).norm(), std::abs(b.n.dot(p.n))) * 180.0 / M_PI;
      r.g1Deg = std::max(r.g1Deg, deg);
      if (r.level >= 1) figure = deg;
      if (r.level == 2) {
        if (b.firstOrder && p.firstOrder) {
          const Eigen::Vector3d across = b.n.cross(B[k].s).normalized();
          const Eigen::Vector3d np = p.n.dot(b.n) < 0 ? Eigen::Vector3d(-p.n) : p.n;
          const double kb = normalCurvature(B[k], b.n, across), kp = normalCurvature(P[k], np, across);
          const double rel = std::abs(kb - kp) / std::max({std::abs(kb), std::abs(kp), 1.0 / size});
          r.g2Rel = std::max(r.g2Rel, rel);
          figure = rel;
          ++measured;
        } else {
          ++r.degenerate;
        }
      } else {
        ++measured;
      }
    } else {
      ++r.degenerate;
      if (r.level == 0) ++measured;
    }
    if (figure > worstFigure) worstFigure = figure, r.worstV = v;
  }
  return measured;
}

bool keepsPromise(const JoinResult& r, int measured) {
  return r.g0 <= kG0Tolerance && !r.fold && measured > 0 && (r.level < 1 || r.g1Deg <= kG1ToleranceDeg) && (r.level < 2 || r.g2Rel <= kG2Tolerance);
}

// The bounding box of a patch's 32×32 samples, grown by points.
struct Box {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = Eigen::Vector3d::Constant(-INFINITY);
  void add(const Eigen::Vector3d& x) { lo = lo.cwiseMin(x), hi = hi.cwiseMax(x); }
  void add(const SeparableSurface& s) {
    const GridSamples g = sampleGrid(s, 32, 32);
    for (size_t k = 0; k < g.X.size(); k += 3) add(Eigen::Vector3d(&g.X[k]));
  }
  double diagonal() const {
    const double d = (hi - lo).norm();
    return std::isfinite(d) && d > 0 ? d : 1.0;
  }
};

JoinResult certifyOne(const Patch& primary, const Meets& m, const SolvedPatch& prim, const SolvedPatch& target, const EdgeReader& read) {
  const SeparableSurface& ts = target.surface;
  const SourceEdge source = sourceEdgeOf(primary, m);
  JoinResult r;
  r.patch = m.patch;
  r.end = std::string(m.alongU ? "v" : "u") + (m.end ? "1" : "0");
  r.surface = primary.name;
  // A trimmed surface's edge is its trimline (t = 0 after the trim): name the border it replaces.
  r.edge = m.curve ? std::string("curve replacing ") + (m.replacesT1 ? "t1" : "t0") : m.namedT >= 0 ? (m.namedT ? "t1" : "t0") : source.name;
  r.level = promisedLevel(*target.patch, m.alongU ? 0 : m.end);
  // The target's border parameter runs over its own range (a fill's side: its part of it); the
  // primary's v over the given interval, else (PDE) the same v as the target, else (Bézier)
  // the primary's v-range.
  const JoinRanges ranges = joinRanges(m, prim.surface, target);
  const bool part = ranges.part;
  const double a0 = ranges.a0, a1 = ranges.a1;
  double p0 = ranges.p0, p1 = ranges.p1;
  const auto sample = part ? openEdgeSamples : edgeSamples;
  const auto B = read ? read(target, m.alongU, m.end, sampleParameters(a0, a1, kJoinSamples, part))
                      : sample(ts, m.alongU, m.end, a0, a1, kJoinSamples);
  std::vector<EdgePoint> P;
  if (m.eased) {  // the fill's evenly spaced samples, at the edge's parameters they map to
    std::vector<double> at;
    for (int k = 0; k < kJoinSamples; ++k) {
      const double w = (k + 0.5) / kJoinSamples, sigma = w - kFillEase * std::sin(2 * M_PI * w) / (2 * M_PI);
      at.push_back(p0 + (p1 - p0) * sigma);
    }
    P = read ? read(prim, source.alongU, source.end, at) : edgeSamplesAt(prim.surface, source.alongU, source.end, at);
  } else {
    P = read ? read(prim, source.alongU, source.end, sampleParameters(p0, p1, kJoinSamples, part))
             : sample(prim.surface, source.alongU, source.end, p0, p1, kJoinSamples);
  }
  // A reversed Bézier border (version 4) runs over the primary's v backwards.
  if (m.reversed) std::reverse(P.begin(), P.end()), std::swap(p0, p1);
  // What is joined: the promising patch and the edge it meets (the met surface may be far
  // larger: a plane; the rest of the scene does not count).
  Box box;
  box.add(ts);
  for (const EdgePoint& e : P) box.add(e.X);
  r.size = box.diagonal();
  const double size = r.size;
  const int measured = compareEdges(B, P, p0, p1, size, &r);
  // Far beyond rounding: the primary's edge is not this border at all; a scene error.
  if (r.g0 > 1e-3)
    throw Error(ErrorCode::InvalidField, (m.curve ? "the " : "edge ") + r.edge + " of '" + r.surface + "' is not the border " + r.end + " of '" + r.patch +
                                             "': they are " + numberText(r.g0 * r.size) + " apart at v = " + numberText(r.worstV));
  // A Bézier border by reference is a fit of the edge: its distance between the samples too,
  // proven (or found, or not provable) when the border was derived.
  if (!std::isnan(m.borderGap) && m.borderGap / size > r.g0) {
    r.g0 = m.borderGap / size;
    if (r.g0 > kG0Tolerance) r.worstV = m.borderGapV;
  }
  r.ok = keepsPromise(r, measured);
  return r;
}

// A pde patch's v closes on itself when both its u-edges do (a loop at u = 0 and at u = 1:
// a tube, a vase, a fill): then v = v0 and v = v1 are one curve, a join of the patch with
// itself. Corners this far apart (of the patch's size) are an open patch, not a torn one.
constexpr double kClosedCorners = 1e-6;

bool closesInV(const SeparableSurface& s, double size) {
  for (double u : {s.u0, s.u1})
    if (!((evalPoint(s, u, s.v0) - evalPoint(s, u, s.v1)).norm() <= kClosedCorners * size)) return false;
  return true;
}

// Whether the patch's own u-edges (its data) run smoothly through the seam: the same tangent
// direction at v0 and v1 (or none: a pole). A blend of a lens section is sharp at its seam by
// declaration; it is judged there as a G0 edge (an acute edge's sides leave the same way: not
// a fold).
bool dataSmoothAcrossSeam(const SeparableSurface& s, double size) {
  for (double u : {s.u0, s.u1}) {
    const Eigen::Vector3d a = evalPoint(s, u, s.v0, 0, 1), b = evalPoint(s, u, s.v1, 0, 1);
    const double scale = std::max(a.norm(), b.norm());
    if (!(scale > kClosedCorners * size)) continue;  // a pole (a fill's centre), to rounding
    if (!(a.cross(b).norm() <= 1e-8 * scale * scale && a.dot(b) > 0)) return false;
  }
  return true;
}

// What a closed patch promises across its own seam: at least G1 (a smooth surface has no
// seam), G2 where its operator or its fill asks for curvature; G0 where its data are sharp
// there (a fill's seam is mid-side unless it has one border: then it is that border's ends,
// a wing tip's trailing edge, say).
int seamLevel(const Patch& p, const SeparableSurface& s, double size) {
  if (!dataSmoothAcrossSeam(s, size)) return 0;
  if (p.isFill()) return std::max(1, static_cast<int>(p.fill().continuity));
  int order = 6;
  for (const ComponentOperator& op : p.op()) order = std::min(order, op.order);
  return std::max(1, order / 2 - 1);
}

const SolvedPatch& solvedOf(const std::vector<SolvedPatch>& solved, const std::string& name) {
  for (const SolvedPatch& s : solved)
    if (s.patch->name == name) return s;
  throw Error(ErrorCode::UnknownName, "no solved patch named '" + name + "'");
}

}  // namespace

JoinRanges joinRanges(const Meets& m, const SeparableSurface& primary, const SolvedPatch& target) {
  const SeparableSurface& ts = target.surface;
  JoinRanges r;
  r.part = !std::isnan(m.targetFrom);
  r.a0 = r.part ? m.targetFrom : m.alongU ? ts.u0 : ts.v0;
  r.a1 = r.part ? m.targetTo : m.alongU ? ts.u1 : ts.v1;
  r.p0 = m.v0, r.p1 = m.v1;
  if (std::isnan(r.p0)) {
    const bool sameV = target.patch->solvedAsPde();
    r.p0 = sameV ? r.a0 : primary.v0;
    r.p1 = sameV ? r.a1 : primary.v1;
  }
  return r;
}

const char* levelName(int level) { return level <= 0 ? "G0" : level == 1 ? "G1" : "G2"; }

double sceneSizeOf(const std::vector<SolvedPatch>& solved) {
  Box box;
  for (const SolvedPatch& sp : solved) inPatch(sp.patch->name, [&] { box.add(sp.surface); });
  return box.diagonal();
}

double patchSizeOf(const SeparableSurface& surface) {
  Box box;
  box.add(surface);
  return box.diagonal();
}

JoinResult certifyJoin(const Scene& scene, const std::vector<SolvedPatch>& solved, size_t i, size_t k, const EdgeReader& read) {
  const Patch& p = *solved[i].patch;
  const Meets& m = p.meets[k];
  try {
    return certifyOne(p, m, solved[i], solvedOf(solved, m.patch), read);
  } catch (const Error& e) {
    // A join derived from an end is that end's; the scene's own is the surface's `meets`.
    size_t index = 0;
    while (index < scene.patches.size() && &scene.patches[index] != &p) ++index;
    throw Error(e.code(), (m.by.empty() ? "patches[" + std::to_string(index) + "].meets" : m.by) + ": " + e.what());
  }
}

std::vector<JoinResult> certifyJoins(const Scene& scene, const std::vector<SolvedPatch>& solved, const EdgeReader& read) {
  std::vector<JoinResult> out;
  for (size_t i = 0; i < solved.size(); ++i)
    for (size_t k = 0; k < solved[i].patch->meets.size(); ++k) out.push_back(certifyJoin(scene, solved, i, k, read));
  return out;
}

std::optional<JoinResult> certifySeam(const SolvedPatch& sp) {
  const SeparableSurface& s = sp.surface;
  if (!sp.patch->solvedAsPde()) return std::nullopt;
  const double size = patchSizeOf(s);
  if (!closesInV(s, size)) return std::nullopt;
  JoinResult r;
  r.size = size;
  r.patch = r.surface = sp.patch->name;
  r.end = "v1", r.edge = "v0";
  r.level = seamLevel(*sp.patch, s, size);
  // v = v1 (its inward derivative -X_v) against v = v0 (+X_v), point by point along u, on the
  // open interval: the ends u0, u1 are the loops' own points (a fill's corner, its centre).
  const auto B = openEdgeSamples(s, true, 1, s.u0, s.u1, kJoinSamples), P = openEdgeSamples(s, true, 0, s.u0, s.u1, kJoinSamples);
  const int measured = compareEdges(B, P, s.u0, s.u1, size, &r);
  if (r.level == 0) r.fold = false;
  r.ok = keepsPromise(r, measured);
  return r;
}

std::vector<JoinResult> certifySeams(const std::vector<SolvedPatch>& solved) {
  std::vector<JoinResult> out;
  for (const SolvedPatch& sp : solved)
    if (auto r = certifySeam(sp)) out.push_back(*r);
  return out;
}

SceneReport checkScene(const Scene& scene, const std::vector<SolvedPatch>& solved, int crossingGrid) {
  SceneReport r;
  r.sceneSize = sceneSizeOf(solved);
  r.joins = certifyJoins(scene, solved);
  r.seams = certifySeams(solved);
  for (const SolvedPatch& sp : solved)
    if (sp.patch->isFill()) r.centres.push_back(measureFillCentre(sp.patch->name, sp.surface));
  if (crossingGrid > 0) r.crossings = findCrossings(solved, r.sceneSize, crossingGrid);
  r.ok = r.crossings.empty();
  for (const JoinResult& j : r.joins) r.ok = r.ok && j.ok;
  for (const JoinResult& j : r.seams) r.ok = r.ok && j.ok;
  for (const FillCentre& c : r.centres) r.ok = r.ok && c.ok;
  return r;
}

}  // namespace pdesurf
