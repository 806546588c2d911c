// IGES with a topology is a B-rep (issue 36, cad/iges_writer.cpp): a manifold solid (186) per
// closed shell and an open shell (514 form 2) per open one, faces (510) named, loops (508) of
// the topology's edges (504 over one 502 vertex list) counter-clockwise about each surface's
// normal, each use with its curve in (u, v) but rings on faces closed in v. Read back from the
// file's own records; Open CASCADE's reading is tests/cli/cad-export.test.mjs's.
#include <doctest.h>

#include <algorithm>
#include <map>

#include "cad/border_joins.hpp"
#include "cad/brep_topology.hpp"
#include "cad/iges_writer.hpp"
#include "cad/scene_fit.hpp"
#include "iges_records.hpp"
#include "scene/scene.hpp"
#include "test_util.hpp"

using namespace pdesurf;
using namespace pdesurf::testing;

namespace {

struct IgesEntity {
  int de, type, form;
  std::string status, label;
  std::vector<std::string> params;
};

// Every entity of an IGES file: its directory entry and its parameters.
std::vector<IgesEntity> igesEntities(const std::string& text) {
  Iges f = igesRecords(text);
  const auto& D = f.sections['D'];
  const auto& P = f.sections['P'];
  std::vector<IgesEntity> out;
  for (size_t k = 0; k + 1 < D.size(); k += 2) {
    IgesEntity e{int(k + 1), std::stoi(D[k].substr(0, 8)), std::stoi(D[k + 1].substr(32, 8)), D[k].substr(64, 8), D[k + 1].substr(56, 8), {}};
    const int first = std::stoi(D[k].substr(8, 8)), count = std::stoi(D[k + 1].substr(24, 8));
    std::string t;
    for (int r = first; r < first + count; ++r) t += P[size_t(r) - 1].substr(0, 64);
    e.params = igesParams(t);
    out.push_back(e);
  }
  return out;
}

}  // namespace

