// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The double-lane kernels of src/kernels/math_f64-inl.h against 50-digit values
// (Boost.Multiprecision cpp_bin_float_50 with Boost.Math erfc) on every
// compiled target (one gtest case per target): exp(-x^2) on [-30, 30] at
// full-mantissa points, and Beckmann's Lambda(a) swept log-uniformly over
// [1e-8, 30], uniformly over [0, 30], at the subnormal and overflow edges,
// and at a = 0, negative a, +-inf and NaN, and against its scalar twin
// BeckmannNdf<double>::UnitLambda; erfcx(a) over [0, 12] and [1e-10,
// 1e150]; exp(x) over [-700, 700] without a range guard; cos(x) over [0,
// pi]. Each check asserts the bound documented
// beside the kernel and prints the observed maximum.

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "brdfbake/models/beckmann.h"

// The 50-digit references, computed once (this part is outside the per-target
// re-inclusion by foreach_target.h).
#ifndef BRDFBAKE_TESTS_SIMD_MATH_F64_TEST_REF_
#define BRDFBAKE_TESTS_SIMD_MATH_F64_TEST_REF_

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/erf.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>

#include "reference/ref_util.h"

namespace brdfbake {
namespace simd_math_f64_test {

using Big = boost::multiprecision::cpp_bin_float_50;

using test::AbsErr;
using test::Ref;
using test::ToRef;

// exp(-x^2) in 50 digits (exact input x).
inline Ref ExpNegSquareRef(double x) {
  const Big bx(x);
  return ToRef(exp(-bx * bx));
}

// Lambda(a) = (exp(-a^2) / (a sqrt(pi)) - erfc(a)) / 2 in 50 digits: the
// difference cancels 2 a^2 of them (3.2 digits at a = 27.5), and
// cpp_bin_float's exponent range holds the values that double rounds to 0
// or to infinity.
inline Ref LambdaRef(double a) {
  if (std::isnan(a)) return {a, 0.0};
  if (!(a > 0)) return {std::numeric_limits<double>::infinity(), 0.0};
  if (std::isinf(a)) return {0.0, 0.0};
  const Big ba(a);
  const Big v = (exp(-ba * ba) / (ba * boost::math::constants::root_pi<Big>()) -
                 boost::math::erfc(ba)) / 2;
  return ToRef(v);
}

// Arguments of Lambda: log-uniform over [1e-8, 30], uniform over [0, 30]
// (both with random low mantissa bits), the edges where 1/den overflows
// (1.39e-309), Lambda overflows (1.57e-309), a is subnormal, Lambda turns
// subnormal (26.6) or rounds to 0 (27.1) or is cut (27.5), and the special
// values.
inline const std::vector<double>& LambdaArgs() {
  static const std::vector<double> args = [] {
    std::vector<double> v;
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> jitter(0.0, 1.0);
    const int kLog = 12000, kUni = 12000;
    for (int i = 0; i <= kLog; ++i) {
      v.push_back(std::pow(10.0, -8.0 + (std::log10(30.0) + 8.0) * (i + jitter(rng)) / kLog));
    }
    for (int i = 0; i <= kUni; ++i) v.push_back(30.0 * (i + jitter(rng)) / kUni);
    const double inf = std::numeric_limits<double>::infinity();
    for (double e : {1e-300, 1e-200, 1e-100, 1e-30, 1e-12, 1e-9, DBL_MIN, 2 * DBL_MIN, 0.5 * DBL_MIN,
                     1.6e-309, 1.58e-309, 1.57e-309, 1.5e-309, 1.4e-309, 1.39e-309, 1e-310,
                     4.9406564584124654e-324, 26.5, 26.6, 26.7, 27.0, 27.1, 27.2, 27.4, 27.5,
                     27.500000000000004, 27.6, 27.675675675675677, 28.0, 1e3, 1e20, 1e154, 1e155,
                     1e300, DBL_MAX, 0.0, -0.0, -1e-300, -1.0, -30.0, -DBL_MAX,
                     inf, -inf, std::numeric_limits<double>::quiet_NaN()}) {
      v.push_back(e);
    }
    for (int i = 0; i < 200; ++i) {  // around x = 0 (a = 3.10), where c - k a cancels
      v.push_back(4.0 / (165.0 / 128.0) * (1 + 1e-3 * (jitter(rng) - 0.5)));
    }
    return v;
  }();
  return args;
}

inline const std::vector<Ref>& LambdaRefs() {
  static const std::vector<Ref> refs = [] {
    std::vector<Ref> r;
    for (double a : LambdaArgs()) r.push_back(LambdaRef(a));
    return r;
  }();
  return refs;
}

// exp(-x^2): x uniform over [-30, 30] with random low bits, plus specials.
inline const std::vector<double>& ExpArgs() {
  static const std::vector<double> args = [] {
    std::vector<double> v;
    std::mt19937_64 rng(9);
    std::uniform_real_distribution<double> jitter(0.0, 1.0);
    const int kN = 60000;
    for (int i = 0; i <= kN; ++i) v.push_back(-30.0 + 60.0 * (i + jitter(rng)) / kN);
    for (double e : {0.0, -0.0, 1e-300, 4.9406564584124654e-324, 1e-8, 1.0, 26.6, 27.29, 27.3,
                     27.31, 28.0, 28.000000000000004, 1e154, 1e155, 1e300, -1e300, DBL_MAX,
                     std::numeric_limits<double>::infinity(),
                     -std::numeric_limits<double>::infinity(),
                     std::numeric_limits<double>::quiet_NaN()}) {
      v.push_back(e);
    }
    return v;
  }();
  return args;
}

inline const std::vector<Ref>& ExpRefs() {
  static const std::vector<Ref> refs = [] {
    std::vector<Ref> r;
    for (double x : ExpArgs()) {
      r.push_back(std::isnan(x) ? Ref{x, 0.0} : std::isinf(x) ? Ref{0.0, 0.0} : ExpNegSquareRef(x));
    }
    return r;
  }();
  return refs;
}

// erfcx(a) = exp(a^2) erfc(a) in 50 digits, a uniform over [0, 12] (the
// visible-slope sampler's range is |x| <= 9) and log-uniform over [1e-10,
// 1e150], with random low bits, plus the branch point 1/2 and 0.
inline const std::vector<double>& ErfcxArgs() {
  static const std::vector<double> args = [] {
    std::vector<double> v;
    std::mt19937_64 rng(13);
    std::uniform_real_distribution<double> jitter(0.0, 1.0);
    const int kN = 20000;
    for (int i = 0; i <= kN; ++i) v.push_back(12.0 * (i + jitter(rng)) / kN);
    for (int i = 0; i <= kN; ++i) v.push_back(std::pow(10.0, -10.0 + 160.0 * (i + jitter(rng)) / kN));
    for (double e : {0.0, 0.5, std::nextafter(0.5, 0.0), 1e-300, 4.0 / (165.0 / 128.0), 1e150}) {
      v.push_back(e);
    }
    return v;
  }();
  return args;
}

inline const std::vector<Ref>& ErfcxRefs() {
  static const std::vector<Ref> refs = [] {
    std::vector<Ref> r;
    for (double a : ErfcxArgs()) {
      const Big ba(a);
      if (a <= 20) {
        r.push_back(ToRef(exp(ba * ba) * boost::math::erfc(ba)));
        continue;
      }
      // Beyond, exp(a^2) erfc(a) leaves the range of Boost's erfc: the
      // continued fraction (A&S 7.1.14) erfcx(a) = 1 / (sqrt(pi) (a + (1/2)
      // / (a + 1 / (a + (3/2) / (a + ...))))), 200 levels (converged to 50
      // digits from a = 5 on).
      Big tail = ba;
      for (int k = 200; k >= 1; --k) tail = ba + Big(k) / 2 / tail;
      r.push_back(ToRef(1 / (boost::math::constants::root_pi<Big>() * tail)));
    }
    return r;
  }();
  return refs;
}

// exp(x): x uniform over [-700, 700] and over [-40, 40] (the sheen
// Lambda's exponents), with random low bits, plus the ends and ties of
// the reduction (x = (k + 1/2) ln 2).
inline const std::vector<double>& ExpUnguardedArgs() {
  static const std::vector<double> args = [] {
    std::vector<double> v;
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> jitter(0.0, 1.0);
    const int kN = 30000;
    for (int i = 0; i <= kN; ++i) v.push_back(-700.0 + 1400.0 * (i + jitter(rng)) / kN);
    for (int i = 0; i <= kN; ++i) v.push_back(-40.0 + 80.0 * (i + jitter(rng)) / kN);
    for (double e : {-700.0, 700.0, 0.0, -0.0, 1e-300, -1e-300, 1e-17}) v.push_back(e);
    for (int k = -20; k <= 20; ++k) v.push_back((k + 0.5) * 0.69314718055994531);
    return v;
  }();
  return args;
}

inline const std::vector<Ref>& ExpUnguardedRefs() {
  static const std::vector<Ref> refs = [] {
    std::vector<Ref> r;
    for (double x : ExpUnguardedArgs()) r.push_back(ToRef(exp(Big(x))));
    return r;
  }();
  return refs;
}

// cos(x): x uniform over [0, pi] with random low bits, within 1e-6 of pi/2
// (where cos vanishes), near 0 and pi, and the ends.
inline const std::vector<double>& CosArgs() {
  static const std::vector<double> args = [] {
    std::vector<double> v;
    std::mt19937_64 rng(19);
    std::uniform_real_distribution<double> jitter(0.0, 1.0);
    const double pi = 3.141592653589793;
    const int kN = 50000;
    for (int i = 0; i < kN; ++i) v.push_back(pi * (i + jitter(rng)) / kN);
    for (int i = 0; i < 5000; ++i) v.push_back(0.5 * pi + 2e-6 * (jitter(rng) - 0.5));
    for (int i = 0; i < 5000; ++i) v.push_back(std::pow(10.0, -12.0 * jitter(rng)));
    for (int i = 0; i < 5000; ++i) v.push_back(pi - std::pow(10.0, -12.0 * jitter(rng)));
    for (double e : {0.0, pi, 0.5 * pi, std::nextafter(0.5 * pi, 0.0), std::nextafter(0.5 * pi, 4.0), 1e-300}) {
      v.push_back(e);
    }
    return v;
  }();
  return args;
}

// sin(t): t uniform over [-pi/2, pi/2] with random low bits, near 0 (both
// signs), and the ends.
inline const std::vector<double>& SinArgs() {
  static const std::vector<double> args = [] {
    std::vector<double> v;
    std::mt19937_64 rng(23);
    std::uniform_real_distribution<double> jitter(0.0, 1.0);
    const double half_pi = 1.5707963267948966;
    const int kN = 50000;
    for (int i = 0; i < kN; ++i) v.push_back(half_pi * (2 * (i + jitter(rng)) / kN - 1));
    for (int i = 0; i < 15000; ++i) v.push_back((i % 2 ? -1 : 1) * std::pow(10.0, -12.0 * jitter(rng)));
    for (double e : {0.0, half_pi, -half_pi, std::nextafter(half_pi, 0.0), 1e-300}) v.push_back(e);
    return v;
  }();
  return args;
}

inline const std::vector<Ref>& SinRefs() {
  static const std::vector<Ref> refs = [] {
    std::vector<Ref> r;
    for (double x : SinArgs()) r.push_back(ToRef(sin(Big(x))));
    return r;
  }();
  return refs;
}

inline const std::vector<Ref>& CosRefs() {
  static const std::vector<Ref> refs = [] {
    std::vector<Ref> r;
    for (double x : CosArgs()) r.push_back(ToRef(cos(Big(x))));
    return r;
  }();
  return refs;
}

}  // namespace simd_math_f64_test
}  // namespace brdfbake

