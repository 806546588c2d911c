// Benchmark (not a test): median solve time per example, and tessellation throughput against
// a memcpy of the same output bytes (the floor any tessellator must pay to write its output).
// Built natively and as wasm for node; run both with scripts/bench.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <sstream>
#include <utility>
#include <vector>

#include "analysis/join_certificate.hpp"
#include "common/errors.hpp"
#include "common/vector_clones.hpp"
#include "bezier/bezier_assembly.hpp"
#include "bezier/bezier_solver.hpp"
#include "methods/method.hpp"
#include "ode/basis_cache.hpp"
#include "scene/scene.hpp"
#include "surface/mesh.hpp"
#include "../cli/retain_freed_memory.hpp"

using namespace pdesurf;
using Clock = std::chrono::steady_clock;

namespace {

std::string readText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Median over 15 samples of the time per call, each sample batching enough calls to last ~1 ms.
double medianSeconds(const std::function<void()>& f) {
  int batch = 1;
  for (;;) {
    const auto t0 = Clock::now();
    for (int i = 0; i < batch; ++i) f();
    if (std::chrono::duration<double>(Clock::now() - t0).count() > 1e-3 || batch > (1 << 24)) break;
    batch *= 2;
  }
  std::vector<double> samples;
  for (int s = 0; s < 15; ++s) {
    const auto t0 = Clock::now();
    for (int i = 0; i < batch; ++i) f();
    samples.push_back(std::chrono::duration<double>(Clock::now() - t0).count() / batch);
  }
  std::nth_element(samples.begin(), samples.begin() + 7, samples.end());
  return samples[7];
}

volatile size_t sink;

// A pts×pts control net over the unit square with a wavy height, λ 10, γ 1.
BezierProblem benchBezierNet(int pts, BezierEnergy energy) {
  BezierProblem p;
  p.n = p.m = pts - 1;
  p.energy = energy;
  p.lambda = 10, p.gamma = 1;
  for (int i = 0; i < pts; ++i)
    for (int j = 0; j < pts; ++j) {
      const double x = static_cast<double>(i) / (pts - 1), y = static_cast<double>(j) / (pts - 1);
      p.initial.emplace_back(x, y, 0.3 * std::sin(3 * x) * std::cos(2 * y));
    }
  return p;
}

// Seconds per solve from scratch (BezierSolver built, factored and solved), and per solve
// reusing one factorisation (BezierSolver::solve after a drag of the middle control point).
std::pair<double, double> fullAndReused(const BezierProblem& p) {
  const double full = medianSeconds([&] { sink = solveBezier(p).size(); });
  const BezierSolver solver(p);
  ControlNet dragged = p.initial;
  const int mid = (p.n / 2) * (p.m + 1) + p.m / 2;
  const double reused = medianSeconds([&] {
    dragged[mid].z() += 1e-3;
    sink = solver.solve(dragged).size();
  });
  return {full, reused};
}

}  // namespace

namespace pdesurf {
double benchMedianSeconds(const std::function<void()>& f) { return medianSeconds(f); }
void benchModels(const std::string& dir);  // bench/models_bench.cpp
void benchFills(const std::string& dir, const char* file);
void benchCad(const std::string& dir);     // bench/cad_bench.cpp
void benchNurbs(const std::string& dir);   // bench/nurbs_bench.cpp
}  // namespace pdesurf

