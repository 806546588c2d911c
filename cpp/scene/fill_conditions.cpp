// A fill's conditions (docs/chains-and-fills.md). The loop is the fill's border u = 0: v in
// [0, 2π], border k of N on fillSideRange(k, N) (border 0 wrapping through v = 0), mapped onto
// the part of the edge it names through σ, which slows down at the corners. Along it
//   X(0, v)   = the borders' positions, piecewise,
//   X_u(0, v) = k_k d_k: each border's derivative across its edge out of its patch, continued
//               into the fill (so the fill is G1 to every side), scaled so that its mean length
//               is the loop's mean radius R (times the border's power), plus a tangential part
//               at the corners;
// and at u = 1 a centre point C with a tangent plane normal to n:
//   X(1, v) = C,  X_u(1, v) = -(a cos v + b sin v),
// a and b the first Fourier harmonic of the loop projected on that plane about C, so the fill
// leaves its centre as a linear image of polar coordinates: a regular point (not a cone).
// n is the loop's area vector (Newell) unless given; C the loop's centroid lifted along n by
// height × the mean rise of X_u(0, v) along n, unless given. The data are one periodic loop
// (PdeProblem::periodicV): the modal method expands them whole and lifts its remainder with a
// decaying profile (methods/boundary_lift.hpp).
#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>

#include "basis/general_function.hpp"

#include "common/errors.hpp"
#include "common/limits.hpp"
#include "scene/chain_conditions.hpp"
#include "scene/expression_fields.hpp"
#include "scene/fill_corners.hpp"
#include "scene/loop_sheet.hpp"
#include "scene/patch_graph.hpp"
#include "scene/solved_edges.hpp"

