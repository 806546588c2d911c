// occt_import_check (issue 40): faces made by Open CASCADE — random B-spline surfaces of
// degrees 1–5 (rational, periodic, with repeated knots) and trimmed planes, cylinders, cones,
// spheres and tori — written to STEP and IGES by OCCT, imported by `pdesurf import`'s library,
// parsed and solved by the core, and evaluated against OCCT's own BRepAdaptor_Surface of the
// faces it reads back, at random (u, v) of each face: within 1e-12 of the face's size. Then
// hostile files, each refused by name before the work (limits in docs/limits.md). Exit 0 only
// when all is well.
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>

#include <BRepAdaptor_Surface.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRep_Builder.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_ConicalSurface.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <Geom_Plane.hxx>
#include <Geom_SphericalSurface.hxx>
#include <Geom_ToroidalSurface.hxx>
#include <IGESControl_Controller.hxx>
#include <IGESControl_Reader.hxx>
#include <IGESControl_Writer.hxx>
#include <Interface_Static.hxx>
#include <STEPControl_Reader.hxx>
#include <STEPControl_Writer.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <BRepTools.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_Printer.hxx>

#include "../../cli/import/cad_import.hpp"
#include "common/errors.hpp"
#include "scene/scene.hpp"
#include "surface/separable_surface.hpp"

namespace {

int failures = 0;
#define EXPECT(cond, what)                                              \
  do {                                                                  \
    if (!(cond)) {                                                      \
      ++failures;                                                       \
      std::cerr << "FAIL: " << what << " (" #cond ")" << std::endl;     \
    }                                                                   \
  } while (0)

std::mt19937 rng(20261205);
double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); }
int integer(int a, int b) { return std::uniform_int_distribution<int>(a, b)(rng); }

// Distinct knots and multiplicities for `poles` poles of degree p: clamped ends, interior
// knots repeated up to p - 1 times (the surface stays C1: a kink is no one's design here).
void randomKnots(int p, int poles, TColStd_Array1OfReal*& knots, TColStd_Array1OfInteger*& mults, double a, double b) {
  std::vector<double> k{a};
  std::vector<int> m{p + 1};
  int left = poles - p - 1;
  while (left > 0) {
    const int r = std::min(left, integer(1, std::max(1, p - 1)));
    k.push_back(0), m.push_back(r), left -= r;
  }
  k.push_back(b), m.push_back(p + 1);
  for (size_t i = 1; i + 1 < k.size(); ++i) k[i] = a + (b - a) * (double(i) + uniform(-0.3, 0.3)) / double(k.size() - 1);
  knots = new TColStd_Array1OfReal(1, int(k.size()));
  mults = new TColStd_Array1OfInteger(1, int(k.size()));
  for (size_t i = 0; i < k.size(); ++i) (*knots)(int(i) + 1) = k[i], (*mults)(int(i) + 1) = m[i];
}

