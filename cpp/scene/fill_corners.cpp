#include "scene/fill_corners.hpp"

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "common/errors.hpp"

namespace pdesurf {

namespace {
// How far apart (of 4 × the longer cross derivative) the two sides' lines may pass and still
// be taken as crossing (the planes some 15° apart); past it, the fallback below.
constexpr double kNearLines = 0.25;
}  // namespace

std::vector<SideMix> cornerDirections(const std::vector<FillSide>& sides, const std::vector<double>& scale) {
  const size_t n = sides.size();
  std::vector<SideMix> mix(n, {1.0, 0.0, 1.0, 0.0});  // γ, α at v0; γ, α at v1
  // At each corner the two sides' cross derivatives differ (by up to the corner's angle): left
  // so, the fill's iso-u curves would turn back on themselves there and fold. Adding a part of
  // the side's own tangent T keeps the tangent plane (G1 is untouched) and lets both sides
  // leave the corner along one vector W: along side k, X_u = γ k_k D_k + α T_k, with (γ, α)
  // linear in σ between the values that give W at its two corners (1, 0 where no W fits).
  const auto fit = [](const Eigen::Vector3d& D, const Eigen::Vector3d& T, const Eigen::Vector3d& W, double* gamma, double* alpha) {
    Eigen::Matrix2d A;
    A << D.dot(D), D.dot(T), D.dot(T), T.dot(T);
    const Eigen::Vector2d x = A.fullPivLu().solve(Eigen::Vector2d(D.dot(W), T.dot(W)));
    if (!(x.allFinite() && x(0) > 0.2 && x(0) < 5 && (x(0) * D + x(1) * T - W).norm() <= 1e-6 * W.norm())) return;
    *gamma = x(0), *alpha = x(1);
  };
  for (size_t k = 0; k < n; ++k) {
    const FillSide &s = sides[k], &next = sides[(k + 1) % n];
    // One-sided, just inside each side: a border may have a kink exactly at the corner, where
    // its expression's derivative is the mean of the two sides'.
    const double ve = s.v1 - kInside * (s.v1 - s.v0), vs = next.v0 + kInside * (next.v1 - next.v0);
    const Eigen::Vector3d De = scale[k] * valueAt(s.D, ve), Ds = scale[(k + 1) % n] * valueAt(next.D, vs);
    const Eigen::Vector3d Te = valueAt(s.T, ve), Ts = valueAt(next.T, vs);
    const double longest = 4 * std::max(De.norm(), Ds.norm());
    // No corner (a closed border's ends, ranges of one curve): the sides already leave it along
    // one vector (to the 2 kInside of a side between the two points read). Solving for W there
    // would divide that difference by a vanishing angle: the loop's data differed across v = 0
    // by 1e-10 (a G2 cap's seam parted by 5e-12 of the scene).
    if ((Ds - De).norm() <= 1e-6 * longest && Te.cross(Ts).norm() <= 1e-6 * Te.norm() * Ts.norm() && Te.dot(Ts) > 0) continue;
    // First choice: W where the two sides' lines De + αTe and Ds + βTs cross, so each side keeps
    // its own cross derivative (γ = 1): a corner of any angle short of straight. Where the
    // sides' tangent planes differ a little the lines pass near each other instead: each side
    // leaves along its own nearest point (in its own plane: G1 untouched), the two directions
    // apart by the planes' difference. Continuous in it: a 1e-5 difference once fell through
    // to the fallback below and folded a flat hexagon's fill at its corners (issue 38 #14).
    Eigen::Matrix<double, 3, 2> A;
    A << Te, -Ts;
    const Eigen::Vector2d ab = A.colPivHouseholderQr().solve(Ds - De);
    const Eigen::Vector3d W = De + ab(0) * Te;
    if (ab.allFinite() && (A * ab - (Ds - De)).norm() <= kNearLines * longest && W.norm() <= longest) {
      mix[k][3] = ab(0), mix[(k + 1) % n][1] = ab(1);
      continue;
    }
    // Else the mean of the two, reached with γ != 1 where it can be.
    const Eigen::Vector3d mean = (De + Ds) / 2;
    if (!(mean.norm() > 0.05 * std::max(De.norm(), Ds.norm()))) continue;  // the sides leave in opposite directions
    fit(De, Te, mean, &mix[k][2], &mix[k][3]);
    fit(Ds, Ts, mean, &mix[(k + 1) % n][0], &mix[(k + 1) % n][1]);
  }
  return mix;
}

std::vector<SideMix> curvatureCorners(const FillLoop& loop, const std::vector<FillSide>& sides, const std::vector<double>& scale,
                                      const std::vector<SideMix>& mix, double radius) {
  const size_t n = sides.size();
  std::vector<SideMix> tangential(n, {0.0, 0.0, 0.0, 0.0});  // δ_T, δ_D at v0; at v1
  const auto refuse = [](const std::string& path, const std::string& why) { throw Error(ErrorCode::InvalidField, path + ": " + why); };
  // Curvature: X_uu along side k continues its border's surface S in the direction the fill
  // leaves it, X ≈ S(s + αu, βu) with β = γ k_k: X_uu = α² S_ss + 2αβ S_sw + β² S_ww, whose
  // normal part is S's second fundamental form in that direction (G2 by construction). At a
  // corner the two sides must agree on it; a tangential part (δ_T T + δ_D D, linear in σ) lets
  // them meet at their mean without touching the normal part.
  const auto secondAt = [&](size_t k, double v, double sigma) {
    const FillSide& s = sides[k];
    const auto& m = mix[k];
    const double alpha = m[1] + (m[3] - m[1]) * sigma, beta = (m[0] + (m[2] - m[0]) * sigma) * scale[k];
    return Eigen::Vector3d(alpha * alpha * valueAt(s.Xss, v) + 2 * alpha * beta * valueAt(s.Xsw, v) + beta * beta * valueAt(s.Xww, v));
  };
  for (size_t k = 0; k < n && n > 1; ++k) {
    const size_t j = (k + 1) % n;
    const FillSide &s = sides[k], &next = sides[j];
    const double ve = s.v1 - kInside * (s.v1 - s.v0), vs = next.v0 + kInside * (next.v1 - next.v0);
    const Eigen::Vector3d De = valueAt(s.D, ve), Ds = valueAt(next.D, vs), Te = valueAt(s.T, ve), Ts = valueAt(next.T, vs);
    const Eigen::Vector3d We = mix[k][2] * scale[k] * De + mix[k][3] * Te, Ws = mix[j][0] * scale[j] * Ds + mix[j][1] * Ts;
    const std::string corner = "the corner where " + s.name + " meets " + next.name;
    if (!((We - Ws).norm() <= 1e-6 * std::max(We.norm(), Ws.norm())))
      refuse(loop.borders[j].path,
           "a curvature fill cannot be G2 at " + corner + ": the two sides cannot leave it along one direction; fill it with tangency");
    const Eigen::Vector3d Ne = Te.cross(De).normalized(), Ns = Ts.cross(Ds).normalized();
    const Eigen::Vector3d Qe = secondAt(k, ve, 1.0), Qs = secondAt(j, vs, 0.0);
    const double planes = std::atan2(Ne.cross(Ns).norm(), std::abs(Ne.dot(Ns))) * 180 / M_PI;
    const double ke = Qe.dot(Ne) / We.squaredNorm(), ks = Qs.dot(Ne.dot(Ns) < 0 ? Eigen::Vector3d(-Ns) : Ns) / Ws.squaredNorm();
    const double room = 1e-6 * std::max({std::abs(ke), std::abs(ks), 1.0 / radius});
    if (!(planes <= 1e-6) || !(std::abs(ke - ks) <= room))
      refuse(loop.borders[j].path,
           "a curvature fill cannot be G2 at " + corner + ": " +
               (planes > 1e-6 ? "the two surfaces' tangent planes differ there by " + shortNumber(planes) + "°"
                              : "the two surfaces bend differently there (normal curvature " + shortNumber(ke) + " against " + shortNumber(ks) + " along the fill's direction)") +
               "; fill it with tangency, or make the surfaces meet G2 at that corner");
    const Eigen::Vector3d M = (Qe + Qs) / 2;
    const auto inPlane = [](const Eigen::Vector3d& T, const Eigen::Vector3d& D, const Eigen::Vector3d& d) {
      Eigen::Matrix<double, 3, 2> A;
      A << T, D;
      return Eigen::Vector2d(A.colPivHouseholderQr().solve(d));
    };
    const Eigen::Vector2d de = inPlane(Te, De, M - Qe), ds = inPlane(Ts, Ds, M - Qs);
    tangential[k][2] = de(0), tangential[k][3] = de(1), tangential[j][0] = ds(0), tangential[j][1] = ds(1);
  }
  return tangential;
}

}  // namespace pdesurf
