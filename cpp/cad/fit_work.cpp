#include "cad/fit_work.hpp"

#include <cmath>
#include <cstdio>

namespace pdesurf {

namespace {
std::string exceeded(double limit) {
  char buf[300];
  std::snprintf(buf, sizeof buf,
                "the CAD fit of the scene would need more than %.0e units of work (certificate points by their terms, derivative bounds; "
                "docs/limits.md): raise the tolerance, or simplify the patches' expressions",
                limit);
  return buf;
}
}  // namespace

SceneWorkExceeded::SceneWorkExceeded(double limit) : Error(ErrorCode::TooLarge, exceeded(limit)) {}

void FitWork::charge(double units) {
  const double clamped = std::min(std::max(units, 0.0), 1e18);
  const uint64_t add = uint64_t(std::ceil(clamped));
  const uint64_t total = used_.fetch_add(add) + add;
  if (!(units < 1e18) || double(total) > limit_) throw SceneWorkExceeded(limit_);
}

}  // namespace pdesurf
