// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// StudentTLambdaF64 (src/kernels/std_f64-inl.h) on every compiled target (one
// gtest case per target), for gamma in {1.5+1e-6, 1.501, 1.55, 1.6, 2, 2.5,
// 3, 3.5, 7, 10, 17, 30, 1e3, 1e6, 1e9, 1e15, 9.9e19}:
//  - against 40-digit values (Boost.Multiprecision cpp_bin_float<40>) on a
//    quarter-decade grid of a over [1e-8, 1e8], both sides of each form
//    switch (a = 4, u = 1) and out to 1e-300 and 1e300;
//  - against the scalar twin StudentTNdf<double>::UnitLambda on 3001 log-spaced a
//    in [1e-8, 1e8] (random low bits) per gamma;
//  - the special values (a <= 0, +inf, tiny and huge a), and that a lane's
//    value does not depend on its neighbours (the branches that skip a form
//    when no lane needs it).
// Each check asserts the bound documented beside the kernel and prints the
// observed maximum.
//
// The 40-digit reference uses other switch points than the kernel, so that
// the forms check one another: the series (Y) for u < 1/2 and a <= 2.5 (at
// most 5 of the 40 digits lost to its subtraction of 1/2), the x0 series of
// form (X) for u >= 1/2, and form (S) with the Gauss continued fraction of
// std_ndf.h elsewhere; the scalar twin itself was checked against 50-digit
// mpmath quadrature of the definition (std_ndf.h).

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "brdfbake/models/std_ndf.h"

// The references, computed once (outside the per-target re-inclusion by
// foreach_target.h).
#ifndef BRDFBAKE_TESTS_SIMD_STD_F64_TEST_REF_
#define BRDFBAKE_TESTS_SIMD_STD_F64_TEST_REF_

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/gamma.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>

#include "reference/ref_util.h"

