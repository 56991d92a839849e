// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0

#include "quadrature/adaptive_rule.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace brdfbake {
namespace {

// WrapAngle is std::remainder(d, 2 pi) bit for bit, on its short path
// (|d| < 2.5 pi, the differences of two angles) and beyond it.
TEST(AdaptiveRuleTest, WrapAngleIsTheRemainderModuloTwoPi) {
  constexpr double kTwoPi = 2 * kPi<double>;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-4 * kPi<double>, 4 * kPi<double>);
  for (int i = 0; i < 200000; ++i) {
    const double d = u(rng);
    ASSERT_EQ(WrapAngle(d), std::remainder(d, kTwoPi)) << d;
  }
  for (double d : {0.0, kPi<double>, -kPi<double>, std::nextafter(kPi<double>, 4.0),
                   std::nextafter(-kPi<double>, -4.0), 2.5 * kPi<double>, kTwoPi, -kTwoPi,
                   3 * kPi<double>, 1e3}) {
    EXPECT_EQ(WrapAngle(d), std::remainder(d, kTwoPi)) << d;
  }
}

}  // namespace
}  // namespace brdfbake