int main(int argc, char** argv) {
  platform::retainFreedMemory();  // as the CLI does: native rows measure the solver, not page faults
  // `pdesurf_bench fills`: only the fills' section (a quick look while working on them).
  if (argc > 1 && std::string(argv[1]) == "fills") {
    for (int warm = 0; warm < 3; ++warm)  // the wasm engine's optimising tier, as below
      for (const char* f : {"you2004-fig8c.json", "you2004-fig8d.json"})
        for (const SolvedPatch& sp : solveScene(parseScene(readText(std::string(PDESURF_EXAMPLES_DIR) + "/" + f))))
          sink = tessellate(sp.surface, 64, 64).vertexCount();
    for (const char* f : {"you2004-fig8c.json", "you2004-fig8d.json"}) benchFills(PDESURF_EXAMPLES_DIR, f);
    return 0;
  }
  // `pdesurf_bench nurbs`: only the NURBS drawing section.
  if (argc > 1 && std::string(argv[1]) == "nurbs") {
    benchNurbs(PDESURF_EXAMPLES_DIR);
    return 0;
  }
#ifdef __EMSCRIPTEN__
  const char* target = "wasm (node)";
#else
  const char* target = "native";
#endif
  const std::string dir = PDESURF_EXAMPLES_DIR;
  const auto index = nlohmann::json::parse(readText(dir + "/index.json"));
  std::printf("pdesurf benchmark, %s\n\n", target);
  // Warm-up: every example solved and drawn once before anything is timed (wasm engines run
  // a module's first calls in a baseline tier).
  for (const auto& e : index["examples"])
    for (const SolvedPatch& sp : solveScene(parseScene(readText(dir + "/" + e["file"].get<std::string>()))))
      sink = tessellate(sp.surface, 64, 64).vertexCount();
  // Every example: parse+solve of the whole scene, then each applicable method on its blend.
  std::printf("%-22s %10s %10s %10s %12s %12s %12s %12s\n", "example", "scene [us]", "closed", "warm", "pseudo-nav.", "modal:16", "fourier:20", "auto");
  for (const auto& e : index["examples"]) {
    const std::string text = readText(dir + "/" + e["file"].get<std::string>());
    const double both = medianSeconds([&] { sink = solveScene(parseScene(text)).size(); });
    const Scene scene = parseScene(text);
    // Seed 002's Bézier scenes, and models whose first pde patch takes its conditions from
    // others (benchModels has those): whole-scene time only.
    if (!scene.firstPde() || !scene.firstPde()->dependsOn.empty()) {
      std::printf("%-22s %10.1f\n", e["id"].get<std::string>().c_str(), both * 1e6);
      continue;
    }
    const PdeProblem& p = scene.firstPde()->pde();
    const auto applicable = applicableMethods(p);
    std::printf("%-22s %10.1f", e["id"].get<std::string>().c_str(), both * 1e6);
    {  // "warm": the closed form with its ODE bases kept, as the page keeps them between solves
      BasisCache cache;
      PdeProblem restored;
      const bool closedOk = std::find(applicable.begin(), applicable.end(), "closed") != applicable.end();
      const Method closed = parseMethod("closed");
      bool closedRuns = closedOk;
      try {  // applicableMethods looks at the terms' families only; a force may still refuse
        if (closedOk) solveWithMethod(p, closed);
      } catch (const Error&) {
        closedRuns = false;
      }
      if (closedRuns) {
        const double cold = medianSeconds([&] { sink = solveWithMethod(p, closed).surface.component[0].size(); });
        const double warm = medianSeconds([&] { sink = solveWithMethod(p, closed, &cache).surface.component[0].size(); });
        std::printf(" %10.2f %10.2f", cold * 1e6, warm * 1e6);
      } else {
        std::printf(" %10s %10s", "-", "-");
      }
    }
    for (const char* name : {"pseudo-navier", "modal:16", "fourier:20", "auto"}) {
      const bool ok = std::find(applicable.begin(), applicable.end(), name) != applicable.end();
      if (!ok) {
        std::printf(" %12s", "-");
        continue;
      }
      const Method m = parseMethod(name);
      try {
        solveWithMethod(p, m);
      } catch (const Error&) {
        std::printf(" %12s", "refused");
        continue;
      }
      const double t = medianSeconds([&] { sink = solveWithMethod(p, m).surface.component[0].size(); });
      std::printf(" %12.2f", t * 1e6);
    }
    std::printf("\n");
  }
  std::printf("(solve times of the blend in microseconds, median)\n");

  // Ends by reference (issue 17): the derivation alone (parseScene), with the solve, and with
  // a 64² drawing; the last two rows are hostile expressions of tests/hostile/expressions.
  std::printf("\nends by reference [us, median]\n%-28s %12s %14s %16s\n", "scene", "derive", "derive+solve", "+draw 64x64");
  for (const std::string file : {"ref-sphere-fillet.json", "ref-torus-plane.json", "ref-pipe-tjoint.json", "ref-offset-cylinders-g2.json",
                                 "../tests/hostile/expressions/product-300-curve.json", "../tests/hostile/expressions/trimmed-power-60-g2.json"}) {
    const std::string text = readText(dir + "/" + file);
    const double derive = medianSeconds([&] { sink = parseScene(text).patches.size(); });
    const double solve = medianSeconds([&] { sink = solveScene(parseScene(text)).size(); });
    const double draw = medianSeconds([&] {
      for (const SolvedPatch& sp : solveScene(parseScene(text))) sink = tessellate(sp.surface, 64, 64).vertexCount();
    });
    std::printf("%-28s %12.1f %14.1f %16.1f\n", file.substr(file.rfind('/') + 1).c_str(), derive * 1e6, solve * 1e6, draw * 1e6);
  }

  // Seed 002: one solve from scratch (assemble, factor, solve) against a solve that reuses the
  // factorisation (a drag of the initial surface's control points). 17x17 is degree 16, the cap.
  std::printf("\nvariational Bezier surfaces (membrane, continuous normals of degree 3, lambda 10, gamma 1)\n");
  std::printf("%-10s %16s %16s %10s\n", "net", "assemble+solve [ms]", "reused [ms]", "gain");
  for (int pts : {5, 8, 16, 17}) {
    BezierProblem p = benchBezierNet(pts, BezierEnergy::Membrane);
    p.normals.n1 = p.normals.m1 = 3;
    for (int k = 0; k < 16; ++k) p.normals.vectors.emplace_back(0.1 * (k % 4), 0.1 * (k / 4), 1.0);
    const auto [full, reused] = fullAndReused(p);
    std::printf("%2dx%-7d %16.3f %16.3f %9.0fx\n", pts, pts, full * 1e3, reused * 1e3, full / reused);
  }
  // A discrete field at degree 16: the assembly runs over every sample (tensor-product Gram
  // matrices, docs/bezier.md); "assembly" is assembleBezierForms alone.
  std::printf("\nvariational Bezier surfaces (thin plate, degree 16, discrete normals, lambda 10, gamma 1)\n");
  std::printf("%-10s %14s %20s %14s %10s\n", "field", "assembly [ms]", "assemble+solve [ms]", "reused [ms]", "gain");
  for (int grid : {32, 256}) {
    BezierProblem p = benchBezierNet(17, BezierEnergy::ThinPlate);
    BezierNormalField& f = p.normals;
    f.discrete = true, f.np = f.mp = grid;
    for (int i = 0; i <= grid; ++i)
      for (int j = 0; j <= grid; ++j) {
        const double u = static_cast<double>(i) / grid, v = static_cast<double>(j) / grid;
        f.vectors.emplace_back(-0.9 * std::cos(3 * u) * std::cos(2 * v), 0.6 * std::sin(3 * u) * std::sin(2 * v), 1.0);  // S's normals
      }
    const double assembly = medianSeconds([&] { sink = assembleBezierForms(p).normal.size(); });
    const auto [full, reused] = fullAndReused(p);
    std::printf("%4dx%-5d %14.3f %20.3f %14.3f %9.0fx\n", grid, grid, assembly * 1e3, full * 1e3, reused * 1e3, full / reused);
  }

  const Scene scene = parseScene(readText(dir + "/you2004-fig4a.json"));
  const SeparableSurface blend = solvePatch(*scene.firstPde()).surface;
  // The floor: a memcpy of the bytes the reused path writes, positions and normals (24 per
  // vertex; uvs and indices are written only when the grid changes). Natively the rows are
  // measured with every copy of the per-vertex loops the CPU runs: the baseline copy, 128
  // bits wide as wasm's simd128, then AVX2 and AVX-512 where there are.
  std::printf("\ntessellation of you2004-fig4a's blend (new mesh: + uvs, indices; reused: positions, normals;\n"
              "+curvature: reused, with mean and Gaussian curvature)\n");
  std::printf("%-8s %-10s %14s %12s %14s %16s %14s %10s\n", "vectors", "grid", "new mesh [ms]", "reused [ms]", "Mvertices/s",
              "+curvature [ms]", "memcpy [ms]", "x memcpy");
  for (VectorCopy copy : availableVectorCopies()) {
    limitVectorCopy(copy);
    const char* label = vectorCopyName(copy);
    for (int n : {64, 256, 1024}) {
      const Mesh probe = tessellate(blend, n, n);
      const size_t bytes = (probe.positions.size() + probe.normals.size()) * sizeof(float);
      std::vector<char> src(bytes, 1), dst(bytes);
      const double fresh = medianSeconds([&] { sink = tessellate(blend, n, n).vertexCount(); });
      Mesh reused, curved;
      const double t = medianSeconds([&] {
        tessellateInto(blend, n, n, reused);
        sink = reused.vertexCount();
      });
      const double withCurvature = medianSeconds([&] {
        tessellateInto(blend, n, n, curved, true);
        sink = curved.vertexCount();
      });
      const double floor = medianSeconds([&] {
        std::memcpy(dst.data(), src.data(), bytes);
        sink = static_cast<size_t>(dst[bytes / 2]);
      });
      const double verts = static_cast<double>(probe.vertexCount());
      std::printf("%-8s %4dx%-5d %14.3f %12.3f %14.1f %16.3f %14.3f %10.1f\n", label, n, n, fresh * 1e3, t * 1e3, verts / t / 1e6,
                  withCurvature * 1e3, floor * 1e3, t / floor);
    }
  }
  limitVectorCopy(VectorCopy::Avx512);

  // What analysis adds to a page re-solve at 256² (every patch solved with warm caches and
  // tessellated into reused meshes): curvature per vertex, the join report (256 points per
  // join), and the crossing test on the 48² meshes the page uses.
  std::printf("\nanalysis at 256x256, whole scene (warm caches, reused meshes) [ms]\n");
  std::printf("%-18s %10s %12s %10s %12s %12s\n", "example", "plain", "+curvature", "+joins", "+crossings", "curv+joins");
  for (const char* id : {"you2004-fig4a", "zhang-c2-ex1", "wu2015-fig4"}) {
    const Scene sc = parseScene(readText(dir + "/" + id + ".json"));
    SolveCache cache;
    std::vector<Mesh> meshes(sc.patches.size());
    auto run = [&](bool curvature, bool joins, int crossingGrid) {
      const auto solved = solveScene(sc, &cache);
      for (size_t k = 0; k < solved.size(); ++k) tessellateInto(solved[k].surface, 256, 256, meshes[k], curvature);
      if (joins) sink = checkScene(sc, solved, crossingGrid).joins.size();
    };
    const double plain = medianSeconds([&] { run(false, false, 0); });
    const double curv = medianSeconds([&] { run(true, false, 0); });
    const double joins = medianSeconds([&] { run(false, true, 0); });
    const double cross = medianSeconds([&] { run(false, true, 48); });
    const double both = medianSeconds([&] { run(true, true, 0); });
    std::printf("%-18s %10.3f %11.3f%% %9.1f%% %11.1f%% %11.1f%%\n", id, plain * 1e3, 100 * (curv / plain - 1), 100 * (joins / plain - 1),
                100 * (cross / plain - 1), 100 * (both / plain - 1));
  }
  benchModels(dir);
  benchCad(dir);
  benchNurbs(dir);
  return 0;
}