namespace pdesurf {

namespace {

constexpr double kCloseTolerance = 1e-10;  // of the loop's size: a gap beyond this is refused


// 1 on [v0, v1], ½ at a corner; from = -inf: everything below v1 too, to = inf: above v0.
Expr indicator(double v0, double v1) {
  const Expr v = variable(ExprVar::V);
  const Expr up = std::isinf(v0) ? constant(1.0) : call(ExprFn::Sign, subtract(v, constant(v0)));
  const Expr down = std::isinf(v1) ? constant(-1.0) : call(ExprFn::Sign, subtract(v, constant(v1)));
  return multiply(constant(0.5), subtract(up, down));
}

}  // namespace

void deriveFill(const Patch& fill, const SolvedLookup& solved, PdeProblem& out) {
  const FillLoop& loop = fill.fill();
  const int depth = static_cast<int>(loop.continuity);
  const bool tangency = depth >= 1, curvature = depth >= 2;
  const size_t n = loop.borders.size();
  out.periodicV = true;  // one loop: the fill closes on itself across v = 0 (corner or not)
  std::vector<FillSide> sides;
  for (size_t k = 0; k < n; ++k) sides.push_back(fillSideOf(fill, k, solved, depth));

  // The loop's size, centroid and mean radius, over evenly spaced v.
  Eigen::Vector3d lo = sides[0].x[0], hi = lo, centroid = Eigen::Vector3d::Zero(), area = Eigen::Vector3d::Zero();
  for (const FillSide& s : sides)
    for (size_t i = 0; i < s.x.size(); ++i) {
      lo = lo.cwiseMin(s.x[i]), hi = hi.cwiseMax(s.x[i]);
      if (i < s.x.size() - 1) centroid += s.x[i], area += s.x[i].cross(s.x[i + 1]) / 2;
    }
  const double size = (hi - lo).norm();
  centroid /= static_cast<double>(n * kPerSide);
  // Every side must end where the next starts (the last where the first starts).
  for (size_t k = 0; k < n; ++k) {
    const FillSide& s = sides[k];
    const FillSide& next = sides[(k + 1) % n];
    const double gap = (s.x.back() - next.x.front()).norm();
    if (!(gap <= kCloseTolerance * size))
      fail(ErrorCode::InvalidField, loop.borders[(k + 1) % n].path,
           "the loop does not close: " + s.name + " ends " + shortNumber(gap) + " (scene units) from where " + next.name + " starts" +
               (n == 1 ? " (a single border must be a closed curve)" : ""));
  }
  if (!(size > 0)) fail(ErrorCode::InvalidField, loop.path + ".borders", "the loop is a single point");
  // Within that tolerance the sides still part by their sources' rounding (a cap's border by
  // 2e-11 of the aeroplane): each side is moved, linearly in σ, to corners halfway between, so
  // the loop's data close exactly and the fill closes across v = 0 to rounding.
  std::vector<Eigen::Vector3d> corner(n);
  for (size_t k = 0; k < n; ++k) corner[k] = (sides[(k + n - 1) % n].x.back() + sides[k].x.front()) / 2;
  for (size_t k = 0; k < n; ++k) {
    FillSide& s = sides[k];
    const Eigen::Vector3d c0 = corner[k] - s.x.front(), c1 = corner[(k + 1) % n] - s.x.back();
    for (int c = 0; c < 3; ++c)
      if (c0[c] != 0 || c1[c] != 0) s.X[c] = add(s.X[c], add(constant(c0[c]), multiply(constant(c1[c] - c0[c]), s.sigma)));
  }
  double radius = 0.0;
  for (const FillSide& s : sides)
    for (int i = 0; i < kPerSide; ++i) radius += (s.x[i] - centroid).norm();
  radius /= static_cast<double>(n * kPerSide);

  if (loop.centreGiven && !((loop.centre - centroid).stableNorm() <= limits::kEndScale * radius)) {
    char why[200];
    std::snprintf(why, sizeof why, "is %.3g loop radii from the loop's centroid (at most %.0f): the fill would be a spike",
                  (loop.centre - centroid).stableNorm() / radius, limits::kEndScale);
    fail(ErrorCode::InvalidField, loop.path + ".centre", why);
  }
  Eigen::Vector3d normal = loop.normal;
  if (!loop.normalGiven) {
    if (!(area.norm() > 1e-9 * radius * radius))
      fail(ErrorCode::InvalidField, loop.path + ".borders", "the loop encloses no area (its curves lie on a line): give the fill a \"normal\"");
    normal = area.normalized();
  }
  // Each side's cross derivative scaled to the loop's mean radius; the lift of the centre.
  std::vector<double> scale(n, 0.0);
  double rise = 0.0;
  for (size_t k = 0; k < n && tangency; ++k) {
    double mean = 0.0;
    for (int i = 0; i < kPerSide; ++i) mean += sides[k].d[i].norm();
    mean /= kPerSide;
    if (!(mean > 1e-12 * radius))
      fail(ErrorCode::InvalidField, loop.borders[k].path, sides[k].name + " has no derivative across it (the surface stops there): it cannot set a tangent plane");
    scale[k] = loop.borders[k].power->value * radius / mean;
    for (int i = 0; i < kPerSide; ++i) rise += scale[k] * sides[k].d[i].dot(normal);
  }
  rise /= static_cast<double>(n * kPerSide);
  // The sheet the loop lies in (scene/loop_sheet.hpp): where a cubic height over the plane
  // follows the loop and its borders' tangent planes, the centre goes on it (height × its
  // height at the centroid), leaves along its tangent plane and, curvature fills, with its
  // curvature. Else (a cap on a tube: its borders are steep over the plane) the centroid is
  // lifted by height × the mean rise of the cross derivatives.
  LoopSheet sheet;
  if (tangency && !loop.normalGiven) {
    std::vector<Eigen::Vector3d> xs, ts, ds;
    for (size_t k = 0; k < n; ++k)
      for (int i = 0; i < kPerSide; ++i) xs.push_back(sides[k].x[i]), ts.push_back(sides[k].t[i]), ds.push_back(sides[k].d[i]);
    sheet = fitLoopSheet(xs, ts, ds, centroid, normal, radius);
  }
  const double lift = sheet.fitted ? sheet.c[0] : rise;
  const Eigen::Vector3d centre = loop.centreGiven ? loop.centre : Eigen::Vector3d(centroid + loop.height * lift * normal);

  // The centre's spokes: the first harmonic of the loop projected on the tangent plane (the
  // sheet's, when fitted: the plane's, lifted by its slopes).
  Eigen::Vector3d a = Eigen::Vector3d::Zero(), b = Eigen::Vector3d::Zero();
  for (const FillSide& s : sides)
    for (int i = 0; i < kPerSide; ++i) {
      const double v = s.v0 + (s.v1 - s.v0) * i / kPerSide;
      Eigen::Vector3d p = s.x[i] - centre;
      p -= p.dot(normal) * normal;
      a += p * std::cos(v), b += p * std::sin(v);
    }
  a *= 2.0 / (n * kPerSide), b *= 2.0 / (n * kPerSide);
  if (sheet.fitted) {
    a += (sheet.c[1] * a.dot(sheet.e1) + sheet.c[2] * a.dot(sheet.e2)) * normal;
    b += (sheet.c[1] * b.dot(sheet.e1) + sheet.c[2] * b.dot(sheet.e2)) * normal;
  }
  if (!(a.cross(b).norm() > 1e-3 * radius * radius))
    fail(ErrorCode::InvalidField, loop.path + ".borders",
         "the loop does not turn around the centre's normal (seen along it, it is flat or folded): the centre cannot be regular");

  const std::vector<SideMix> mix = tangency ? cornerDirections(sides, scale) : std::vector<SideMix>(n, {1.0, 0.0, 1.0, 0.0});
  // From a at the side's start to b at its end, in σ (so its v-derivative too is 0 at corners).
  const auto linear = [](double a, double b, const Expr& sigma) { return add(constant(a), multiply(constant(b - a), sigma)); };

  const std::vector<SideMix> tangential = curvature ? curvatureCorners(loop, sides, scale, mix, radius) : std::vector<SideMix>(n, {0.0, 0.0, 0.0, 0.0});
  // X_uu(1, v) = B(v) n, B a quadratic form in p(v) = a cos v + b sin v, so the fill leaves C as
  // X ≈ C + r p(v) + ½ r² B(v) n (r = 1 - u), a function of r cos v, r sin v only (harmonics 0
  // and 2): a regular point. B is the sheet's 2 h₂(p) when fitted (exact for a cubic sheet),
  // else the umbilic κ |p|², κ the loop's mean normal curvature across its borders. Kept as its
  // constant, cos 2v and sin 2v parts.
  std::array<double, 3> centreBend{};
  // (pa cos v + pb sin v)(qa cos v + qb sin v) as its constant, cos 2v and sin 2v parts.
  const auto product = [](double pa, double pb, double qa, double qb) {
    return std::array<double, 3>{(pa * qa + pb * qb) / 2, (pa * qa - pb * qb) / 2, (pa * qb + pb * qa) / 2};
  };
  const auto addTimes = [&](double w, const std::array<double, 3>& h) {
    for (int i = 0; i < 3; ++i) centreBend[i] += w * h[i];
  };
  if (curvature && sheet.fitted) {
    const double a1 = a.dot(sheet.e1), b1 = b.dot(sheet.e1), a2 = a.dot(sheet.e2), b2 = b.dot(sheet.e2);
    addTimes(2 * sheet.c[3], product(a1, b1, a1, b1));
    addTimes(2 * sheet.c[4], product(a1, b1, a2, b2));
    addTimes(2 * sheet.c[5], product(a2, b2, a2, b2));
  } else if (curvature) {
    double kappa = 0.0;
    for (const FillSide& s : sides)
      for (int i = 0; i < kPerSide; ++i) {
        Eigen::Vector3d N = s.t[i].cross(s.d[i]).normalized();
        if (N.dot(normal) < 0) N = -N;
        kappa += s.dd[i].dot(N) / s.d[i].squaredNorm();
      }
    kappa /= static_cast<double>(n * kPerSide);
    addTimes(kappa, {(a.dot(a) + b.dot(b)) / 2, (a.dot(a) - b.dot(b)) / 2, a.dot(b)});
  }

  // Border 0 runs over [-π/n, π/n]: its own expression on [0, π/n] (and below, so that the
  // certificate may read it there), the same shifted by 2π on [2π - π/n, 2π].
  const Expr wrapped = subtract(variable(ExprVar::V), constant(2 * M_PI));
  for (int c = 0; c < 3; ++c) {
    Expr x, d, dd;
    const auto place = [](Expr& sum, const Expr& chi, const Expr& e) { sum = sum ? add(sum, multiply(chi, e)) : multiply(chi, e); };
    for (size_t k = 0; k < n; ++k) {
      const FillSide& s = sides[k];
      Expr dk, ddk;
      if (tangency) {
        const auto& m = mix[k];
        const Expr beta = multiply(linear(m[0], m[2], s.sigma), constant(scale[k])), alpha = linear(m[1], m[3], s.sigma);
        dk = multiply(beta, s.D[c]);
        if (m[1] != 0.0 || m[3] != 0.0) dk = add(dk, multiply(alpha, s.T[c]));
        if (curvature) {
          const auto& q = tangential[k];
          ddk = add(add(multiply(multiply(alpha, alpha), s.Xss[c]), multiply(multiply(constant(2.0), multiply(alpha, beta)), s.Xsw[c])),
                    multiply(multiply(beta, beta), s.Xww[c]));
          ddk = add(ddk, add(multiply(linear(q[0], q[2], s.sigma), s.T[c]), multiply(linear(q[1], q[3], s.sigma), s.D[c])));
        }
      }
      if (n == 1) {
        x = s.X[c], d = dk, dd = ddk;
        continue;
      }
      const bool first = k == 0;
      const Expr chi = indicator(first ? -INFINITY : s.v0, s.v1);
      place(x, chi, s.X[c]);
      if (tangency) place(d, chi, dk);
      if (curvature) place(dd, chi, ddk);
      if (!first) continue;
      // From the last side's own end (the same double): v0 + 2π can differ from it by an ulp,
      // and at that one v the two indicators then summed to ½ (the fill's point halved there).
      const Expr tail = indicator(sides[n - 1].v1, INFINITY);
      place(x, tail, substitute(s.X[c], ExprVar::V, wrapped));
      if (tangency) place(d, tail, substitute(dk, ExprVar::V, wrapped));
      if (curvature) place(dd, tail, substitute(ddk, ExprVar::V, wrapped));
    }
    ComponentProblem& cp = out.component[c];
    const std::string text = loop.path + " (the loop)";
    // A loop of several borders is piecewise (each piece times its indicator): nothing in it is
    // a family term of the whole loop, and the modal method expands it whole, so it is one
    // general function; splitting it symbolically cost a fill's solve a fifth of its time. A
    // cap (one border) keeps its family terms, solved exactly.
    const auto slot = [&](const Expr& e) {
      if (n == 1) return scene_json::slotFromExpr(e, text);
      VFunction g;
      g.family = Family::General;
      g.general = std::make_shared<GeneralFunction>(text, e);
      return VExpansion{{g, 1.0}};
    };
    cp.left[0] = slot(x);
    cp.right[0] = {{VFunction{Family::Poly, 1.0, 0}, centre[c]}};
    if (tangency) {
      cp.left[1] = slot(d);
      cp.right[1] = {{VFunction{Family::Cos, 1.0}, -a[c]}, {VFunction{Family::Sin, 1.0}, -b[c]}};
    }
    if (curvature) {
      cp.left[2] = slot(dd);
      cp.right[2] = {{VFunction{Family::Poly, 1.0, 0}, centreBend[0] * normal[c]},
                     {VFunction{Family::Cos, 2.0}, centreBend[1] * normal[c]},
                     {VFunction{Family::Sin, 2.0}, centreBend[2] * normal[c]}};
    }
  }
}

}  // namespace pdesurf
