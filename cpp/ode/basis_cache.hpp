// Bases of the two-point ODE keyed by (operator coefficients, sigma, force degree). They depend
// on the operator and the v-frequency only, not on boundary data: a slider that moves a
// trimline re-solves with cached bases (one back-substitution per term), so a long-lived cache
// (the page's, the benchmark's) makes repeated closed-form solves cheap.
#pragma once
#include <array>
#include <map>
#include <memory>
#include <tuple>
#include <vector>

#include "ode/even_ode.hpp"

namespace pdesurf {

class BasisCache {
 public:
  explicit BasisCache(size_t capacity = 1024) : capacity_(capacity) {}
  const EvenOdeBasis& get(const std::vector<double>& alpha, double sigma, int forceDegree) {
    Key key{};
    std::get<0>(key) = static_cast<int>(alpha.size());
    for (size_t k = 0; k < alpha.size() && k < 4; ++k) std::get<1>(key)[k] = alpha[k];
    std::get<2>(key) = sigma;
    std::get<3>(key) = forceDegree;
    const auto it = bases_.find(key);
    if (it != bases_.end()) return *it->second;
    if (bases_.size() >= capacity_) bases_.clear();  // simple bound: start afresh
    auto basis = std::make_unique<EvenOdeBasis>(alpha, sigma, forceDegree);
    return *bases_.emplace(key, std::move(basis)).first->second;
  }
  size_t size() const { return bases_.size(); }

 private:
  using Key = std::tuple<int, std::array<double, 4>, double, int>;
  size_t capacity_;
  std::map<Key, std::unique_ptr<EvenOdeBasis>> bases_;
};

}  // namespace pdesurf
