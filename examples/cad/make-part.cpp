// Writes examples/cad/part.step, the part examples/cad-part.json imports: a vessel of two faces
// made with Open CASCADE — "body", a B-spline surface (a bellied profile swept around z by a
// periodic quintic), and "neck", a cylinder — named in the file (STEP faces' names). Built as occt_make_part (tests/occt/CMakeLists.txt); run it with the
// output path to make the file again: `build/native/tests/occt/occt_make_part examples/cad/part.step`.
#include <iostream>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <cmath>
#include <BRep_Builder.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_Printer.hxx>
#include <STEPCAFControl_Writer.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Compound.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>


int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: occt_make_part OUT.step\n";
    return 2;
  }
  Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_Printer));
  // The body: a B-spline surface, its profile (u, bottom to top, a cubic with a belly) swept
  // around z by a periodic quintic in v over [0, 2π] — twelve poles on a circle, scaled so the
  // curve's mean radius is the profile's.
  const double px[] = {1.0, 1.35, 1.6, 1.45, 1.0, 0.8}, pz[] = {0.0, 0.6, 1.5, 2.4, 3.0, 3.4};
  constexpr int kAround = 12;
  const double scale = 1.0 / 0.93360;  // a uniform periodic quintic through 12 poles on radius 1 runs at 0.9336 (0.93361 at its knots, 0.93359 between)
  TColgp_Array2OfPnt poles(1, 6, 1, kAround);
  for (int i = 1; i <= 6; ++i)
    for (int j = 1; j <= kAround; ++j) {
      const double a = 2 * M_PI * (j - 1) / kAround - M_PI / 3;  // shifted so v = 0 is on the x axis, as the cylinder's
      poles(i, j) = gp_Pnt(scale * px[i - 1] * std::cos(a), scale * px[i - 1] * std::sin(a), pz[i - 1]);
    }
  TColStd_Array1OfReal uk(1, 4), vk(1, kAround + 1);
  TColStd_Array1OfInteger um(1, 4), vm(1, kAround + 1);
  uk(1) = 0, uk(2) = 1, uk(3) = 2, uk(4) = 3, um(1) = 4, um(2) = 1, um(3) = 1, um(4) = 4;
  for (int j = 1; j <= kAround + 1; ++j) vk(j) = 2 * M_PI * (j - 1) / kAround, vm(j) = 1;
  const TopoDS_Face body = BRepBuilderAPI_MakeFace(new Geom_BSplineSurface(poles, uk, vk, um, vm, 3, 5, false, true), 1e-9).Face();
  // The neck: a cylinder (an analytic face) a little above and inside the body's top rim.
  const TopoDS_Face neck = BRepBuilderAPI_MakeFace(new Geom_CylindricalSurface(gp_Ax3(gp_Pnt(0, 0, 4.2), gp_Dir(0, 0, 1)), 0.5), 0, 2 * M_PI, 0, 0.8, 1e-9).Face();

  TopoDS_Compound part;
  BRep_Builder b;
  b.MakeCompound(part);
  b.Add(part, body);
  b.Add(part, neck);
  Handle(TDocStd_Document) doc;
  XCAFApp_Application::GetApplication()->NewDocument("MDTV-XCAF", doc);
  const Handle(XCAFDoc_ShapeTool) tool = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
  const TDF_Label top = tool->AddShape(part, false);
  TDataStd_Name::Set(top, "vessel");
  TDataStd_Name::Set(tool->AddSubShape(top, body), "body");
  TDataStd_Name::Set(tool->AddSubShape(top, neck), "neck");
  STEPCAFControl_Writer writer;
  Interface_Static::SetIVal("write.stepcaf.subshapes.name", 1);  // the faces' names (off by default)
  writer.SetNameMode(true);
  if (!writer.Transfer(doc, STEPControl_AsIs) || writer.Write(argv[1]) != IFSelect_RetDone) {
    std::cerr << "occt_make_part: could not write " << argv[1] << "\n";
    return 1;
  }
  return 0;
}
