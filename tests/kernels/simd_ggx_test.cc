// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The GGX SIMD kernels against the double scalar reference on every compiled
// target (one gtest case per target): dense sweeps including alpha 1e-4,
// anisotropy 1000:1 and grazing directions, and a check that the forced
// target is the one that ran. (Counts and sentinels: batch_test.cc.)

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "brdfbake/batch.h"
#include "brdfbake/models/brdf.h"
#include "brdfbake/models/ggx.h"
#include "brdfbake/targets.h"

#include "util/simd_test_util.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "tests/kernels/simd_ggx_test.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>
#include <hwy/tests/hwy_gtest.h>

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {

using test::Dirs;
using test::RandomDirs;
using test::RelErr;

// Documented bound (src/kernels/ggx-inl.h): relative error of the float kernels
// against the double reference at the same float inputs.
constexpr double kMaxRelError = 2e-6;




void CheckTargetIsUsed() {
  EXPECT_EQ(BatchTarget(), hwy::TargetName(HWY_TARGET));
}

void CheckBrdfAgainstScalar() {
  const size_t n = 20000;
  const Dirs wi = RandomDirs(n, 1), wo = RandomDirs(n, 2);
  std::vector<float> out(n);
  const float alphas[][2] = {{1e-4f, 1e-4f}, {1e-3f, 1e-3f}, {0.05f, 0.05f}, {0.3f, 0.3f},
                             {1.0f, 1.0f},   {1.0f, 1e-3f},  {2e-3f, 0.8f}};
  double worst = 0;
  for (const auto& a : alphas) {
    for (Masking masking : {Masking::kHeightCorrelated, Masking::kSeparable}) {
      for (float f0 : {1.0f, 0.04f}) {
        BatchModel p{ModelKind::kGgx};
        p.alpha_x = a[0];
        p.alpha_y = a[1];
        p.f0 = f0;
        p.masking = masking;
        EvalBatch(p, Quantity::kBrdf, {wi.x.data(), wi.y.data(), wi.z.data()},
                  {wo.x.data(), wo.y.data(), wo.z.data()}, out.data(), n);
        const GgxNdf<double> ndf(a[0], a[1]);
        const Fresnel fr = Fresnel::Schlick({f0, f0, f0});
        for (size_t i = 0; i < n; ++i) {
          const double ref = Brdf(ndf, fr, wi.At(i), wo.At(i), masking);
          const double err = RelErr(out[i], ref);
          worst = std::max(worst, err);
          ASSERT_LE(err, kMaxRelError) << "alpha " << a[0] << "," << a[1] << " i=" << i
                                       << " got " << out[i] << " ref " << ref;
        }
      }
    }
  }
  std::printf("%s: GGX BRDF max relative error %.3g (bound %.1g)\n", hwy::TargetName(HWY_TARGET),
              worst, kMaxRelError);
}

void CheckDAndLambdaAgainstScalar() {
  const size_t n = 20000;
  const Dirs m = RandomDirs(n, 3);
  std::vector<float> out(n);
  double worst_d = 0, worst_l = 0;
  for (const auto& a : {std::pair<float, float>{1e-4f, 1e-4f}, {0.2f, 0.2f}, {1.0f, 1e-3f}}) {
    BatchModel p{ModelKind::kGgx};
    p.alpha_x = a.first;
    p.alpha_y = a.second;
    const GgxNdf<double> ndf(a.first, a.second);
    EvalBatch(p, Quantity::kD, {m.x.data(), m.y.data(), m.z.data()}, out.data(), n);
    for (size_t i = 0; i < n; ++i) {
      const double err = RelErr(out[i], ndf.D(m.At(i)));
      worst_d = std::max(worst_d, err);
      ASSERT_LE(err, kMaxRelError) << i;
    }
    EvalBatch(p, Quantity::kLambda, {m.x.data(), m.y.data(), m.z.data()}, out.data(), n);
    for (size_t i = 0; i < n; ++i) {
      const double ref = ndf.Lambda(m.At(i));
      const double err = std::abs(out[i] - ref) / std::max(1.0, ref);
      worst_l = std::max(worst_l, err);
      ASSERT_LE(err, kMaxRelError) << i;
    }
  }
  std::printf("%s: GGX D max rel error %.3g, Lambda %.3g\n", hwy::TargetName(HWY_TARGET),
              worst_d, worst_l);
}

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace brdfbake {
HWY_BEFORE_TEST(SimdGgxTest);
HWY_EXPORT_AND_TEST_P(SimdGgxTest, CheckTargetIsUsed);
HWY_EXPORT_AND_TEST_P(SimdGgxTest, CheckBrdfAgainstScalar);
HWY_EXPORT_AND_TEST_P(SimdGgxTest, CheckDAndLambdaAgainstScalar);

TEST(SimdGgxTest, ForceTargetRejectsUnknownNames) {
  EXPECT_THROW(ForceTarget("NEON"), std::invalid_argument);
  EXPECT_FALSE(AvailableTargets().empty());
  for (const std::string& t : AvailableTargets()) {
    ForceTarget(t);
    EXPECT_EQ(BatchTarget(), t);
  }
  ForceTarget("best");
  EXPECT_EQ(BatchTarget(), AvailableTargets().front());
}

// Forcing a target narrows dispatch only: listing the targets keeps the
// forced one, BestTarget stays the CPU's best, and "best" restores it.
TEST(SimdGgxTest, TargetFunctionsAgreeWhileForced) {
  const std::vector<std::string> available = AvailableTargets();
  const std::string best = BestTarget();
  ASSERT_FALSE(available.empty());
  EXPECT_EQ(best, available.front());
  EXPECT_EQ(BatchTarget(), best);
  const std::vector<std::string> compiled = CompiledTargets();
  for (const std::string& t : available) {
    EXPECT_NE(std::find(compiled.begin(), compiled.end(), t), compiled.end()) << t;
  }
  for (const std::string& t : available) {
    ForceTarget(t);
    EXPECT_EQ(AvailableTargets(), available) << "after forcing " << t;
    EXPECT_EQ(BatchTarget(), t) << "listing the targets undid forcing " << t;
    EXPECT_EQ(BestTarget(), best) << "while " << t << " is forced";
    // Evaluating a batch runs on the forced target too.
    const float x = 0.0f, y = 0.6f, z = 0.8f;
    float d = 0;
    EvalBatch(BatchModel{}, Quantity::kD, DirArrays{&x, &y, &z}, &d, 1);
    EXPECT_GT(d, 0.0f);
    EXPECT_EQ(BatchTarget(), t);
  }
  ForceTarget("best");
  EXPECT_EQ(BatchTarget(), best);
  EXPECT_EQ(AvailableTargets(), available);
}
}  // namespace brdfbake
#endif
