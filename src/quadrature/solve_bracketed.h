// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// A root of a function known to change sign on a bracket.

#ifndef BRDFBAKE_SRC_QUADRATURE_SOLVE_BRACKETED_H_
#define BRDFBAKE_SRC_QUADRATURE_SOLVE_BRACKETED_H_

namespace brdfbake {

// A root of g in [lo, hi], where g(lo) = glo and g(hi) = ghi have opposite
// signs, to within `tol` in t. Regula falsi keeps the root bracketed; the
// Illinois modification (halving the stored value at an end that is kept
// twice in a row) stops one end from sticking, which makes the convergence
// superlinear; a bisection step is taken whenever three steps have not
// halved the bracket, so the iteration is never slower than bisection by
// more than a constant factor. Deterministic: a pure function of its input.
template <class G>
double SolveBracketed(const G& g, double lo, double hi, double glo, double ghi, double tol) {
  int kept = 0;  // -1: lo was replaced last, +1: hi was
  int steps = 0;
  double width_before = hi - lo;
  bool bisect = false;
  for (int it = 0; it < 200 && hi - lo > tol; ++it) {
    double c = bisect ? 0.5 * (lo + hi) : (lo * ghi - hi * glo) / (ghi - glo);
    if (!(c > lo && c < hi)) c = 0.5 * (lo + hi);
    if (!(c > lo && c < hi)) break;  // the bracket is down to adjacent doubles
    bisect = false;
    const double gc = g(c);
    if (gc == 0) return c;
    if ((gc > 0) == (glo > 0)) {
      lo = c;
      glo = gc;
      if (kept == -1) ghi *= 0.5;
      kept = -1;
    } else {
      hi = c;
      ghi = gc;
      if (kept == 1) glo *= 0.5;
      kept = 1;
    }
    if (++steps == 3) {
      bisect = hi - lo > 0.5 * width_before;
      width_before = hi - lo;
      steps = 0;
    }
  }
  return 0.5 * (lo + hi);
}

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_QUADRATURE_SOLVE_BRACKETED_H_
