// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0

#include "quadrature/poly_roots.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "util/poly_test_util.h"

namespace brdfbake {
namespace {

TEST(PolyRootsTest, FindsEverySignChangeInTheInterval) {
  struct Case {
    std::vector<double> roots;   // of the polynomial
    std::vector<double> inside;  // those in (0, 1), ascending
    double tol = 1e-12;          // their conditioning from rounded coefficients
  };
  const Case cases[] = {
      {{0.3, 0.7, -2, 5}, {0.3, 0.7}},
      // Two roots 1e-5 apart (a ray grazing the clamp's edge) and a third.
      {{0.4, 0.40001, 0.9, 3}, {0.4, 0.40001, 0.9}, 1e-10},
      {{0.1, 0.2, 0.3, 0.95}, {0.1, 0.2, 0.3, 0.95}},
      {{1.5, -0.5, 2, 7}, {}},
      {{0.25, 4}, {0.25}},
      {{0.6}, {0.6}},
      {{0.6, 0.2}, {0.2, 0.6}},
  };
  for (const Case& c : cases) {
    const std::vector<double> p = FromRoots(c.roots);
    for (double scale : {1.0, -3e-9, 2e7}) {
      std::vector<double> q = p;
      for (double& x : q) x *= scale;
      double got[kMaxPolyDegree];
      const int n = PolyRootsIn(q.data(), static_cast<int>(q.size()) - 1, 0.0, 1.0, 1e-15, got);
      ASSERT_EQ(n, static_cast<int>(c.inside.size())) << c.roots[0] << " scale " << scale;
      for (int i = 0; i < n; ++i) EXPECT_NEAR(got[i], c.inside[i], c.tol);
    }
  }
}

// (t - 0.8) ((t - 0.5)^2 + 1e-6) (t + 1): near 0.5 the quartic comes within
// 1e-7 of zero without crossing it.
TEST(PolyRootsTest, NearTouchIsNoRoot) {
  const double q[3] = {0.25 + 1e-6, -1, 1};
  const std::vector<double> l = FromRoots({0.8, -1});
  double c[5] = {0, 0, 0, 0, 0};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) c[i + j] += q[i] * l[j];
  }
  double got[kMaxPolyDegree];
  ASSERT_EQ(PolyRootsIn(c, 4, 0.0, 1.0, 1e-15, got), 1);
  EXPECT_NEAR(got[0], 0.8, 1e-13);
}

TEST(PolyRootsTest, ConstantAndVanishingLeadingTerms) {
  double got[kMaxPolyDegree];
  const double constant[] = {2, 0, 0, 0, 0};
  EXPECT_EQ(PolyRootsIn(constant, 4, 0.0, 1.0, 1e-15, got), 0);
  // A cubic stored as a quartic with a zero leading coefficient.
  std::vector<double> c = FromRoots({0.2, 0.5, 3});
  c.push_back(0);
  ASSERT_EQ(PolyRootsIn(c.data(), 4, 0.0, 1.0, 1e-15, got), 2);
  EXPECT_NEAR(got[0], 0.2, 1e-13);
  EXPECT_NEAR(got[1], 0.5, 1e-13);
}

// The batch gives each problem exactly PolyRootsIn's roots: random
// quartics with 0 to 4 roots in the interval (some nearly double), cubics
// and quadratics stored as quartics, constants, in batches of 1 to 40.
TEST(PolyRootsTest, BatchMatchesOneByOneBitForBit) {
  std::mt19937_64 rng(12);
  int roots_seen = 0;
  for (int batch = 1; batch <= 40; ++batch) {
    std::vector<PolyRootsProblem> problems(batch);
    for (PolyRootsProblem& q : problems) q = RandomRootsProblem(rng, 0);
    PolyRootsInBatch(problems.data(), batch);
    for (const PolyRootsProblem& q : problems) {
      double want[kMaxPolyDegree];
      const int n = PolyRootsIn(q.c, q.n, q.lo, q.hi, q.tol, want);
      ASSERT_EQ(q.count, n);
      for (int k = 0; k < n; ++k) EXPECT_EQ(q.roots[k], want[k]);
      roots_seen += n;
    }
  }
  EXPECT_GT(roots_seen, 200);
}

}  // namespace
}  // namespace brdfbake
