// The report session (cpp/analysis/report_session.cpp): part by part, the same report as the
// one-off checkScene and measureBodies, bit for bit, on every kind of scene; after an edit it
// measures again exactly the parts whose surfaces or declared joins changed (a join's
// tolerances are its own: a far patch moved keeps every join) and still equals a fresh report
// of the edited scene.
#include <doctest.h>

#include <nlohmann/json.hpp>

#include "analysis/report_session.hpp"
#include "test_util.hpp"

using namespace pdesurf;
using json = nlohmann::json;
using namespace pdesurf::testing;

namespace {

void sameJoins(const std::vector<JoinResult>& a, const std::vector<JoinResult>& b) {
  REQUIRE(a.size() == b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    INFO(a[i].patch << " " << a[i].end << " - " << a[i].surface << " " << a[i].edge);
    CHECK(a[i].patch == b[i].patch);
    CHECK(a[i].end == b[i].end);
    CHECK(a[i].surface == b[i].surface);
    CHECK(a[i].edge == b[i].edge);
    CHECK(a[i].level == b[i].level);
    CHECK(a[i].size == b[i].size);
    CHECK(a[i].g0 == b[i].g0);
    CHECK(a[i].g1Deg == b[i].g1Deg);
    CHECK(a[i].g2Rel == b[i].g2Rel);
    CHECK(a[i].worstV == b[i].worstV);
    CHECK(a[i].fold == b[i].fold);
    CHECK(a[i].degenerate == b[i].degenerate);
    CHECK(a[i].ok == b[i].ok);
  }
}

// The session's report against checkScene's and measureBodies' of the same solve.
void sameAsOneOff(ReportSession& session, const Scene& scene, const std::vector<SolvedPatch>& solved, int crossingGrid) {
  const SceneReport want = checkScene(scene, solved, crossingGrid);
  const std::vector<Body> bodies = measureBodies(solved, want.sceneSize);
  const SceneReport& got = session.report();
  CHECK(got.sceneSize == want.sceneSize);
  CHECK(got.ok == want.ok);
  sameJoins(got.joins, want.joins);
  sameJoins(got.seams, want.seams);
  REQUIRE(got.centres.size() == want.centres.size());
  for (size_t i = 0; i < got.centres.size(); ++i) {
    CHECK(got.centres[i].patch == want.centres[i].patch);
    CHECK(got.centres[i].normalSpreadDeg == want.centres[i].normalSpreadDeg);
    CHECK(got.centres[i].curvatureRatio == want.centres[i].curvatureRatio);
    CHECK(got.centres[i].ok == want.centres[i].ok);
  }
  CHECK(got.crossings.size() == want.crossings.size());
  REQUIRE(session.bodies().size() == bodies.size());
  for (size_t i = 0; i < bodies.size(); ++i) {
    CHECK(session.bodies()[i].patches == bodies[i].patches);
    CHECK(session.bodies()[i].closed == bodies[i].closed);
    CHECK(session.bodies()[i].area == bodies[i].area);
    CHECK(session.bodies()[i].volume == bodies[i].volume);
  }
}

int runAll(ReportSession& s) {
  int steps = 1;
  while (!s.step()) ++steps;
  return steps;
}

}  // namespace

TEST_CASE("report session: part by part, the one-off report of every kind of scene, bit for bit") {
  for (const char* id : {"you2004-fig4a", "you2004-fig8c", "bottle-solid", "wu2015-fig4", "zhang-vase-fig1b", "ref-pipe-tjoint"}) {
    INFO(id);
    const Scene scene = parseScene(readText(examplePath(std::string(id) + ".json")));
    const auto solved = solveScene(scene);
    ReportSession session;
    session.begin(scene, solved, 16);
    const size_t parts = session.partsLeft();
    // Nothing kept on a first report: one part a step, the crossings in several (each patch's
    // mesh, then blocks of the hash and of the pairs), so that an edit can come between them.
    CHECK(runAll(session) >= int(parts) - 1 + int(solved.size()) + 2);
    CHECK(session.partsMeasured() == parts);
    sameAsOneOff(session, scene, solved, 16);
    // The same solve again: every part kept, nothing measured, the same report.
    session.begin(scene, solved, 16);
    CHECK(runAll(session) == 1);
    CHECK(session.partsMeasured() == 0);
    CHECK(session.partsKept() == parts);
    sameAsOneOff(session, scene, solved, 16);
  }
}

TEST_CASE("report session: an edit measures again only the parts it changed, and the report is a fresh one's") {
  json j = json::parse(readText(examplePath("you2004-fig8d.json")));
  SolveCache cache;
  ReportSession session;
  const Scene first = parseScene(j.dump());
  const auto solvedFirst = solveScene(first, &cache);
  session.begin(first, solvedFirst);
  runAll(session);
  const size_t parts = session.partsMeasured();
  // The tail's lift: the tail and what follows it change (scene size too: every part), the
  // stabiliser's position does not move the bounding box (the fuselage spans it): fewer parts.
  j["parameters"]["stab_dihedral"]["value"] = double(j["parameters"]["stab_dihedral"]["value"]) + 0.02;
  const Scene edited = parseScene(j.dump());
  const auto solvedEdited = solveScene(edited, &cache);
  session.begin(edited, solvedEdited);
  runAll(session);
  MESSAGE("aeroplane: " << parts << " parts; after stab_dihedral " << session.partsMeasured() << " measured, " << session.partsKept() << " kept");
  CHECK(session.partsMeasured() > 0);
  CHECK(session.partsKept() > 0);
  CHECK(session.partsMeasured() + session.partsKept() == parts);
  sameAsOneOff(session, edited, solvedEdited, 0);
}

TEST_CASE("report session: moving a far patch (the scene's size changes) keeps every join; only that patch and the bodies are measured") {
  json j = json::parse(readText(examplePath("you2004-fig4a.json")));
  j["parameters"]["far"] = {{"value", 40.0}, {"min", 0.0}, {"max", 1e6}};
  j["patches"].push_back({{"name", "far"}, {"kind", "surface"}, {"v_range", {0, "2*pi"}}, {"t_range", {0, 1}},
                          {"x", "cos(v)"}, {"y", "sin(v)"}, {"z", "far + t"}});
  ReportSession session;
  const Scene first = parseScene(j.dump());
  const auto solvedFirst = solveScene(first);
  session.begin(first, solvedFirst);
  runAll(session);
  j["parameters"]["far"]["value"] = 1e5;
  const Scene edited = parseScene(j.dump());
  const auto solvedEdited = solveScene(edited);
  session.begin(edited, solvedEdited);
  runAll(session);
  CHECK(session.report().sceneSize > 1e4);
  CHECK(session.partsMeasured() == 3);  // the far patch's seam test and face, the bodies
  sameAsOneOff(session, edited, solvedEdited, 0);
  for (const JoinResult& r : session.report().joins) CHECK(r.size < 10);  // the blend's and its edge's
}
