// The primary surfaces' patches, "ruled", "separable" and "surface" (scene/patch_kinds.hpp),
// and the `meets` a primary may declare.
#include <cmath>

#include "scene/expression_fields.hpp"
#include "scene/json_fields.hpp"
#include "scene/nurbs_json.hpp"
#include "scene/patch_parsers.hpp"
#include "scene/placement.hpp"

namespace pdesurf {

using namespace scene_json;

namespace {

void parseMeets(const json& j, const std::string& path, const Resolver& r, Patch& patch) {
  if (!j.contains("meets")) return;
  const std::string mp = path + ".meets";
  allowOnly(j["meets"], mp, {"patch", "end", "at", "v_range"});
  Meets& meets = patch.meets.emplace_back();
  meets.patch = stringField(require(j["meets"], "patch", mp), mp + ".patch", 64);
  const std::string end = stringField(require(j["meets"], "end", mp), mp + ".end");
  if (end != "u0" && end != "u1" && end != "v0" && end != "v1")
    fail(ErrorCode::InvalidField, mp + ".end", "expected \"u0\", \"u1\" (or, for a bezier patch, \"v0\", \"v1\")");
  meets.end = end[1] == '0' ? 0 : 1;
  meets.alongU = end[0] == 'v';
  if (j["meets"].contains("v_range")) {
    const auto vr = r.range(j["meets"], "v_range", mp, 0.0, 1.0);
    if (vr[0] == vr[1]) fail(ErrorCode::InvalidField, mp + ".v_range", "the interval is empty");
    meets.v0 = vr[0], meets.v1 = vr[1];
  }
  if (j["meets"].contains("at")) {
    const std::string at = stringField(j["meets"]["at"], mp + ".at");
    if (at != "t0" && at != "t1") fail(ErrorCode::InvalidField, mp + ".at", "expected \"t0\" or \"t1\"");
    meets.atT1 = at == "t1";
  }
}

void primaryRanges(const json& j, const std::string& path, const Resolver& r, PrimarySurface& s) {
  const auto vr = r.range(j, "v_range", path, 0.0, 2 * M_PI);
  const auto tr = r.range(j, "t_range", path, 0.0, 1.0);
  s.v0 = vr[0], s.v1 = vr[1], s.t0 = tr[0], s.t1 = tr[1];
}

}  // namespace

// "ruled": C(v) + t D(v).
void parseRuled(const json& j, const std::string& path, const Resolver& r, Patch& patch) {
  allowOnly(j, path, {"name", "kind", "v_range", "t_range", "curve", "direction", "meets"});
  parseMeets(j, path, r, patch);
  primaryRanges(j, path, r, patch.primary());
  require(j, "curve", path);
  require(j, "direction", path);
  const auto curve = r.vectorTerms(j, "curve", path);
  const auto direction = r.vectorTerms(j, "direction", path);
  for (int c = 0; c < 3; ++c) {
    for (const VTerm& t : curve[c]) patch.primary().terms[c].push_back({VFunction{Family::Poly, 1.0, 0}, t.g, t.coef});
    for (const VTerm& t : direction[c]) patch.primary().terms[c].push_back({VFunction{Family::Poly, 1.0, 1}, t.g, t.coef});
  }
}

// "surface" (version 2): per coordinate an expression in t and v, or (version 4) a NURBS
// surface (scene/nurbs_json.hpp); version 4 may place it
// (scene/placement.hpp), which rewrites the three expressions before they are split.
void parseSurface(const json& j, const std::string& path, const Resolver& r, int version, Patch& patch) {
  allowOnly(j, path, {"name", "kind", "v_range", "t_range", "x", "y", "z", "nurbs", "meets", "placement"});
  parseMeets(j, path, r, patch);
  PrimarySurface& S = patch.primary();
  std::array<Expr, 3> xyz;
  if (j.contains("nurbs")) {  // a NURBS surface instead of expressions (scene/nurbs_json.hpp)
    if (version < 4) fail(ErrorCode::InvalidField, path + ".nurbs", "a NURBS surface needs scene version 4");
    for (int c = 0; c < 3; ++c)
      if (j.contains(kAxis[c])) fail(ErrorCode::InvalidField, path + "." + kAxis[c], "a surface is given either by \"nurbs\" or by x, y, z, not both");
    NurbsDomain d{};
    xyz = parseNurbs(j["nurbs"], path, &d);
    const auto tr = r.range(j, "t_range", path, d.t0, d.t1), vr = r.range(j, "v_range", path, d.v0, d.v1);
    // Outside its knots a B-spline is not the surface: a range must stay within them.
    if (tr[0] < d.t0 || tr[1] > d.t1)
      fail(ErrorCode::InvalidField, path + ".t_range", "leaves the NURBS surface's domain in t, [" + std::to_string(d.t0) + ", " + std::to_string(d.t1) + "]");
    if (vr[0] < d.v0 || vr[1] > d.v1)
      fail(ErrorCode::InvalidField, path + ".v_range", "leaves the NURBS surface's domain in v, [" + std::to_string(d.v0) + ", " + std::to_string(d.v1) + "]");
    S.t0 = tr[0], S.t1 = tr[1], S.v0 = vr[0], S.v1 = vr[1];
  } else {
    primaryRanges(j, path, r, S);
    for (int c = 0; c < 3; ++c)  // a missing coordinate is 0
      xyz[c] = j.contains(kAxis[c]) ? surfaceField(j[kAxis[c]], path + "." + kAxis[c], r) : constant(0.0);
  }
  if (j.contains("placement")) {
    if (version < 4) fail(ErrorCode::InvalidField, path + ".placement", "a placement needs scene version 4");
    const Placement placement = parsePlacement(j["placement"], path + ".placement", r);
    checkPlacementReach(placement, xyz, S.t0, S.t1, S.v0, S.v1, path + ".placement");
    xyz = applyPlacement(placement, xyz);
  }
  for (int c = 0; c < 3; ++c) {
    S.full[c] = xyz[c];
    splitSurface(xyz[c], S.terms[c], &S.pointwise[c]);
  }
}

// "separable": per coordinate, terms with an optional factor "t": {fn, w, n} of t.
void parseSeparable(const json& j, const std::string& path, const Resolver& r, Patch& patch) {
  allowOnly(j, path, {"name", "kind", "v_range", "t_range", "x", "y", "z", "meets"});
  parseMeets(j, path, r, patch);
  primaryRanges(j, path, r, patch.primary());
  for (int c = 0; c < 3; ++c) {
    if (!j.contains(kAxis[c])) continue;
    const std::string cp = path + "." + kAxis[c];
    const json& list = j[kAxis[c]];
    if (!list.is_array()) fail(ErrorCode::InvalidField, cp, "expected an array of terms");
    for (size_t k = 0; k < list.size(); ++k) {
      const std::string tp = cp + "[" + std::to_string(k) + "]";
      if (!list[k].is_object()) fail(ErrorCode::InvalidField, tp, "expected an object");
      json vpart = list[k];
      VFunction tf{Family::Poly, 1.0, 0};
      if (vpart.contains("t")) {
        const json tj = vpart["t"];
        allowOnly(tj, tp + ".t", {"fn", "w", "n"});
        json as = tj;
        as["coef"] = 1;
        tf = r.terms(json::array({as}), tp + ".t", false).front().g;
        vpart.erase("t");
      }
      const VTerm vt = r.terms(json::array({vpart}), cp).front();
      patch.primary().terms[c].push_back({tf, vt.g, vt.coef});
    }
  }
}

}  // namespace pdesurf
