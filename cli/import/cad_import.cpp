#include "cad_import.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <optional>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <GeomConvert.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_ConicalSurface.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <Geom_Plane.hxx>
#include <Geom_SphericalSurface.hxx>
#include <Geom_ToroidalSurface.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <IGESCAFControl_Reader.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <STEPCAFControl_Reader.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>

#include "common/errors.hpp"
#include "common/limits.hpp"
#include "scene/scene.hpp"

namespace pdesurf::cad_import {
namespace {

using json = nlohmann::json;

std::string lower(std::string s) {
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// Names the file gives its faces (STEP: the ADVANCED_FACEs' names, read when asked for).
void collectNames(const TDF_Label& label, const TopLoc_Location& loc, std::vector<std::pair<TopoDS_Face, std::string>>* out) {
  TopoDS_Shape shape;
  Handle(TDataStd_Name) name;
  if (XCAFDoc_ShapeTool::GetShape(label, shape) && shape.ShapeType() == TopAbs_FACE && label.FindAttribute(TDataStd_Name::GetID(), name))
    out->push_back({TopoDS::Face(shape.Moved(loc)), TCollection_AsciiString(name->Get()).ToCString()});
  TDF_LabelSequence children;
  XCAFDoc_ShapeTool::GetSubShapes(label, children);
  for (const TDF_Label& c : children) collectNames(c, loc, out);
  children.Clear();
  XCAFDoc_ShapeTool::GetComponents(label, children);
  for (const TDF_Label& c : children) {
    TDF_Label referred;
    if (XCAFDoc_ShapeTool::GetReferredShape(c, referred)) collectNames(referred, loc * XCAFDoc_ShapeTool::GetLocation(c), out);
  }
}

// A patch name the scene accepts: printable, at most kNameChars, unique.
std::string patchName(std::string want, int index, std::vector<std::string>& taken) {
  std::string s;
  for (char c : want)
    if (std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == ' ' || c == '.') s += c;
  if (s.size() > limits::kNameChars - 8) s.resize(limits::kNameChars - 8);
  if (s.empty()) s = "face " + std::to_string(index + 1);
  std::string name = s;
  for (int k = 2; std::find(taken.begin(), taken.end(), name) != taken.end(); ++k) name = s + " " + std::to_string(k);
  taken.push_back(name);
  return name;
}

// swap: the patch's t is OCCT's v (points and weights transposed).
json nurbsOf(const Handle(Geom_BSplineSurface) & s, const std::string& who, bool swap) {
  const int nt = s->NbUPoles(), nv = s->NbVPoles();
  if (size_t(nt) * size_t(nv) > limits::kNurbsPoints)
    fail(ErrorCode::TooLarge, who, std::to_string(nt) + " × " + std::to_string(nv) + " control points: a surface has at most " +
                                      std::to_string(limits::kNurbsPoints));
  if (s->UDegree() > limits::kNurbsDegree || s->VDegree() > limits::kNurbsDegree)
    fail(ErrorCode::TooLarge, who, "degree " + std::to_string(std::max(s->UDegree(), s->VDegree())) + ": at most " + std::to_string(limits::kNurbsDegree));
  json points = json::array(), weights = json::array();
  bool rational = false;
  for (int i = 1; i <= nt; ++i) {
    json row = json::array(), wrow = json::array();
    for (int j = 1; j <= nv; ++j) {
      const gp_Pnt p = s->Pole(i, j);
      const double w = s->Weight(i, j);
      for (double x : {p.X(), p.Y(), p.Z(), w})
        if (!std::isfinite(x)) fail(ErrorCode::NonFinite, who, "control point (" + std::to_string(i) + ", " + std::to_string(j) + ") is not finite");
      row.push_back({p.X(), p.Y(), p.Z()});
      wrow.push_back(w);
      rational = rational || w != s->Weight(1, 1);
    }
    points.push_back(row), weights.push_back(wrow);
  }
  auto flat = [](const TColStd_Array1OfReal& k) {
    std::vector<double> out;
    for (int i = k.Lower(); i <= k.Upper(); ++i) out.push_back(k(i));
    return out;
  };
  if (swap) {
    json tp = json::array(), tw = json::array();
    for (int j = 0; j < nv; ++j) {
      json row = json::array(), wrow = json::array();
      for (int i = 0; i < nt; ++i) row.push_back(points[size_t(i)][size_t(j)]), wrow.push_back(weights[size_t(i)][size_t(j)]);
      tp.push_back(row), tw.push_back(wrow);
    }
    points = tp, weights = tw;
  }
  const json degree = swap ? json{s->VDegree(), s->UDegree()} : json{s->UDegree(), s->VDegree()};
  const json knots = swap ? json{flat(s->VKnotSequence()), flat(s->UKnotSequence())} : json{flat(s->UKnotSequence()), flat(s->VKnotSequence())};
  json n = {{"degree", degree}, {"knots", knots}, {"points", points}};
  if (rational) n["weights"] = weights;
  return n;
}

// Whether the face closes in u (its u0 and u1 edges are one curve), sampled over its v.
bool closesIn(const Handle(Geom_Surface) & s, bool inU, double u0, double u1, double v0, double v1) {
  double size = 0.0, gap = 0.0;
  for (int k = 0; k <= 8; ++k) {
    const double w = (inU ? v0 : u0) + ((inU ? v1 : u1) - (inU ? v0 : u0)) * k / 8;
    const gp_Pnt a = inU ? s->Value(u0, w) : s->Value(w, v0), b = inU ? s->Value(u1, w) : s->Value(w, v1);
    size = std::max({size, gp_Vec(a.XYZ()).Magnitude(), s->Value(0.5 * (u0 + u1), 0.5 * (v0 + v1)).Distance(a)});
    gap = std::max(gap, a.Distance(b));
  }
  return gap <= 1e-9 * std::max(size, 1e-300);
}

// The shortest decimal text that reads back to x (0.5, not 0.50000000000000000).
std::string num(double x) {
  if (x == 0) return "0";
  char buf[32];
  for (int digits = 1; digits <= 17; ++digits) {
    std::snprintf(buf, sizeof buf, "%.*g", digits, x);
    if (std::strtod(buf, nullptr) == x) break;
  }
  return buf;
}

// Text in parentheses where it is a sum.
std::string group(const std::string& e) { return e.find(' ') == std::string::npos ? e : "(" + e + ")"; }

// c·f as text ("" where c is 0, f alone where c is 1); f "" means the number c itself.
std::string term(double c, const std::string& f) {
  if (c == 0 || f == "0") return "";
  if (f.empty()) return num(c);
  if (c == 1) return f;
  if (c == -1) return "-" + group(f);
  return num(c) + "*" + group(f);
}

// Terms joined by + ("- …" for a negative one); "0" when none.
std::string sum(const std::vector<std::string>& terms) {
  std::string out;
  for (const std::string& t : terms) {
    if (t.empty()) continue;
    if (out.empty()) out = t;
    else if (t[0] == '-') out += " - " + t.substr(1);
    else out += " + " + t;
  }
  return out.empty() ? "0" : out;
}

// The analytic surfaces as expressions in t (OCCT's u) and v, in OCCT's own parametrisation
// (Geom_*Surface's documentation): exact, and closed-form families for the blends that meet
// them. u and v name OCCT's u and v in the text ("t" and "v", or swapped). Null for any other
// surface.
std::optional<std::array<std::string, 3>> analyticExpressions(const Handle(Geom_Surface) & s, const std::string& u, const std::string& v) {
  gp_Ax3 a;
  std::array<std::string, 3> xyz;
  // Each coordinate o + radial·(x cos u + y sin u) + axial·z in the frame's components.
  auto frame = [&](const std::string& radial, const std::string& axial) {
    for (int c = 0; c < 3; ++c) {
      const double x = a.XDirection().Coord(c + 1), y = a.YDirection().Coord(c + 1), z = a.Direction().Coord(c + 1);
      const std::string around = sum({term(x, "cos(" + u + ")"), term(y, "sin(" + u + ")")});
      const std::string radialTerm = around == "0" ? "" : radial == "1" ? around : group(radial) + "*" + group(around);
      xyz[size_t(c)] = sum({term(a.Location().Coord(c + 1), ""), radialTerm, term(z, axial)});
    }
    return xyz;
  };
  if (auto p = Handle(Geom_Plane)::DownCast(s); !p.IsNull()) {
    a = p->Position();
    for (int c = 0; c < 3; ++c)
      xyz[size_t(c)] = sum({term(a.Location().Coord(c + 1), ""), term(a.XDirection().Coord(c + 1), u), term(a.YDirection().Coord(c + 1), v)});
    return xyz;
  }
  if (auto c = Handle(Geom_CylindricalSurface)::DownCast(s); !c.IsNull()) return a = c->Position(), frame(num(c->Radius()), v);
  if (auto c = Handle(Geom_ConicalSurface)::DownCast(s); !c.IsNull())
    return a = c->Position(), frame(sum({term(c->RefRadius(), ""), term(std::sin(c->SemiAngle()), v)}), term(std::cos(c->SemiAngle()), v));
  if (auto c = Handle(Geom_SphericalSurface)::DownCast(s); !c.IsNull())
    return a = c->Position(), frame(term(c->Radius(), "cos(" + v + ")"), term(c->Radius(), "sin(" + v + ")"));
  if (auto c = Handle(Geom_ToroidalSurface)::DownCast(s); !c.IsNull())
    return a = c->Position(), frame(sum({term(c->MajorRadius(), ""), term(c->MinorRadius(), "cos(" + v + ")")}), term(c->MinorRadius(), "sin(" + v + ")"));
  return std::nullopt;
}

}  // namespace

json importCadFile(const std::string& path) {
  // Errors name the file's part ("the file", a face); the CLI names the file itself.
  const std::string file = "the file";
  const std::string title = std::filesystem::path(path).filename().string();
  std::error_code ec;
  const auto bytes = std::filesystem::file_size(path, ec);
  if (ec) fail(ErrorCode::InvalidField, file, "cannot be read");
  if (static_cast<long long>(bytes) > kMaxFileBytes)
    fail(ErrorCode::TooLarge, file, std::to_string(bytes >> 20) + " MB: at most " + std::to_string(kMaxFileBytes >> 20) + " MB are imported");
  const std::string ext = lower(path.substr(path.find_last_of('.') + 1));
  const bool step = ext == "step" || ext == "stp", iges = ext == "igs" || ext == "iges";
  if (ext == "3dm")  // no openNURBS natively: the page's reader, under node
    fail(ErrorCode::InvalidField, file, "a .3dm file is read by rhino3dm: node scripts/import-3dm.mjs " + title + " -o scene.json");
  if (!step && !iges) fail(ErrorCode::InvalidField, file, "unknown extension ." + ext + " (want .step, .stp, .igs or .iges; .3dm: node scripts/import-3dm.mjs)");

  // OCCT reports to its own messenger (stdout); the CLI's output is the scene.
  Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_Printer));
  Handle(TDocStd_Document) doc;
  XCAFApp_Application::GetApplication()->NewDocument("MDTV-XCAF", doc);
  try {
    if (step) {
      STEPCAFControl_Reader reader;
      Interface_Static::SetIVal("read.stepcaf.subshapes.name", 1);  // the faces' names (off by default)
      reader.SetNameMode(true);
      if (reader.ReadFile(path.c_str()) != IFSelect_RetDone) fail(ErrorCode::ParseError, file, "Open CASCADE could not read it as STEP");
      if (!reader.Transfer(doc)) fail(ErrorCode::InvalidField, file, "holds no shape Open CASCADE can transfer");
    } else {
      IGESCAFControl_Reader reader;
      reader.SetNameMode(true);
      if (reader.ReadFile(path.c_str()) != IFSelect_RetDone) fail(ErrorCode::ParseError, file, "Open CASCADE could not read it as IGES");
      if (!reader.Transfer(doc)) fail(ErrorCode::InvalidField, file, "holds no shape Open CASCADE can transfer");
    }
  } catch (const Standard_Failure& f) {
    fail(ErrorCode::ParseError, file, std::string("Open CASCADE: ") + f.DynamicType()->Name() + ": " + f.GetMessageString());
  }