TEST_CASE("cad writers: IGES with a topology is a B-rep: a solid per closed shell, shared edges, named faces") {
  for (const char* file : {"bottle-solid.json", "you2004-fig4a.json"}) {
    CAPTURE(std::string(file));
    const Scene scene = parseScene(readText(examplePath(file)));
    const auto solved = solveScene(scene);
    double tolerance = 0;
    std::vector<BSplineSurface> faces;
    for (const PatchFit& f : fitScene(solved, SceneFitOptions{}, &tolerance)) faces.push_back(f.surface);
    const BrepTopology t = buildTopology(faces, borderJoins(solved), tolerance);
    const std::vector<IgesEntity> all = igesEntities(writeIges(faces, CadFileInfo{scene.title, tolerance, ""}, &t));
    std::map<int, const IgesEntity*> at;
    std::map<int, std::vector<const IgesEntity*>> ofType;
    for (const IgesEntity& e : all) at[e.de] = &e, ofType[e.type].push_back(&e);
    // Roots: a 186 per closed shell, a 514 form 2 per open one; all else dependent, the loops'
    // curves in (u, v) with entity use 05 (parametric).
    size_t closed = 0;
    for (const BrepShell& sh : t.shells) closed += sh.closed;
    REQUIRE(ofType[186].size() == closed);
    REQUIRE(ofType[514].size() == t.shells.size());
    for (const IgesEntity& e : all) {
      const bool root = e.type == 186 || (e.type == 514 && e.form == 2);
      if (e.status != "00010500") CHECK(e.status == (root ? "00000000" : "00010000"));
      if (e.status == "00010500") CHECK(e.type == 126);
    }
    // One vertex list, one edge list over every edge: its curve, start and end vertices.
    REQUIRE(ofType[502].size() == 1);
    REQUIRE(ofType[504].size() == 1);
    const IgesEntity& vertices = *ofType[502][0];
    CHECK(std::stoi(vertices.params[1]) == int(t.vertices.size()));
    const IgesEntity& edges = *ofType[504][0];
    REQUIRE(std::stoi(edges.params[1]) == int(t.edges.size()));
    for (size_t k = 0; k < t.edges.size(); ++k) {
      const auto p = [&](int i) { return std::stoi(edges.params[2 + 5 * k + size_t(i)]); };
      CHECK(at[p(0)]->type == 126);
      CHECK(p(1) == vertices.de);
      CHECK(p(2) == t.edges[k].start + 1);
      CHECK(p(4) == t.edges[k].end + 1);
      const BSplineCurve& c = t.edges[k].curve;
      const IgesEntity& curve = *at[p(0)];
      CHECK(std::stoi(curve.params[1]) == int(c.poles.size()) - 1);
      CHECK(parseReal(curve.params[7 + c.knots.size() + c.poles.size()]) == c.poles[0].x());
    }
    // A face per surface, named, its loop the topology's; shells list them with their senses.
    REQUIRE(ofType[510].size() == faces.size());
    for (size_t f = 0; f < faces.size(); ++f) {
      const IgesEntity& face = *ofType[510][f];
      CHECK(face.label == std::string(8 - std::min<size_t>(8, faces[f].name.size()), ' ') + faces[f].name.substr(0, 8));
      CHECK(at[std::stoi(face.params[1])]->type == 128);
      const IgesEntity& name = *at[std::stoi(face.params.back())];
      CHECK(name.type == 406);
      CHECK(name.params[2] == faces[f].name);
      // The loop counter-clockwise about the surface's own normal: a flipped face's turned back.
      std::vector<BrepEdgeUse> uses = t.faces[f].loop;
      if (t.faces[f].flipped) {
        std::reverse(uses.begin(), uses.end());
        for (BrepEdgeUse& u : uses) u.forward = !u.forward;
      }
      const IgesEntity& loop = *at[std::stoi(face.params[4])];
      REQUIRE(loop.type == 508);
      REQUIRE(std::stoi(loop.params[1]) == int(uses.size()));
      // Each use: type, edge list, index, sense, then one curve in the face's (u, v) (a 126 in
      // z = 0), but for a ring on a face closed in v (Open CASCADE projects those itself).
      size_t at0 = 2;
      for (size_t u = 0; u < uses.size(); ++u) {
        const auto p = [&](int i) { return std::stoi(loop.params[at0 + size_t(i)]); };
        const BrepEdge& e = t.edges[size_t(uses[u].edge)];
        const int curves = e.start == e.end && faces[f].closedV ? 0 : 1;
        CHECK(p(0) == 0);  // an edge, not a vertex
        CHECK(p(1) == edges.de);
        CHECK(p(2) == uses[u].edge + 1);
        CHECK(p(3) == int(uses[u].forward));
        REQUIRE(p(4) == curves);
        if (curves) {
          const IgesEntity& pcurve = *at[p(6)];
          CHECK(pcurve.type == 126);
          CHECK(pcurve.status == "00010500");
          CHECK(pcurve.params[3] == "1");  // planar
        }
        at0 += 5 + 2 * size_t(curves);
      }
      CHECK(at0 == loop.params.size());
    }
    for (size_t s = 0; s < t.shells.size(); ++s) {
      const IgesEntity& shell = *ofType[514][s];
      CHECK(shell.form == (t.shells[s].closed ? 1 : 2));
      REQUIRE(std::stoi(shell.params[1]) == int(t.shells[s].faces.size()));
      for (size_t k = 0; k < t.shells[s].faces.size(); ++k) {
        const int f = t.shells[s].faces[k];
        CHECK(std::stoi(shell.params[2 + 2 * k]) == ofType[510][size_t(f)]->de);
        CHECK(std::stoi(shell.params[3 + 2 * k]) == int(!t.faces[size_t(f)].flipped));
      }
    }
  }
}
