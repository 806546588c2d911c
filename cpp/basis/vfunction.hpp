// The boundary-function families of seed 000 Eqs. 6-8: v^n, cos(wv), sin(wv), exp(wv),
// cosh(wv), sinh(wv). The trigonometric and exponential ones are eigenfunctions of d²/dv²
// (g'' = sigma g), which turns the PDE into one ODE in u per term.
#pragma once
#include <memory>
#include <string>

namespace pdesurf {

class GeneralFunction;

// General: any other function of v, typed as an expression (basis/general_function.hpp);
// only the general methods (pseudo-Navier, modal, …) take it.
// Bernstein: B_n^degree(v) on [0, 1], the v-factor of a Bézier patch (seed 002); made only by
// bezierToSeparable, never typed in a scene.
enum class Family { Poly, Cos, Sin, Exp, Cosh, Sinh, General, Bernstein };

struct VFunction {
  Family family = Family::Poly;
  double w = 1.0;  // frequency; for Poly the scale of ((v - c) w)^n
  int n = 0;       // power (Poly only)
  double c = 0.0;  // centre (Poly only): the general methods use scaled powers for conditioning
  int degree = 0;  // Bernstein only: B_n^degree
  std::shared_ptr<const GeneralFunction> general;  // General only

  bool isPoly() const { return family == Family::Poly; }
  bool isGeneral() const { return family == Family::General; }
  // sigma with g'' = sigma g; only meaningful when !isPoly().
  double sigma() const { return (family == Family::Cos || family == Family::Sin) ? -w * w : w * w; }
  // The k-th derivative d^k g / dv^k at v.
  double eval(double v, int k = 0) const;
  // out[k] = d^k g / dv^k at v for k = 0..maxK (a cosine or sine computed once for all).
  void evalUpTo(double v, int maxK, double* out) const;
  // Cos and Sin only: the same from c = cos(w v) and sn = sin(w v) already computed (a grid
  // shares them between the coordinates and between a cosine and a sine of one frequency).
  void trigUpTo(double c, double sn, int maxK, double* out) const;
  // The same at v[0..n) into out (a general function's compiled program runs once over all).
  void evalMany(const double* v, size_t n, int k, double* out) const;
  bool operator==(const VFunction& o) const {
    return family == o.family && w == o.w && n == o.n && c == o.c && degree == o.degree && general == o.general;
  }
};

const char* familyName(Family f);
// For messages: "cos(3*v)", "v^2", or a general function's own text.
std::string describeFunction(const VFunction& g);
bool familyFromName(const std::string& name, Family* out);

}  // namespace pdesurf