Handle(Geom_BSplineSurface) randomBSpline(bool rational, bool periodicU, double x0) {
  const int p = integer(1, 5), q = integer(1, 5);
  TColStd_Array1OfReal *uk, *vk;
  TColStd_Array1OfInteger *um, *vm;
  int nu;
  if (periodicU) {  // distinct knots, each once: as many poles as spans, a ring around z
    const int spans = integer(p + 2, p + 6);
    uk = new TColStd_Array1OfReal(1, spans + 1), um = new TColStd_Array1OfInteger(1, spans + 1);
    for (int i = 1; i <= spans + 1; ++i) (*uk)(i) = 2.0 * (i - 1) / spans + (i > 1 && i <= spans ? uniform(-0.2, 0.2) / spans : 0.0), (*um)(i) = 1;
    nu = spans;
  } else {
    nu = integer(p + 1, p + 6);
    randomKnots(p, nu, uk, um, uniform(-1, 0), uniform(0.5, 2));
  }
  const int nv = integer(q + 1, q + 6);
  randomKnots(q, nv, vk, vm, uniform(-1, 0), uniform(0.5, 2));
  TColgp_Array2OfPnt poles(1, nu, 1, nv);
  TColStd_Array2OfReal weights(1, nu, 1, nv);
  for (int i = 1; i <= nu; ++i)
    for (int j = 1; j <= nv; ++j) {
      const double a = 2 * M_PI * (i - 1) / nu;
      poles(i, j) = periodicU ? gp_Pnt(x0 + (1.5 + uniform(-0.2, 0.2)) * std::cos(a), (1.5 + uniform(-0.2, 0.2)) * std::sin(a), 0.5 * j)
                              : gp_Pnt(x0 + 0.5 * i, 0.5 * j, uniform(-0.3, 0.3));
      weights(i, j) = rational ? uniform(0.5, 2.0) : 1.0;
    }
  Handle(Geom_BSplineSurface) s = rational ? new Geom_BSplineSurface(poles, weights, *uk, *vk, *um, *vm, p, q, periodicU, false)
                                           : new Geom_BSplineSurface(poles, *uk, *vk, *um, *vm, p, q, periodicU, false);
  delete uk, delete vk, delete um, delete vm;
  return s;
}

gp_Ax3 randomFrame(double x0) {
  gp_Dir z(uniform(-1, 1), uniform(-1, 1), uniform(0.2, 1)), x0dir(uniform(-1, 1), uniform(0.2, 1), uniform(-1, 1));
  gp_Ax3 a(gp_Pnt(x0, uniform(-1, 1), uniform(-1, 1)), z, z.Crossed(x0dir).Crossed(z));
  if (integer(0, 1)) a.YReverse();  // a left-handed frame too
  return a;
}

TopoDS_Face face(const Handle(Geom_Surface) & s, double u0, double u1, double v0, double v1) {
  BRepBuilderAPI_MakeFace make(s, u0, u1, v0, v1, 1e-9);
  if (!make.IsDone()) throw std::runtime_error("MakeFace failed");
  return make.Face();
}

// Faces of every kind the importer meets, with what each is.
std::vector<std::pair<TopoDS_Face, std::string>> randomFaces(int round) {
  std::vector<std::pair<TopoDS_Face, std::string>> out;
  double x = 10.0 * round;
  for (int k = 0; k < 6; ++k, x += 4) {
    const bool rational = k % 2, periodic = k >= 4;
    Handle(Geom_BSplineSurface) s = randomBSpline(rational, periodic, x);
    double a, b, c, d;
    s->Bounds(a, b, c, d);
    // A face over part of the surface (its bounds inside) or all of it.
    if (k % 3 == 0) {
      const double ua = a + 0.2 * (b - a) * uniform(0, 1), ub = b - 0.2 * (b - a) * uniform(0, 1);
      const double va = c + 0.2 * (d - c) * uniform(0, 1), vb = d - 0.2 * (d - c) * uniform(0, 1);
      out.push_back({face(s, ua, ub, va, vb), std::string("bspline ") + (rational ? "rational " : "") + (periodic ? "periodic " : "") + "part"});
    } else {
      out.push_back({face(s, a, b, c, d), std::string("bspline ") + (rational ? "rational " : "") + (periodic ? "periodic" : "")});
    }
  }
  out.push_back({face(new Geom_Plane(randomFrame(x)), -1, uniform(0.5, 2), -0.5, uniform(0.5, 2)), "plane"}), x += 4;
  out.push_back({face(new Geom_CylindricalSurface(randomFrame(x), uniform(0.5, 2)), 0.3, uniform(1, 2 * M_PI), -1, uniform(0, 2)), "cylinder"}), x += 4;
  out.push_back({face(new Geom_ConicalSurface(randomFrame(x), uniform(0.1, 1.0), uniform(0.5, 1.5)), 0, 2 * M_PI, -0.2, uniform(0.3, 1)), "cone"}), x += 4;
  out.push_back({face(new Geom_SphericalSurface(randomFrame(x), uniform(0.5, 2)), 0.1, uniform(1, 6), -1.2, uniform(0, 1.4)), "sphere"}), x += 4;
  out.push_back({face(new Geom_ToroidalSurface(randomFrame(x), uniform(1.5, 2.5), uniform(0.2, 0.8)), 0, uniform(2, 2 * M_PI), 0, 2 * M_PI), "torus"});
  return out;
}

