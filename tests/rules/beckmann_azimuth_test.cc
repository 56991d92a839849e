// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Beckmann's E with the azimuth in closed form (src/rules/beckmann/beckmann_azimuth.h):
// - the moments M_0, M_1, M_2 against 50-digit values of their Bessel
//   forms (Boost.Math cyl_bessel_i in cpp_bin_float_50, independent of the
//   code's series and asymptotic expansion) for x in [0, 1e6], and beyond
//   1e6, where the Bessel functions are too slow in 50 digits, against the
//   asymptotic expansion summed to convergence in 50 digits (a check of the
//   tables and the truncation); the scalar reference and the lanes, on
//   every compiled target;
// - E(mu) by the closed form against the numerical azimuthal rule of
//   azimuthal_slope.h (an independent integration of the same integrand
//   over phi), both maskings, alpha from 1e-4 to 1;
// - the lanes' E against the scalar reference texel by texel.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#ifndef BRDFBAKE_TESTS_BECKMANN_AZIMUTH_TEST_REF_
#define BRDFBAKE_TESTS_BECKMANN_AZIMUTH_TEST_REF_

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/bessel.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>

#include "lanes/slope_lanes.h"
#include "reference/ref_util.h"
#include "rules/beckmann/beckmann_azimuth.h"
#include "rules/slope/azimuthal_slope.h"

namespace brdfbake {
namespace beckmann_azimuth_test {

using Big = boost::multiprecision::cpp_bin_float_50;
using test::AbsErr;
using test::Ref;
using test::ToRef;

struct MomentRefs {
  Ref m[3];
};

// M_0 = pi e^-y I0(y), M_1 = (pi/2) e^-y (I0 - I1), M_2 = (pi/4) e^-y
// (2 I0 - 2 I1 - I1 / y), y = x / 2 (x <= 1e6), and the asymptotic
// expansion Gamma(k + 1/2) x^(-k-1/2) sum (k + 1/2)_n (1/2)_n / n! x^-n to
// 50 digits beyond.
inline MomentRefs MomentRef(double x) {
  const Big pi = boost::math::constants::pi<Big>();
  MomentRefs r;
  if (x == 0) {
    r.m[0] = ToRef(pi);
    r.m[1] = ToRef(pi / 2);
    r.m[2] = ToRef(3 * pi / 8);
    return r;
  }
  if (x <= 1e6) {
    const Big y = Big(x) / 2;
    const Big i0 = boost::math::cyl_bessel_i(0, y), i1 = boost::math::cyl_bessel_i(1, y);
    const Big e = exp(-y);
    r.m[0] = ToRef(pi * e * i0);
    r.m[1] = ToRef(pi / 2 * e * (i0 - i1));
    r.m[2] = ToRef(pi / 4 * e * (2 * i0 - 2 * i1 - i1 / y));
    return r;
  }
  const Big bx(x), root_pi = sqrt(pi);
  const Big gamma[3] = {root_pi, root_pi / 2, 3 * root_pi / 4};
  for (int k = 0; k < 3; ++k) {
    Big term = 1, sum = 0;
    for (int n = 0; n < 200 && term > Big(1e-55) * sum; ++n) {
      sum += term;
      term *= (k + Big(0.5) + n) * (n + Big(0.5)) / ((n + 1) * bx);
    }
    r.m[k] = ToRef(gamma[k] * pow(bx, -(k + Big(0.5))) * sum);
  }
  return r;
}

// Log-uniform over [1e-6, 1e12] with random low bits, uniform around the
// switch at 40 and its term-count steps, and the edges.
inline const std::vector<double>& MomentArgs() {
  static const std::vector<double> args = [] {
    std::vector<double> v = {0.0, 1e-300, 1e-12, 39.999999999999993, 40.0, 49.999999999999993,
                             50.0, 80.0, 200.0, 1000.0, 1e5, 1e6, 1.0000000000000002e6, 1e12,
                             1e20, 1e300};
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < 600; ++i) v.push_back(std::pow(10.0, -6.0 + 10.0 * (i + u(rng)) / 600));
    for (int i = 0; i < 40; ++i) v.push_back(std::pow(10.0, 4.0 + 8.0 * (i + u(rng)) / 40));
    for (int i = 0; i < 300; ++i) v.push_back(30.0 + 30.0 * (i + u(rng)) / 300);
    return v;
  }();
  return args;
}

inline const std::vector<MomentRefs>& MomentRefTable() {
  static const std::vector<MomentRefs> refs = [] {
    std::vector<MomentRefs> r;
    for (double x : MomentArgs()) r.push_back(MomentRef(x));
    return r;
  }();
  return refs;
}

// The documented bound (src/rules/beckmann/beckmann_azimuth.h): relative error <= 2e-15.
constexpr double kMomentRel = 2e-15;

}  // namespace beckmann_azimuth_test
}  // namespace brdfbake

#endif  // BRDFBAKE_TESTS_BECKMANN_AZIMUTH_TEST_REF_

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "tests/rules/beckmann_azimuth_test.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>
#include <hwy/tests/hwy_gtest.h>