namespace brdfbake {
namespace simd_std_f64_test {

using Big = boost::multiprecision::number<boost::multiprecision::cpp_bin_float<40>>;

constexpr double kInf = std::numeric_limits<double>::infinity();

inline const std::vector<double>& Gammas() {
  static const std::vector<double> g = {1.5 + 1e-6, 1.501, 1.55, 1.6, 2.0, 2.5, 3.0, 3.5, 7.0,
                                        10.0, 17.0, 30.0, 1e3, 1e6, 1e9, 1e15, 9.9e19};
  return g;
}

using test::AbsErr;
using test::Ref;
using test::ToRef;

// kt = Gamma(gamma - 1/2) / (sqrt(pi) Gamma(gamma - 1) sqrt(gamma - 1)).
inline Big KtBig(const Big& g) {
  const Big z = g - 1;
  return 1 / (boost::math::constants::root_pi<Big>() * sqrt(z) *
              boost::math::tgamma_delta_ratio(z, Big(0.5)));
}

// Lambda(a) for gamma in 40 digits (see the top of the file).
inline Big LambdaBig(double gamma, const Big& kt, double a_d) {
  const Big g(gamma), a(a_d), gm1 = g - 1;
  const Big eps = std::numeric_limits<Big>::epsilon() / 1000;
  const Big u = a * a / gm1;
  const Big e = exp(-(g - Big(1.5)) * log1p(u));  // (1 + u)^(3/2 - gamma)
  if (u >= Big(0.5)) {  // (X): x0 2F1(nu, 1; nu + 3/2; x0), nu = gamma - 1/2
    const Big x0 = 1 / (1 + u);
    Big h = 1, sum = 1;
    for (int n = 0; n < 100000; ++n) {
      h *= (g - Big(0.5) + n) / (g + 1 + n) * x0;
      sum += h;
      if (h < eps * sum) break;
    }
    return kt / (2 * a) * e * (1 / (2 * g - 3) + x0 * sum / (2 * g));
  }
  if (a_d <= 2.5) {  // (Y)
    const Big w = a * a / (1 + u);
    Big c = 1, sum = 1;
    for (int n = 0; n < 100000; ++n) {
      c *= (g - Big(0.5) + n) / (gm1 * (n + Big(1.5))) * w;
      sum += c;
      if (c < eps * sum) break;
    }
    return kt / a * e * (gm1 / (2 * g - 3) + w * sum) - Big(0.5);
  }
  // (S) with G = 2F1(1, 3/2; gamma + 1; -v) by the Stieltjes fraction of
  // student_t_detail::StudentTHyp2F1G (modified Lentz).
  const Big v = gm1 / (a * a);
  Big h = 1, cc = 1, dd = 0;
  for (int n = 1; n < 100000; ++n) {
    Big k;
    if (n % 2 == 1) {
      const Big j((n - 1) / 2);
      k = (Big(1.5) + j) / (g + 2 * j + 1) * ((g + j) / (g + 2 * j));
    } else {
      const Big j(n / 2);
      k = j / (g + 2 * j - 1) * ((g - Big(1.5) + j) / (g + 2 * j));
    }
    dd = 1 / (1 + k * v * dd);
    cc = 1 + k * v / cc;
    const Big delta = cc * dd;
    h *= delta;
    if (abs(delta - 1) < eps) break;
  }
  return kt / (2 * a) * e * (1 / (2 * g - 3) + v / h / (2 * g));
}

// The 40-digit cases: per gamma of Gammas() a 1/16-decade grid over [1e-8,
// 1e8], 100 random a in [0.5, 4.5] (where (Y) is least accurate), 40 around
// u = 1 and both sides of the kernel's switches (a = 4, u = 1), 1e-300 ..
// 1e300; then 1200 random (gamma, a), gamma - 1.5 log-uniform in [1e-6,
// 1e19] and a in [1e-3, 1e3] (200 of them in [1e-300, 1e300]).
struct BigCase {
  double gamma, a;
  Ref ref;
};
inline const std::vector<BigCase>& BigCases() {
  static const std::vector<BigCase> cases = [] {
    std::vector<BigCase> v;
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> uni(0.0, 1.0);
    for (double gamma : Gammas()) {
      const Big kt = KtBig(Big(gamma));
      std::vector<double> as;
      for (int k = -128; k <= 128; ++k) as.push_back(std::pow(10.0, (k + uni(rng)) / 16.0));
      for (int k = 0; k < 100; ++k) as.push_back(0.5 + 4 * uni(rng));
      for (int k = 0; k < 40; ++k) as.push_back(std::sqrt(gamma - 1) * (0.8 + 0.4 * uni(rng)));
      for (double s : {1 - 1e-9, 1 + 1e-9, 0.999, 1.001}) {
        as.push_back(4.0 * s);
        as.push_back(std::sqrt(gamma - 1) * s);
      }
      for (double e : {1e-300, 1e-200, 1e-100, 1e-30, 1e30, 1e100, 1e150, 0x1p500, 3.3e150, 1e154,
                       1e155, 1e181, 1e200, 1e300}) {
        as.push_back(e);
      }
      for (double a : as) v.push_back({gamma, a, ToRef(LambdaBig(gamma, kt, a))});
    }
    for (int k = 0; k < 1200; ++k) {
      const double gamma = 1.5 + std::pow(10.0, -6 + 25 * uni(rng));
      const double a = k < 1000 ? std::pow(10.0, -3 + 6 * uni(rng))
                                : std::pow(10.0, -300 + 600 * uni(rng));
      v.push_back({gamma, a, ToRef(LambdaBig(gamma, KtBig(Big(gamma)), a))});
    }
    return v;
  }();
  return cases;
}

// Log-spaced a over [1e-8, 1e8] with random low bits, for the comparison
// with the scalar twin.
inline const std::vector<double>& SweepArgs() {
  static const std::vector<double> args = [] {
    std::vector<double> v;
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> jitter(0.0, 1.0);
    const int kN = 3000;
    for (int i = 0; i <= kN; ++i) v.push_back(std::pow(10.0, -8.0 + 16.0 * (i + jitter(rng)) / kN));
    return v;
  }();
  return args;
}

}  // namespace simd_std_f64_test
}  // namespace brdfbake

#endif  // BRDFBAKE_TESTS_SIMD_STD_F64_TEST_REF_

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "tests/kernels/simd_std_f64_test.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>
#include <hwy/tests/hwy_gtest.h>

