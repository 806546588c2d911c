#include "scene/placement.hpp"

#include <cmath>
#include <cstdio>

#include "common/errors.hpp"
#include "common/text.hpp"

namespace pdesurf::scene_json {

namespace {

constexpr double kPi = 3.14159265358979323846;

std::array<double, 3> vector3(const json& j, const std::string& path, const Resolver& r) {
  if (!j.is_array() || j.size() != 3) fail(ErrorCode::InvalidField, path, "expected an array of three numbers [x, y, z]");
  return {r.number(j[0], path + "[0]"), r.number(j[1], path + "[1]"), r.number(j[2], path + "[2]")};
}

// cos and sin of a whole number of quarter turns are exact, so a surface turned by 90° keeps
// exactly the terms it had (no 6e-17 multiples of the other coordinates).
void cosSin(double degrees, double& c, double& s) {
  const double quarters = degrees / 90.0;
  if (quarters == std::round(quarters)) {
    const long long q = static_cast<long long>(std::fmod(std::round(quarters), 4.0) + 4) % 4;
    const double cs[4] = {1, 0, -1, 0}, sn[4] = {0, 1, 0, -1};
    c = cs[q], s = sn[q];
    return;
  }
  c = std::cos(degrees * kPi / 180.0);
  s = std::sin(degrees * kPi / 180.0);
}

}  // namespace

Placement parsePlacement(const json& j, const std::string& path, const Resolver& r) {
  if (!j.is_object()) fail(ErrorCode::InvalidField, path, "expected an object {translate, rotate, scale}");
  allowOnly(j, path, {"translate", "rotate", "scale"});
  Placement p;
  if (j.contains("translate")) {
    const auto t = vector3(j["translate"], path + ".translate", r);
    p.translate = Eigen::Vector3d(t[0], t[1], t[2]);
  }
  Eigen::Vector3d scale(1, 1, 1);
  if (j.contains("scale")) {
    const std::string sp = path + ".scale";
    if (j["scale"].is_array()) {
      const auto s = vector3(j["scale"], sp, r);
      scale = Eigen::Vector3d(s[0], s[1], s[2]);
    } else {
      scale.setConstant(r.number(j["scale"], sp));
    }
    for (int k = 0; k < 3; ++k) {
      if (scale[k] == 0.0) fail(ErrorCode::InvalidField, sp, "a scale of 0 flattens the surface");
      // Past 10^±12 the drawn (float) surface and the joins' products of its derivatives leave
      // the range numbers hold (a scale of 1e-150 drew every patch at 0).
      if (!(std::abs(scale[k]) >= kPlacementScaleMin && std::abs(scale[k]) <= 1 / kPlacementScaleMin))
        fail(ErrorCode::InvalidField, sp, "a scale of " + numberText(scale[k]) + " is outside 1e-12 .. 1e12 (in size)");
    }
  }
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  if (j.contains("rotate")) {
    const auto a = vector3(j["rotate"], path + ".rotate", r);
    for (int k = 0; k < 3; ++k)
      if (std::abs(a[k]) > 1e6) fail(ErrorCode::InvalidField, path + ".rotate[" + std::to_string(k) + "]", "an angle beyond ±1e6 degrees");
    double c[3], s[3];
    for (int k = 0; k < 3; ++k) cosSin(a[k], c[k], s[k]);
    Eigen::Matrix3d rx, ry, rz;
    rx << 1, 0, 0, 0, c[0], -s[0], 0, s[0], c[0];
    ry << c[1], 0, s[1], 0, 1, 0, -s[1], 0, c[1];
    rz << c[2], -s[2], 0, s[2], c[2], 0, 0, 0, 1;
    rotation = rx * ry * rz;
  }
  p.linear = rotation * scale.asDiagonal();
  if (!p.linear.allFinite() || !p.translate.allFinite()) fail(ErrorCode::NonFinite, path, "the placement is not finite");
  return p;
}

void checkPlacementReach(const Placement& p, const std::array<Expr, 3>& xyz, double t0, double t1, double v0, double v1,
                         const std::string& path) {
  const double far = p.translate.cwiseAbs().maxCoeff();
  if (far == 0.0) return;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = -lo;
  for (int i = 0; i <= 8; ++i)
    for (int k = 0; k <= 8; ++k) {
      const double vars[2] = {v0 + (v1 - v0) * k / 8, t0 + (t1 - t0) * i / 8};  // ExprVar V, U (t)
      Eigen::Vector3d x;
      for (int c = 0; c < 3; ++c) x[c] = evaluate(*xyz[c], vars);
      if (!x.allFinite()) return;  // the surface's own checks name it
      x = p.linear * x;
      lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
    }
  const double size = (hi - lo).norm();
  if (!(size > 0) || far <= kPlacementReach * size) return;
  char why[320];
  std::snprintf(why, sizeof why,
                "%.6g is %.3g times the surface's size (%.6g): that far from the origin double precision rounds its points by more than the "
                "joins' tolerance (1e-9 of a size); place it within %.0e sizes, or model it nearer the origin",
                far, far / size, size, kPlacementReach);
  fail(ErrorCode::InvalidField, path + ".translate", why);
}

std::array<Expr, 3> applyPlacement(const Placement& p, const std::array<Expr, 3>& xyz) {
  std::array<Expr, 3> out;
  for (int c = 0; c < 3; ++c) {
    Expr acc = constant(p.translate[c]);
    for (int k = 0; k < 3; ++k) {
      const double m = p.linear(c, k);
      if (m == 0.0) continue;
      acc = add(acc, m == 1.0 ? xyz[k] : multiply(constant(m), xyz[k]));
    }
    out[c] = acc;
  }
  return out;
}

}  // namespace pdesurf::scene_json