#endif  // BRDFBAKE_TESTS_SIMD_MATH_F64_TEST_REF_

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "tests/kernels/simd_math_f64_test.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>
#include <hwy/tests/hwy_gtest.h>

#include "kernels/math_f64-inl.h"
#include "kernels/simd_map_f64-inl.h"

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;
namespace {  // internal linkage: other test files define their own helpers

using simd_math_f64_test::AbsErr;
using simd_math_f64_test::Ref;

// Documented bounds (src/kernels/math_f64-inl.h): |err| <= rel |f| + one
// subnormal ulp, and for Lambda also |err| <= 2e-15 max(1, Lambda).
constexpr double kExpNegSqRel = 3.3e-16;   // ExpNegSquareF64
constexpr double kLambdaRel = 1.5e-15;     // BeckmannLambdaF64
constexpr double kLambdaBound = 2e-15;
constexpr double kErfcxRel = 1e-15;       // ErfcxF64
constexpr double kExpRel = 3e-16;         // ExpF64Unguarded
constexpr double kCosRel = 5e-16;         // CosF64ZeroToPi: rel |cos| + kCosAbs
constexpr double kCosAbs = 1e-32;
constexpr double kCosAbsMax = 5e-16;
constexpr double kSinRel = 5e-16;         // SinF64HalfPi: rel |sin| + kCosAbs
constexpr double kSubnormalUlp = 4.9406564584124654e-324;

void CheckExpNegSquareF64() {
  const std::vector<double>& xs = simd_math_f64_test::ExpArgs();
  const std::vector<Ref>& refs = simd_math_f64_test::ExpRefs();
  const auto got = MapF64(xs, [](auto d, auto v) { return ExpNegSquareF64(d, v); });
  double worst = 0, worst_x = 0, worst_sub = 0;
  for (size_t i = 0; i < xs.size(); ++i) {
    const double x = xs[i];
    if (std::isnan(x)) {
      ASSERT_TRUE(std::isnan(got[i])) << "exp(-x^2) of NaN gave " << got[i];
      continue;
    }
    const double err = AbsErr(got[i], refs[i]);
    ASSERT_LE(err, kExpNegSqRel * refs[i].hi + kSubnormalUlp)
        << "exp(-x^2) x=" << x << " got " << got[i] << " ref " << refs[i].hi;
    if (refs[i].hi >= DBL_MIN) {
      const double rel = err / refs[i].hi;
      if (rel > worst) worst = rel, worst_x = x;
    } else {
      worst_sub = std::max(worst_sub, err / kSubnormalUlp);
    }
  }
  std::printf("%s: ExpNegSquareF64 max rel error %.3g at x=%.17g (bound %.2g), %.2f subnormal "
              "ulp where below DBL_MIN\n",
              hwy::TargetName(HWY_TARGET), worst, worst_x, kExpNegSqRel, worst_sub);
}

void CheckBeckmannLambdaF64() {
  const std::vector<double>& as = simd_math_f64_test::LambdaArgs();
  const std::vector<Ref>& refs = simd_math_f64_test::LambdaRefs();
  const auto got = MapF64(as, [](auto d, auto v) { return BeckmannLambdaF64(d, v); });
  const BeckmannNdf<double> ndf(1.0);  // the scalar twin, UnitLambda
  double worst_bound = 0, worst_rel = 0, worst_a = 0, worst_sub = 0;
  double worst_twin = 0, worst_scalar = 0, worst_scalar_rel = 0;
  for (size_t i = 0; i < as.size(); ++i) {
    const double a = as[i];
    const Ref& ref = refs[i];
    if (std::isnan(a)) {
      ASSERT_TRUE(std::isnan(got[i])) << "Lambda of NaN gave " << got[i];
      continue;
    }
    if (std::isinf(ref.hi)) {  // a <= 0, or the true value exceeds DBL_MAX
      ASSERT_EQ(got[i], ref.hi) << "Lambda a=" << a;
      continue;
    }
    const double err = AbsErr(got[i], ref);
    const double scaled = err / std::max(1.0, ref.hi);
    // The scalar twin is accurate in this measure too (its cancellation at
    // large a costs relative, not absolute, accuracy): the two agree to the
    // sum of their errors.
    if (a >= 1e-300 && a <= 26) {
      const double twin = ndf.UnitLambda(a);
      const double twin_err = AbsErr(twin, ref);
      worst_scalar = std::max(worst_scalar, twin_err / std::max(1.0, ref.hi));
      worst_scalar_rel = std::max(worst_scalar_rel, twin_err / ref.hi);
      const double diff = std::abs(got[i] - twin) / std::max(1.0, ref.hi);
      worst_twin = std::max(worst_twin, diff);
      ASSERT_LE(diff, 2 * kLambdaBound) << "Lambda a=" << a << " got " << got[i] << " scalar twin "
                                        << twin;
    }
    worst_bound = std::max(worst_bound, scaled);
    ASSERT_LE(scaled, kLambdaBound) << "Lambda a=" << a << " got " << got[i] << " ref " << ref.hi;
    ASSERT_LE(err, kLambdaRel * ref.hi + kSubnormalUlp)
        << "Lambda a=" << a << " got " << got[i] << " ref " << ref.hi;
    if (ref.hi >= DBL_MIN) {
      const double rel = err / ref.hi;
      if (rel > worst_rel) worst_rel = rel, worst_a = a;
    } else {
      worst_sub = std::max(worst_sub, err / kSubnormalUlp);
    }
  }
  std::printf("%s: BeckmannLambdaF64 max |err| / max(1, Lambda) %.3g (bound %.2g), max rel "
              "error %.3g at a=%.17g (bound %.2g), %.2f subnormal ulp where below DBL_MIN (%zu "
              "points)\n",
              hwy::TargetName(HWY_TARGET), worst_bound, kLambdaBound, worst_rel, worst_a,
              kLambdaRel, worst_sub, as.size());
  std::printf(
      "%s: |BeckmannLambdaF64 - UnitLambda| / max(1, Lambda) %.3g; UnitLambda itself: %.3g, "
      "max rel error %.3g (a <= 26)\n",
      hwy::TargetName(HWY_TARGET), worst_twin, worst_scalar, worst_scalar_rel);
}

void CheckErfcxF64() {
  const std::vector<double>& as = simd_math_f64_test::ErfcxArgs();
  const std::vector<Ref>& refs = simd_math_f64_test::ErfcxRefs();
  const auto got = MapF64(as, [](auto d, auto v) { return ErfcxF64(d, v); });
  double worst = 0, worst_a = 0;
  for (size_t i = 0; i < as.size(); ++i) {
    const double rel = AbsErr(got[i], refs[i]) / refs[i].hi;
    ASSERT_LE(rel, kErfcxRel) << "erfcx a=" << as[i] << " got " << got[i] << " ref "
                              << refs[i].hi;
    if (rel > worst) worst = rel, worst_a = as[i];
  }
  std::printf("%s: ErfcxF64 max rel error %.3g at a=%.17g (bound %.2g, %zu points)\n",
              hwy::TargetName(HWY_TARGET), worst, worst_a, kErfcxRel, as.size());
}

void CheckExpF64Unguarded() {
  const std::vector<double>& xs = simd_math_f64_test::ExpUnguardedArgs();
  const std::vector<Ref>& refs = simd_math_f64_test::ExpUnguardedRefs();
  const auto got = MapF64(xs, [](auto d, auto v) { return ExpF64Unguarded(d, v); });
  double worst = 0, worst_x = 0;
  for (size_t i = 0; i < xs.size(); ++i) {
    const double rel = AbsErr(got[i], refs[i]) / refs[i].hi;
    ASSERT_LE(rel, kExpRel) << "exp x=" << xs[i] << " got " << got[i] << " ref " << refs[i].hi;
    if (rel > worst) worst = rel, worst_x = xs[i];
  }
  std::printf("%s: ExpF64Unguarded max rel error %.3g at x=%.17g (bound %.2g, %zu points)\n",
              hwy::TargetName(HWY_TARGET), worst, worst_x, kExpRel, xs.size());
}

void CheckCosF64ZeroToPi() {
  const std::vector<double>& xs = simd_math_f64_test::CosArgs();
  const std::vector<Ref>& refs = simd_math_f64_test::CosRefs();
  const auto got = MapF64(xs, [](auto d, auto v) { return CosF64ZeroToPi(d, v); });
  double worst_abs = 0, worst_rel = 0, worst_x = 0;
  for (size_t i = 0; i < xs.size(); ++i) {
    const double err = AbsErr(got[i], refs[i]);
    ASSERT_LE(err, kCosRel * std::abs(refs[i].hi) + kCosAbs)
        << "cos x=" << xs[i] << " got " << got[i] << " ref " << refs[i].hi;
    ASSERT_LE(err, kCosAbsMax) << "cos x=" << xs[i];
    worst_abs = std::max(worst_abs, err);
    if (refs[i].hi != 0 && err / std::abs(refs[i].hi) > worst_rel) {
      worst_rel = err / std::abs(refs[i].hi), worst_x = xs[i];
    }
  }
  std::printf(
      "%s: CosF64ZeroToPi max abs error %.3g (bound %.2g), max rel error %.3g at x=%.17g "
      "(bound %.2g + %.0e, %zu points)\n",
      hwy::TargetName(HWY_TARGET), worst_abs, kCosAbsMax, worst_rel, worst_x, kCosRel, kCosAbs, xs.size());
}

void CheckSinF64HalfPi() {
  const std::vector<double>& xs = simd_math_f64_test::SinArgs();
  const std::vector<Ref>& refs = simd_math_f64_test::SinRefs();
  const auto got = MapF64(xs, [](auto d, auto v) { return SinF64HalfPi(d, v); });
  double worst_rel = 0, worst_x = 0;
  for (size_t i = 0; i < xs.size(); ++i) {
    const double err = AbsErr(got[i], refs[i]);
    ASSERT_LE(err, kSinRel * std::abs(refs[i].hi) + kCosAbs)
        << "sin t=" << xs[i] << " got " << got[i] << " ref " << refs[i].hi;
    if (refs[i].hi != 0 && err / std::abs(refs[i].hi) > worst_rel) {
      worst_rel = err / std::abs(refs[i].hi), worst_x = xs[i];
    }
  }
  std::printf("%s: SinF64HalfPi max rel error %.3g at t=%.17g (bound %.2g + %.0e, %zu points)\n",
              hwy::TargetName(HWY_TARGET), worst_rel, worst_x, kSinRel, kCosAbs, xs.size());
}

}  // namespace
}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace brdfbake {
HWY_BEFORE_TEST(SimdMathF64Test);
HWY_EXPORT_AND_TEST_P(SimdMathF64Test, CheckExpNegSquareF64);
HWY_EXPORT_AND_TEST_P(SimdMathF64Test, CheckBeckmannLambdaF64);
HWY_EXPORT_AND_TEST_P(SimdMathF64Test, CheckErfcxF64);
HWY_EXPORT_AND_TEST_P(SimdMathF64Test, CheckExpF64Unguarded);
HWY_EXPORT_AND_TEST_P(SimdMathF64Test, CheckCosF64ZeroToPi);
HWY_EXPORT_AND_TEST_P(SimdMathF64Test, CheckSinF64HalfPi);
}  // namespace brdfbake
#endif
