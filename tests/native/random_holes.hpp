// Random fill holes for the tests (issue 35): an irregular convex N-gon cut in the sheet
// z = a x² + b y² + c xy + d x³, ringed by strips of it (strip k is the sheet over a band
// outside side k; its t0 is the side), filled by a "fill" of the strips' t0.
#pragma once
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <vector>

namespace pdesurf::testing {

// A number as a scene expression, every bit kept.
inline std::string exactNumber(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "(%.17g)", x);
  return buf;
}

struct Sheet {
  double a = 0, b = 0, c = 0, d = 0;  // z = a x² + b y² + c x y + d x³
  std::string z(const std::string& X, const std::string& Y) const {
    return exactNumber(a) + "*(" + X + ")^2 + " + exactNumber(b) + "*(" + Y + ")^2 + " + exactNumber(c) + "*(" + X + ")*(" + Y + ") + " +
           exactNumber(d) + "*(" + X + ")^3";
  }
  double at(double x, double y) const { return a * x * x + b * y * y + c * x * y + d * x * x * x; }
};

// Corners at uneven angles (jitter × 2π/n) and radii (1 ± 7.5 %), turned at random; the fill
// asks for `continuity`.
inline nlohmann::json randomHole(int n, const Sheet& sheet, std::mt19937& rng, double jitter, const std::string& continuity = "tangency") {
  std::uniform_real_distribution<double> unit(-0.5, 0.5);
  const double turn = 2 * M_PI * (unit(rng) + 0.5);
  std::vector<double> angle(n), radius(n);
  for (int k = 0; k < n; ++k) angle[k] = turn + 2 * M_PI * (k + jitter * unit(rng)) / n, radius[k] = 1 + 0.15 * unit(rng);
  nlohmann::json patches = nlohmann::json::array(), borders = nlohmann::json::array();
  for (int k = 0; k < n; ++k) {
    const int m = (k + 1) % n;
    const double x0 = radius[k] * std::cos(angle[k]), y0 = radius[k] * std::sin(angle[k]);
    const double x1 = radius[m] * std::cos(angle[m]), y1 = radius[m] * std::sin(angle[m]);
    const double ex = x1 - x0, ey = y1 - y0, l = std::hypot(ex, ey);
    const std::string X = exactNumber(x0) + " + " + exactNumber(ex) + "*v + " + exactNumber(0.5 * ey / l) + "*t";
    const std::string Y = exactNumber(y0) + " + " + exactNumber(ey) + "*v + " + exactNumber(-0.5 * ex / l) + "*t";
    const std::string name = "strip" + std::to_string(k);
    patches.push_back({{"name", name}, {"kind", "surface"}, {"t_range", {0, 1}}, {"v_range", {0, 1}}, {"x", X}, {"y", Y}, {"z", sheet.z(X, Y)}});
    borders.push_back({{"patch", name}, {"at", "t0"}});
  }
  patches.push_back({{"name", "fill"}, {"kind", "fill"}, {"borders", borders}, {"continuity", continuity}});
  return {{"format", "pdesurf-scene"}, {"version", 4}, {"patches", patches}};
}

// A cone frustum of radii r0, r1 and height h (t from 0 to 1, closed in v) capped by a fill on
// each ring: one closed body.
inline nlohmann::json cappedTube(double r0, double r1, double h) {
  const std::string r = "(" + exactNumber(r0) + " + " + exactNumber(r1 - r0) + "*t)";
  using nlohmann::json;
  return {{"format", "pdesurf-scene"}, {"version", 4},
          {"patches", json::array({{{"name", "tube"}, {"kind", "surface"}, {"t_range", {0, 1}}, {"v_range", {0, "2*pi"}},
                                    {"x", r + "*cos(v)"}, {"y", r + "*sin(v)"}, {"z", exactNumber(h) + "*t"}},
                                   {{"name", "bottom"}, {"kind", "fill"}, {"borders", {{{"patch", "tube"}, {"at", "t0"}}}}, {"height", 0.3}},
                                   {{"name", "top"}, {"kind", "fill"}, {"borders", {{{"patch", "tube"}, {"at", "t1"}}}}, {"height", 0.3}}})}};
}

}  // namespace pdesurf::testing
