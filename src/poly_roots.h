// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Real roots of a polynomial of low degree in an interval, isolated
// between the roots of its derivative (found the same way, down to the
// quadratic, solved in closed form), so that every sign change in the
// interval is found but for pairs of nearly double roots. A root of even
// multiplicity (the polynomial touches zero without changing sign) is not
// a sign change.

#ifndef BRDFBAKE_SRC_POLY_ROOTS_H_
#define BRDFBAKE_SRC_POLY_ROOTS_H_

#include <algorithm>
#include <cmath>
#include <utility>

namespace brdfbake {

inline constexpr int kMaxPolyDegree = 4;

// c[0] + c[1] t + ... + c[n] t^n by Horner's rule.
inline double PolyAt(const double* c, int n, double t) {
  double v = c[n];
  for (int k = n - 1; k >= 0; --k) v = v * t + c[k];
  return v;
}

// The root of c in [a, b] (n >= 1), where c(a) = pa and c(b) = pb have
// opposite signs, to within tol: Newton steps (quadratic near a simple
// root) kept inside the bracket, which each step shrinks; bisection where
// a Newton step would leave it or shrink it too little.
inline double PolyRootBracketed(const double* c, int n, double a, double b, double pa, double tol) {
  double x = 0.5 * (a + b);
  for (int it = 0; it < 100 && b - a > tol; ++it) {
    double v = c[n], dv = 0;
    for (int k = n - 1; k >= 0; --k) {
      dv = dv * x + v;
      v = v * x + c[k];
    }
    if (v == 0) return x;
    if ((v > 0) == (pa > 0)) {
      a = x;
    } else {
      b = x;
    }
    const double step = v / dv;
    // A converged Newton step: the root is within |step| of x. (Tested
    // before the bracket: once x is within rounding of the root, v's sign
    // is noise and x - step can fall just outside [a, b], which used to
    // send the loop through ~40 bisections instead.)
    if (std::abs(step) <= 0.5 * tol) return std::clamp(x - step, a, b);
    const double newton = x - step;
    const bool inside = newton > a && newton < b;
    x = inside ? newton : 0.5 * (a + b);
  }
  return x;
}

// The roots in (lo, hi) where c[0] + ... + c[n] t^n (n <= kMaxPolyDegree)
// changes sign, ascending, each to within `tol`; returns their count. The
// derivative's roots only isolate them and are found to
// max(tol, 1e-7 (hi - lo)): two roots closer than about that (a nearly
// double root) may be missed.
inline int PolyRootsIn(const double* c, int n, double lo, double hi, double tol, double* roots) {
  while (n > 0 && c[n] == 0) --n;
  if (n <= 0) return 0;
  if (n == 1) {
    const double r = -c[0] / c[1];
    if (!(r > lo && r < hi)) return 0;
    roots[0] = r;
    return 1;
  }
  if (n == 2) {
    // Without cancellation: q = -(c1 + sign(c1) sqrt(disc)) / 2, roots q / c2
    // and c0 / q. A double root (disc = 0) is no sign change.
    const double disc = c[1] * c[1] - 4 * c[0] * c[2];
    if (!(disc > 0)) return 0;
    const double q = -0.5 * (c[1] + std::copysign(std::sqrt(disc), c[1]));
    double r1 = q / c[2], r2 = c[0] / q;  // q != 0: disc > 0
    if (r1 > r2) std::swap(r1, r2);
    int m = 0;
    for (double r : {r1, r2}) {
      if (r > lo && r < hi) roots[m++] = r;
    }
    return m;
  }
  double ends[kMaxPolyDegree + 1];
  double derivative[kMaxPolyDegree];
  for (int k = 0; k < n; ++k) derivative[k] = (k + 1) * c[k + 1];
  int count = 0;
  ends[count++] = lo;
  count += PolyRootsIn(derivative, n - 1, lo, hi, std::max(tol, 1e-7 * (hi - lo)), ends + 1);
  ends[count++] = hi;
  int found = 0;
  for (int i = 0; i + 1 < count; ++i) {
    const double a = ends[i], b = ends[i + 1];
    const double pa = PolyAt(c, n, a), pb = PolyAt(c, n, b);
    if (pa == 0 || pb == 0 || (pa > 0) == (pb > 0)) continue;
    roots[found++] = PolyRootBracketed(c, n, a, b, pa, tol);
  }
  return found;
}

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_POLY_ROOTS_H_
