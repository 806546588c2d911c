#include "basis/vfunction.hpp"

#include <cmath>
#include <cstdio>

#include "basis/general_function.hpp"
#include "bezier/bernstein.hpp"

namespace pdesurf {

void VFunction::evalMany(const double* v, size_t n, int k, double* out) const {
  if (family == Family::General) return general->evalMany(v, n, k, out);
  for (size_t i = 0; i < n; ++i) out[i] = eval(v[i], k);
}

void VFunction::evalUpTo(double v, int maxK, double* out) const {
  if (family != Family::Cos && family != Family::Sin) {
    for (int k = 0; k <= maxK; ++k) out[k] = eval(v, k);
    return;
  }
  // One cosine and one sine for every order (what eval would compute, term for term).
  const double a = w * v;
  trigUpTo(std::cos(a), std::sin(a), maxK, out);
}

void VFunction::trigUpTo(double c, double sn, int maxK, double* out) const {
  double wk = 1.0;
  for (int k = 0; k <= maxK; ++k) {
    if (k >= 3) wk = std::pow(w, k);
    const int turn = (k + (family == Family::Sin ? 3 : 0)) % 4;
    out[k] = turn == 0 ? wk * c : turn == 1 ? -wk * sn : turn == 2 ? -wk * c : wk * sn;
    if (k < 2) wk = k == 0 ? w : w * w;
  }
}

double VFunction::eval(double v, int k) const {
  if (family == Family::General) return general->eval(v, k);
  if (family == Family::Bernstein) return bernsteinBasis(degree, n, v, k);
  if (family == Family::Poly) {
    if (k > n) return 0.0;
    const double s = (v - c) * w;
    double factor = 1.0, power = 1.0;
    for (int i = 0; i < k; ++i) factor *= (n - i) * w;
    for (int i = 0; i < n - k; ++i) power *= s;
    return factor * power;
  }
  const double a = w * v;
  const double wk = k == 0 ? 1.0 : k == 1 ? w : k == 2 ? w * w : std::pow(w, k);  // the same numbers, no pow for the orders a grid needs
  switch (family) {
    case Family::Cos:
    case Family::Sin: {
      // Each derivative is a quarter turn: cos -> -sin -> -cos -> sin; sin starts one turn later.
      const int turn = (k + (family == Family::Sin ? 3 : 0)) % 4;
      switch (turn) {
        case 0: return wk * std::cos(a);
        case 1: return -wk * std::sin(a);
        case 2: return -wk * std::cos(a);
        default: return wk * std::sin(a);
      }
    }
    case Family::Exp: return wk * std::exp(a);
    case Family::Cosh: return wk * (k % 2 == 0 ? std::cosh(a) : std::sinh(a));
    case Family::Sinh: return wk * (k % 2 == 0 ? std::sinh(a) : std::cosh(a));
    case Family::Poly:
    case Family::General:
    case Family::Bernstein: break;
  }
  return 0.0;
}

std::string describeFunction(const VFunction& g) {
  if (g.isGeneral()) return g.general->text();
  char buf[64];
  if (g.family == Family::Bernstein) {
    std::snprintf(buf, sizeof buf, "B_%d^%d(v)", g.n, g.degree);
    return buf;
  }
  if (g.isPoly()) {
    if (g.c == 0 && g.w == 1) std::snprintf(buf, sizeof buf, "v^%d", g.n);
    else std::snprintf(buf, sizeof buf, "((v - %g)*%g)^%d", g.c, g.w, g.n);
  } else {
    std::snprintf(buf, sizeof buf, "%s(%g*v)", familyName(g.family), g.w);
  }
  return buf;
}

const char* familyName(Family f) {
  switch (f) {
    case Family::Poly: return "poly";
    case Family::Cos: return "cos";
    case Family::Sin: return "sin";
    case Family::Exp: return "exp";
    case Family::Cosh: return "cosh";
    case Family::Sinh: return "sinh";
    case Family::General: return "expr";
    case Family::Bernstein: return "bernstein";
  }
  return "?";
}

bool familyFromName(const std::string& name, Family* out) {
  static const Family all[] = {Family::Poly, Family::Cos, Family::Sin, Family::Exp, Family::Cosh, Family::Sinh, Family::General};
  for (Family f : all)
    if (name == familyName(f)) {
      *out = f;
      return true;
    }
  return false;
}

}  // namespace pdesurf
