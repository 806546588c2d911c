// A patch's one payload (scene/scene.hpp: Patch::data), the data of its kind.
#include "common/errors.hpp"
#include "scene/scene.hpp"

namespace pdesurf {

namespace {

template <class T>
T& dataOf(std::variant<PdeData, PrimarySurface, BezierData>& data, const std::string& name, const char* wanted) {
  if (T* d = std::get_if<T>(&data)) return *d;
  throw Error(ErrorCode::Internal, "patch '" + name + "' has no " + wanted + " data (it is of another kind)");
}

}  // namespace

void Patch::setKind(PatchKind k) {
  kind = k;
  switch (k) {
    case PatchKind::Pde:
    case PatchKind::Fill: data = PdeData{}; break;
    case PatchKind::Primary: data = PrimarySurface{}; break;
    case PatchKind::Bezier: data = BezierData{}; break;
  }
}

PdeData& Patch::pdeData() { return dataOf<PdeData>(data, name, "pde"); }
const PdeData& Patch::pdeData() const { return const_cast<Patch*>(this)->pdeData(); }
BezierData& Patch::bezierData() { return dataOf<BezierData>(data, name, "Bezier"); }
const BezierData& Patch::bezierData() const { return const_cast<Patch*>(this)->bezierData(); }
PrimarySurface& Patch::primary() { return dataOf<PrimarySurface>(data, name, "primary surface"); }
const PrimarySurface& Patch::primary() const { return const_cast<Patch*>(this)->primary(); }

}  // namespace pdesurf
