// occt_writers_selftest: writes surfaces that cover what pdesurf hands to CAD (open degree 3
// and 5, a closed-v tube, a closed-v cap with a degenerate border, an open face with one,
// non-uniform knots, names that need escaping) with writeStep and writeIges, reads both back
// with Open CASCADE through the checker of occt_readback, and compares against
// pdesurf::evaluate. Then mutations the checker must catch. Exit 0 only when all is well.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>

#include <Geom_BSplineSurface.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>

#include "cad/iges_writer.hpp"
#include "cad/step_writer.hpp"
#include "occt_check.hpp"

using pdesurf::BSplineSurface;

namespace {

const double kTol = 1e-6;

std::vector<double> clamped(int count, int degree, double a, double b) {
  std::vector<double> k(size_t(degree) + 1, a);
  const int interior = count - degree - 1;
  for (int i = 1; i <= interior; ++i) k.push_back(a + (b - a) * i / (interior + 1));
  k.insert(k.end(), size_t(degree) + 1, b);
  return k;
}

BSplineSurface grid(const std::string& name, int p, int q, std::vector<double> ku, std::vector<double> kv,
                    double (*height)(double, double)) {
  BSplineSurface s;
  s.name = name;
  s.degreeU = p, s.degreeV = q;
  s.countU = int(ku.size()) - p - 1, s.countV = int(kv.size()) - q - 1;
  s.knotsU = std::move(ku), s.knotsV = std::move(kv);
  for (int i = 0; i < s.countU; ++i)
    for (int j = 0; j < s.countV; ++j) s.poles.emplace_back(1.5 * i, 1.1 * j + 0.2 * i, height(i, j));
  return s;
}

// A surface of revolution-like tube, closed in v: a periodic cubic in v (OCCT builds it and
// clamps it at the seam, as pdesurf's fit does), radius(i) per pole row along u.
BSplineSurface tube(const std::string& name, int countU, int around, double (*radius)(int, int)) {
  TColgp_Array2OfPnt poles(1, countU, 1, around);
  for (int i = 1; i <= countU; ++i)
    for (int j = 1; j <= around; ++j) {
      const double a = 2 * M_PI * (j - 1) / around, r = radius(i - 1, countU);
      poles(i, j) = gp_Pnt(r * std::cos(a) + 0.1 * i, r * std::sin(a), 2.0 * (i - 1) + 0.3 * std::sin(3 * a));
    }
  TColStd_Array1OfReal uk(1, 2), vk(1, around + 1);
  TColStd_Array1OfInteger um(1, 2), vm(1, around + 1);
  uk(1) = 0, uk(2) = 3, um(1) = um(2) = countU;  // Bézier in u, degree countU - 1
  for (int j = 1; j <= around + 1; ++j) vk(j) = 0.25 * (j - 1), vm(j) = 1;
  Handle(Geom_BSplineSurface) g = new Geom_BSplineSurface(poles, uk, vk, um, vm, countU - 1, 3, false, true);
  g->SetVNotPeriodic();                // floating knots past both ends of the period...
  g->Segment(0, 3, 0, 0.25 * around);  // ...clamped at the seam
  BSplineSurface s;
  s.name = name;
  s.degreeU = g->UDegree(), s.degreeV = g->VDegree();
  s.countU = g->NbUPoles(), s.countV = g->NbVPoles();
  TColStd_Array1OfReal fu(1, g->NbUPoles() + s.degreeU + 1), fv(1, g->NbVPoles() + s.degreeV + 1);
  g->UKnotSequence(fu);
  g->VKnotSequence(fv);
  s.knotsU.assign(fu.begin(), fu.end());
  s.knotsV.assign(fv.begin(), fv.end());
  for (int i = 1; i <= s.countU; ++i)
    for (int j = 1; j <= s.countV; ++j) s.poles.emplace_back(g->Pole(i, j).X(), g->Pole(i, j).Y(), g->Pole(i, j).Z());
  s.closedV = true;
  for (int i = 0; i < s.countU; ++i) s.pole(i, s.countV - 1) = s.pole(i, 0);  // exactly, as pdesurf writes it
  return s;
}

std::vector<BSplineSurface> fixtures() {
  std::vector<BSplineSurface> out;
  out.push_back(grid("open cubic", 3, 3, clamped(6, 3, 0.5, 2.0), clamped(5, 3, 0.0, 1.0),
                     [](double i, double j) { return 0.4 * std::sin(i) * std::cos(j); }));
  out.push_back(grid("quintic", 5, 5, clamped(8, 5, -1.0, 1.0), clamped(7, 5, 0.0, 3.0),
                     [](double i, double j) { return 0.1 * i * j - 0.05 * i * i; }));
  out.push_back(tube("tube", 4, 8, [](int, int) { return 2.0; }));
  BSplineSurface cap = tube("cap (fill centre)", 4, 8, [](int i, int n) { return 2.0 * (n - 1 - i) / (n - 1); });
  for (int j = 0; j < cap.countV; ++j) cap.pole(cap.countU - 1, j) = cap.pole(cap.countU - 1, 0);
  cap.degenerate[1] = true;
  out.push_back(cap);
  BSplineSurface tri = grid("triangle", 2, 3, clamped(4, 2, 0.0, 1.0), clamped(5, 3, 0.0, 1.0),
                            [](double i, double j) { return 0.2 * i + 0.1 * j * j; });
  for (int j = 0; j < tri.countV; ++j) tri.pole(0, j) = tri.pole(0, 0);
  tri.degenerate[0] = true;
  out.push_back(tri);
  out.push_back(
      grid("Na\xC3\xAFve 'quoted' \\ back \xE2\x80\x94 \xCE\xA9, a name long enough to continue on the next line", 3, 2,
           {0, 0, 0, 0, 0.1, 0.35, 0.35, 0.8, 1, 1, 1, 1}, {0, 0, 0, 0.2, 0.25, 0.9, 1.3, 1.3, 1.3},
           [](double i, double j) { return 0.3 * std::cos(i + j); }));
  return out;
}

// Samples: the corners, every pole's Greville point (where that pole weighs most) and
// random points, with the expected point from pdesurf::evaluate of `truth`.
pdesurf_occt::ExpectedFace expected(const BSplineSurface& s, const BSplineSurface& truth, const std::string& name) {
  std::vector<std::pair<double, double>> uv = {{s.u0(), s.v0()}, {s.u1(), s.v0()}, {s.u0(), s.v1()}, {s.u1(), s.v1()}};
  auto greville = [](const std::vector<double>& k, int p, int i) {
    double g = 0;
    for (int r = 1; r <= p; ++r) g += k[size_t(i + r)];
    return g / p;
  };
  for (int i = 0; i < s.countU; ++i)
    for (int j = 0; j < s.countV; ++j)
      uv.emplace_back(greville(s.knotsU, s.degreeU, i), greville(s.knotsV, s.degreeV, j));
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> ru(s.u0(), s.u1()), rv(s.v0(), s.v1());
  for (int k = 0; k < 40; ++k) uv.emplace_back(ru(rng), rv(rng));
  pdesurf_occt::ExpectedFace f{name, {}};
  for (auto [u, v] : uv) {
    const Eigen::Vector3d p = pdesurf::evaluate(truth, u, v);
    f.samples.push_back({u, v, p.x(), p.y(), p.z()});
  }
  return f;
}

pdesurf_occt::Expectation expectation(const std::vector<BSplineSurface>& faces, bool iges) {
  pdesurf_occt::Expectation e{kTol, {}};
  for (const BSplineSurface& s : faces) e.faces.push_back(expected(s, s, iges ? pdesurf::igesText(s.name) : s.name));
  return e;
}

int failures = 0;

void expect(bool ok, const std::string& what, const nlohmann::json& report) {
  std::cout << (ok ? "ok    " : "FAIL  ") << what << "\n";
  if (!ok) {
    ++failures;
    std::cout << report.dump(2) << "\n";
  }
}

}  // namespace

