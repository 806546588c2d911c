#include "scene/derived_ends.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "common/limits.hpp"
#include "expr/budget.hpp"
#include "scene/expression_fields.hpp"
#include "scene/trimline_checks.hpp"

#include "scene/surface_reference.hpp"

namespace pdesurf {

namespace {

constexpr int kSamples = 129;  // along the trimline, for the checks and the power's scale

using Vec3Expr = std::array<Expr, 3>;


Eigen::Vector3d eval3(const Vec3Expr& e, double v) {
  const double vars[2] = {v, 0.0};
  return {evaluate(*e[0], vars), evaluate(*e[1], vars), evaluate(*e[2], vars)};
}

Vec3Expr map3(const Vec3Expr& e, Expr (*f)(const Expr&, ExprVar)) {
  return {f(e[0], ExprVar::U), f(e[1], ExprVar::U), f(e[2], ExprVar::U)};
}

Vec3Expr onTrimline(const Vec3Expr& e, const Expr& tau) {
  return {substitute(e[0], ExprVar::U, tau), substitute(e[1], ExprVar::U, tau), substitute(e[2], ExprVar::U, tau)};
}

const char* edgeName(bool t1) { return t1 ? "t1" : "t0"; }

// One referenced end: the surface's position and t-derivatives on its trimline, in v, all in
// the surface's own (untrimmed) parametrisation. Or a fill's border on a surface (border set,
// end -1): it takes part in the trimming rules, and a curve border is checked and trims.
struct DerivedEnd {
  Patch* blend = nullptr;  // the blend, or the fill
  int end = 0;
  EndReference* ref = nullptr;
  LoopBorder* border = nullptr;
  Patch* surface = nullptr;
  size_t surfaceIndex = 0;
  TrimlineExprs e;
  double meanT = 0.0;  // mean |S_t| along the trimline
};

// Step 1: the surface an end names (a "surface" patch), untouched.
DerivedEnd locate(Scene& scene, Patch& blend, int end) {
  DerivedEnd d;
  d.blend = &blend, d.end = end, d.ref = &blend.ends()[end];
  d.surfaceIndex = scene_json::referencedSurface(scene, d.ref->surface, d.ref->path, "an end");
  d.surface = &scene.patches[d.surfaceIndex];
  return d;
}

// A fill's border on a surface patch (a curve needs a "surface" patch; an iso-line on any
// other primary is left to linkPatches, as it cannot be trimmed).
bool locateBorder(Scene& scene, Patch& fill, LoopBorder& b, DerivedEnd& d) {
  Patch* source = nullptr;
  for (size_t i = 0; i < scene.patches.size(); ++i)
    if (scene.patches[i].name == b.patch) source = &scene.patches[i], d.surfaceIndex = i;
  if (!b.curve.given) {
    if (!source || source->kind != PatchKind::Primary || b.edge > 1) return false;
    b.curve.surface = b.patch, b.curve.atT1 = b.edge == 1, b.curve.path = b.path;
  } else {
    if (!source) fail(ErrorCode::UnknownName, b.path + ".patch", "no patch named '" + b.patch + "'");
    if (source->kind != PatchKind::Primary || !source->primary().full[0])
      fail(ErrorCode::InvalidField, b.path + ".at",
           "'" + b.patch + "' is a " + source->kindName + " patch; a trimline curve is drawn on a \"surface\" patch (expressions in t and v)");
    b.curve.power = constant(1.0);
  }
  d.blend = &fill, d.end = -1, d.ref = &b.curve, d.border = &b, d.surface = source;
  return true;
}

// Step 2: the rules between ends, whatever the patches' order: a surface is trimmed along one
// curve at most (ends and fill borders may share it: the same τ, replacing the same border),
// and the border that curve replaces is met by no other end.
const DerivedEnd* trimOf(const std::vector<DerivedEnd>& all, const Patch* surface) {
  for (const DerivedEnd& d : all)
    if (d.surface == surface && d.ref->curve) return &d;
  return nullptr;
}

bool sameCurve(const EndReference& a, const EndReference& b) {
  return a.atT1 == b.atT1 && a.tau == b.tau;  // interned: equal expressions are one node
}

void checkRules(const std::vector<DerivedEnd>& all) {
  for (const DerivedEnd& d : all) {
    // Both ends of one blend on one border: it would start and end on the same curve.
    if (d.end == 1 && &d != &all.front()) {
      const DerivedEnd& o = *(&d - 1);
      if (o.blend == d.blend && o.surface == d.surface && !o.ref->curve && !d.ref->curve && o.ref->atT1 == d.ref->atT1)
        fail(ErrorCode::InvalidField, d.ref->path + ".at",
             std::string("meets ") + edgeName(d.ref->atT1) + " of '" + d.ref->surface + "', as " + o.ref->path +
                 " does: the blend would start and end on the same curve");
    }
    const DerivedEnd* cut = trimOf(all, d.surface);
    if (!cut || cut == &d) continue;
    if (d.ref->curve && sameCurve(*d.ref, *cut->ref)) continue;
    if (d.ref->curve)
      fail(ErrorCode::InvalidField, d.ref->path + ".at",
           "'" + d.ref->surface + "' is already trimmed along a curve by " + cut->ref->path + "; a surface can be trimmed along one curve only");
    if (d.ref->atT1 == cut->ref->atT1)
      fail(ErrorCode::InvalidField, d.ref->path + ".at",
           std::string("meets ") + edgeName(d.ref->atT1) + " of '" + d.ref->surface + "', which " + cut->ref->path + " replaces by a curve");
  }
}

// Step 3: S, S_t (and S_tt) on the trimline, checked.
void derive(DerivedEnd& d) {
  const EndReference& ref = *d.ref;
  const PrimarySurface& S = d.surface->primary();
  d.e.tau = ref.curve ? ref.tau : constant(ref.atT1 ? S.t1 : S.t0);
  // Built under the scene's budget (deriveEnds); S_tt only where curvature is asked.
  const Vec3Expr St = map3(S.full, derivative);
  d.e.P = onTrimline(S.full, d.e.tau);
  d.e.T = onTrimline(St, d.e.tau);
  if (ref.continuity == Continuity::Curvature) d.e.C = onTrimline(map3(St, derivative), d.e.tau);
  // A fill's curve is checked over the surface's whole v-range: the surface is drawn over it.
  d.meanT = d.border ? checkTrimline(ref, S, d.e, S.v0, S.v1) : checkTrimline(ref, S, d.e, d.blend->pde().v0, d.blend->pde().v1);
}

// Mean distance between the two ends' curves over the blend's v-range.
double meanGap(const std::array<Vec3Expr, 2>& pos, double v0, double v1) {
  double sum = 0.0;
  for (int k = 0; k < kSamples; ++k) {
    const double v = v0 + (v1 - v0) * k / (kSamples - 1);
    const double g = (eval3(pos[1], v) - eval3(pos[0], v)).norm();
    if (std::isfinite(g)) sum += g;
  }
  return sum / kSamples;
}

// The blend's boundary slots from its ends (derived, or typed for the extra conditions).
void writeConditions(Patch& blend, const std::array<const DerivedEnd*, 2>& derived, ExprBudget& budget) {
  std::array<Vec3Expr, 2> pos;
  for (int end = 0; end < 2; ++end) {
    if (derived[end]) {
      pos[end] = derived[end]->e.P;
    } else {
      for (int c = 0; c < 3; ++c) pos[end][c] = blend.typedPosition()[end][c] ? blend.typedPosition()[end][c] : constant(0.0);
    }
  }
  const double gap = meanGap(pos, blend.pde().v0, blend.pde().v1);
  for (int end = 0; end < 2; ++end) {
    if (!derived[end]) continue;
    EndReference& ref = blend.ends()[end];
    budget.setPath(ref.path);
    const DerivedEnd& d = *derived[end];
    // "gap" scale, power 1: a mean tangent as long as the mean gap (of unit length when the
    // ends touch); "surface": power 1 continues the surface's t at its own speed.
    // Beside a chained end (version 4) the other end's curve is known only once solved: the
    // surface's own speed then.
    const bool chained = !blend.ends()[0].patch.empty() || !blend.ends()[1].patch.empty();
    const double k = ref.surfaceScale || chained ? 1.0 : (gap > 0 ? gap : 1.0) / d.meanT;
    const double away = (ref.atT1 ? 1.0 : -1.0) * (ref.flip ? -1.0 : 1.0);  // the blend's side, in t
    const double sign = end == 0 ? away : -away;
    const int level = static_cast<int>(ref.continuity);
    for (int c = 0; c < 3; ++c) {
      ComponentProblem& cp = blend.pde().component[c];
      std::vector<VExpansion>& slots = end == 0 ? cp.left : cp.right;
      const int n = blend.op()[c].order / 2;
      slots.assign(n, {});
      std::array<Expr, 3> e;
      e[0] = d.e.P[c];
      if (n >= 2) e[1] = level >= 1 ? multiply(constant(sign * k), multiply(ref.power, d.e.T[c])) : subtract(pos[1][c], pos[0][c]);
      if (n >= 3) e[2] = level >= 2 ? multiply(constant(k * k), multiply(multiply(ref.power, ref.power), d.e.C[c])) : constant(0.0);
      ref.derived[c].clear();
      for (int i = 0; i < n; ++i) {
        ref.derived[c].push_back(toTextLimited(e[i], limits::kDerivedTextChars));
        slots[i] = scene_json::slotFromExpr(e[i], ref.path + " (" + ref.derived[c].back() + ")");
      }
    }
  }
}

// Step 4: the join, in the surface's drawn parametrisation: a trimmed surface runs from its
// curve (t0 = 0) to the border the curve does not replace (t1 = 1).
void recordJoin(const DerivedEnd& d, bool trimmed) {
  const EndReference& ref = *d.ref;
  Meets m;
  m.patch = d.blend->name;
  m.end = d.end;
  m.atT1 = ref.curve ? false : trimmed ? true : ref.atT1;
  m.curve = ref.curve, m.replacesT1 = ref.curve && ref.atT1;
  if (trimmed && !ref.curve) m.namedT = ref.atT1 ? 1 : 0;
  m.by = ref.path;
  for (const Meets& have : d.surface->meets) {
    if (have.patch != m.patch || have.end != m.end || have.alongU) continue;
    if (have.atT1 == m.atT1) return;  // already recorded (the scene's own meets says the same)
    fail(ErrorCode::InvalidField, "patches[" + std::to_string(d.surfaceIndex) + "].meets",
         "disagrees with " + ref.path + " (which makes edge " + edgeName(m.atT1) + " meet " + (d.end ? "u1" : "u0") + ")");
  }
  d.surface->meets.push_back(m);
}

// Step 5: the surface met along a curve is drawn from its trimline: t = tau + s (t_far - tau), s in [0, 1].
// Its pointwise expression and the partial derivatives drawing needs are built here, under the
// scene's budget, so tessellation never differentiates an unbounded graph.
void trim(Patch& surface, const EndReference& ref) {
  PrimarySurface& S = surface.primary();
  if (S.trimmed) return;  // by an end or border with the same curve
  const Expr tFar = constant(ref.atT1 ? S.t0 : S.t1);
  const Expr t = add(ref.tau, multiply(variable(ExprVar::U), subtract(tFar, ref.tau)));
  for (int c = 0; c < 3; ++c) {
    S.terms[c].clear();
    S.pointwise[c] = substitute(S.full[c], ExprVar::U, t);
    S.pointwisePartials[c] = partialDerivatives(S.pointwise[c], true);
  }
  S.t0 = 0.0;
  S.t1 = 1.0;
  S.trimmed = true;
  S.trimReplacesT1 = ref.atT1;
}

// A fill's border in the drawn parametrisation: a curve is the trimmed surface's edge 0, the
// border a curve does not replace its edge 1 (the rules refused the one it replaces).
void pointBorder(const DerivedEnd& d, bool trimmed) {
  LoopBorder& b = *d.border;
  b.edge = d.ref->curve ? 0 : trimmed ? 1 : b.edge;
}

}  // namespace

// Every end is resolved against the untrimmed surfaces before anything is trimmed, so the
// result does not depend on the patches' order: find every end's surface, check the rules
// between ends, derive and check every end, write every blend's conditions, record every
// join in the trimmed parametrisation, and only then trim.
void deriveEnds(Scene& scene, ExprBudget& budget) {
  // One budget for the whole scene (the caller's, shared with the Bezier borders): every node
  // built for any end (and for the surfaces they trim) counts, and the first node over the
  // limit stops the derivation.
  std::vector<DerivedEnd> all;
  for (Patch& blend : scene.patches) {
    if (!blend.solvedAsPde()) continue;
    for (int end = 0; end < 2; ++end)
      if (blend.ends()[end].given && blend.ends()[end].patch.empty()) all.push_back(locate(scene, blend, end));
    for (LoopBorder& b : blend.fill().borders) {
      DerivedEnd d;
      if (locateBorder(scene, blend, b, d)) all.push_back(d);
    }
  }
  if (all.empty()) return;
  checkRules(all);
  for (DerivedEnd& d : all) {
    if (d.border && !d.ref->curve) continue;  // an iso-line border: nothing to derive here
    budget.setPath(d.ref->path);
    derive(d);
  }
  for (size_t i = 0; i < all.size();) {
    std::array<const DerivedEnd*, 2> ends = {nullptr, nullptr};
    Patch* blend = all[i].blend;
    const bool fill = all[i].border != nullptr;
    for (; i < all.size() && all[i].blend == blend; ++i)
      if (!fill) ends[all[i].end] = &all[i];
    if (!fill) writeConditions(*blend, ends, budget);
  }
  for (const DerivedEnd& d : all) {
    const bool trimmed = trimOf(all, d.surface) != nullptr;
    if (d.border) pointBorder(d, trimmed);  // its join is recorded by linkPatches
    else recordJoin(d, trimmed);
  }
  for (const DerivedEnd& d : all)
    if (d.ref->curve) {
      budget.setPath(d.ref->path);
      trim(*d.surface, *d.ref);
    }
}

}  // namespace pdesurf
