// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Polynomials with known roots for the root finders' tests
// (poly_roots_test.cc, quadrature_simd_test.cc).

#ifndef BRDFBAKE_TESTS_UTIL_POLY_TEST_UTIL_H_
#define BRDFBAKE_TESTS_UTIL_POLY_TEST_UTIL_H_

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "quadrature/poly_roots.h"

namespace brdfbake {

// Coefficients of prod (t - r_i), lowest degree first.
inline std::vector<double> FromRoots(const std::vector<double>& r) {
  std::vector<double> c = {1};
  for (double x : r) {
    std::vector<double> n(c.size() + 1, 0.0);
    for (size_t k = 0; k < c.size(); ++k) {
      n[k + 1] += c[k];
      n[k] -= x * c[k];
    }
    c = n;
  }
  return c;
}

// A random problem for PolyRootsInBatch: degree 0 to 4 (stored as a
// quartic), roots in (-0.2, 1.2), scaled by -3e-5 or 7e3, on an interval
// near (0, 1), to 1e-12 or 1e-9. Its roots are at least `min_gap` apart,
// or (min_gap 0) a fifth of those of degree 2 and more have a pair 1e-6
// apart or closer.
inline PolyRootsProblem RandomRootsProblem(std::mt19937_64& rng, double min_gap) {
  std::uniform_real_distribution<double> u(-0.2, 1.2);
  std::uniform_int_distribution<int> degree(0, 4);
  const int deg = degree(rng);
  std::vector<double> r;
  while (static_cast<int>(r.size()) < deg) {
    const double x = u(rng);
    bool apart = true;
    for (double y : r) apart = apart && std::abs(x - y) > min_gap;
    if (apart) r.push_back(x);
  }
  if (min_gap == 0 && deg >= 2 && u(rng) < 0.2) r[1] = r[0] + 1e-6 * u(rng);
  const std::vector<double> c = deg == 0 ? std::vector<double>{u(rng) + 2} : FromRoots(r);
  const double scale = u(rng) < 0.5 ? -3e-5 : 7e3;
  PolyRootsProblem q;
  std::fill(q.c, q.c + kMaxPolyDegree + 1, 0.0);
  for (size_t k = 0; k < c.size(); ++k) q.c[k] = scale * c[k];
  q.n = kMaxPolyDegree;
  q.lo = 0.05 * u(rng);
  q.hi = 1 - 0.05 * u(rng);
  q.tol = u(rng) < 0.5 ? 1e-12 : 1e-9;
  return q;
}

}  // namespace brdfbake

#endif  // BRDFBAKE_TESTS_UTIL_POLY_TEST_UTIL_H_
