#include "methods/approximate.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <unsupported/Eigen/FFT>

#include "common/text.hpp"
#include "basis/general_function.hpp"
#include "common/errors.hpp"
#include "expr/program.hpp"

namespace pdesurf {

double expansionValue(const VExpansion& f, double v, int k) {
  double s = 0.0;
  for (const VTerm& t : f) s += t.coef * t.g.eval(v, k);
  return s;
}

namespace {

// Names the offending term: "'sqrt(1 - 4*cos(v)^2)' is not finite at v = 0".
void requireFinite(const VExpansion& f, double v) {
  for (const VTerm& t : f) {
    const double x = t.g.eval(v);
    if (std::isfinite(x)) continue;
    const std::string name = t.g.isGeneral() ? t.g.general->text() : std::string(familyName(t.g.family));
    throw Error(ErrorCode::NonFinite, "'" + name + "' is not finite at v = " + numberText(v));
  }
}

}  // namespace

namespace {

// The trapezoid rule's K + 1 points over one period (both ends), K = max(1024, 16 N).
std::vector<double> periodGrid(double v0, double v1, int N) {
  const double L = v1 - v0;
  const int K = std::max(1024, 16 * N);
  std::vector<double> vs(K + 1);
  for (int j = 0; j <= K; ++j) vs[j] = v0 + L * j / K;
  return vs;
}

// Each expansion's samples at vs, term by term in its order; the general terms of all of them
// by one program over all the points (a general function's values are its program's, so each
// sample is what evalMany gives).
std::vector<std::vector<double>> sampleAll(const std::vector<const VExpansion*>& fs, const std::vector<double>& vs) {
  std::vector<const GeneralFunction*> generals;
  std::vector<Expr> roots;
  for (const VExpansion* f : fs)
    for (const VTerm& t : *f)
      if (t.g.isGeneral() && std::find(generals.begin(), generals.end(), t.g.general.get()) == generals.end())
        generals.push_back(t.g.general.get()), roots.push_back(t.g.general->derivativeExpr(0));
  std::vector<std::vector<double>> values(generals.size(), std::vector<double>(vs.size()));
  if (!generals.empty()) {
    std::vector<double*> outs;
    for (std::vector<double>& v : values) outs.push_back(v.data());
    ExprProgram(roots).runAll(vs.data(), nullptr, vs.size(), outs.data());
  }
  std::vector<std::vector<double>> out;
  std::vector<double> g(vs.size());
  for (const VExpansion* f : fs) {
    std::vector<double> samples(vs.size(), 0.0);
    for (const VTerm& t : *f) {
      const double* x = g.data();
      if (t.g.isGeneral()) x = values[size_t(std::find(generals.begin(), generals.end(), t.g.general.get()) - generals.begin())].data();
      else t.g.evalMany(vs.data(), vs.size(), 0, g.data());
      for (size_t j = 0; j < vs.size(); ++j) samples[j] += t.coef * x[j];
    }
    out.push_back(std::move(samples));
  }
  return out;
}

VExpansion seriesOfSamples(const VExpansion& f, const std::vector<double>& vs, const std::vector<double>& samples, double v0, double v1, int N,
                           double noiseFloor, bool dropNoise);

}  // namespace

VExpansion fourierSeries(const VExpansion& f, double v0, double v1, int N, double noiseFloor, bool dropNoise) {
  return fourierSeriesMany({&f}, v0, v1, N, noiseFloor, dropNoise).front();
}

std::vector<VExpansion> fourierSeriesMany(const std::vector<const VExpansion*>& fs, double v0, double v1, int N, double noiseFloor, bool dropNoise) {
  const std::vector<double> vs = periodGrid(v0, v1, N);
  const std::vector<std::vector<double>> samples = sampleAll(fs, vs);
  std::vector<VExpansion> out;
  for (size_t k = 0; k < fs.size(); ++k) out.push_back(seriesOfSamples(*fs[k], vs, samples[k], v0, v1, N, noiseFloor, dropNoise));
  return out;
}

namespace {

VExpansion seriesOfSamples(const VExpansion& f, const std::vector<double>& vs, const std::vector<double>& samples, double v0, double v1, int N,
                           double noiseFloor, bool dropNoise) {
  const double L = v1 - v0, omega = 2 * M_PI / L;
  const int K = int(vs.size()) - 1;
  for (int j = 0; j <= K; ++j)
    if (!std::isfinite(samples[j])) requireFinite(f, vs[j]);
  // a_k + i b_k = Σ_j w_j f_j e^{ikωv_j} (trapezoid weights) by one FFT: the ends are one
  // point of the period (e^{ikωv_K} = e^{ikωv_0}), so the sum is e^{ikωv_0} times the
  // conjugate of the K-point DFT of f_0' = (f_0 + f_K)/2, f_1, …, f_{K-1}: O(K log K), where
  // the sum mode by mode was O(K N) (a root blend's modal:64 spent a quarter of its solve there).
  std::vector<double> periodSamples(samples.begin(), samples.end() - 1);
  periodSamples[0] = 0.5 * (samples[0] + samples[K]);
  std::vector<std::complex<double>> spectrum;
  Eigen::FFT<double> fft;
  fft.fwd(spectrum, periodSamples);
  std::vector<double> a(N + 1, 0.0), b(N + 1, 0.0);
  for (int k = 0; k <= N; ++k) {
    const std::complex<double> c = std::polar(1.0, k * omega * v0) * std::conj(spectrum[size_t(k)]);
    a[k] = c.real(), b[k] = c.imag();
  }
  // Modes at the rounding level of the sums are noise, and the k-th mode's noise enters the
  // surface's v-derivatives (normals, curvature, the PDE's ∂v^2n) times (kω)^j: leave them out.
  double largest = std::abs(a[0]);
  for (int k = 1; k <= N; ++k) largest = std::max(largest, 2.0 * std::max(std::abs(a[k]), std::abs(b[k])));
  // a, b are K times the coefficients; -1: keep every mode (the Bloor-Wilson baselines, as published)
  const double noise = dropNoise ? std::max(1e-15 * largest, 2.0 * noiseFloor * K) : -1.0;
  VExpansion out;
  out.push_back({VFunction{Family::Poly, 1.0, 0}, a[0] / K});
  for (int k = 1; k <= N; ++k) {
    if (std::abs(2.0 * a[k]) > noise) out.push_back({VFunction{Family::Cos, k * omega, 0}, 2.0 * a[k] / K});
    if (std::abs(2.0 * b[k]) > noise) out.push_back({VFunction{Family::Sin, k * omega, 0}, 2.0 * b[k] / K});
  }
  return out;
}

}  // namespace

namespace {

// Coefficients of T_0..T_N interpolating the values at the Chebyshev points cos(π(j+½)/(N+1)).
std::vector<double> chebyshevCoefficients(const std::vector<double>& values) {
  const int N = static_cast<int>(values.size()) - 1;
  std::vector<double> cheb(N + 1, 0.0);
  for (int k = 0; k <= N; ++k) {
    double sum = 0.0;
    for (int j = 0; j <= N; ++j) sum += values[j] * std::cos(M_PI * k * (j + 0.5) / (N + 1));
    cheb[k] = sum * (k == 0 ? 1.0 : 2.0) / (N + 1);
  }
  return cheb;
}

// Σ cheb[k] T_k(s) in powers of s, with T_k = 2 s T_{k-1} - T_{k-2}.
std::vector<double> chebyshevToPowers(const std::vector<double>& cheb) {
  const int N = static_cast<int>(cheb.size()) - 1;
  std::vector<double> power(N + 1, 0.0), older(N + 1, 0.0), old(N + 1, 0.0);  // T_{k-2}, T_{k-1}
  for (int k = 0; k <= N; ++k) {
    std::vector<double> t(N + 1, 0.0);
    if (k == 0) t[0] = 1.0;
    else if (k == 1) t[1] = 1.0;
    else
      for (int d = 0; d <= N; ++d) t[d] = (d > 0 ? 2 * old[d - 1] : 0.0) - older[d];
    for (int d = 0; d <= N; ++d) power[d] += cheb[k] * t[d];
    older.swap(old);
    old.swap(t);
  }
  return power;
}

}  // namespace

VExpansion chebyshevInterpolant(const VExpansion& f, double v0, double v1, int N) {
  const double c = 0.5 * (v0 + v1), w = 2.0 / (v1 - v0);
  std::vector<double> val(N + 1);
  for (int j = 0; j <= N; ++j) {
    const double s = std::cos(M_PI * (j + 0.5) / (N + 1));
    val[j] = expansionValue(f, c + s / w);
    if (!std::isfinite(val[j])) requireFinite(f, c + s / w);
  }
  const std::vector<double> power = chebyshevToPowers(chebyshevCoefficients(val));
  VExpansion out;
  for (int d = 0; d <= N; ++d) {
    VFunction g{Family::Poly, w, d};
    g.c = c;
    out.push_back({g, power[d]});
  }
  return out;
}

namespace {

VExpansion asExpansion(const GeneralForce& f, double u) {
  VFunction g;
  g.family = Family::General;
  g.general = std::make_shared<GeneralFunction>(f.text, substitute(f.f, ExprVar::U, u));
  return {{g, 1.0}};
}

}  // namespace

std::vector<ForceTerm> approximateForce(const GeneralForce& f, double v0, double v1, int N) {
  const int Du = std::min(N, 16);
  bool periodic = true;
  for (double u : {0.0, 0.5, 1.0}) periodic = periodic && isPeriodic(asExpansion(f, u), v0, v1);
  // coefficients[i][k]: the k-th v-term's coefficient at the i-th Chebyshev node in u.
  std::vector<VTerm> basis;
  std::vector<std::vector<double>> coefficients;
  for (int i = 0; i <= Du; ++i) {
    const double u = 0.5 + 0.5 * std::cos(M_PI * (i + 0.5) / (Du + 1));
    const VExpansion e = asExpansion(f, u);
    const VExpansion approx = periodic ? fourierSeries(e, v0, v1, N) : chebyshevInterpolant(e, v0, v1, std::min(N, 20));
    if (basis.empty()) basis = approx;
    std::vector<double> c;
    for (const VTerm& t : approx) c.push_back(t.coef);
    coefficients.push_back(c);
  }
  std::vector<ForceTerm> out;
  for (size_t k = 0; k < basis.size(); ++k) {
    // Chebyshev coefficients in s = 2u - 1, then powers of s, then powers of u.
    std::vector<double> values(Du + 1);
    for (int i = 0; i <= Du; ++i) values[i] = coefficients[i][k];
    const std::vector<double> inS = chebyshevToPowers(chebyshevCoefficients(values));
    std::vector<double> inU(Du + 1, 0.0);  // (2u - 1)^d expanded
    for (int d = 0; d <= Du; ++d) {
      double binom = 1.0;
      for (int j = 0; j <= d; ++j) {
        inU[j] += inS[d] * binom * std::pow(2.0, j) * ((d - j) % 2 ? -1.0 : 1.0);
        binom = binom * (d - j) / (j + 1);
      }
    }
    out.push_back({basis[k].g, inU});
  }
  return out;
}

PdeProblem familyProblem(const PdeProblem& p) {
  PdeProblem q = mapSlots(p, familyPart);
  for (auto& c : q.component) c.generalForce.clear();
  return q;
}

namespace {

// Two values of a boundary function at v0 and v1 that are one value (to 1e-9 of their size).
bool sameValue(double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(1.0, std::max(std::abs(a), std::abs(b))); }

bool sameAtEnds(const VExpansion& f, double v0, double v1, int k = 0) {
  return sameValue(expansionValue(f, v0, k), expansionValue(f, v1, k));
}

}  // namespace

bool isPeriodic(const VExpansion& f, double v0, double v1) {
  for (int k = 0; k <= 2; ++k)
    if (!sameAtEnds(f, v0, v1, k)) return false;
  return true;
}

bool hasSeamCorner(const PdeProblem& p) {
  bool corner = false;
  for (const auto& c : p.component)
    for (const auto* side : {&c.left, &c.right})
      for (const VExpansion& slot : *side) {
        if (!sameAtEnds(slot, p.v0, p.v1)) return false;
        corner = corner || !isPeriodic(slot, p.v0, p.v1);
      }
  return corner;
}

bool familyTermsClose(const PdeProblem& p) {
  for (const auto& c : p.component)
    for (const auto* side : {&c.left, &c.right})
      for (const VExpansion& slot : *side)
        for (const VTerm& t : slot)
          if (!t.g.isGeneral() && !sameAtEnds({t}, p.v0, p.v1)) return false;
  return true;
}

PdeProblem mapSlots(const PdeProblem& p, const std::function<VExpansion(const VExpansion&)>& map) {
  static const char* axis[3] = {"x", "y", "z"};
  PdeProblem out = p;
  for (int c = 0; c < 3; ++c) {
    try {
      for (auto& slot : out.component[c].left) slot = map(slot);
      for (auto& slot : out.component[c].right) slot = map(slot);
    } catch (const Error& e) {
      throw Error(e.code(), std::string("component ") + axis[c] + ": " + e.what());
    }
  }
  return out;
}

VExpansion generalPart(const VExpansion& slot) {
  VExpansion out;
  for (const VTerm& t : slot)
    if (t.g.isGeneral()) out.push_back(t);
  return out;
}

VExpansion familyPart(const VExpansion& slot) {
  VExpansion out;
  for (const VTerm& t : slot)
    if (!t.g.isGeneral()) out.push_back(t);
  return out;
}

bool hasGeneralTerms(const PdeProblem& p) {
  for (const auto& c : p.component) {
    for (const auto& slot : c.left)
      if (!generalPart(slot).empty()) return true;
    for (const auto& slot : c.right)
      if (!generalPart(slot).empty()) return true;
    if (!c.generalForce.empty()) return true;
  }
  return false;
}

}  // namespace pdesurf

namespace pdesurf {

bool restoreFamilies(const PdeProblem& p, PdeProblem* out) {
  bool complete = true;
  *out = mapSlots(p, [&](const VExpansion& slot) {
    VExpansion r;
    for (VTerm t : slot) {
      if (t.g.isGeneral()) {
        if (t.g.general->hasOrigin) t.g = t.g.general->origin;
        else complete = false;
      }
      r.push_back(t);
    }
    return r;
  });
  for (const auto& c : p.component) complete = complete && c.generalForce.empty();
  return complete;
}

}  // namespace pdesurf
