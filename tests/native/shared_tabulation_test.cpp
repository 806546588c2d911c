// The tabulation's shared work (surface/tabulation.cpp) gives what each term alone gives: the
// exponentials kept per (rate, shift) across terms (ExpOnGrid) and a general function's orders
// run as one program (evalManyUpTo), on every solved patch of every example.
#include <doctest.h>

#include <filesystem>
#include <set>

#include "analysis/edge_samples.hpp"
#include "analysis/join_certificate.hpp"
#include "basis/general_function.hpp"
#include "methods/measures.hpp"
#include "test_util.hpp"

using namespace pdesurf;
using namespace pdesurf::testing;

TEST_CASE("shared tabulation: kept exponentials and one program for every order equal the term-by-term values") {
  size_t pieces = 0, kept = 0, generals = 0;
  for (const auto& entry : std::filesystem::directory_iterator(examplePath(""))) {
    const std::string file = entry.path().filename().string();
    if (entry.path().extension() != ".json" || file == "index.json") continue;
    INFO(file);
    const Scene scene = parseScene(readText(entry.path().string()));
    const auto solved = solveScene(scene);
    std::vector<double> u;
    for (int i = 0; i <= 20; ++i) u.push_back(i / 20.0);
    for (const SolvedPatch& sp : solved) {
      ExpOnGrid exps(u.data(), int(u.size()));
      std::vector<double> alone(u.size() * 3), shared(u.size() * 3);
      std::set<std::pair<std::pair<double, double>, double>> rates;
      for (const auto& component : sp.surface.component)
        for (const SeparableTerm& t : component) {
          t.G.tabulate(u.data(), int(u.size()), 2, alone.data());
          t.G.tabulate(u.data(), int(u.size()), 2, shared.data(), nullptr, &exps);
          CHECK(alone == shared);
          for (const ExpPoly& p : t.G.pieces)
            if (p.rate != 0.0) ++pieces, rates.insert({{p.rate.real(), p.rate.imag()}, p.shift});
          if (t.g.family != Family::General) continue;
          ++generals;
          std::vector<double> v(u), a0(u.size()), a1(u.size()), a2(u.size()), b0(u.size()), b1(u.size()), b2(u.size());
          for (double& x : v) x = sp.surface.v0 + (sp.surface.v1 - sp.surface.v0) * x;
          t.g.general->evalMany(v.data(), v.size(), 0, a0.data());
          t.g.general->evalMany(v.data(), v.size(), 1, a1.data());
          t.g.general->evalMany(v.data(), v.size(), 2, a2.data());
          double* outs[3] = {b0.data(), b1.data(), b2.data()};
          t.g.general->evalManyUpTo(v.data(), v.size(), 2, outs);
          CHECK(a0 == b0);
          CHECK(a1 == b1);
          CHECK(a2 == b2);
        }
      kept += rates.size();
    }
  }
  MESSAGE("examples: " << pieces << " exponential pieces, " << kept << " distinct (rate, shift) per patch; " << generals << " general v-factors");
  CHECK(pieces > 0);
  CHECK(generals > 0);
  CHECK(kept < pieces);  // the sharing is real: terms do share their rates
}