  const Handle(XCAFDoc_ShapeTool) tool = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
  TDF_LabelSequence roots;
  tool->GetFreeShapes(roots);
  TopoDS_Compound all;
  BRep_Builder builder;
  builder.MakeCompound(all);
  std::vector<std::pair<TopoDS_Face, std::string>> names;
  for (const TDF_Label& root : roots) {
    builder.Add(all, XCAFDoc_ShapeTool::GetShape(root));
    collectNames(root, TopLoc_Location(), &names);
  }
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(all, TopAbs_FACE, faces);
  // Counted before any face is converted: a scene holds kPatches patches.
  if (faces.Extent() == 0) fail(ErrorCode::InvalidField, file, "has no faces");
  if (faces.Extent() > limits::kPatches)
    fail(ErrorCode::TooLarge, file, std::to_string(faces.Extent()) + " faces: a scene holds at most " + std::to_string(limits::kPatches) + " patches");

  json patches = json::array();
  std::vector<std::string> taken;
  for (int i = 1; i <= faces.Extent(); ++i) {
    const TopoDS_Face face = TopoDS::Face(faces(i));
    std::string given;
    for (const auto& [f, n] : names)
      if (f.IsSame(face)) given = n;
    const std::string name = patchName(given, i - 1, taken);
    const std::string who = "face '" + name + "' (" + std::to_string(i) + " of " + std::to_string(faces.Extent()) + ")";
    try {
      double u0, u1, v0, v1;
      BRepTools::UVBounds(face, u0, u1, v0, v1);
      for (double x : {u0, u1, v0, v1})
        if (!std::isfinite(x) || std::abs(x) > 1e12) fail(ErrorCode::NonFinite, who, "its parameter bounds are not finite");
      if (!(u1 > u0 && v1 > v0)) fail(ErrorCode::InvalidField, who, "its parameter bounds are empty");
      Handle(Geom_Surface) surface = BRep_Tool::Surface(face);
      if (surface.IsNull()) fail(ErrorCode::InvalidField, who, "has no surface");
      // The face's bounds within its surface's where that is bounded (a file's bounds may
      // overshoot by its tolerance); then trimmed to them: a plane or a cone is infinite, and a
      // periodic surface converts without its seam moving.
      double su0, su1, sv0, sv1;
      surface->Bounds(su0, su1, sv0, sv1);
      if (!surface->IsUPeriodic()) u0 = std::max(u0, su0), u1 = std::min(u1, su1);
      if (!surface->IsVPeriodic()) v0 = std::max(v0, sv0), v1 = std::min(v1, sv1);
      if (!(u1 > u0 && v1 > v0)) fail(ErrorCode::InvalidField, who, "its bounds lie outside its surface");
      if (auto trimmed = Handle(Geom_RectangularTrimmedSurface)::DownCast(surface); !trimmed.IsNull()) surface = trimmed->BasisSurface();
      // pdesurf's v runs around a closed surface (blends meet its t-borders): a face closed in
      // u only (a cylinder's, a cone's, a sphere's angle) is swapped, t = its v, v = its u.
      const bool swap = closesIn(surface, true, u0, u1, v0, v1) && !closesIn(surface, false, u0, u1, v0, v1);
      const json tRange = swap ? json{v0, v1} : json{u0, u1}, vRange = swap ? json{u0, u1} : json{v0, v1};
      if (const auto xyz = analyticExpressions(surface, swap ? "v" : "t", swap ? "t" : "v")) {
        patches.push_back({{"name", name}, {"kind", "surface"}, {"x", (*xyz)[0]}, {"y", (*xyz)[1]}, {"z", (*xyz)[2]}, {"t_range", tRange}, {"v_range", vRange}});
        continue;
      }
      // Any other surface as NURBS: a B-spline as it is; the rest (Bézier, revolved, extruded,
      // offset surfaces) converted by OCCT over the face's bounds.
      Handle(Geom_BSplineSurface) bs = Handle(Geom_BSplineSurface)::DownCast(surface);
      if (bs.IsNull()) bs = GeomConvert::SurfaceToBSplineSurface(new Geom_RectangularTrimmedSurface(surface, u0, u1, v0, v1));
      if (bs.IsNull()) fail(ErrorCode::InvalidField, who, "Open CASCADE could not convert its surface to a B-spline");
      bs = Handle(Geom_BSplineSurface)::DownCast(bs->Copy());
      if (bs->IsUPeriodic()) bs->SetUNotPeriodic();
      if (bs->IsVPeriodic()) bs->SetVNotPeriodic();
      double bu0, bu1, bv0, bv1;
      bs->Bounds(bu0, bu1, bv0, bv1);
      // The face's bounds within the converted surface's (equal, up to rounding).
      const double tu0 = std::max(u0, bu0), tu1 = std::min(u1, bu1), tv0 = std::max(v0, bv0), tv1 = std::min(v1, bv1);
      if (!(tu1 > tu0 && tv1 > tv0)) fail(ErrorCode::InvalidField, who, "its bounds lie outside its surface");
      const json tr = swap ? json{tv0, tv1} : json{tu0, tu1}, vr = swap ? json{tu0, tu1} : json{tv0, tv1};
      json patch = {{"name", name}, {"kind", "surface"}, {"nurbs", nurbsOf(bs, who, swap)}, {"t_range", tr}, {"v_range", vr}};
      patches.push_back(patch);
    } catch (const Standard_Failure& f) {
      fail(ErrorCode::InvalidField, who, std::string("Open CASCADE: ") + f.DynamicType()->Name() + ": " + f.GetMessageString());
    }
  }
  json scene = {{"format", "pdesurf-scene"},
                {"version", 4},
                {"title", title},
                {"description", "Imported from " + title + ": " + std::to_string(patches.size()) +
                                    " faces over their parameter bounds (trims not kept); a face closed in u only has t and v swapped."},
                {"patches", patches}};
  // The scene the CLI writes reads: anything the core refuses is named here, per face.
  try {
    parseScene(scene.dump());
  } catch (const Error& e) {
    std::string what = e.what();
    const auto at = what.find("patches[");
    if (at != std::string::npos) {
      const size_t k = std::stoul(what.substr(at + 8));
      if (k < patches.size()) what = "face '" + patches[k]["name"].get<std::string>() + "': " + what;
    }
    throw Error(e.code(), what);
  }
  return scene;
}

}  // namespace pdesurf::cad_import
