// pdesurf check: the join certificate and crossing test of a scene (docs/analysis.md).
#include <cstdio>
#include <string>
#include <nlohmann/json.hpp>
#include <ostream>

#include "analysis/bodies.hpp"
#include "analysis/report_json.hpp"
#include "analysis/interior_creases.hpp"
#include "analysis/join_certificate.hpp"
#include "cli.hpp"
#include "surface/mesh.hpp"
#include "methods/measures.hpp"

namespace pdesurf::cli {

namespace {

// The interior's PDE residual of every pde patch, beside the joins (which are exact by method).
struct PatchResidual {
  std::string patch, method;
  PdeResidual r;
};

std::vector<PatchResidual> residuals(const std::vector<SolvedPatch>& solved) {
  std::vector<PatchResidual> out;
  for (const SolvedPatch& s : solved)
    if (s.patch->solvedAsPde()) out.push_back({s.patch->name, methodName(s.used), interiorResidual(s.pde(), s.surface)});
  return out;
}

// Creases inside every patch (analysis/interior_creases.hpp), reported beside the verdict,
// not in it: a typed surface or a blend of kinked data has the creases its model declares, and
// a fill's corners still turn its normal fast nearby (docs/chains-and-fills.md, Limits).
std::vector<InteriorCreases> creases(const std::vector<SolvedPatch>& solved, const SceneReport& report) {
  std::vector<InteriorCreases> out;
  for (const SolvedPatch& s : solved) {
    bool sharpSeam = false;
    for (const JoinResult& seam : report.seams) sharpSeam = sharpSeam || (seam.patch == s.patch->name && seam.level == 0);
    out.push_back(measureCreases(s.patch->name, s.surface, kCreaseGrid, 0.05, sharpSeam));
  }
  return out;
}

// The report (analysis/report_json.hpp) with what only the CLI measures: the PDE residual and
// the creases inside each patch.
nlohmann::json toJson(const SceneReport& r, const std::vector<PatchResidual>& res, const std::vector<InteriorCreases>& cr,
                      const std::vector<Body>& bs) {
  using nlohmann::json;
  json report = reportJson(r, bs);  // the module's report, the same keys
  json interior = json::array();
  for (const PatchResidual& p : res)
    interior.push_back({{"patch", p.patch}, {"method", p.method}, {"residual", p.r.absolute}, {"residual_rel", p.r.relative},
                        {"worst_u", p.r.u}, {"worst_v", p.r.v}});
  json creases = json::array();
  for (const InteriorCreases& c : cr)
    creases.push_back({{"patch", c.patch}, {"coarse_deg", c.coarseDeg}, {"fine_deg", c.fineDeg}, {"crease_deg", c.creaseDeg}, {"worst_u", c.u},
                       {"worst_v", c.v}, {"smooth", c.ok}});
  report["interior"] = interior;
  report["creases"] = creases;
  return report;
}

}  // namespace

int runCheck(const Options& o, std::ostream& out) {
  const Scene scene = parseScene(readFile(o.scenePath));
  const int grid = o.gridGiven ? std::max(o.nu, o.nv) : 64;
  checkSceneGrid(scene, grid, grid);
  const auto solved = solveScene(scene);
  // The surfaces as the page and export draw them, first: what cannot be drawn (beyond a
  // float, not finite) is the same NonFinite here (issue 38 #12: check measured joins of it).
  Mesh drawn;
  for (const SolvedPatch& sp : solved) drawn = tessellatePatch(sp, grid, grid);
  drawn = Mesh{};
  const SceneReport r = checkScene(scene, solved, grid);
  const std::vector<PatchResidual> res = residuals(solved);
  const std::vector<InteriorCreases> cr = creases(solved, r);
  const std::vector<Body> bodies = measureBodies(solved, r.sceneSize);
  if (o.json) {
    out << toJson(r, res, cr, bodies).dump(2) << "\n";
    return r.ok ? 0 : 1;
  }
  char line[512];
  for (const JoinResult& j : r.joins) {
    char g2[32] = "-";
    if (j.level == 2) std::snprintf(g2, sizeof g2, "%.2e", j.g2Rel);
    std::snprintf(line, sizeof line, "join %s:%s - %s:%s  promise %s  G0 %.2e  G1 %.2e deg  G2 %s  fold %s  degenerate %d  %s\n",
                  j.patch.c_str(), j.end.c_str(), j.surface.c_str(), j.edge.c_str(), levelName(j.level), j.g0, j.g1Deg, g2,
                  j.fold ? "YES" : "no", j.degenerate, j.ok ? "ok" : "FAILS");
    out << line;
  }
  for (const JoinResult& j : r.seams) {
    char g2[32] = "-";
    if (j.level == 2) std::snprintf(g2, sizeof g2, "%.2e", j.g2Rel);
    std::snprintf(line, sizeof line, "seam %s: v1 - v0%s  promise %s  G0 %.2e  G1 %.2e deg  G2 %s  fold %s  degenerate %d  %s\n", j.patch.c_str(),
                  j.level == 0 ? " (sharp in its data)" : "", levelName(j.level), j.g0, j.g1Deg, g2, j.fold ? "YES" : "no", j.degenerate,
                  j.ok ? "ok" : "FAILS");
    out << line;
  }
  for (const FillCentre& c : r.centres) {
    std::snprintf(line, sizeof line, "centre %s: normal spread %.2e deg (%.2e deg 2^-6 out)  fold %s  curvature %.3g (ratio %.2f to the outer rings)  %s\n", c.patch.c_str(),
                  c.normalSpreadDeg, c.normalSpreadOuterDeg, c.fold ? "YES" : "no", c.curvatureNear, c.curvatureRatio, c.ok ? "ok" : "FAILS");
    out << line;
  }
  for (const PatchResidual& p : res) {
    std::snprintf(line, sizeof line, "interior %s (%s): PDE residual %.2e, relative %.2e at (u, v) = (%.3g, %.3g)\n", p.patch.c_str(),
                  p.method.c_str(), p.r.absolute, p.r.relative, p.r.u, p.r.v);
    out << line;
  }
  for (const InteriorCreases& c : cr) {
    std::snprintf(line, sizeof line, "creases %s: normal turn %.3g deg (h) %.3g deg (h/2): crease %.2e deg at (u, v) = (%.3g, %.3g)  %s\n",
                  c.patch.c_str(), c.coarseDeg, c.fineDeg, c.creaseDeg, c.u, c.v, c.ok ? "smooth" : "creased");
    out << line;
  }
  for (const Crossing& c : r.crossings) {
    std::snprintf(line, sizeof line, "crossing %s x %s: u %.4g..%.4g, v %.4g..%.4g (%d triangle pairs)\n", c.patch.c_str(), c.other.c_str(),
                  c.u[0], c.u[1], c.v[0], c.v[1], c.triangles);
    out << line;
  }
  // Each body: the patches its joins connect, closed or open, its area and a closed one's volume.
  for (size_t k = 0; k < bodies.size(); ++k) {
    const Body& b = bodies[k];
    std::string names;
    for (const std::string& n : b.patches) names += (names.empty() ? "" : ", ") + n;
    if (b.closed) std::snprintf(line, sizeof line, "body %zu: closed, area %.7g, volume %.7g: ", k + 1, b.area, b.volume);
    else std::snprintf(line, sizeof line, "body %zu: open (%d free edges), area %.7g: ", k + 1, b.freeEdges, b.area);
    out << line << names << "\n";
  }
  std::string summary = std::to_string(r.joins.size()) + " joins, ";
  if (!r.seams.empty()) summary += std::to_string(r.seams.size()) + (r.seams.size() == 1 ? " seam, " : " seams, ");
  if (!r.centres.empty()) summary += std::to_string(r.centres.size()) + " centres, ";
  summary += std::to_string(r.crossings.size()) + " crossings: " + (r.ok ? "ok" : "FAILS") + "\n";
  out << summary;
  return r.ok ? 0 : 1;
}

}  // namespace pdesurf::cli
