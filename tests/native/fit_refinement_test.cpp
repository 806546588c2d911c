// Where the certified fit refines (cpp/cad/fit_refinement.cpp): the plan's predictions from
// the errors' orders, the spans it cuts, and the grid's limit turning finer cells into cut spans.
#include <doctest.h>

#include <cmath>

#include "cad/bspline_fit.hpp"
#include "cad/fit_refinement.hpp"

using namespace pdesurf;

namespace {

// A certificate of nu × nv spans with `cells` cells each, every cell passing, residuals zero.
struct Case {
  SpanSet u, v;
  CertificateGrid grid;
  Certificate cert;
  std::vector<double> ru, rv;
  Case(int nu, int nv, int cells) : u(initialSpans(0, 1, nu, cells, {})), v(initialSpans(0, 1, nv, cells, {})) {
    certificateLine(u, &grid.u, &grid.uSpan);
    certificateLine(v, &grid.v, &grid.vSpan);
    ru.assign(size_t(nu), 0.0), rv.assign(size_t(nv), 0.0);
  }
  FailedCell& fail(Eigen::Index i, Eigen::Index j) {
    cert.failed.push_back({i, j, 0, 0, 0, 0, 0});
    return cert.failed.back();
  }
  RefinePlan plan(double tol) { return planRefinement({&u, &v, &grid, &cert, &ru, &rv, tol, 0.01, 5, false}); }
};

}  // namespace

TEST_CASE("fit refinement: spans cut into as many pieces as the residual's h^6 predicts, at most four") {
  Case c(4, 4, 4);
  const double tol = 1e-6;
  c.ru = {0.2e-6, 0.3e-6, 64 * 0.25e-6 * 0.999, 1e-3};  // kept, 2 (≥ 2 when missed), 2 (64^(1/6) = 2), 4 (capped)
  c.rv = {0.0, 729 * 0.25e-6, 0.0, NAN};                 // 729^(1/6) = 3; a residual that is not finite: halved
  const RefinePlan p = c.plan(tol);
  CHECK(p.piecesU == std::vector<int>{1, 2, 2, 4});
  CHECK(p.piecesV == std::vector<int>{1, 3, 1, 2});
  CHECK(p.splitsSpans());
  SpanSet u = c.u;
  applyPlan(u, p.piecesU, p.cutsU);
  REQUIRE(u.count() == 1 + 2 + 2 + 4);
  CHECK(u.breaks.front() == 0.0);
  CHECK(u.breaks.back() == 1.0);
  CHECK(u.breaks[6] == doctest::Approx(0.75 + 0.25 / 4));
  for (int k = 0; k < u.count(); ++k) CHECK(u.cuts[size_t(k)] == 4);  // each piece keeps the span's cells
}

TEST_CASE("fit refinement: a cell whose samples pass and whose bound fails gets finer cells in the dominant direction") {
  Case c(2, 2, 4);
  const double tol = 1e-6;
  // Cell (1, 5): in u-span 0 and v-span 1; slack mostly u: 9× the budget the v part leaves.
  FailedCell& f = c.fail(1, 5);
  f.bound = 2e-6, f.sampled = 0.1e-6, f.slackV = 0.1e-6, f.slackU = 9 * (0.9e-6 - 0.1e-6 - 0.1e-6);
  const RefinePlan p = c.plan(tol);
  CHECK_FALSE(p.splitsSpans());
  CHECK(p.cutsU == std::vector<int>{12, 4});  // sqrt(9) = 3 times the cells, in that span only
  CHECK(p.cutsV == std::vector<int>{4, 4});
  // A cell whose samples miss half the tolerance: both its spans halved, cells kept.
  FailedCell& g = c.fail(6, 2);
  g.sampled = 0.6e-6, g.bound = 0.7e-6 + 1e-6;
  const RefinePlan q = c.plan(tol);
  CHECK(q.piecesU == std::vector<int>{1, 2});
  CHECK(q.piecesV == std::vector<int>{2, 1});
}

TEST_CASE("fit refinement: past 64 cells a span is halved; past the grid's limit finer cells become cut spans") {
  Case c(2, 2, 64);
  const double tol = 1e-6;
  FailedCell& f = c.fail(3, 3);
  f.bound = 2e-6, f.sampled = 0.1e-6, f.slackU = 4e-6;
  RefinePlan p = c.plan(tol);
  CHECK(p.piecesU == std::vector<int>{2, 1});
  CHECK(p.cutsU[0] == 64);
  // 8 × 512 spans of 64 cells: finer cells in u would pass the 2^20 points; the span is halved
  // with half its cells instead (as many points, the halves' own bounds).
  Case big(8, 16, 32);
  FailedCell& b = big.fail(3, 3);
  b.bound = 2e-6, b.sampled = 0.1e-6, b.slackU = 1e-6;
  const long before = long(big.grid.u.size()) * long(big.grid.v.size());
  REQUIRE(before * 2 > kFitMaxGridPoints / 4);
  big.v = initialSpans(0, 1, 512, 64, {});
  big.rv.assign(512, 0.0);
  certificateLine(big.v, &big.grid.v, &big.grid.vSpan);
  const RefinePlan q = big.plan(tol);
  CHECK(q.piecesU[0] == 2);
  CHECK(q.cutsU[0] == 16);
  long points = 1;
  for (size_t k = 0; k < q.cutsU.size(); ++k) points += q.piecesU[k] * q.cutsU[k];
  CHECK(points == long(big.grid.u.size()));
}

TEST_CASE("fit refinement: creases are breaks of their own; a single span between two (or an end) is halved") {
  const SpanSet s = initialSpans(0, 1, 4, 4, {0.26, 0.3});
  // 0.25 gives way to 0.26 (within a tenth of a span); 0-0.26 and 0.26-0.3 are single spans
  // between an end or a crease and a crease: halved.
  REQUIRE(s.breaks.size() == 8);
  CHECK(s.breaks == std::vector<double>{0, 0.13, 0.26, 0.28, 0.3, 0.5, 0.75, 1});
  CHECK(s.crease == std::vector<bool>{false, false, true, false, true, false, false, false});
  CHECK(s.cuts == std::vector<int>(7, 4));
}
