// Factored Bézier solvers keyed by everything their matrix depends on (degree, energy, λ, γ,
// normal field) but not the initial surface S. Dragging a control point of S in the page
// re-sends the scene; with this cache the re-solve is a back-substitution (20-330× faster natively)
// instead of a fresh assembly and factorisation.
#pragma once
#include <cstring>
#include <map>
#include <memory>
#include <string>

#include "bezier/bezier_solver.hpp"

namespace pdesurf {

class BezierSolverCache {
 public:
  explicit BezierSolverCache(size_t capacity = 8) : capacity_(capacity) {}

  const BezierSolver& get(const BezierProblem& p) {
    const std::string key = keyOf(p);
    const auto it = solvers_.find(key);
    if (it != solvers_.end()) return *it->second;
    auto solver = std::make_unique<BezierSolver>(p);  // throws before anything is cached
    if (solvers_.size() >= capacity_) solvers_.clear();
    return *solvers_.emplace(key, std::move(solver)).first->second;
  }

 private:
  // The bytes of every input of Q (exact: a changed bit is a different matrix).
  static std::string keyOf(const BezierProblem& p) {
    std::string k;
    auto put = [&k](const void* data, size_t n) { k.append(static_cast<const char*>(data), n); };
    const BezierNormalField& f = p.normals;
    const int ints[8] = {p.n, p.m, static_cast<int>(p.energy), f.discrete, f.n1, f.m1, f.np, f.mp};
    put(ints, sizeof ints);
    put(&p.lambda, sizeof p.lambda);
    put(&p.gamma, sizeof p.gamma);
    for (const auto& v : f.vectors) put(v.data(), 3 * sizeof(double));
    const size_t sizes[2] = {f.lambdaWeight.size(), f.gammaWeight.size()};
    put(sizes, sizeof sizes);
    put(f.lambdaWeight.data(), f.lambdaWeight.size() * sizeof(double));
    put(f.gammaWeight.data(), f.gammaWeight.size() * sizeof(double));
    return k;
  }

  size_t capacity_;
  std::map<std::string, std::unique_ptr<BezierSolver>> solvers_;
};

}  // namespace pdesurf
