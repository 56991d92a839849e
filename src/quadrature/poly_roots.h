// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Real roots of a polynomial of low degree in an interval, isolated
// between the roots of its derivative (found the same way, down to the
// quadratic, solved in closed form), so that every sign change in the
// interval is found but for pairs of nearly double roots. A root of even
// multiplicity (the polynomial touches zero without changing sign) is not
// a sign change.

#ifndef BRDFBAKE_SRC_QUADRATURE_POLY_ROOTS_H_
#define BRDFBAKE_SRC_QUADRATURE_POLY_ROOTS_H_

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace brdfbake {

inline constexpr int kMaxPolyDegree = 4;

// c[0] + c[1] t + ... + c[n] t^n by Horner's rule.
inline double PolyAt(const double* c, int n, double t) {
  double v = c[n];
  for (int k = n - 1; k >= 0; --k) v = v * t + c[k];
  return v;
}

// The search for the root of c in [a, b] (n >= 1), where c(a) = pa and
// c(b) have opposite signs, to within tol: Newton steps (quadratic near a
// simple root) kept inside the bracket, which each step shrinks;
// bisection where a Newton step would leave it or shrink it too little.
// Step() takes one step and returns false once x is the root.
struct RootBracket {
  double a, b, pa, tol, x;
  int it = 0;

  RootBracket(double a_, double b_, double pa_, double tol_)
      : a(a_), b(b_), pa(pa_), tol(tol_), x(0.5 * (a_ + b_)) {}

  bool Step(const double* c, int n) {
    if (!(it < 100 && b - a > tol)) return false;
    ++it;
    double v = c[n], dv = 0;
    for (int k = n - 1; k >= 0; --k) {
      dv = dv * x + v;
      v = v * x + c[k];
    }
    if (v == 0) return false;
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
    if (std::abs(step) <= 0.5 * tol) {
      x = std::clamp(x - step, a, b);
      return false;
    }
    const double newton = x - step;
    const bool inside = newton > a && newton < b;
    x = inside ? newton : 0.5 * (a + b);
    return true;
  }
};

inline double PolyRootBracketed(const double* c, int n, double a, double b, double pa, double tol) {
  RootBracket r(a, b, pa, tol);
  while (r.Step(c, n)) {
  }
  return r.x;
}

// The roots in (lo, hi) of c[0] + c[1] t + c[2] t^2 with n <= 2 (its
// degree, leading coefficient non-zero), ascending; returns their count.
inline int PolyRootsLowDegree(const double* c, int n, double lo, double hi, double* roots) {
  if (n <= 0) return 0;
  if (n == 1) {
    const double r = -c[0] / c[1];
    if (!(r > lo && r < hi)) return 0;
    roots[0] = r;
    return 1;
  }
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

// The tolerance to which PolyRootsIn finds the derivative's roots, which
// only isolate the polynomial's.
inline double IsolationTol(double tol, double lo, double hi) {
  return std::max(tol, 1e-7 * (hi - lo));
}

// The roots in (lo, hi) where c[0] + ... + c[n] t^n (n <= kMaxPolyDegree)
// changes sign, ascending, each to within `tol`; returns their count. The
// derivative's roots only isolate them and are found to
// max(tol, 1e-7 (hi - lo)): two roots closer than about that (a nearly
// double root) may be missed.
inline int PolyRootsIn(const double* c, int n, double lo, double hi, double tol, double* roots) {
  while (n > 0 && c[n] == 0) --n;
  if (n <= 2) return PolyRootsLowDegree(c, n, lo, hi, roots);
  double ends[kMaxPolyDegree + 1];
  double derivative[kMaxPolyDegree];
  for (int k = 0; k < n; ++k) derivative[k] = (k + 1) * c[k + 1];
  int count = 0;
  ends[count++] = lo;
  count += PolyRootsIn(derivative, n - 1, lo, hi, IsolationTol(tol, lo, hi), ends + 1);
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

// A bracket to search (RootBracket) on the polynomial c[0..n] (3 <= n <=
// kMaxPolyDegree), its root to be stored at *out.
struct RootTask {
  RootBracket r;
  const double* c;
  int n;
  double* out;
};

// Searches tasks[0..m) to their ends, a step of each in turn, so that
// their dependency chains (a Horner loop and a division per step) overlap
// instead of running one after the other: each root is the one
// PolyRootBracketed gives, bit for bit.
struct InterleavedRootSearch {
  void operator()(RootTask* tasks, int m) const {
    thread_local std::vector<int> active;
    active.resize(m);
    for (int t = 0; t < m; ++t) active[t] = t;
    int left = m;
    while (left > 0) {
      int kept = 0;
      for (int k = 0; k < left; ++k) {
        RootTask& t = tasks[active[k]];
        if (t.r.Step(t.c, t.n)) {
          active[kept++] = active[k];
        } else {
          *t.out = t.r.x;
        }
      }
      left = kept;
    }
  }
};

// One polynomial for PolyRootsInBatch: c[0..n] on (lo, hi) to tol, and
// its roots there (at most kMaxPolyDegree).
struct PolyRootsProblem {
  double c[kMaxPolyDegree + 1];
  int n;
  double lo, hi, tol;
  int count;
  double roots[kMaxPolyDegree];
};

// PolyRootsIn for each of m problems: the same isolation by the
// derivatives' roots, level by level, with the brackets of all the
// problems at a level searched together by `search` (RootTask). With
// InterleavedRootSearch the results are PolyRootsIn's bit for bit; a search
// in SIMD lanes (lanes/ellipsoid_lanes.cc) gives each root to the same
// tolerance.
template <class Search = InterleavedRootSearch>
void PolyRootsInBatch(PolyRootsProblem* problems, int m, const Search& search = Search()) {
  // Per problem its chain of derivatives as PolyRootsIn recurses: level 0
  // the polynomial, each next one the derivative of the last, down to a
  // degree of at most 2 (closed form).
  struct Level {
    double c[kMaxPolyDegree + 1];
    int n;
    double tol;
    int count;
    double roots[kMaxPolyDegree];
  };
  struct Chain {
    Level level[kMaxPolyDegree];
    int depth;
  };
  thread_local std::vector<Chain> chains;
  thread_local std::vector<RootTask> tasks;
  chains.resize(m);
  int height = 0;
  for (int p = 0; p < m; ++p) {
    const PolyRootsProblem& q = problems[p];
    Chain& ch = chains[p];
    Level* l = &ch.level[0];
    std::copy(q.c, q.c + q.n + 1, l->c);
    l->n = q.n;
    l->tol = q.tol;
    ch.depth = 1;
    for (;;) {
      while (l->n > 0 && l->c[l->n] == 0) --l->n;
      if (l->n <= 2) break;
      Level* next = l + 1;
      for (int k = 0; k < l->n; ++k) next->c[k] = (k + 1) * l->c[k + 1];
      next->n = l->n - 1;
      next->tol = IsolationTol(l->tol, q.lo, q.hi);
      l = next;
      ++ch.depth;
    }
    l->count = PolyRootsLowDegree(l->c, l->n, q.lo, q.hi, l->roots);
    height = std::max(height, ch.depth);
  }
  // Upwards from the closed forms, one level of every chain at a time.
  for (int h = 1; h < height; ++h) {
    tasks.clear();
    for (int p = 0; p < m; ++p) {
      Chain& ch = chains[p];
      const int i = ch.depth - 1 - h;
      if (i < 0) continue;
      Level& l = ch.level[i];
      const Level& below = ch.level[i + 1];
      double ends[kMaxPolyDegree + 1];
      int count = 0;
      ends[count++] = problems[p].lo;
      for (int k = 0; k < below.count; ++k) ends[count++] = below.roots[k];
      ends[count++] = problems[p].hi;
      l.count = 0;
      for (int k = 0; k + 1 < count; ++k) {
        const double a = ends[k], b = ends[k + 1];
        const double pa = PolyAt(l.c, l.n, a), pb = PolyAt(l.c, l.n, b);
        if (pa == 0 || pb == 0 || (pa > 0) == (pb > 0)) continue;
        tasks.push_back({RootBracket(a, b, pa, l.tol), l.c, l.n, &l.roots[l.count++]});
      }
    }
    search(tasks.data(), static_cast<int>(tasks.size()));
  }
  for (int p = 0; p < m; ++p) {
    const Level& top = chains[p].level[0];
    problems[p].count = top.count;
    std::copy(top.roots, top.roots + top.count, problems[p].roots);
  }
}

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_QUADRATURE_POLY_ROOTS_H_