int main() {
  const std::vector<BSplineSurface> faces = fixtures();
  for (const BSplineSurface& s : faces) {
    std::string why;
    if (!pdesurf::wellFormed(s, &why)) {
      std::cout << "FAIL  fixture '" << s.name << "' is not well formed: " << why << "\n";
      return 1;
    }
  }
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "pdesurf-occt-selftest";
  std::filesystem::create_directories(dir);
  const pdesurf::CadFileInfo info{"selftest 'surfaces'", kTol, "2026-01-02T03:04:05"};
  const std::string stepPath = (dir / "faces.step").string(), igesPath = (dir / "faces.igs").string();
  std::ofstream(stepPath) << pdesurf::writeStep(faces, info);
  std::ofstream(igesPath) << pdesurf::writeIges(faces, info);

  for (const auto& [path, iges] : {std::pair{stepPath, false}, std::pair{igesPath, true}}) {
    const char* fmt = iges ? "IGES" : "STEP";
    const pdesurf_occt::Expectation good = expectation(faces, iges);
    std::ofstream(path + ".json") << pdesurf_occt::toJson(good).dump();  // for occt_readback by hand
    const pdesurf_occt::CheckResult r = pdesurf_occt::checkCadFile(path, good);
    expect(r.ok, std::string(fmt) + ": valid, 6 faces found by name, within tolerance, bounds agree", r.report);
    if (r.ok) {
      for (const auto& f : r.report["faces"])
        std::printf("      %-20.20s max deviation %8.3g, %d edges (%d degenerated, %d seam)\n",
                    f["name"].get<std::string>().c_str(), f["maxDeviation"].get<double>(), f["edges"].get<int>(),
                    f["degeneratedEdges"].get<int>(), f["seamEdges"].get<int>());
      std::cout << "      " << r.report["messages"].size() << " OCCT messages, file tolerance "
                << r.report["fileTolerance"] << ", largest edge/vertex tolerance " << r.report["maxEdgeVertexTolerance"]
                << "\n";
      for (const auto& m : r.report["messages"]) std::cout << "      OCCT: " << m.get<std::string>() << "\n";
    }

    // Mutations the checker must catch: a pole moved by 10 tolerances, a wrong name, a face too many.
    pdesurf_occt::Expectation moved = good;
    BSplineSurface perturbed = faces[0];
    perturbed.pole(perturbed.countU / 2, perturbed.countV / 2).z() += 10 * kTol;
    moved.faces[0] = expected(faces[0], perturbed, good.faces[0].name);
    const pdesurf_occt::CheckResult m1 = pdesurf_occt::checkCadFile(path, moved);
    expect(!m1.ok && m1.report["errors"].dump().find("deviates") != std::string::npos,
           std::string(fmt) + ": a pole moved by 10 tolerances is caught", m1.report);
    pdesurf_occt::Expectation renamed = good;
    renamed.faces[1].name = "no such face";
    const pdesurf_occt::CheckResult m2 = pdesurf_occt::checkCadFile(path, renamed);
    expect(!m2.ok && m2.report["errors"].dump().find("no face named") != std::string::npos,
           std::string(fmt) + ": a missing name is caught", m2.report);
    pdesurf_occt::Expectation extra = good;
    extra.faces.push_back(good.faces[0]);
    const pdesurf_occt::CheckResult m3 = pdesurf_occt::checkCadFile(path, extra);
    expect(!m3.ok && m3.report["errors"].dump().find("faces, expected") != std::string::npos,
           std::string(fmt) + ": a wrong face count is caught", m3.report);
  }
  std::cout << (failures ? "FAILED" : "passed") << " (files in " << dir.string() << ")\n";
  return failures ? 1 : 0;
}
