#include "expr/taylor.hpp"

#include "expr/spline.hpp"

#include <cmath>
#include <unordered_map>

namespace pdesurf {

namespace {

using Series = std::vector<double>;
using Op = ExprNode::Op;

Series mul(const Series& a, const Series& b) {
  Series r(a.size(), 0.0);
  for (size_t k = 0; k < a.size(); ++k)
    for (size_t j = 0; j <= k; ++j) r[k] += a[j] * b[k - j];
  return r;
}

Series div(const Series& a, const Series& b) {
  Series q(a.size(), 0.0);
  for (size_t k = 0; k < a.size(); ++k) {
    double s = a[k];
    for (size_t j = 1; j <= k; ++j) s -= b[j] * q[k - j];
    q[k] = s / b[0];
  }
  return q;
}

// y with y' = a' w, y_0 given: y_k = (1/k) Σ_{j=1}^{k} j a_j w_{k-j}.
Series integrate(const Series& a, const Series& w, double y0) {
  Series y(a.size(), 0.0);
  y[0] = y0;
  for (size_t k = 1; k < a.size(); ++k) {
    double s = 0.0;
    for (size_t j = 1; j <= k; ++j) s += j * a[j] * w[k - j];
    y[k] = s / k;
  }
  return y;
}

Series expS(const Series& a) {
  Series e(a.size(), 0.0);
  e[0] = std::exp(a[0]);
  for (size_t k = 1; k < a.size(); ++k) {
    double s = 0.0;
    for (size_t j = 1; j <= k; ++j) s += j * a[j] * e[k - j];
    e[k] = s / k;
  }
  return e;
}

Series logS(const Series& a) {
  Series l(a.size(), 0.0);
  l[0] = std::log(a[0]);
  for (size_t k = 1; k < a.size(); ++k) {
    double s = a[k];
    for (size_t j = 1; j < k; ++j) s -= static_cast<double>(j) / k * l[j] * a[k - j];
    l[k] = s / a[0];
  }
  return l;
}

// sin and cos (or sinh and cosh, sign +1) of a together.
void sinCos(const Series& a, double sign, Series* s, Series* c) {
  const size_t K = a.size();
  s->assign(K, 0.0), c->assign(K, 0.0);
  (*s)[0] = sign > 0 ? std::sinh(a[0]) : std::sin(a[0]);
  (*c)[0] = sign > 0 ? std::cosh(a[0]) : std::cos(a[0]);
  for (size_t k = 1; k < K; ++k) {
    double ss = 0.0, cc = 0.0;
    for (size_t j = 1; j <= k; ++j) ss += j * a[j] * (*c)[k - j], cc += j * a[j] * (*s)[k - j];
    (*s)[k] = ss / k;
    (*c)[k] = sign * cc / k;
  }
}

Series constantS(size_t K, double c) {
  Series r(K, 0.0);
  r[0] = c;
  return r;
}

// a^r for a constant r. A whole r is a product (binary powering; 1/a^|r| for negative r):
// exact where the recurrence below would divide by a base near 0 (cos(v)^2 at v = π/2).
// Otherwise p_k = (1/(k a_0)) Σ_{j=1}^{k} ((r+1) j - k) a_j p_{k-j}, which at a_0 = 0 has no
// finite derivatives (sqrt at 0), as it should.
Series powConst(const Series& a, double r) {
  const size_t K = a.size();
  if (r == std::floor(r) && std::abs(r) <= 1024) {
    Series result = constantS(K, 1.0), base = a;
    for (long n = static_cast<long>(std::abs(r)); n > 0; n >>= 1) {
      if (n & 1) result = mul(result, base);
      if (n > 1) base = mul(base, base);
    }
    return r < 0 ? div(constantS(K, 1.0), result) : result;
  }
  Series p(K, 0.0);
  p[0] = std::pow(a[0], r);
  for (size_t k = 1; k < K; ++k) {
    double s = 0.0;
    for (size_t j = 1; j <= k; ++j) s += ((r + 1) * j - static_cast<double>(k)) * a[j] * p[k - j];
    p[k] = s / (k * a[0]);
  }
  return p;
}

struct Evaluator {
  ExprVar var;
  const double* vars;
  size_t K;
  std::unordered_map<const ExprNode*, Series> memo;

  const Series& at(const ExprNode& e) {
    auto it = memo.find(&e);
    if (it != memo.end()) return it->second;
    Series r = compute(e);
    return memo.emplace(&e, std::move(r)).first->second;
  }

