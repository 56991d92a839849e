// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The squared ellipsoidal lobe's SIMD kernel (sel-inl.h, [TokuyoshiHarada]) against
// SelLobe<double>::K on every compiled target.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <vector>

#include "brdfbake/batch.h"
#include "brdfbake/models/kernel_bounds.h"
#include "brdfbake/models/sel.h"
#include "brdfbake/targets.h"

#include "util/simd_test_util.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "tests/kernels/simd_sel_test.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>
#include <hwy/tests/hwy_gtest.h>

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace {

using test::Dirs;
using test::RandomDirs;
using test::RelErr;


const char* Target() { return hwy::TargetName(HWY_TARGET); }

}  // namespace

// SEL K against the double SelLobe::K at the same float inputs: 2e-6
// relative plus the change of the exact K when v = Q w moves by the float
// rounding of the rotation (see src/kernels/sel-inl.h).
#if BRDFBAKE_WITH_SEL
void CheckSelK() {
  const size_t n = 20000;
  const Dirs w = RandomDirs(n, 41);
  std::vector<float> out(n);
  struct Cfg {
    float ax, ay, tx, ty, tz;
  };
  const Cfg cfgs[] = {{0.3f, 0.3f, 0, 0, 0},       {1e-4f, 1e-4f, 0, 0, 0},
                      {0.5f, 0.01f, 0, 0, 0},      {0.2f, 0.6f, 0.4f, -0.3f, 1.0f},
                      {1e-3f, 0.05f, 1.2f, 0.7f, -0.5f}, {1.0f, 1.0f, 0.1f, 0.2f, 0.3f}};
  double worst = 0, worst_raw = 0;
  for (const Cfg& c : cfgs) {
    BatchModel p{ModelKind::kSel};
    p.alpha_x = c.ax;
    p.alpha_y = c.ay;
    p.theta_x = c.tx;
    p.theta_y = c.ty;
    p.theta_z = c.tz;
    EvalBatch(p, Quantity::kK, {w.x.data(), w.y.data(), w.z.data()}, out.data(), n);
    const SelLobe<double> lobe = SelLobe<double>::FromAngles(c.ax, c.ay, c.tx, c.ty, c.tz);
    const SelLobe<double> in_lobe_space(c.ax, c.ay, Mat3<double>::Diagonal(1, 1, 1));
    const Mat3<double>& q = lobe.q();
    for (size_t i = 0; i < n; ++i) {
      const Vec3<double> wi = w.At(i);
      const double ref = lobe.K(wi);
      const Vec3<double> v = q * wi;
      double sens = 0;
      for (int k = 0; k < 3; ++k) {
        const double mag = std::abs(q.m[k][0] * wi.x) + std::abs(q.m[k][1] * wi.y) +
                           std::abs(q.m[k][2] * wi.z);
        for (double sgn : {-1.0, 1.0}) {
          Vec3<double> vp = v;
          (k == 0 ? vp.x : k == 1 ? vp.y : vp.z) += sgn * 3 * 0x1p-24 * mag;
          sens = std::max(sens, std::abs(in_lobe_space.K(vp) - ref) / ref);
        }
      }
      const double err = RelErr(out[i], ref);
      worst_raw = std::max(worst_raw, err);
      worst = std::max(worst, err / (2e-6 + sens));
      ASSERT_LE(err, 2e-6 + sens) << "cfg " << c.ax << "," << c.ay << "," << c.tx << " i=" << i
                                  << " got " << out[i] << " ref " << ref;
    }
  }
  std::printf("%s: SEL K max error / bound %.3g (max relative error %.3g)\n", Target(), worst,
              worst_raw);
}
#endif  // BRDFBAKE_WITH_SEL

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace brdfbake {
#if BRDFBAKE_WITH_SEL
HWY_BEFORE_TEST(SimdSelTest);
HWY_EXPORT_AND_TEST_P(SimdSelTest, CheckSelK);
#endif
}  // namespace brdfbake
#endif
