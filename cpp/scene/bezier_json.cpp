// The "bezier" patch (seed 002): degree, initial control net, energy, λ, γ and the guiding
// normal field, continuous (control vectors of its own degree) or discrete (a sample grid of
// normals, given as vectors or as expressions in u and v, with optional per-sample weights).
#include "bezier/bezier_assembly.hpp"
#include "expr/parse.hpp"
#include "expr/program.hpp"
#include "common/text.hpp"
#include "common/limits.hpp"
#include "scene/json_fields.hpp"
#include "scene/patch_parsers.hpp"
#include "scene/scene.hpp"

namespace pdesurf {

using namespace scene_json;

namespace {

std::array<int, 2> pair(const json& j, const std::string& path, int lo, int hi) {
  if (!j.is_array() || j.size() != 2) fail(ErrorCode::InvalidField, path, "expected [integer, integer]");
  return {integerField(j[0], path + "[0]", lo, hi), integerField(j[1], path + "[1]", lo, hi)};
}

std::vector<Eigen::Vector3d> points(const json& j, const std::string& path, const Resolver& r, size_t count) {
  if (!j.is_array() || j.size() != count) fail(ErrorCode::InvalidField, path, "expected " + std::to_string(count) + " points [x, y, z]");
  std::vector<Eigen::Vector3d> out;
  for (size_t k = 0; k < count; ++k) {
    const std::string p = path + "[" + std::to_string(k) + "]";
    if (!j[k].is_array() || j[k].size() != 3) fail(ErrorCode::InvalidField, p, "expected [x, y, z]");
    out.emplace_back(r.number(j[k][0], p + "[0]"), r.number(j[k][1], p + "[1]"), r.number(j[k][2], p + "[2]"));
  }
  return out;
}

// A per-sample list: an array of count values or an expression in u and v. An expression is
// compiled once and run over every sample; its samples × instructions are charged to the
// scene's total (limits::kFieldSampling) before it runs.
std::vector<double> sampled(const json& j, const std::string& path, const Resolver& r, int np, int mp, size_t& samplingWork) {
  const size_t count = static_cast<size_t>(np + 1) * (mp + 1);
  std::vector<double> out;
  if (j.is_array()) {
    if (j.size() != count) fail(ErrorCode::InvalidField, path, "expected " + std::to_string(count) + " values");
    for (size_t k = 0; k < count; ++k) out.push_back(r.number(j[k], path + "[" + std::to_string(k) + "]"));
    return out;
  }
  const std::string text = stringField(j, path, kMaxExpressionLength);
  Expr e;
  try {
    e = parseExpression(text, r.values, AllowedVariables{true, true});
  } catch (const Error& err) {
    fail(err.code(), path, err.what());
  }
  const ExprProgram program(std::vector<Expr>{e});
  samplingWork += count * program.instructions();
  if (samplingWork > limits::kFieldSampling)
    fail(ErrorCode::TooLarge, path,
         "sampling '" + clipText(text, 60) + "' (" + std::to_string(program.instructions()) + " operations) on " + std::to_string(count) +
             " points brings the scene's normal fields to " + numberText(double(samplingWork)) + " operations, over the limit " +
             numberText(double(limits::kFieldSampling)) + " (use coarser grids, shorter expressions or fewer patches)");
  std::vector<double> us, vs;
  for (int i = 0; i <= np; ++i)
    for (int k = 0; k <= mp; ++k) us.push_back(static_cast<double>(i) / np), vs.push_back(static_cast<double>(k) / mp);
  out.resize(count);
  program.run(vs.data(), us.data(), count, out.data());
  for (size_t q = 0; q < count; ++q)
    if (!std::isfinite(out[q]))
      fail(ErrorCode::NonFinite, path, "'" + text + "' is not finite at (u, v) = (" + numberText(us[q]) + ", " + numberText(vs[q]) + ")");
  return out;
}

// Adds this patch's assembly and factorisation work (bezier_assembly.hpp) to the scene's
// running total, before the normal field's samples are read; refuses the scene once the total
// passes the limit. normals: false for a patch without guiding normals.
void addAssemblyWork(const BezierProblem& b, const std::string& path, bool normals, size_t& total) {
  int Nu = 0, Nv = 0;
  bezierNormalNodes(b.n, b.m, b.normals, Nu, Nv);
  const size_t work = bezierAssemblyWork(b.n, b.m, Nu, Nv);
  total += work;
  if (total > limits::kBezierAssembly)
    fail(ErrorCode::TooLarge, path,
         "a patch of degree " + std::to_string(b.n) + "x" + std::to_string(b.m) +
             (normals ? " with a normal field on " + std::to_string(Nu) + "x" + std::to_string(Nv) + " nodes" : std::string()) + " is " +
             std::to_string(work) + " units of assembly work; with the Bezier patches before it, " + std::to_string(total) + ", over the limit " +
             std::to_string(limits::kBezierAssembly) + " per scene (use coarser normal grids, lower degrees or fewer patches)");
}

// Version 4: "borders": {"u0": {"surface", "at", "reverse"}, ...}, any of the four edges.
void parseBorders(const json& j, const std::string& path, int version, Patch& patch) {
  const std::string bp = path + ".borders";
  if (version < 4) fail(ErrorCode::InvalidField, bp, "Bezier borders by reference need scene version 4");
  allowOnly(j, bp, {"u0", "u1", "v0", "v1"});
  for (int e = 0; e < 4; ++e) {
    if (!j.contains(kBezierEdge[e])) continue;
    const std::string ep = bp + "." + kBezierEdge[e];
    const json& ej = j[kBezierEdge[e]];
    allowOnly(ej, ep, {"surface", "at", "reverse"});
    BorderReference& ref = patch.borders()[e];
    ref.given = true;
    ref.path = ep;
    ref.surface = stringField(require(ej, "surface", ep), ep + ".surface", 64);
    const std::string at = stringField(require(ej, "at", ep), ep + ".at");
    if (at != "t0" && at != "t1") fail(ErrorCode::InvalidField, ep + ".at", "expected \"t0\" or \"t1\" (the surface's border t = t0 or t = t1)");
    ref.atT1 = at == "t1";
    if (ej.contains("reverse")) {
      if (!ej["reverse"].is_boolean()) fail(ErrorCode::InvalidField, ep + ".reverse", "expected true or false");
      ref.reverse = ej["reverse"].get<bool>();
    }
  }
}

}  // namespace

void parseBezierPatch(const json& j, const std::string& path, const Resolver& r, int version, Patch& patch, BezierWork& work) {
  allowOnly(j, path, {"name", "kind", "energy", "degree", "control_net", "lambda", "gamma", "normals", "borders"});
  if (j.contains("borders")) parseBorders(j["borders"], path, version, patch);
  bool allFour = true;
  for (const BorderReference& ref : patch.borders()) allFour = allFour && ref.given;
  BezierProblem& b = patch.bezier();
  const std::string energy = stringField(require(j, "energy", path), path + ".energy");
  if (energy == "membrane") b.energy = BezierEnergy::Membrane;
  else if (energy == "thin-plate") b.energy = BezierEnergy::ThinPlate;
  else fail(ErrorCode::InvalidField, path + ".energy", "expected \"membrane\" or \"thin-plate\"");
  const auto deg = pair(require(j, "degree", path), path + ".degree", 1, limits::kBezierDegree);
  b.n = deg[0], b.m = deg[1];
  // With all four borders given by reference the net may be left out: deriveBorders builds it
  // (scene/bezier_borders.hpp).
  if (j.contains("control_net") || !allFour)
    b.initial = points(require(j, "control_net", path), path + ".control_net", r, static_cast<size_t>(b.n + 1) * (b.m + 1));
  b.lambda = j.contains("lambda") ? r.number(j["lambda"], path + ".lambda") : 0.0;
  b.gamma = j.contains("gamma") ? r.number(j["gamma"], path + ".gamma") : 0.0;
  const std::string np = path + ".normals";
  BezierNormalField& f = b.normals;
  // Version 4: a patch without guiding normals (a fill by its borders) has none to weigh.
  if (!j.contains("normals") && version >= 4) {
    if (b.lambda != 0.0)
      fail(ErrorCode::InvalidField, path + ".lambda", "lambda weighs the guiding normals, and this patch has none: give \"normals\" or set lambda to 0");
    f.n1 = f.m1 = 0;
    f.vectors = {Eigen::Vector3d(0, 0, 1)};  // weighed by lambda = 0: no effect
    addAssemblyWork(b, path + ".degree", false, work.assembly);  // its energy and factorisation still count
    return;
  }
  const json& nj = require(j, "normals", path);
  if (!nj.is_object()) fail(ErrorCode::InvalidField, np, "expected an object");
  if (nj.contains("degree")) {
    allowOnly(nj, np, {"degree", "vectors"});
    const auto d = pair(nj["degree"], np + ".degree", 0, 24);
    f.n1 = d[0], f.m1 = d[1];
    addAssemblyWork(b, np + ".degree", true, work.assembly);
    f.vectors = points(require(nj, "vectors", np), np + ".vectors", r, static_cast<size_t>(f.n1 + 1) * (f.m1 + 1));
  } else {
    allowOnly(nj, np, {"grid", "vectors", "field", "lambda_weights", "gamma_weights"});
    f.discrete = true;
    const auto g = pair(require(nj, "grid", np), np + ".grid", 1, 256);
    f.np = g[0], f.mp = g[1];
    const size_t count = static_cast<size_t>(f.np + 1) * (f.mp + 1);
    addAssemblyWork(b, np + ".grid", true, work.assembly);
    if (nj.contains("vectors") == nj.contains("field")) fail(ErrorCode::InvalidField, np, "give either \"vectors\" or \"field\"");
    if (nj.contains("vectors")) {
      f.vectors = points(nj["vectors"], np + ".vectors", r, count);
    } else {
      const std::string fp = np + ".field";
      allowOnly(nj["field"], fp, {"x", "y", "z"});
      std::array<std::vector<double>, 3> c;
      for (int k = 0; k < 3; ++k)
        c[k] = sampled(require(nj["field"], kAxis[k], fp), fp + "." + kAxis[k], r, f.np, f.mp, work.sampling);
      for (size_t q = 0; q < count; ++q) f.vectors.emplace_back(c[0][q], c[1][q], c[2][q]);
    }
    if (nj.contains("lambda_weights")) f.lambdaWeight = sampled(nj["lambda_weights"], np + ".lambda_weights", r, f.np, f.mp, work.sampling);
    if (nj.contains("gamma_weights")) f.gammaWeight = sampled(nj["gamma_weights"], np + ".gamma_weights", r, f.np, f.mp, work.sampling);
  }
}

}  // namespace pdesurf
