#include "scene/patch_graph.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "common/errors.hpp"

namespace pdesurf {

namespace {

std::string number(double x) {
  std::ostringstream o;
  o << x;
  return o.str();
}

std::string exact(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

size_t indexOf(const Scene& scene, const std::string& name, const std::string& path, const std::string& self) {
  for (size_t i = 0; i < scene.patches.size(); ++i)
    if (scene.patches[i].name == name) {
      if (name == self) fail(ErrorCode::InvalidField, path + ".patch", "'" + name + "' cannot continue its own border");
      return i;
    }
  fail(ErrorCode::UnknownName, path + ".patch", "no patch named '" + name + "'");
}

// Which edges a patch has: a surface t0, t1; a pde patch u0, u1 (a fill none: its u = 0 is the
// loop it closes, its u = 1 a point); a Bézier patch all four.
void checkEdge(const Patch& p, int edge, const std::string& path, bool surfaceAllowed) {
  if (p.kind == PatchKind::Primary && !surfaceAllowed)
    fail(ErrorCode::InvalidField, path + ".patch", "'" + p.name + "' is a surface: an end on a surface names it with \"surface\"");
  if (p.isFill()) fail(ErrorCode::InvalidField, path + ".patch", "'" + p.name + "' is a fill: its border belongs to the patches it closes");
  if (p.kind != PatchKind::Bezier && edge > 1)
    fail(ErrorCode::InvalidField, path + ".at", "'" + p.name + "' is a " + (p.solvedAsPde() ? "pde patch: its ends are u0 and u1" : "surface: its borders are t0 and t1"));
}

void depend(Patch& p, const std::string& on) {
  if (std::find(p.dependsOn.begin(), p.dependsOn.end(), on) == p.dependsOn.end()) p.dependsOn.push_back(on);
}

void linkEnd(Scene& scene, size_t index, int end) {
  Patch& blend = scene.patches[index];
  const EndReference& ref = blend.ends()[end];
  const size_t si = indexOf(scene, ref.patch, ref.path, blend.name);
  Patch& source = scene.patches[si];
  checkEdge(source, ref.patchEdge, ref.path, false);
  if (source.solvedAsPde() && (source.pde().v0 != blend.pde().v0 || source.pde().v1 != blend.pde().v1)) {
    // As many digits as tell the two apart (one ulp apart, 6 digits print the same numbers).
    const auto differs = [](double a, double b) { return number(a) != number(b) ? std::make_pair(number(a), number(b)) : std::make_pair(exact(a), exact(b)); };
    const auto [a0, b0] = differs(blend.pde().v0, source.pde().v0);
    const auto [a1, b1] = differs(blend.pde().v1, source.pde().v1);
    fail(ErrorCode::InvalidField, ref.path + ".patch",
         "the v_range [" + a0 + ", " + a1 + "] differs from '" + source.name + "''s [" + b0 + ", " + b1 + "]: a chain shares v with the patch it continues");
  }
  // Both ends on one edge: three sheets would meet along it (version 3 refuses the same for a
  // surface's border).
  const EndReference& other = blend.ends()[1 - end];
  if (end == 1 && other.given && other.patch == ref.patch && other.patchEdge == ref.patchEdge)
    fail(ErrorCode::InvalidField, ref.path + ".at",
         "continues " + edgeName(source, ref.patchEdge) + " of '" + source.name + "', as " + other.path + " does: the patch would start and end on the same edge");
  if (ref.reverse && source.kind != PatchKind::Bezier) fail(ErrorCode::InvalidField, ref.path + ".reverse", "only a Bézier border can be run backwards");
  depend(blend, source.name);
  Meets m;
  m.patch = blend.name;
  m.end = end;
  m.sourceEdge = ref.patchEdge;
  m.atT1 = ref.patchEdge % 2 == 1;
  if (source.kind == PatchKind::Bezier) m.v0 = 0.0, m.v1 = 1.0, m.reversed = ref.reverse;
  m.by = ref.path;
  source.meets.push_back(m);
}

void linkFill(Scene& scene, size_t index) {
  Patch& fill = scene.patches[index];
  const size_t n = fill.fill().borders.size();
  for (size_t k = 0; k < n; ++k) {
    LoopBorder& b = fill.fill().borders[k];
    Patch& source = scene.patches[indexOf(scene, b.patch, b.path, fill.name)];
    checkEdge(source, b.edge, b.path, true);
    const auto range = edgeRange(source);
    if (std::isnan(b.from)) b.from = range[0], b.to = range[1];
    const double slack = 1e-12 * std::max({1.0, std::abs(range[0]), std::abs(range[1])});
    if (b.from < range[0] - slack || b.to > range[1] + slack)
      fail(ErrorCode::InvalidField, b.path + ".range",
           "[" + number(b.from) + ", " + number(b.to) + "] is not inside the range [" + number(range[0]) + ", " + number(range[1]) + "] of " +
               edgeName(source, b.edge) + " of '" + source.name + "'");
    depend(fill, source.name);
    Meets m;
    m.patch = fill.name;
    m.end = 0;
    m.atT1 = b.edge % 2 == 1;
    m.sourceEdge = source.kind == PatchKind::Primary ? -1 : b.edge;
    m.curve = b.curve.curve, m.replacesT1 = b.curve.curve && b.curve.atT1;  // for the certificate's label
    // The far border of a trimmed surface, named as the scene names it (locateBorder kept it).
    if (source.kind == PatchKind::Primary && source.primary().trimmed && !b.curve.curve) m.namedT = b.curve.atT1 ? 1 : 0;
    m.v0 = b.from, m.v1 = b.to, m.reversed = b.reverse;
    const auto part = fillSideRange(k, n);
    m.targetFrom = part[0], m.targetTo = part[1];
    m.eased = n > 1;
    m.by = b.path;
    source.meets.push_back(m);
  }
}

// Depth-first over dependsOn: every patch after what it depends on; a patch met again while
// its own dependencies are being visited closes a cycle.
struct Order {
  const Scene& scene;
  std::vector<int> state;  // 0 new, 1 on the path, 2 done
  std::vector<size_t> path, out;

  size_t find(const std::string& name) const {
    for (size_t i = 0; i < scene.patches.size(); ++i)
      if (scene.patches[i].name == name) return i;
    throw Error(ErrorCode::Internal, "no patch '" + name + "'");
  }

  void visit(size_t i) {
    if (state[i] == 2) return;
    if (state[i] == 1) {
      std::string cycle;
      const auto start = std::find(path.begin(), path.end(), i);
      for (auto it = start; it != path.end(); ++it) cycle += "'" + scene.patches[*it].name + "' -> ";
      cycle += "'" + scene.patches[i].name + "'";
      const Patch& last = scene.patches[path.back()];
      fail(ErrorCode::InvalidField, refPath(last, scene.patches[i].name),
           "a cycle of references: " + cycle + " (each patch's conditions would need the next one solved first)");
    }
    state[i] = 1;
    path.push_back(i);
    for (const std::string& d : scene.patches[i].dependsOn) visit(find(d));
    path.pop_back();
    state[i] = 2;
    out.push_back(i);
  }

  static std::string refPath(const Patch& p, const std::string& on) {
    for (const EndReference& e : p.ends())
      if (e.given && e.patch == on) return e.path;
    for (const LoopBorder& b : p.fill().borders)
      if (b.patch == on) return b.path;
    return p.fill().path;
  }
};

}  // namespace

std::array<double, 2> edgeRange(const Patch& p) {
  if (p.kind == PatchKind::Bezier) return {0.0, 1.0};
  if (p.kind == PatchKind::Primary) return {p.primary().v0, p.primary().v1};
  return {p.pde().v0, p.pde().v1};
}

std::string edgeName(const Patch& p, int edge) {
  if (p.kind == PatchKind::Primary) return edge ? "t1" : "t0";
  return kBezierEdge[edge];
}

namespace {

// Where on its patch's edge a join lies: the edge (a surface's trimline apart from its
// borders) and the interval of the edge's parameter it covers.
struct EdgeSpan {
  int edge = 0;
  double from = 0, to = 0;
  const Meets* meets = nullptr;
};

EdgeSpan spanOf(const Scene& scene, const Patch& p, const Meets& m) {
  EdgeSpan e;
  e.meets = &m;
  e.edge = m.curve ? 4 : m.sourceEdge >= 0 ? m.sourceEdge : (m.atT1 ? 1 : 0);
  std::array<double, 2> range = edgeRange(p);
  if (!std::isnan(m.v0)) {
    range = {m.v0, m.v1};
  } else if (p.kind == PatchKind::Primary) {
    // A pde blend shares v with the surface: its own v-range.
    const Patch* target = scene.find(m.patch);
    if (target && target->solvedAsPde() && !target->isFill()) range = {target->pde().v0, target->pde().v1};
  }
  e.from = std::min(range[0], range[1]), e.to = std::max(range[0], range[1]);
  return e;
}

size_t sceneIndex(const Scene& scene, const std::string& name) {
  const Patch* p = scene.find(name);
  return p ? static_cast<size_t>(p - scene.patches.data()) : scene.patches.size();
}

std::string joinName(size_t index, const Meets& m) {
  return m.by.empty() ? "patches[" + std::to_string(index) + "].meets" : m.by;
}

}  // namespace

void checkEdgesMetOnce(const Scene& scene) {
  for (size_t i = 0; i < scene.patches.size(); ++i) {
    const Patch& p = scene.patches[i];
    std::vector<EdgeSpan> spans;
    for (const Meets& m : p.meets) spans.push_back(spanOf(scene, p, m));
    std::sort(spans.begin(), spans.end(), [](const EdgeSpan& a, const EdgeSpan& b) { return a.edge != b.edge ? a.edge < b.edge : a.from < b.from; });
    const auto range = edgeRange(p);
    const double slack = 1e-9 * std::max({1.0, std::abs(range[0]), std::abs(range[1])});
    for (size_t k = 1; k < spans.size(); ++k) {
      const EdgeSpan &a = spans[k - 1], &b = spans[k];
      if (a.edge != b.edge || b.from >= a.to - slack) continue;
      // The later of the two in the scene is the one refused.
      const bool aFirst = sceneIndex(scene, a.meets->patch) < sceneIndex(scene, b.meets->patch) || (a.meets->patch == b.meets->patch && a.meets < b.meets);
      const Meets &first = aFirst ? *a.meets : *b.meets, &second = aFirst ? *b.meets : *a.meets;
      const std::string edge = a.edge == 4 ? "the curve trimming '" + p.name + "'" : "edge " + edgeName(p, a.edge) + " of '" + p.name + "'";
      fail(ErrorCode::InvalidField, joinName(i, second),
           edge + " is already met by " + joinName(i, first) + " ('" + first.patch + "') over [" + number(std::max(a.from, b.from)) + ", " +
               number(std::min(a.to, b.to)) + "]: three sheets would meet along it");
    }
  }
}

void linkPatches(Scene& scene) {
  for (size_t i = 0; i < scene.patches.size(); ++i) {
    Patch& p = scene.patches[i];
    if (!p.solvedAsPde()) continue;
    for (int end = 0; end < 2; ++end)
      if (p.ends()[end].given && !p.ends()[end].patch.empty()) linkEnd(scene, i, end);
    if (p.isFill()) linkFill(scene, i);
  }
  Order order{scene, std::vector<int>(scene.patches.size(), 0), {}, {}};
  for (size_t i = 0; i < scene.patches.size(); ++i) order.visit(i);
  scene.solveOrder = std::move(order.out);
}

}  // namespace pdesurf
