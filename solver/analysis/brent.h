// Brent's methods (Algorithms for Minimization without Derivatives, 1973, chapters 4 and 5):
// a zero of a function bracketed by a sign change, and a minimum of a function on an interval,
// both by inverse interpolation safeguarded by bisection or golden section. Used to place the
// extremes of a curve between its samples with the solver's exact values.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

namespace linkage::brent {

// A zero of f in [a, b], where fa = f(a) and fb = f(b) do not have the same sign; to within
// tol + 4 eps |x|.
template <class F>
double zero(F f, double a, double b, double fa, double fb, double tol) {
  const double eps = std::numeric_limits<double>::epsilon();
  auto opposite = [](double u, double v) { return (u > 0 && v < 0) || (u < 0 && v > 0); };
  double c = a, fc = fa, d = b - a, e = d;
  for (int iter = 0; iter < 200; ++iter) {
    if (!opposite(fb, fc) && fb != 0) {
      c = a;
      fc = fa;
      d = e = b - a;
    }
    if (std::abs(fc) < std::abs(fb)) {  // b the best so far, a the previous b
      std::tie(a, b, c) = std::make_tuple(b, c, b);
      std::tie(fa, fb, fc) = std::make_tuple(fb, fc, fb);
    }
    const double tol1 = 2 * eps * std::abs(b) + 0.5 * tol;
    const double xm = 0.5 * (c - b);
    if (std::abs(xm) <= tol1 || fb == 0) return b;
    if (std::abs(e) >= tol1 && std::abs(fa) > std::abs(fb)) {
      const double s = fb / fa;
      double p, q;
      if (a == c) {  // secant
        p = 2 * xm * s;
        q = 1 - s;
      } else {  // inverse quadratic interpolation
        const double qa = fa / fc, r = fb / fc;
        p = s * (2 * xm * qa * (qa - r) - (b - a) * (r - 1));
        q = (qa - 1) * (r - 1) * (s - 1);
      }
      if (p > 0)
        q = -q;
      else
        p = -p;
      if (2 * p < std::min(3 * xm * q - std::abs(tol1 * q), std::abs(e * q))) {
        e = d;
        d = p / q;
      } else {
        d = e = xm;
      }
    } else {
      d = e = xm;
    }
    a = b;
    fa = fb;
    b += std::abs(d) > tol1 ? d : std::copysign(tol1, xm);
    fb = f(b);
  }
  return b;
}

// A minimum of f on [a, b] (a local one if f has several), to within tol + sqrt(eps) |x|;
// *fmin receives f there.
template <class F>
double minimum(F f, double a, double b, double tol, double* fmin) {
  const double golden = 0.5 * (3 - std::sqrt(5.0));
  const double sqrtEps = std::sqrt(std::numeric_limits<double>::epsilon());
  double x = a + golden * (b - a), w = x, v = x, d = 0, e = 0;
  double fx = f(x), fw = fx, fv = fx;
  for (int iter = 0; iter < 200; ++iter) {
    const double xm = 0.5 * (a + b);
    const double tol1 = sqrtEps * std::abs(x) + tol / 3, tol2 = 2 * tol1;
    if (std::abs(x - xm) <= tol2 - 0.5 * (b - a)) break;
    bool goldenStep = true;
    if (std::abs(e) > tol1) {  // a parabola through x, w, v
      double r = (x - w) * (fx - fv), q = (x - v) * (fx - fw), p = (x - v) * q - (x - w) * r;
      q = 2 * (q - r);
      if (q > 0)
        p = -p;
      else
        q = -q;
      const double last = e;
      e = d;
      if (std::abs(p) < std::abs(0.5 * q * last) && p > q * (a - x) && p < q * (b - x)) {
        d = p / q;
        const double u = x + d;
        if (u - a < tol2 || b - u < tol2) d = std::copysign(tol1, xm - x);
        goldenStep = false;
      }
    }
    if (goldenStep) {
      e = (x >= xm) ? a - x : b - x;
      d = golden * e;
    }
    const double u = x + (std::abs(d) >= tol1 ? d : std::copysign(tol1, d));
    const double fu = f(u);
    if (fu <= fx) {
      (u >= x ? a : b) = x;
      std::tie(v, fv, w, fw, x, fx) = std::make_tuple(w, fw, x, fx, u, fu);
    } else {
      (u < x ? a : b) = u;
      if (fu <= fw || w == x) {
        v = w;
        fv = fw;
        w = u;
        fw = fu;
      } else if (fu <= fv || v == x || v == w) {
        v = u;
        fv = fu;
      }
    }
  }
  *fmin = fx;
  return x;
}

}  // namespace linkage::brent