TEST_CASE("the interior residual tabulated once per grid line is the point-by-point one, on every example's pde patches") {
  // Issue 38 #2: point by point, a heavy fill's general functions were re-expanded for every
  // point and order (check took 11 s). The tabulated sums must give the same figure and place.
  size_t patches = 0;
  for (const char* id : {"you2004-fig3b", "you2004-fig5", "you2004-fig8d", "bottle-solid", "zhang-c2-ex1", "ref-pipe-tjoint", "you2004-fig8c"}) {
    INFO(id);
    const Scene scene = parseScene(readText(examplePath(std::string(id) + ".json")));
    for (const SolvedPatch& sp : solveScene(scene)) {
      if (!sp.patch->solvedAsPde()) continue;
      INFO(sp.patch->name);
      ++patches;
      const PdeProblem& p = sp.pde();
      const int grid = 8;
      double worst = -1.0, scale = 0.0, wu = 0, wv = 0;
      for (int i = 1; i < grid; ++i)
        for (int j = 1; j < grid; ++j) {
          const double u = double(i) / grid, v = p.v0 + (p.v1 - p.v0) * j / grid;
          double r = 0.0;
          for (int c = 0; c < 3; ++c) {
            const auto& a = p.component[c].alpha;
            const int n = int(a.size()) - 1;
            const double f = forceAt(p.component[c].force, u, v);
            double sum = -f, mag = std::abs(f);
            for (int k = 0; k <= n; ++k) {
              const double part = a[k] * evalComponent(sp.surface, c, u, v, 2 * (n - k), 2 * k);
              sum += part, mag += std::abs(part);
            }
            r = std::max(r, std::abs(sum));
            scale = std::max(scale, mag);
          }
          if (r > worst) worst = r, wu = u, wv = v;
        }
      const PdeResidual got = interiorResidual(p, sp.surface, grid);
      CHECK(std::abs(got.absolute - worst) <= 1e-9 * scale);
      CHECK(std::abs(got.relative - worst / scale) <= 1e-9);
      if (worst > 1e-6 * scale) CHECK((got.u == wu && got.v == wv));  // the same place, where it is not rounding
    }
  }
  CHECK(patches > 20);
}

TEST_CASE("an edge's samples, tabulated on its own line, are its point-by-point partials, on every example's patches") {
  // The certificate tabulates only the edge it reads (one u or one v), not the grid's other end.
  size_t edges = 0;
  for (const char* id : {"you2004-fig4a", "you2004-fig8d", "bottle-solid", "ref-sphere-fillet", "wu2015-fig1a", "ref-pipe-tjoint"}) {
    INFO(id);
    const Scene scene = parseScene(readText(examplePath(std::string(id) + ".json")));
    for (const SolvedPatch& sp : solveScene(scene)) {
      INFO(sp.patch->name);
      const SeparableSurface& s = sp.surface;
      for (bool alongU : {false, true})
        for (int end : {0, 1}) {
          const double a0 = alongU ? s.u0 : s.v0, a1 = alongU ? s.u1 : s.v1;
          const std::vector<EdgePoint> line = edgeSamples(s, alongU, end, a0, a1, 7);
          std::vector<double> at;
          for (int k = 0; k < 7; ++k) at.push_back(k == 6 ? a1 : a0 + (a1 - a0) * k / 6);
          const std::vector<EdgePoint> given = edgeSamplesAt(s, alongU, end, at);
          const double scale = patchSizeOf(s);
          for (int k = 0; k < 7; ++k) {
            const double u = alongU ? at[size_t(k)] : (end ? s.u1 : s.u0), v = alongU ? (end ? s.v1 : s.v0) : at[size_t(k)];
            const EdgePoint e = edgePointFrom(alongU, end, evalPoint(s, u, v), evalPoint(s, u, v, 1, 0), evalPoint(s, u, v, 0, 1),
                                              evalPoint(s, u, v, 2, 0), evalPoint(s, u, v, 1, 1), evalPoint(s, u, v, 0, 2));
            for (const EdgePoint* p : {&line[size_t(k)], &given[size_t(k)]}) {
              const double tol = 1e-9 * std::max(1.0, scale) * (1.0 + e.ss.norm() + e.ww.norm() + e.sw.norm() + e.s.norm() + e.w.norm());
              CHECK((p->X - e.X).norm() <= tol);
              CHECK((p->s - e.s).norm() <= tol);
              CHECK((p->w - e.w).norm() <= tol);
              CHECK((p->ss - e.ss).norm() <= tol);
              CHECK((p->sw - e.sw).norm() <= tol);
              CHECK((p->ww - e.ww).norm() <= tol);
            }
          }
          ++edges;
        }
    }
  }
  MESSAGE(edges << " edges");
  CHECK(edges > 40);
}
