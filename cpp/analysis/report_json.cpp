#include "analysis/report_json.hpp"

#include <cmath>

namespace pdesurf {

namespace {

using nlohmann::json;

json number(double x) { return std::isfinite(x) ? json(x) : json(nullptr); }

// A join, or a seam (a closed patch joined to itself across v0 = v1: where it is worst is a u).
json joinJson(const JoinResult& j, bool seam) {
  json o = {{"patch", j.patch}, {"level", levelName(j.level)}, {"size", number(j.size)}, {"g0", number(j.g0)}, {"g1_deg", number(j.g1Deg)},
            {"g2_rel", j.level == 2 ? number(j.g2Rel) : json(nullptr)}, {"fold", j.fold}, {"degenerate", j.degenerate}, {"ok", j.ok}};
  if (seam) {
    o["sharp_in_data"] = j.level == 0;
    o["worst_u"] = number(j.worstV);
  } else {
    o["end"] = j.end, o["surface"] = j.surface, o["edge"] = j.edge;
    o["worst_v"] = number(j.worstV);
  }
  return o;
}

}  // namespace

json bodyJson(const Body& b) {
  return {{"patches", b.patches}, {"closed", b.closed}, {"area", number(b.area)}, {"volume", b.closed ? number(b.volume) : json(nullptr)},
          {"free_edges", b.freeEdges}};
}

json reportJson(const SceneReport& r, const std::vector<Body>& bodies) {
  json joins = json::array(), seams = json::array(), crossings = json::array(), centres = json::array(), out = json::array();
  for (const JoinResult& j : r.joins) joins.push_back(joinJson(j, false));
  for (const JoinResult& j : r.seams) seams.push_back(joinJson(j, true));
  for (const Crossing& c : r.crossings)
    crossings.push_back({{"patch", c.patch}, {"other", c.other}, {"u", c.u}, {"v", c.v}, {"other_u", c.otherU}, {"other_v", c.otherV},
                         {"triangles", c.triangles}});
  for (const FillCentre& c : r.centres)
    centres.push_back({{"patch", c.patch}, {"normal_spread_deg", number(c.normalSpreadDeg)}, {"normal_spread_outer_deg", number(c.normalSpreadOuterDeg)},
                       {"fold", c.fold}, {"curvature_near", number(c.curvatureNear)}, {"curvature_ratio", number(c.curvatureRatio)}, {"ok", c.ok}});
  for (const Body& b : bodies) out.push_back(bodyJson(b));
  return {{"ok", r.ok}, {"scene_size", number(r.sceneSize)}, {"joins", joins}, {"seams", seams}, {"crossings", crossings}, {"centres", centres},
          {"bodies", out}};
}

}  // namespace pdesurf