#include "kernels/simd_map_f64-inl.h"
#include "kernels/std_f64-inl.h"

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;
namespace {  // internal linkage: other test files define their own helpers

using simd_std_f64_test::AbsErr;
using simd_std_f64_test::BigCase;
using simd_std_f64_test::kInf;
using simd_std_f64_test::Ref;

// Documented bounds (src/kernels/std_f64-inl.h): |err| <= kBound max(1, Lambda);
// where form (X) or (L) is used and Lambda is normal, relative error <=
// kRelS + kRelExpo expo (exp(-expo) = (1 + u)^(3/2 - gamma) costs ~expo ulp)
// plus the quadrature's error in (L).
constexpr double kBound = 8e-15;
constexpr double kRelS = 2e-15, kRelExpo = 5e-16;
// (L): 8-point Gauss-Laguerre, relative 5e-12 at a = 4, decaying.
constexpr double kQuadRel = 6e-12, kQuadDecay = 4.0;
// Kernel vs scalar twin: kBound plus the twin's own error in the same
// measure (below 1e-15; see the printout of CheckAgainstFortyDigits).
constexpr double kTwinBound = kBound + 2e-15;

// StudentTLambdaF64 for each a on this target.
std::vector<double> Map(const StudentTLambdaF64Consts& c, const std::vector<double>& x) {
  return MapF64(x, [&](auto d, auto v) { return StudentTLambdaF64(d, c, v); });
}

// The same, one a per vector (all lanes equal).
double One(const StudentTLambdaF64Consts& c, double a) {
  const hn::ScalableTag<double> d;
  return hn::GetLane(StudentTLambdaF64(d, c, hn::Set(d, a)));
}

// 0: form (Y), 1: (X), 2: (L) (as the kernel decides, up to rounding).
int Form(double gamma, double a) {
  if (a * a * (1 / (gamma - 1)) >= 1) return 1;
  return a < StudentTLambdaF64Consts::kSeriesMaxA ? 0 : 2;
}

void CheckAgainstFortyDigits() {
  const std::vector<BigCase>& cases = simd_std_f64_test::BigCases();
  double worst = 0, worst_g = 0, worst_a = 0, worst_twin = 0, worst_ratio = 0;
  double worst_rel[3] = {0, 0, 0}, worst_rel_g[3] = {0, 0, 0}, worst_rel_a[3] = {0, 0, 0};
  size_t i = 0;
  while (i < cases.size()) {
    const double gamma = cases[i].gamma;
    size_t end = i;
    std::vector<double> as;
    while (end < cases.size() && cases[end].gamma == gamma) as.push_back(cases[end++].a);
    const StudentTLambdaF64Consts c(gamma);
    const StudentTNdf<double> ndf(1.0, 1.0, gamma);
    const std::vector<double> got = Map(c, as);
    for (size_t k = 0; k < as.size(); ++k) {
      const double a = as[k];
      const Ref& ref = cases[i + k].ref;
      const double err = AbsErr(got[k], ref) / std::max(1.0, ref.hi);
      ASSERT_LE(err, kBound) << "gamma=" << gamma << " a=" << a << " got " << got[k] << " ref "
                             << ref.hi;
      if (err > worst) worst = err, worst_g = gamma, worst_a = a;
      const int form = Form(gamma, a);
      if (ref.hi >= DBL_MIN) {
        const double rel = AbsErr(got[k], ref) / ref.hi;
        if (form != 0) {
          // Relative: kRelS, plus the quadrature's error near a = 4 in (L).
          const double quad = form == 2 ? kQuadRel * std::exp(-kQuadDecay * (a - 4)) : 0.0;
          const double expo = (gamma - 1.5) * std::log1p(a * a / (gamma - 1));
          const double allowed = kRelS + kRelExpo * expo + quad;
          ASSERT_LE(rel, allowed) << "gamma=" << gamma << " a=" << a << " got " << got[k]
                                  << " ref " << ref.hi;
          worst_ratio = std::max(worst_ratio, rel / allowed);
        }
        if (rel > worst_rel[form]) {
          worst_rel[form] = rel, worst_rel_g[form] = gamma, worst_rel_a[form] = a;
        }
      }
      worst_twin = std::max(worst_twin, AbsErr(ndf.UnitLambda(a), ref) / std::max(1.0, ref.hi));
      // A lane's value does not depend on its neighbours.
      ASSERT_EQ(One(c, a), got[k]) << "gamma=" << gamma << " a=" << a;
    }
    i = end;
  }
  std::printf("%s: StudentTLambdaF64 vs 40 digits (%zu points): max |err| / max(1, Lambda) %.3g "
              "at gamma=%g a=%.17g (bound %.2g); scalar UnitLambda: %.3g\n",
              hwy::TargetName(HWY_TARGET), cases.size(), worst, worst_g, worst_a, kBound,
              worst_twin);
  std::printf("%s:   forms X, L: max rel error / (%.2g + %.2g expo + quadrature) %.3g\n",
              hwy::TargetName(HWY_TARGET), kRelS, kRelExpo, worst_ratio);
  const char* names[3] = {"Y", "X", "L"};
  for (int f = 0; f < 3; ++f) {
    std::printf("%s:   max rel error in form %s %.3g at gamma=%g a=%.17g\n",
                hwy::TargetName(HWY_TARGET), names[f], worst_rel[f], worst_rel_g[f],
                worst_rel_a[f]);
  }
}

void CheckAgainstScalarTwin() {
  const std::vector<double>& as = simd_std_f64_test::SweepArgs();
  double worst = 0, worst_g = 0, worst_a = 0;
  for (double gamma : simd_std_f64_test::Gammas()) {
    const StudentTLambdaF64Consts c(gamma);
    const StudentTNdf<double> ndf(1.0, 1.0, gamma);
    const std::vector<double> got = Map(c, as);
    for (size_t k = 0; k < as.size(); ++k) {
      const double ref = ndf.UnitLambda(as[k]);
      const double diff = std::abs(got[k] - ref) / std::max(1.0, ref);
      ASSERT_LE(diff, kTwinBound) << "gamma=" << gamma << " a=" << as[k] << " got " << got[k]
                                  << " scalar " << ref;
      if (diff > worst) worst = diff, worst_g = gamma, worst_a = as[k];
    }
  }
  std::printf("%s: |StudentTLambdaF64 - UnitLambda| / max(1, Lambda) max %.3g at gamma=%g a=%.17g "
              "(%zu a x %zu gamma, bound %.2g)\n",
              hwy::TargetName(HWY_TARGET), worst, worst_g, worst_a, as.size(),
              simd_std_f64_test::Gammas().size(), kTwinBound);
}

void CheckSpecialValues() {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (double gamma : simd_std_f64_test::Gammas()) {
    const StudentTLambdaF64Consts c(gamma);
    const std::vector<double> as = {0.0,    -0.0,     -1e-300, -1.0, -kInf, kInf,
                                    DBL_MAX, 1e300,   1e-300,  nan,  4.9406564584124654e-324};
    const std::vector<double> got = Map(c, as);
    for (size_t k = 0; k < 5; ++k) EXPECT_EQ(got[k], kInf) << "gamma=" << gamma << " a=" << as[k];
    EXPECT_EQ(got[5], 0.0) << "gamma=" << gamma;
    for (size_t k = 6; k < 9; ++k) {
      EXPECT_TRUE(got[k] >= 0 && !std::isnan(got[k])) << "gamma=" << gamma << " a=" << as[k];
    }
    EXPECT_EQ(got[10], kInf) << "gamma=" << gamma;  // the true value exceeds DBL_MAX
  }
}

}  // namespace
}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace brdfbake {
HWY_BEFORE_TEST(SimdStudentTF64Test);
HWY_EXPORT_AND_TEST_P(SimdStudentTF64Test, CheckAgainstFortyDigits);
HWY_EXPORT_AND_TEST_P(SimdStudentTF64Test, CheckAgainstScalarTwin);
HWY_EXPORT_AND_TEST_P(SimdStudentTF64Test, CheckSpecialValues);
}  // namespace brdfbake
#endif
