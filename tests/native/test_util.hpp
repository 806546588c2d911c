// Helpers shared by the native tests: reading example files, boundary and PDE residual checks.
#pragma once
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "common/errors.hpp"
#include "pde/pde_problem.hpp"
#include "scene/scene.hpp"
#include "surface/separable_surface.hpp"

namespace pdesurf::testing {

// AddressSanitizer replaces the allocator and runs the same code several times slower.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kAddressSanitizer = true;
#else
constexpr bool kAddressSanitizer = false;
#endif
#else
constexpr bool kAddressSanitizer = false;
#endif

// The few bounds on time in these tests say that work is refused before it is done (a
// fraction of a second, where doing it would take minutes). Under AddressSanitizer (and the
// sanitize row runs two suites side by side) the bound is scaled, not dropped.
constexpr double kTimeScale = kAddressSanitizer ? 5.0 : 1.0;

// Long double is slow under AddressSanitizer and in wasm (a software binary128 there, 30 s
// for one degree-16 reference solve): the long-double reference tests take a spread of
// their cases in those builds, every case natively.
#if defined(__EMSCRIPTEN__)
constexpr bool kSlowLongDouble = true;
#else
constexpr bool kSlowLongDouble = kTimeScale > 1;
#endif

// The solved patch of that name (a test's own scene: a missing name is the test's bug).
inline const SolvedPatch& solvedNamed(const std::vector<SolvedPatch>& s, const std::string& name) {
  for (const SolvedPatch& p : s)
    if (p.patch->name == name) return p;
  throw std::runtime_error("no patch " + name);
}

// "<ErrorCode>: <message>" of the error parseScene(text) throws, or "" when it reads.
inline std::string parseErrorOf(const std::string& text) {
  try {
    parseScene(text);
  } catch (const Error& e) {
    return std::string(errorCodeName(e.code())) + ": " + e.what();
  }
  return "";
}

inline std::string readText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

inline std::string examplePath(const std::string& file) { return std::string(PDESURF_EXAMPLES_DIR) + "/" + file; }
// Version-1 copies of the examples, kept so the version-1 reader stays tested forever.
inline std::string v1FixturePath(const std::string& file) { return std::string(PDESURF_FIXTURES_DIR) + "/v1/" + file; }

inline double expansionAt(const VExpansion& e, double v, double* scale = nullptr) {
  double s = 0.0, mag = 0.0;
  for (const VTerm& t : e) {
    const double x = t.coef * t.g.eval(v);
    s += x;
    mag += std::abs(x);
  }
  if (scale) *scale = mag;
  return s;
}

// Largest boundary-condition error over components, ends, derivative orders and 41 v-samples,
// relative to max(1, Σ|terms|). With roots of size R the i-th u-derivative naturally carries a
// factor R^i (and its rounding error too): derivativeScale = R measures derivatives in those
// units.
inline double boundaryError(const PdeProblem& p, const SeparableSurface& s, double derivativeScale = 1.0) {
  double worst = 0.0;
  for (int c = 0; c < 3; ++c) {
    const auto& cp = p.component[c];
    const int n = static_cast<int>(cp.alpha.size()) - 1;
    for (int end = 0; end < 2; ++end)
      for (int i = 0; i < n; ++i)
        for (int k = 0; k <= 40; ++k) {
          const double v = p.v0 + (p.v1 - p.v0) * k / 40;
          double scale = 0.0;
          const double want = expansionAt((end == 0 ? cp.left : cp.right)[i], v, &scale);
          const double got = evalComponent(s, c, end, v, i, 0);
          worst = std::max(worst, std::abs(got - want) / std::max(1.0, scale) / std::pow(derivativeScale, i));
        }
  }
  return worst;
}

inline double forceAt(const std::vector<ForceTerm>& force, double u, double v) {
  double f = 0.0;
  for (const ForceTerm& t : force) {
    double q = 0.0;
    for (size_t k = t.uPoly.size(); k-- > 0;) q = q * u + t.uPoly[k];
    f += q * t.g.eval(v);
  }
  return f;
}

// |Σ_k alpha_k ∂u^{2(n-k)} ∂v^{2k} X - f| relative to the sum of the sizes of its parts, at
// interior grid points.
inline double pdeResidual(const PdeProblem& p, const SeparableSurface& s) {
  double worst = 0.0;
  for (int c = 0; c < 3; ++c) {
    const auto& a = p.component[c].alpha;
    const int n = static_cast<int>(a.size()) - 1;
    for (int iu = 1; iu < 10; ++iu)
      for (int iv = 0; iv <= 10; ++iv) {
        const double u = iu / 10.0, v = p.v0 + (p.v1 - p.v0) * iv / 10;
        const double f = forceAt(p.component[c].force, u, v);
        double sum = -f, mag = std::abs(f);
        for (int k = 0; k <= n; ++k) {
          const double part = a[k] * evalComponent(s, c, u, v, 2 * (n - k), 2 * k);
          sum += part;
          mag += std::abs(part);
        }
        worst = std::max(worst, std::abs(sum) / std::max(1.0, mag));
      }
  }
  return worst;
}

// Unit normal; where X_u vanishes (a blend that leaves its trimline with zero speed, seed 003
// Eq. 14) the limit along u is X_uu × X_v.
inline Eigen::Vector3d unitNormal(const SeparableSurface& s, double u, double v) {
  Eigen::Vector3d xu = evalPoint(s, u, v, 1, 0);
  const Eigen::Vector3d xv = evalPoint(s, u, v, 0, 1);
  if (xu.norm() < 1e-12 * xv.norm()) xu = evalPoint(s, u, v, 2, 0);
  return xu.cross(xv).normalized();
}

}  // namespace pdesurf::testing