  Series compute(const ExprNode& e) {
    switch (e.op) {
      case Op::Const: return constantS(K, e.value);
      case Op::Var: {
        Series r = constantS(K, vars[static_cast<int>(e.var)]);
        if (e.var == var && K > 1) r[1] = 1.0;
        return r;
      }
      case Op::Neg: {
        Series r = at(*e.a);
        for (double& x : r) x = -x;
        return r;
      }
      case Op::Add:
      case Op::Sub: {
        Series r = at(*e.a);
        const Series& b = at(*e.b);
        const double s = e.op == Op::Add ? 1.0 : -1.0;
        for (size_t k = 0; k < K; ++k) r[k] += s * b[k];
        return r;
      }
      case Op::Mul: return mul(at(*e.a), at(*e.b));
      case Op::Div: return div(at(*e.a), at(*e.b));
      case Op::Pow: {
        const Series& b = at(*e.b);
        bool constExponent = true;
        for (size_t k = 1; k < K; ++k) constExponent = constExponent && b[k] == 0.0;
        if (constExponent) return powConst(at(*e.a), b[0]);
        return expS(mul(b, logS(at(*e.a))));
      }
      case Op::Call: return call(e.fn, at(*e.a));
      case Op::Spline: return splineS(*e.spline, at(*e.a));
    }
    return constantS(K, NAN);
  }

  // f(a_0 + h) = Σ_m f^(m)(a_0)/m! h^m, h = a - a_0: the series of h's powers, term by term.
  Series splineS(const SplineFn& f, const Series& a) {
    Series r = constantS(K, f.eval(a[0])), h = a, hm = constantS(K, 1.0);
    h[0] = 0.0;
    double factorial = 1.0;
    const SplineFn* d = &f;
    for (size_t m = 1; m < K && d->derivative(); ++m) {
      d = d->derivative().get();
      factorial *= double(m);
      hm = mul(hm, h);
      const double c = d->eval(a[0]) / factorial;
      for (size_t k = m; k < K; ++k) r[k] += c * hm[k];
    }
    return r;
  }

  Series call(ExprFn f, const Series& a) {
    Series s, c;
    switch (f) {
      case ExprFn::Sqrt: return powConst(a, 0.5);
      case ExprFn::Exp: return expS(a);
      case ExprFn::Log: return logS(a);
      case ExprFn::Sin: sinCos(a, -1, &s, &c); return s;
      case ExprFn::Cos: sinCos(a, -1, &s, &c); return c;
      case ExprFn::Tan: sinCos(a, -1, &s, &c); return div(s, c);
      case ExprFn::Sinh: sinCos(a, 1, &s, &c); return s;
      case ExprFn::Cosh: sinCos(a, 1, &s, &c); return c;
      case ExprFn::Tanh: sinCos(a, 1, &s, &c); return div(s, c);
      case ExprFn::Asin:
      case ExprFn::Acos: {  // ±a' / sqrt(1 - a²)
        Series one = constantS(K, 1.0), sq = mul(a, a);
        for (size_t k = 0; k < K; ++k) one[k] -= sq[k];
        Series w = powConst(one, -0.5);
        if (f == ExprFn::Acos)
          for (double& x : w) x = -x;
        return integrate(a, w, f == ExprFn::Asin ? std::asin(a[0]) : std::acos(a[0]));
      }
      case ExprFn::Atan: {  // a' / (1 + a²)
        Series one = mul(a, a);
        one[0] += 1.0;
        return integrate(a, div(constantS(K, 1.0), one), std::atan(a[0]));
      }
      case ExprFn::Abs: {  // sign(a) a away from 0; at 0 the derivatives are undefined
        Series r = a;
        const double sg = a[0] > 0 ? 1.0 : a[0] < 0 ? -1.0 : NAN;
        r[0] = std::abs(a[0]);
        for (size_t k = 1; k < K; ++k) r[k] *= sg;
        return r;
      }
      case ExprFn::Sign: return constantS(K, applyFn(ExprFn::Sign, a[0]));  // flat on either side of 0
      case ExprFn::General: return a;
    }
    return constantS(K, NAN);
  }
};

}  // namespace

std::vector<double> taylorCoefficients(const ExprNode& e, ExprVar var, const double* vars, int order) {
  Evaluator ev{var, vars, static_cast<size_t>(order) + 1, {}};
  return ev.at(e);
}

double derivativeAt(const ExprNode& e, ExprVar var, const double* vars, int k) {
  const std::vector<double> c = taylorCoefficients(e, var, vars, k);
  double f = 1.0;
  for (int i = 2; i <= k; ++i) f *= i;
  return c[k] * f;
}

}  // namespace pdesurf