void writeStep(const TopoDS_Shape& shape, const std::string& path) {
  STEPControl_Writer w;
  if (w.Transfer(shape, STEPControl_AsIs) != IFSelect_RetDone || w.Write(path.c_str()) != IFSelect_RetDone) throw std::runtime_error("STEP write failed");
}

void writeIges(const TopoDS_Shape& shape, const std::string& path) {
  IGESControl_Controller::Init();
  IGESControl_Writer w("MM", 1);  // B-rep mode: faces with their surfaces
  w.AddShape(shape);
  w.ComputeModel();
  if (!w.Write(path.c_str())) throw std::runtime_error("IGES write failed");
}

// The faces OCCT reads back from the file, in its map's order.
std::vector<TopoDS_Face> readBack(const std::string& path, bool step) {
  TopoDS_Shape shape;
  if (step) {
    STEPControl_Reader r;
    r.ReadFile(path.c_str()), r.TransferRoots(), shape = r.OneShape();
  } else {
    IGESControl_Reader r;
    r.ReadFile(path.c_str()), r.TransferRoots(), shape = r.OneShape();
  }
  TopTools_IndexedMapOfShape map;
  TopExp::MapShapes(shape, TopAbs_FACE, map);
  std::vector<TopoDS_Face> out;
  for (int i = 1; i <= map.Extent(); ++i) out.push_back(TopoDS::Face(map(i)));
  return out;
}

void checkRoundTrip(int round, bool step, double* worst, int* points, int* swaps) {
  const auto made = randomFaces(round);
  TopoDS_Compound all;
  BRep_Builder b;
  b.MakeCompound(all);
  for (const auto& [f, what] : made) b.Add(all, f);
  const std::string path = (std::filesystem::temp_directory_path() / ("pdesurf-import-" + std::to_string(round) + (step ? ".step" : ".igs"))).string();
  step ? writeStep(all, path) : writeIges(all, path);
  const auto occt = readBack(path, step);
  EXPECT(occt.size() == made.size(), "round " << round << ": OCCT reads " << occt.size() << " faces of " << made.size());
  nlohmann::json scene;
  try {
    scene = pdesurf::cad_import::importCadFile(path);
  } catch (const std::exception& e) {
    EXPECT(false, "round " << round << (step ? " STEP" : " IGES") << ": import failed: " << e.what());
    return;
  }
  const pdesurf::Scene parsed = pdesurf::parseScene(scene.dump());
  const auto solved = pdesurf::solveScene(parsed);
  EXPECT(solved.size() == occt.size(), "round " << round << ": " << solved.size() << " patches for " << occt.size() << " faces");
  for (size_t i = 0; i < std::min(solved.size(), occt.size()); ++i) {
    const pdesurf::SeparableSurface& s = solved[i].surface;
    const std::string what = i < made.size() ? made[i].second : "?";
    BRepAdaptor_Surface ref(occt[i], false);  // the surface in its own parameters (no face location on these)
    double u0, u1, v0, v1;
    BRepTools::UVBounds(occt[i], u0, u1, v0, v1);
    // A face closed in u only comes back with t and v swapped (its t is the face's v).
    const auto near = [](double a, double b) { return std::abs(a - b) <= 1e-9 * (1 + std::abs(b)); };
    const bool same = near(s.u0, u0) && near(s.u1, u1) && near(s.v0, v0) && near(s.v1, v1);
    const bool swapped = near(s.u0, v0) && near(s.u1, v1) && near(s.v0, u0) && near(s.v1, u1);
    EXPECT(same || swapped, "round " << round << " face " << i << " (" << what << "): ranges [" << s.u0 << ", " << s.u1 << "] x [" << s.v0 << ", "
                                      << s.v1 << "] against " << u0 << ".." << u1 << " x " << v0 << ".." << v1);
    if (swapped && !same) ++*swaps;
    double size = 0.0, dev = 0.0;
    std::vector<std::pair<double, double>> at;
    for (int k = 0; k < 40; ++k) at.push_back({k < 4 ? (k % 2 ? s.u1 : s.u0) : uniform(s.u0, s.u1), k < 4 ? (k / 2 ? s.v1 : s.v0) : uniform(s.v0, s.v1)});
    for (const auto& [t, v] : at) {
      const gp_Pnt p = swapped && !same ? ref.Value(v, t) : ref.Value(t, v);
      const Eigen::Vector3d q = pdesurf::evalPoint(s, t, v);
      size = std::max(size, std::sqrt(p.X() * p.X() + p.Y() * p.Y() + p.Z() * p.Z()));
      dev = std::max(dev, (q - Eigen::Vector3d(p.X(), p.Y(), p.Z())).norm());
      ++*points;
    }
    *worst = std::max(*worst, dev / size);
    EXPECT(dev <= 1e-12 * size, "round " << round << (step ? " STEP" : " IGES") << " face " << i << " (" << what << "): " << dev << " from OCCT's evaluation (size " << size << ")");
  }
  std::filesystem::remove(path);
}

