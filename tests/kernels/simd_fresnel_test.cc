// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The Fresnel SIMD kernels (fresnel-inl.h) against FresnelDielectric and
// FresnelConductor in double on every compiled target: dense cosine grids
// with a cluster around the critical angle; each test asserts the bound
// documented in the kernel's header and prints the observed maximum.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <vector>

#include "brdfbake/batch.h"
#include "brdfbake/models/fresnel.h"
#include "brdfbake/models/kernel_bounds.h"
#include "brdfbake/targets.h"

#include "util/simd_test_util.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "tests/kernels/simd_fresnel_test.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>
#include <hwy/tests/hwy_gtest.h>

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace {

using test::RelErr;

// Documented bounds (src/kernels/fresnel-inl.h), against the double
// reference at the same float inputs.
constexpr double kDielectricRel = 2e-6;
constexpr double kConductorRel = 2e-6, kConductorAbs = 1e-7;

const char* Target() { return hwy::TargetName(HWY_TARGET); }

// ---------------------------------------------------------------- Fresnel

// Cosines: a dense uniform grid, a log grid down to 1e-6, and for eta < 1 a
// dense cluster around the critical cosine sqrt(1 - eta^2).
std::vector<float> FresnelCosines(double eta) {
  std::vector<float> c;
  for (int i = 0; i <= 20000; ++i) c.push_back(static_cast<float>(i / 20000.0));
  for (int i = 0; i <= 2000; ++i) c.push_back(static_cast<float>(std::pow(10.0, -6 + 6e-3 * i)));
  if (eta < 1) {
    const double crit = std::sqrt((1 - eta) * (1 + eta));
    for (int i = -2000; i <= 2000; ++i) {
      c.push_back(static_cast<float>(crit * (1 + 1e-7 * i * std::abs(i) / 2000.0)));
    }
  }
  return c;
}

}  // namespace

void CheckFresnelDielectric() {
  const float etas[] = {1 / 3.0f, 1 / 1.5f, 0.9f, 0.999f, 1.0f,  1.0001f,
                        1.01f,    1.33f,    1.5f, 2.4f,   3.0f, 1 / 1.0001f};
  double worst = 0;
  for (float eta : etas) {
    const std::vector<float> c = FresnelCosines(eta);
    std::vector<float> out(c.size());
    FresnelDielectricBatch(eta, c.data(), out.data(), c.size());
    for (size_t i = 0; i < c.size(); ++i) {
      if (eta == 1.0f) {
        // No interface: F = 0, except the TIR branch of the reference at
        // cos = 0 (whose value elsewhere is rounding noise, ~1e-22).
        ASSERT_EQ(out[i], c[i] > 0 ? 0.0f : 1.0f) << c[i];
        continue;
      }
      const double ref = FresnelDielectric<double>(eta, c[i]);
      const double err = RelErr(out[i], ref);
      worst = std::max(worst, err);
      ASSERT_LE(err, kDielectricRel) << "eta " << eta << " cos " << c[i] << " got " << out[i]
                                     << " ref " << ref;
    }
  }
  std::printf("%s: Fresnel dielectric max relative error %.3g (bound %.1g)\n", Target(), worst,
              kDielectricRel);
}

void CheckFresnelConductor() {
  const float ns[] = {0.05f, 0.2f, 0.5f, 0.9f, 1.0f, 1.5f, 2.5f, 4.0f};
  const float ks[] = {0.0f, 0.01f, 0.5f, 1.0f, 3.0f, 5.0f, 10.0f};
  double worst_rel = 0, worst_abs = 0, worst_norm = 0;
  for (float n : ns) {
    for (float k : ks) {
      const std::vector<float> c = FresnelCosines(k == 0 ? n : 2.0);
      std::vector<float> out(c.size());
      FresnelConductorBatch(n, k, c.data(), out.data(), c.size());
      for (size_t i = 0; i < c.size(); ++i) {
        const double ref = FresnelConductor<double>(n, k, c[i]);
        if (std::isnan(ref)) continue;  // n = 1, k = 0, cos = 0: 0 / 0 in the reference
        const double err = std::abs(out[i] - ref);
        const double allowed = kConductorRel * ref + kConductorAbs;
        if (ref > 1e-3) worst_rel = std::max(worst_rel, err / ref);
        worst_abs = std::max(worst_abs, err);
        worst_norm = std::max(worst_norm, err / allowed);
        ASSERT_LE(err, allowed) << "n " << n << " k " << k << " cos " << c[i] << " got "
                                << out[i] << " ref " << ref;
      }
    }
  }
  std::printf("%s: Fresnel conductor max error / bound %.3g (bound %.1g F + %.1g); max "
              "relative (F > 1e-3) %.3g, max absolute %.3g\n",
              Target(), worst_norm, kConductorRel, kConductorAbs, worst_rel, worst_abs);
}

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace brdfbake {
HWY_BEFORE_TEST(SimdFresnelTest);
HWY_EXPORT_AND_TEST_P(SimdFresnelTest, CheckFresnelDielectric);
HWY_EXPORT_AND_TEST_P(SimdFresnelTest, CheckFresnelConductor);
}  // namespace brdfbake
#endif
