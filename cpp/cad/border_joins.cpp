#include "cad/border_joins.hpp"

#include <cmath>

#include "analysis/join_certificate.hpp"
#include "common/errors.hpp"

namespace pdesurf {

namespace {

double ease(double w) { return w - kFillEase * std::sin(2 * M_PI * w) / (2 * M_PI); }

// The w in [0, 1] with ease(w) = s: ease is increasing, so bisection to the last bit.
double uneased(double s) {
  double lo = 0, hi = 1;
  for (int k = 0; k < 60; ++k) {
    const double mid = (lo + hi) / 2;
    (ease(mid) < s ? lo : hi) = mid;
  }
  return (lo + hi) / 2;
}

size_t indexOf(const std::vector<SolvedPatch>& solved, const std::string& name) {
  for (size_t i = 0; i < solved.size(); ++i)
    if (solved[i].patch->name == name) return i;
  throw Error(ErrorCode::Internal, "no solved patch '" + name + "'");
}

// A part of a closed border (v periodic over [v0, v1]) that starts below v0 wraps through the
// seam: it becomes two joins, split where a's parameter is v0 (v1), both mapping through the
// whole side's correspondence.
void addWrapped(const BorderJoin& j, const SeparableSurface& sa, std::vector<BorderJoin>* out) {
  const bool periodic = j.a.border < 2 && sa.v1 > sa.v0;
  if (!periodic || std::min(j.a.from, j.a.to) >= sa.v0) {
    out->push_back(j);
    return;
  }
  const double period = sa.v1 - sa.v0, seam = mapAtoB(j, sa.v0);
  BorderJoin before = j, after = j;
  // a runs increasing here (a fill's side): [from + period, v1] then [v0, to].
  before.a.from = j.a.from + period, before.a.to = sa.v1, before.b.to = seam, before.aShift = period;
  after.a.from = sa.v0, after.b.from = seam;
  out->push_back(before);
  out->push_back(after);
}

}  // namespace

double mapAtoB(const BorderJoin& j, double x) {
  const double w = (x - j.aShift - j.a0) / (j.a1 - j.a0);
  return j.b0 + (j.b1 - j.b0) * (j.eased ? ease(w) : w);
}

double mapBtoA(const BorderJoin& j, double y) {
  const double s = (y - j.b0) / (j.b1 - j.b0);
  return j.aShift + j.a0 + (j.a1 - j.a0) * (j.eased ? uneased(s) : s);
}

double mapBtoADerivative(const BorderJoin& j, double y) {
  const double ratio = (j.a1 - j.a0) / (j.b1 - j.b0);
  if (!j.eased) return ratio;
  const double w = uneased((y - j.b0) / (j.b1 - j.b0));
  return ratio / (1 - kFillEase * std::cos(2 * M_PI * w));
}

std::vector<BorderJoin> borderJoins(const std::vector<SolvedPatch>& solved) {
  std::vector<BorderJoin> out;
  for (size_t i = 0; i < solved.size(); ++i) {
    const Patch& primary = *solved[i].patch;
    for (const Meets& m : primary.meets) {
      const size_t t = indexOf(solved, m.patch);
      const SeparableSurface& ts = solved[t].surface;
      BorderJoin j;
      j.a.face = t;
      j.a.border = m.alongU ? 2 + m.end : m.end;
      // As the certificate reads them.
      const JoinRanges r = joinRanges(m, solved[i].surface, solved[t]);
      j.a.from = r.a0, j.a.to = r.a1;
      j.b.face = i;
      j.b.border = m.sourceEdge < 0 ? (m.atT1 ? 1 : 0) : m.sourceEdge;
      double p0 = r.p0, p1 = r.p1;
      if (m.reversed) std::swap(p0, p1);
      j.b.from = p0, j.b.to = p1;
      j.eased = m.eased;
      j.a0 = j.a.from, j.a1 = j.a.to, j.b0 = p0, j.b1 = p1;
      j.label = "'" + m.patch + "' " + (m.alongU ? "v" : "u") + std::to_string(m.end) + " - '" + primary.name + "' " +
                (primary.kind == PatchKind::Primary ? (j.b.border ? "t1" : "t0") : kBezierEdge[j.b.border]);
      addWrapped(j, ts, &out);
    }
  }
  return out;
}

}  // namespace pdesurf