#include "lanes/beckmann_azimuth_f64-inl.h"

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;
namespace {

using beckmann_azimuth_test::AbsErr;
using beckmann_azimuth_test::kMomentRel;

// The lanes and the scalar reference against the 50-digit values, and
// against each other.
void CheckMoments() {
  const std::vector<double>& xs = beckmann_azimuth_test::MomentArgs();
  const auto& refs = beckmann_azimuth_test::MomentRefTable();
  const hn::ScalableTag<double> d;
  const size_t N = hn::Lanes(d);
  std::vector<double> in(xs), out[3];
  in.resize((xs.size() + N - 1) / N * N, 1.0);
  for (auto& o : out) o.resize(in.size());
  for (size_t i = 0; i < in.size(); i += N) {
    hn::Vec<decltype(d)> m[3];
    BeckmannAzimuthMomentsF64(d, hn::LoadU(d, &in[i]), &m[0], &m[1], &m[2]);
    for (int k = 0; k < 3; ++k) hn::StoreU(m[k], d, &out[k][i]);
  }
  double worst_lane = 0, worst_scalar = 0, worst_x = 0, worst_twin = 0;
  for (size_t i = 0; i < xs.size(); ++i) {
    const BeckmannMoments s = BeckmannAzimuthMoments(xs[i]);
    const double scalar[3] = {s.m0, s.m1, s.m2};
    for (int k = 0; k < 3; ++k) {
      const double ref = refs[i].m[k].hi;
      if (ref == 0) {  // beyond double's range (x = 1e300, k = 2)
        ASSERT_LE(std::abs(out[k][i]), 1e-300);
        continue;
      }
      const double lane = AbsErr(out[k][i], refs[i].m[k]) / ref;
      const double sc = AbsErr(scalar[k], refs[i].m[k]) / ref;
      ASSERT_LE(lane, kMomentRel) << "M_" << k << " x=" << xs[i] << " lanes " << out[k][i]
                                  << " ref " << ref;
      ASSERT_LE(sc, kMomentRel) << "M_" << k << " x=" << xs[i] << " scalar " << scalar[k]
                                << " ref " << ref;
      if (lane > worst_lane) worst_lane = lane, worst_x = xs[i];
      worst_scalar = std::max(worst_scalar, sc);
      worst_twin = std::max(worst_twin, std::abs(out[k][i] - scalar[k]) / ref);
    }
  }
  std::printf("%s: Beckmann azimuthal moments, max rel error: lanes %.3g (at x=%.17g), scalar "
              "%.3g, lanes vs scalar %.3g (bound %.2g, %zu points)\n",
              hwy::TargetName(HWY_TARGET), worst_lane, worst_x, worst_scalar, worst_twin,
              kMomentRel, xs.size());
}

}  // namespace
}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace brdfbake {
HWY_BEFORE_TEST(BeckmannAzimuthMomentsTest);
HWY_EXPORT_AND_TEST_P(BeckmannAzimuthMomentsTest, CheckMoments);

namespace {

// The closed form against the numerical azimuth (azimuthal_slope.h) on a
// grid of alpha and mu, both maskings: the two agree within the sum of
// their claims, and the closed form's claim meets its tolerance.
TEST(BeckmannAzimuthTest, ClosedFormAgreesWithTheNumericalAzimuth) {
  double worst = 0, worst_ratio = 0;
  for (double alpha : {1e-4, 1e-3, 0.01, 0.05, 0.2, 0.5, 0.8, 1.0}) {
    for (double mu : {1e-7, 1e-3, 0.05, 0.3, 0.7, 0.95, 1.0}) {
      for (Masking m : {Masking::kHeightCorrelated, Masking::kSeparable}) {
        const RuleResult a = BeckmannAzimuthalAlbedo(alpha, mu, m, 1e-12, 512);
        const AzimuthalDfgResult b =
            SlopeAzimuthalDfg(BeckmannNdf<double>(alpha), mu, m, false, 1e-11, 512);
        ASSERT_LE(a.error, 1e-12) << "alpha " << alpha << " mu " << mu;
        const double diff = std::abs(a.value - b.e);
        ASSERT_LE(diff, a.error + b.err_e) << "alpha " << alpha << " mu " << mu << " closed "
                                           << a.value << " numerical " << b.e;
        ASSERT_LE(a.value, 1 + a.error);
        worst = std::max(worst, diff);
        worst_ratio = std::max(worst_ratio, diff / (a.error + b.err_e));
      }
    }
  }
  std::printf("closed form vs numerical azimuth: max |diff| %.3g, max diff / claims %.3g\n",
              worst, worst_ratio);
}

// The lanes (best target) against the scalar reference at the bake's
// tolerance: the same pieces, and values within the claims' rounding.
TEST(BeckmannAzimuthTest, LanesAgreeWithTheScalarReference) {
  double worst = 0;
  for (double alpha : {1e-4, 2e-3, 0.03, 0.1, 0.3, 0.6, 1.0}) {
    for (int j = 0; j <= 24; ++j) {
      const double mu = j == 0 ? 1e-7 : j / 24.0;
      const RuleResult s =
          BeckmannAzimuthalAlbedo(alpha, mu, Masking::kHeightCorrelated, 1e-7, 512);
      const RuleResult v =
          SimdBeckmannAzimuthalAlbedo(alpha, mu, Masking::kHeightCorrelated, 1e-7, 512);
      ASSERT_EQ(s.pieces, v.pieces) << "alpha " << alpha << " mu " << mu;
      ASSERT_LE(std::abs(s.value - v.value), 1e-13) << "alpha " << alpha << " mu " << mu;
      ASSERT_LE(std::abs(s.error - v.error), 1e-13 + 1e-6 * s.error);
      worst = std::max(worst, std::abs(s.value - v.value));
    }
  }
  std::printf("lanes vs scalar E: max |diff| %.3g\n", worst);
}

}  // namespace
}  // namespace brdfbake
#endif
