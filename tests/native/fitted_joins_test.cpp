// The join certificate of the exported faces (cad/fitted_joins.hpp): it reads the fitted
// B-splines where the surfaces' certificate reads the surfaces, finds the same joins, keeps
// them within both faces' deviations, and fails when a face is moved off its neighbour.
#include <doctest.h>

#include "analysis/join_certificate.hpp"
#include "cad/fitted_joins.hpp"
#include "test_util.hpp"

using namespace pdesurf;

namespace {

struct Fitted {
  Scene scene;
  std::vector<SolvedPatch> solved;
  std::vector<PatchFit> fits;
};

// The scene is owned here: solved patches point into it.
std::unique_ptr<Fitted> fitted(const std::string& file) {
  auto f = std::make_unique<Fitted>();
  f->scene = parseScene(testing::readText(testing::examplePath(file)));
  f->solved = solveScene(f->scene);
  f->fits = fitScene(f->solved, SceneFitOptions{});
  return f;
}

}  // namespace

TEST_CASE("fitted joins: the faces' joins are the surfaces', within both deviations, normals within 0.01°") {
  // A blend between two primaries (G1 both ends), a Bézier patch on a surface, a fill.
  for (const char* file : {"you2004-fig4c.json", "wu2015-fig4.json", "you2004-fig5.json"}) {
    CAPTURE(file);
    const auto f = fitted(file);
    const std::vector<JoinResult> surfaces = certifyJoins(f->scene, f->solved);
    const std::vector<FittedJoin> faces = certifyFittedJoins(f->scene, f->solved, f->fits);
    REQUIRE(faces.size() == surfaces.size());
    REQUIRE(!faces.empty());
    for (size_t k = 0; k < faces.size(); ++k) {
      const FittedJoin& j = faces[k];
      CAPTURE(j.faces.patch);
      CAPTURE(j.faces.surface);
      CHECK(j.faces.patch == surfaces[k].patch);
      CHECK(j.faces.level == surfaces[k].level);
      CHECK(j.faces.ok);
      CHECK(j.faces.g0 * j.faces.size <= j.allowedGap);
      if (j.faces.level >= 1) CHECK(j.faces.g1Deg <= 0.01);
    }
  }
}

TEST_CASE("fitted joins: a face moved off its neighbour, or turned at its border, fails") {
  const auto f = fitted("you2004-fig4c.json");
  size_t blend = 0;
  while (f->solved[blend].patch->name != "blend") ++blend;
  const double tol = f->fits[blend].report.deviation;
  SUBCASE("moved by ten times its deviation") {
    for (auto& p : f->fits[blend].surface.poles) p.z() += 10 * tol;
  }
  SUBCASE("its second pole row at u0 turned: the tangent plane tilts by about 0.05°") {
    BSplineSurface& b = f->fits[blend].surface;
    // Each pole of the second row moved along the net's normal there (across the first row).
    std::vector<Eigen::Vector3d> moved(static_cast<size_t>(b.countV));
    for (int j = 0; j < b.countV; ++j) {
      const Eigen::Vector3d d = b.pole(1, j) - b.pole(0, j);
      const Eigen::Vector3d e = b.pole(0, std::min(j + 1, b.countV - 1)) - b.pole(0, std::max(j - 1, 0));
      moved[size_t(j)] = b.pole(1, j) + 1e-3 * d.norm() * d.cross(e).normalized();
    }
    for (int j = 0; j < b.countV; ++j) b.pole(1, j) = moved[size_t(j)];
  }
  bool failed = false;
  for (const FittedJoin& j : certifyFittedJoins(f->scene, f->solved, f->fits))
    if (j.faces.patch == "blend" && j.faces.end == "u0") failed = !j.faces.ok;
  CHECK(failed);
}
