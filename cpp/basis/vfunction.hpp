// The boundary-function families of seed 000 Eqs. 6-8: v^n, cos(wv), sin(wv), exp(wv),
// cosh(wv), sinh(wv). The trigonometric and exponential ones are eigenfunctions of d²/dv²
// (g'' = sigma g), which turns the PDE into one ODE in u per term.
#pragma once
#include <string>

namespace pdesurf {

enum class Family { Poly, Cos, Sin, Exp, Cosh, Sinh };

struct VFunction {
  Family family = Family::Poly;
  double w = 1.0;  // frequency (not used by Poly)
  int n = 0;       // power (Poly only)

  bool isPoly() const { return family == Family::Poly; }
  // sigma with g'' = sigma g; only meaningful when !isPoly().
  double sigma() const { return (family == Family::Cos || family == Family::Sin) ? -w * w : w * w; }
  // The k-th derivative d^k g / dv^k at v.
  double eval(double v, int k = 0) const;
  bool operator==(const VFunction& o) const { return family == o.family && w == o.w && n == o.n; }
};

const char* familyName(Family f);
bool familyFromName(const std::string& name, Family* out);

}  // namespace pdesurf