// A hostile file: importCadFile refuses it with `code` and a message containing `words`, fast.
void expectRefusal(const std::string& label, const std::string& path, pdesurf::ErrorCode code, const std::string& words) {
  const auto start = std::chrono::steady_clock::now();
  try {
    pdesurf::cad_import::importCadFile(path);
    EXPECT(false, label << ": imported");
  } catch (const pdesurf::Error& e) {
    EXPECT(e.code() == code && std::string(e.what()).find(words) != std::string::npos,
           label << ": " << pdesurf::errorCodeName(e.code()) << ": " << e.what());
    std::cout << "  " << label << ": " << pdesurf::errorCodeName(e.code()) << ": " << e.what() << "\n";
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT(seconds < 5.0, label << ": took " << seconds << " s");
}

void hostile() {
  const auto dir = std::filesystem::temp_directory_path();
  const std::string big = (dir / "pdesurf-import-huge.step").string();
  {
    std::ofstream(big) << "ISO-10303-21;\n";
    std::filesystem::resize_file(big, 200ll << 20);  // sparse: 200 MB of nothing
  }
  expectRefusal("a 200 MB file", big, pdesurf::ErrorCode::TooLarge, "200 MB: at most 64 MB");
  std::filesystem::remove(big);

  const std::string garbage = (dir / "pdesurf-import-garbage.step").string();
  std::ofstream(garbage) << "this is not STEP at all\n";
  expectRefusal("not STEP", garbage, pdesurf::ErrorCode::ParseError, "could not read it as STEP");

  // A good file cut in half.
  const auto faces = randomFaces(99);
  TopoDS_Compound all;
  BRep_Builder b;
  b.MakeCompound(all);
  for (const auto& [f, what] : faces) b.Add(all, f);
  const std::string whole = (dir / "pdesurf-import-whole.step").string();
  writeStep(all, whole);
  const auto n = std::filesystem::file_size(whole);
  std::filesystem::resize_file(whole, n / 2);
  try {
    const auto scene = pdesurf::cad_import::importCadFile(whole);
    // OCCT may recover the entities before the cut: what comes must then be whole faces.
    EXPECT(scene["patches"].size() < faces.size(), "a truncated file gave every face");
    pdesurf::parseScene(scene.dump());
    std::cout << "  a truncated file: " << scene["patches"].size() << " whole faces of " << faces.size() << " recovered\n";
  } catch (const pdesurf::Error& e) {
    std::cout << "  a truncated file: " << pdesurf::errorCodeName(e.code()) << ": " << e.what() << "\n";
  }

  // 65 faces: more than a scene holds, counted before any is converted.
  TopoDS_Compound many;
  b.MakeCompound(many);
  for (int i = 0; i < 65; ++i) b.Add(many, face(new Geom_Plane(gp_Ax3(gp_Pnt(2.0 * i, 0, 0), gp_Dir(0, 0, 1))), 0, 1, 0, 1));
  const std::string manyPath = (dir / "pdesurf-import-many.step").string();
  writeStep(many, manyPath);
  expectRefusal("65 faces", manyPath, pdesurf::ErrorCode::TooLarge, "65 faces: a scene holds at most 64 patches");

  // 130 × 130 control points: past kNurbsPoints (16 384).
  TColgp_Array2OfPnt poles(1, 130, 1, 130);
  for (int i = 1; i <= 130; ++i)
    for (int j = 1; j <= 130; ++j) poles(i, j) = gp_Pnt(i, j, std::sin(i * 0.3) * std::cos(j * 0.2));
  TColStd_Array1OfReal knots(1, 128);
  TColStd_Array1OfInteger mults(1, 128);
  for (int i = 1; i <= 128; ++i) knots(i) = i, mults(i) = (i == 1 || i == 128) ? 4 : 1;
  Handle(Geom_BSplineSurface) dense = new Geom_BSplineSurface(poles, knots, knots, mults, mults, 3, 3);
  TopoDS_Compound one;
  b.MakeCompound(one);
  b.Add(one, face(dense, 1, 128, 1, 128));
  const std::string densePath = (dir / "pdesurf-import-dense.step").string();
  writeStep(one, densePath);
  expectRefusal("130 × 130 control points", densePath, pdesurf::ErrorCode::TooLarge, "130 × 130 control points");

  // A pole written as NaN in the file's text.
  const std::string nanPath = (dir / "pdesurf-import-nan.step").string();
  {
    TopoDS_Compound c;
    b.MakeCompound(c);
    b.Add(c, faces[1].first);
    writeStep(c, nanPath);
    std::ifstream in(nanPath);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto at = text.find("CARTESIAN_POINT('',(");
    if (at != std::string::npos) text.replace(at + 20, 0, "1.E+400,");  // one coordinate overflows: inf
    std::ofstream(nanPath) << text;
  }
  try {
    pdesurf::cad_import::importCadFile(nanPath);
    std::cout << "  a non-finite pole: OCCT read past it (the imported scene parsed)\n";
  } catch (const pdesurf::Error& e) {
    std::cout << "  a non-finite pole: " << pdesurf::errorCodeName(e.code()) << ": " << e.what() << "\n";
  }
  for (const auto& p : {garbage, whole, manyPath, densePath, nanPath}) std::filesystem::remove(p);
}

}  // namespace

int main() {
  Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_Printer));  // OCCT's writers' statistics
  double worst = 0.0;
  int points = 0, swaps = 0;
  for (int round = 0; round < 4; ++round) {
    checkRoundTrip(round, true, &worst, &points, &swaps);
    checkRoundTrip(round, false, &worst, &points, &swaps);
  }
  std::cout << "occt_import_check: " << points << " points of " << 8 * 11 << " imported faces (STEP and IGES, " << swaps
            << " closed in u only, swapped) against OCCT: worst " << worst << " of the face's size\n";
  EXPECT(swaps >= 8, "faces closed in u only: " << swaps);
  hostile();
  if (failures) std::cerr << failures << " failures\n";
  return failures ? 1 : 0;
}
