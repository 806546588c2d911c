#include "occt_check.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <stdexcept>

#include <BRepCheck_Analyzer.hxx>
#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Geom_Surface.hxx>
#include <IGESCAFControl_Reader.hxx>
#include <IGESData_IGESModel.hxx>
#include <Interface_Check.hxx>
#include <Interface_CheckIterator.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <STEPCAFControl_Reader.hxx>
#include <StepBasic_UncertaintyMeasureWithUnit.hxx>
#include <StepData_StepModel.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <Transfer_TransientProcess.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <XSControl_TransferReader.hxx>
#include <XSControl_WorkSession.hxx>

namespace pdesurf_occt {

namespace {

using nlohmann::json;

struct NamedFace {
  TopoDS_Face face;
  std::string name;
  bool used = false;
};

std::string lower(std::string s) {
  for (char& c : s) c = char(std::tolower((unsigned char)c));
  return s;
}

// OCCT prints through its default messenger to stdout; the report owns stdout.
void quietOcct() {
  static bool done = false;
  if (done) return;
  done = true;
  const Handle(Message_Messenger)& m = Message::DefaultMessenger();
  m->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
  m->AddPrinter(new Message_PrinterOStream("cerr", Standard_False, Message_Warning));
}

// Load and transfer messages (OCCT's warnings and fails per entity): reported, not judged.
void collectChecks(const Interface_CheckIterator& checks, const char* stage, json* out) {
  for (checks.Start(); checks.More(); checks.Next()) {
    const Handle(Interface_Check)& c = checks.Value();
    const std::string at = std::string(stage) + " entity " + std::to_string(checks.Number()) + ": ";
    for (int i = 1; i <= c->NbFails(); ++i) out->push_back(at + "fail: " + c->CFail(i));
    for (int i = 1; i <= c->NbWarnings(); ++i) out->push_back(at + "warning: " + c->CWarning(i));
  }
}

void collectMessages(const Handle(XSControl_WorkSession) & ws, json* out) {
  collectChecks(ws->ModelCheckList(), "load", out);
  collectChecks(ws->TransferReader()->TransientProcess()->CheckList(Standard_False), "transfer", out);
}

// Faces with a name anywhere in the document: free shapes, their named sub-shapes (STEP
// faces with read.stepcaf.subshapes.name) and assembly components, placed by their locations.
void collectNamedFaces(const TDF_Label& label, const TopLoc_Location& loc, std::vector<NamedFace>* out) {
  TopoDS_Shape shape;
  Handle(TDataStd_Name) name;
  if (XCAFDoc_ShapeTool::GetShape(label, shape) && shape.ShapeType() == TopAbs_FACE &&
      label.FindAttribute(TDataStd_Name::GetID(), name))
    out->push_back({TopoDS::Face(shape.Moved(loc)), TCollection_AsciiString(name->Get()).ToCString()});
  TDF_LabelSequence children;
  XCAFDoc_ShapeTool::GetSubShapes(label, children);
  for (const TDF_Label& c : children) collectNamedFaces(c, loc, out);
  children.Clear();
  XCAFDoc_ShapeTool::GetComponents(label, children);
  for (const TDF_Label& c : children) {
    TDF_Label referred;
    if (XCAFDoc_ShapeTool::GetReferredShape(c, referred))
      collectNamedFaces(referred, loc * XCAFDoc_ShapeTool::GetLocation(c), out);
  }
}

double stepUncertainty(const Handle(Interface_InterfaceModel) & model) {
  double t = -1.0;
  for (int i = 1; i <= model->NbEntities(); ++i) {
    Handle(StepBasic_UncertaintyMeasureWithUnit) u =
        Handle(StepBasic_UncertaintyMeasureWithUnit)::DownCast(model->Value(i));
    if (!u.IsNull()) t = u->ValueComponent();
  }
  return t;
}

// Topology as OCCT read it (issue 36): solids, shells and which are closed, free edges (on one
// face only, seams aside: the model's open borders), edges on more than two faces (not a
// manifold); the solids' volume and the faces' area (BRepGProp). Judged where the
// expectation states them.
void checkTopology(const TopoDS_Shape& all, const Expectation& expect, json* rep, json* errors) {
  TopTools_IndexedDataMapOfShapeListOfShape edgeFaces;
  TopExp::MapShapesAndUniqueAncestors(all, TopAbs_EDGE, TopAbs_FACE, edgeFaces);
  int freeEdges = 0, overShared = 0;
  for (int i = 1; i <= edgeFaces.Extent(); ++i) {
    const TopoDS_Edge& e = TopoDS::Edge(edgeFaces.FindKey(i));
    const int n = edgeFaces(i).Extent();
    if (BRep_Tool::Degenerated(e)) continue;
    if (n == 1 && !BRep_Tool::IsClosed(e, TopoDS::Face(edgeFaces(i).First()))) ++freeEdges;
    if (n > 2) ++overShared;
  }
  int solids = 0, shells = 0, closedShells = 0;
  for (TopExp_Explorer x(all, TopAbs_SOLID); x.More(); x.Next()) ++solids;
  for (TopExp_Explorer x(all, TopAbs_SHELL); x.More(); x.Next()) {
    ++shells;
    closedShells += BRep_Tool::IsClosed(x.Current());
  }
  GProp_GProps volume, area;
  BRepGProp::VolumeProperties(all, volume);
  BRepGProp::SurfaceProperties(all, area);
  (*rep)["solids"] = solids;
  (*rep)["shells"] = shells;
  (*rep)["closedShells"] = closedShells;
  (*rep)["freeEdges"] = freeEdges;
  (*rep)["edgesOnMoreThanTwoFaces"] = overShared;
  (*rep)["volume"] = volume.Mass();
  (*rep)["area"] = area.Mass();
  const auto want = [&](const char* key, int have) {
    if (expect.topology.contains(key) && expect.topology[key].get<int>() != have)
      errors->push_back(std::string(key) + ": OCCT found " + std::to_string(have) + ", expected " + std::to_string(expect.topology[key].get<int>()));
  };
  want("solids", solids);
  want("closedShells", closedShells);
  want("freeEdges", freeEdges);
  want("edgesOnMoreThanTwoFaces", overShared);
  if (expect.topology.contains("volume")) {
    const double v = expect.topology["volume"].get<double>(), rel = expect.topology.value("volumeRelTol", 1e-4);
    if (!(std::abs(volume.Mass() - v) <= rel * std::abs(v)))
      errors->push_back("volume: OCCT found " + std::to_string(volume.Mass()) + ", expected " + std::to_string(v));
  }
}

}  // namespace

Expectation parseExpectation(const json& j) {
  Expectation e;
  if (!j.is_object() || !j.contains("tolerance") || !j["tolerance"].is_number() || !j.contains("faces") ||
      !j["faces"].is_array())
    throw std::runtime_error("expectation: want {\"tolerance\": t, \"faces\": [...]}");
  e.tolerance = j["tolerance"].get<double>();
  for (const json& f : j["faces"]) {
    if (!f.is_object() || !f.contains("name") || !f["name"].is_string() || !f.contains("samples") ||
        !f["samples"].is_array())
      throw std::runtime_error("expectation: a face wants {\"name\": ..., \"samples\": [...]}");
    ExpectedFace face{f["name"].get<std::string>(), {}};
    for (const json& s : f["samples"]) {
      if (!s.is_array() || s.size() != 5) throw std::runtime_error("expectation: a sample is [u, v, x, y, z]");
      std::array<double, 5> a{};
      for (int k = 0; k < 5; ++k) {
        if (!s[k].is_number()) throw std::runtime_error("expectation: a sample holds numbers only");
        a[k] = s[k].get<double>();
      }
      face.samples.push_back(a);
    }
    if (face.samples.empty()) throw std::runtime_error("expectation: face '" + face.name + "' has no samples");
    e.faces.push_back(face);
  }
  if (j.contains("topology")) {
    if (!j["topology"].is_object()) throw std::runtime_error("expectation: topology is an object");
    e.topology = j["topology"];
  }
  return e;
}

json toJson(const Expectation& e) {
  json faces = json::array();
  for (const ExpectedFace& f : e.faces) faces.push_back({{"name", f.name}, {"samples", f.samples}});
  json out = {{"tolerance", e.tolerance}, {"faces", faces}};
  if (!e.topology.empty()) out["topology"] = e.topology;
  return out;
}

CheckResult checkCadFile(const std::string& path, const Expectation& expect) {
  quietOcct();
  CheckResult r;
  json errors = json::array(), messages = json::array(), faces = json::array();
  json& rep = r.report;
  rep["file"] = path;
  rep["valid"] = false;
  auto finish = [&]() {
    rep["faces"] = faces;
    rep["errors"] = errors;
    rep["messages"] = messages;
    r.ok = errors.empty();
    return r;
  };
  auto fail = [&](const std::string& why) {
    errors.push_back(why);
    return finish();
  };
  if (!std::ifstream(path)) return fail("cannot open " + path);

  Handle(TDocStd_Document) doc;
  XCAFApp_Application::GetApplication()->NewDocument("MDTV-XCAF", doc);
  const std::string ext = lower(path.substr(path.find_last_of('.') + 1));
  try {
    if (ext == "step" || ext == "stp") {
      STEPCAFControl_Reader reader;  // its constructor declares the read.stepcaf.* parameters
      // Face names live on the ADVANCED_FACEs; OCCT attaches them only when asked (off by default).
      Interface_Static::SetIVal("read.stepcaf.subshapes.name", 1);
      reader.SetNameMode(true);
      if (reader.ReadFile(path.c_str()) != IFSelect_RetDone) return fail("OCCT could not read the STEP file");
      if (!reader.Transfer(doc)) errors.push_back("OCCT transferred no shape from the STEP file");
      collectMessages(reader.Reader().WS(), &messages);
      rep["fileTolerance"] = stepUncertainty(reader.Reader().WS()->Model());
    } else if (ext == "igs" || ext == "iges") {
      IGESCAFControl_Reader reader;
      reader.SetNameMode(true);
      if (reader.ReadFile(path.c_str()) != IFSelect_RetDone) return fail("OCCT could not read the IGES file");
      if (!reader.Transfer(doc)) errors.push_back("OCCT transferred no shape from the IGES file");
      collectMessages(reader.WS(), &messages);
      Handle(IGESData_IGESModel) model = Handle(IGESData_IGESModel)::DownCast(reader.WS()->Model());
      if (!model.IsNull()) rep["fileTolerance"] = model->GlobalSection().Resolution();
    } else {
      return fail("unknown extension ." + ext + " (want .step, .stp, .igs or .iges)");
    }
  } catch (const Standard_Failure& f) {
    errors.push_back(std::string("OCCT raised ") + f.DynamicType()->Name() + ": " + f.GetMessageString());
  }
  if (!errors.empty()) return finish();

  const Handle(XCAFDoc_ShapeTool) tool = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
  TDF_LabelSequence roots;
  tool->GetFreeShapes(roots);
  TopoDS_Compound all;
  BRep_Builder builder;
  builder.MakeCompound(all);
  std::vector<NamedFace> named;
  for (const TDF_Label& root : roots) {
    builder.Add(all, XCAFDoc_ShapeTool::GetShape(root));
    collectNamedFaces(root, TopLoc_Location(), &named);
  }

  const bool valid = BRepCheck_Analyzer(all).IsValid();
  rep["valid"] = valid;
  if (!valid) errors.push_back("BRepCheck_Analyzer: the shape is not valid");
  TopTools_IndexedMapOfShape faceMap, edges, vertices;
  TopExp::MapShapes(all, TopAbs_FACE, faceMap);
  TopExp::MapShapes(all, TopAbs_EDGE, edges);
  TopExp::MapShapes(all, TopAbs_VERTEX, vertices);
  rep["faceCount"] = faceMap.Extent();
  if (faceMap.Extent() != int(expect.faces.size()))
    errors.push_back("OCCT found " + std::to_string(faceMap.Extent()) + " faces, expected " +
                     std::to_string(expect.faces.size()));
  double maxTol = 0.0;  // the tolerance OCCT gave the topology: at least the file's, for a good file
  for (int i = 1; i <= edges.Extent(); ++i) maxTol = std::max(maxTol, BRep_Tool::Tolerance(TopoDS::Edge(edges(i))));
  for (int i = 1; i <= vertices.Extent(); ++i)
    maxTol = std::max(maxTol, BRep_Tool::Tolerance(TopoDS::Vertex(vertices(i))));
  rep["maxEdgeVertexTolerance"] = maxTol;
  checkTopology(all, expect, &rep, &errors);

  // OCCT's IGES reader names only root shapes (IGESCAFControl_Reader::Transfer searches the
  // document's top-level shapes), so a B-rep's faces come unnamed (the file names them on its
  // 510 entities): those are matched to the expected faces by their samples instead.
  const bool byGeometry = (ext == "igs" || ext == "iges") && named.empty();
  if (byGeometry)
    for (int i = 1; i <= faceMap.Extent(); ++i) named.push_back({TopoDS::Face(faceMap(i)), "", false});
  rep["facesMatchedBy"] = byGeometry ? "samples" : "name";
  const auto deviation = [](const NamedFace& n, const ExpectedFace& want) {
    const Handle(Geom_Surface) surface = BRep_Tool::Surface(n.face);
    double worst = 0.0;
    for (const auto& s : want.samples) worst = std::max(worst, surface->Value(s[0], s[1]).Distance(gp_Pnt(s[2], s[3], s[4])));
    return worst;
  };
  for (const ExpectedFace& want : expect.faces) {
    auto it = named.end();
    if (byGeometry) {
      double best = HUGE_VAL;
      for (auto n = named.begin(); n != named.end(); ++n)
        if (!n->used && deviation(*n, want) < best) best = deviation(*n, want), it = n;
    } else {
      it = std::find_if(named.begin(), named.end(), [&](const NamedFace& n) { return !n.used && n.name == want.name; });
    }
    if (it == named.end()) {
      errors.push_back("no face named '" + want.name + "'");
      continue;
    }
    it->used = true;
    const Handle(Geom_Surface) surface = BRep_Tool::Surface(it->face);  // a moved copy when the face has a location
    double u0, u1, v0, v1;
    BRepTools::UVBounds(it->face, u0, u1, v0, v1);
    double su0 = HUGE_VAL, su1 = -HUGE_VAL, sv0 = HUGE_VAL, sv1 = -HUGE_VAL, worst = 0.0;
    for (const auto& s : want.samples) {
      su0 = std::min(su0, s[0]), su1 = std::max(su1, s[0]), sv0 = std::min(sv0, s[1]), sv1 = std::max(sv1, s[1]);
      worst = std::max(worst, surface->Value(s[0], s[1]).Distance(gp_Pnt(s[2], s[3], s[4])));
    }
    // Topology as OCCT built it: a closed-v face has a seam, a degenerate border a degenerated edge.
    TopTools_IndexedMapOfShape faceEdges;
    TopExp::MapShapes(it->face, TopAbs_EDGE, faceEdges);
    int degenerated = 0, seams = 0;
    for (int i = 1; i <= faceEdges.Extent(); ++i) {
      const TopoDS_Edge& e = TopoDS::Edge(faceEdges(i));
      degenerated += BRep_Tool::Degenerated(e);
      seams += BRep_Tool::IsClosed(e, it->face);
    }
    faces.push_back({{"name", want.name},
                     {"maxDeviation", worst},
                     {"uRange", {u0, u1}},
                     {"vRange", {v0, v1}},
                     {"edges", faceEdges.Extent()},
                     {"degeneratedEdges", degenerated},
                     {"seamEdges", seams}});
    if (!(worst <= expect.tolerance))
      errors.push_back("face '" + want.name + "' deviates by " + std::to_string(worst) + " > tolerance");
    // Bounds from the face's pcurves; a reader that reparametrised the face would differ (by
    // the order of the range). A pcurve the reader projected from a shared 3D edge (an IGES
    // ring on a periodic face) may pass the face's border by the join's gap, at most the
    // file's tolerance: in parameters, the tolerance over the face's slowest speed between
    // neighbouring samples (measured: 1.2e-7 and 1.3e-7 in u on fig4c's and fig5's blends).
    double slowest = HUGE_VAL;
    for (size_t a = 0; a < want.samples.size(); ++a)
      for (size_t b = a + 1; b < want.samples.size(); ++b) {
        const auto& p = want.samples[a];
        const auto& q = want.samples[b];
        const double dp = std::hypot(q[0] - p[0], q[1] - p[1]);
        if (dp > 0 && (q[0] == p[0] || q[1] == p[1]))
          slowest = std::min(slowest, std::sqrt((q[2] - p[2]) * (q[2] - p[2]) + (q[3] - p[3]) * (q[3] - p[3]) + (q[4] - p[4]) * (q[4] - p[4])) / dp);
      }
    const double byGap = slowest > 0 && slowest < HUGE_VAL ? expect.tolerance / slowest : 0.0;
    const double pu = std::max(1e-7 * std::max(1.0, su1 - su0), byGap), pv = std::max(1e-7 * std::max(1.0, sv1 - sv0), byGap);
    if (std::abs(u0 - su0) > pu || std::abs(u1 - su1) > pu || std::abs(v0 - sv0) > pv || std::abs(v1 - sv1) > pv)
      errors.push_back("face '" + want.name + "' has parameter bounds other than its samples' ranges");
  }
  return finish();
}

}  // namespace pdesurf_occt
