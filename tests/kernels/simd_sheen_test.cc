// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The Charlie sheen and Disney diffuse batch kernels (kernels/sheen-inl.h)
// against CharlieSheen<double> and DisneyDiffuse<double> at the same float
// inputs, on every compiled target, with the bounds of sheen-inl.h; and
// the double lanes of the same kernels, as the baker runs them.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "brdfbake/batch.h"
#include "brdfbake/models/disney_diffuse.h"
#include "brdfbake/models/sheen.h"
#include "brdfbake/targets.h"

#include "util/simd_test_util.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "tests/kernels/simd_sheen_test.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>
#include <hwy/tests/hwy_gtest.h>

#include "kernels/sheen-inl.h"

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace {

using test::Dirs;
using test::RandomDirs;
using test::RelErr;

const char* Target() { return hwy::TargetName(HWY_TARGET); }

// The exponent whose rounding exp amplifies: q log1p(-c^2) of D, L of Lambda.
double DExponent(double alpha, double c) {
  return std::abs(0.5 / ClampSheenAlpha(alpha) * std::log1p(-std::min(c * c, 1.0)));
}

}  // namespace

#if BRDFBAKE_WITH_CHARLIE
void CheckCharlie() {
  const size_t n = 20000;
  const Dirs a = RandomDirs(n, 51), b = RandomDirs(n, 52);
  std::vector<float> out(n);
  double worst[4] = {};
  for (SheenVisibility vis : kSheenVisibilities) {
    for (float alpha : {1e-6f, 1e-3f, 0.04f, 0.3f, 1.0f}) {
      BatchModel p{ModelKind::kCharlie};
      p.alpha_x = p.alpha_y = alpha;
      p.visibility = vis;
      const CharlieSheen<double> s(alpha, vis);
      const bool ck = SheenHasLambda(vis);
      EvalBatch(p, Quantity::kD, {a.x.data(), a.y.data(), a.z.data()}, out.data(), n);
      for (size_t i = 0; i < n; ++i) {
        const Vec3<double> m = a.At(i);
        const double q = 0.5 / ClampSheenAlpha(double(alpha));
        const double ref = s.D(m), bound = 2e-6 + 3e-7 * DExponent(alpha, m.z) + 1.2e-7 * q;
        if (ref < 1e-30) continue;  // below float's range the kernel flushes to 0
        const double e = RelErr(out[i], ref);
        worst[0] = std::max(worst[0], e / bound);
        ASSERT_LE(e, bound) << "D alpha " << alpha << " m.z " << m.z << " got " << out[i] << " ref " << ref;
      }
      EvalBatch(p, Quantity::kBrdf, {a.x.data(), a.y.data(), a.z.data()},
                {b.x.data(), b.y.data(), b.z.data()}, out.data(), n);
      for (size_t i = 0; i < n; ++i) {
        const Vec3<double> wi = a.At(i), wo = b.At(i);
        const double ref = s.Brdf(wi, wo);
        if (ref < 1e-30 || ref > 1e30) continue;
        const Vec3<double> h = Normalize(wi + wo);
        double bound = 4e-6 + 3e-7 * DExponent(alpha, h.z) + 2e-7 * 0.5 / ClampSheenAlpha(double(alpha));
        if (ck) bound += 3e-7 * (std::abs(CharlieL(double(ClampSheenAlpha(alpha)), std::min(wi.z, 0.5), vis)) +
                                 std::abs(CharlieL(double(ClampSheenAlpha(alpha)), std::min(wo.z, 0.5), vis)) + 20);
        const double e = RelErr(out[i], ref);
        worst[1] = std::max(worst[1], e / bound);
        ASSERT_LE(e, bound) << "brdf alpha " << alpha << " got " << out[i] << " ref " << ref;
      }
      if (!ck) continue;
      EvalBatch(p, Quantity::kLambda, {a.x.data(), a.y.data(), a.z.data()}, out.data(), n);
      for (size_t i = 0; i < n; ++i) {
        const double ref = s.LambdaCos(a.z[i]);
        if (!(a.z[i] > 0)) {
          EXPECT_TRUE(std::isinf(out[i]));
          continue;
        }
        const double bound = 2e-6 + 3e-7 * (std::abs(std::log(ref)) + 20);
        const double e = RelErr(out[i], ref);
        worst[2] = std::max(worst[2], e / bound);
        ASSERT_LE(e, bound) << "Lambda z " << a.z[i] << " got " << out[i] << " ref " << ref;
      }
      EvalBatch(p, Quantity::kG2, {a.x.data(), a.y.data(), a.z.data()},
                {b.x.data(), b.y.data(), b.z.data()}, out.data(), n);
      for (size_t i = 0; i < n; ++i) {
        const double ref = s.G2Cos(a.z[i], b.z[i]);
        worst[3] = std::max(worst[3], std::abs(out[i] - ref) / 4e-6);
        ASSERT_LE(std::abs(out[i] - ref), 4e-6) << "G2";
      }
    }
  }
  std::printf("%s: charlie max error / bound: D %.3g, brdf %.3g, Lambda %.3g, G2 %.3g\n", Target(),
              worst[0], worst[1], worst[2], worst[3]);
}

// The double lanes of D and the visibility, as the baker's rule runs them:
// 1e-13 relative of the scalar reference.
void CheckCharlieF64() {
  using D64 = hn::ScalableTag<double>;
  const D64 d;
  const size_t N = hn::Lanes(d);
  double worst = 0;
  for (SheenVisibility vis : kSheenVisibilities) {
    for (double alpha : {1e-6, 0.01, 0.3, 1.0}) {
      const CharlieSheen<double> s(alpha, vis);
      const CharlieConsts<D64> c(d, alpha, vis);
      std::vector<double> x(N), y(N), out(N), out2(N);
      for (int k = 0; k < 400; ++k) {
        for (size_t i = 0; i < N; ++i) {
          x[i] = std::pow(0.97, double(k * N + i) * 0.05);
          y[i] = std::pow(0.9, double(k + i));
        }
        hn::StoreU(CharlieDCos2(d, c, hn::LoadU(d, x.data())), d, out.data());
        hn::StoreU(CharlieVisibility(d, c, hn::LoadU(d, x.data()), hn::LoadU(d, y.data())), d, out2.data());
        for (size_t i = 0; i < N; ++i) {
          const double ref = s.DCos2(x[i]), vref = s.Visibility(x[i], y[i]);
          const double bound = 1e-13 * (1 + DExponent(alpha, std::sqrt(x[i])));
          if (ref > 1e-300) {
            worst = std::max(worst, RelErr(out[i], ref) / bound);
            ASSERT_LE(RelErr(out[i], ref), bound) << alpha << " " << x[i];
          }
          ASSERT_LE(RelErr(out2[i], vref), 1e-12) << alpha << " " << x[i] << " " << y[i];
        }
      }
    }
  }
  std::printf("%s: charlie double lanes D max error / bound %.3g\n", Target(), worst);
}
#endif  // BRDFBAKE_WITH_CHARLIE

#if BRDFBAKE_WITH_DISNEY
void CheckDisney() {
  const size_t n = 20000;
  const Dirs a = RandomDirs(n, 61), b = RandomDirs(n, 62);
  std::vector<float> out(n);
  double worst = 0;
  for (float r : {0.0f, 0.25f, 0.7f, 1.0f}) {
    BatchModel p{ModelKind::kDisneyDiffuse};
    p.alpha_x = p.alpha_y = r * r;
    const DisneyDiffuse<double> f(std::sqrt(double(p.alpha_x)));
    EvalBatch(p, Quantity::kBrdf, {a.x.data(), a.y.data(), a.z.data()},
              {b.x.data(), b.y.data(), b.z.data()}, out.data(), n);
    for (size_t i = 0; i < n; ++i) {
      const double ref = f.Brdf(a.At(i), b.At(i));
      if (ref == 0) {
        EXPECT_EQ(out[i], 0.0f);
        continue;
      }
      const double e = RelErr(out[i], ref);
      worst = std::max(worst, e / 2e-6);
      ASSERT_LE(e, 2e-6) << "r " << r << " got " << out[i] << " ref " << ref;
    }
  }
  std::printf("%s: disney brdf max error / bound %.3g\n", Target(), worst);
}
#endif  // BRDFBAKE_WITH_DISNEY

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace brdfbake {
HWY_BEFORE_TEST(SimdSheenTest);
#if BRDFBAKE_WITH_CHARLIE
HWY_EXPORT_AND_TEST_P(SimdSheenTest, CheckCharlie);
HWY_EXPORT_AND_TEST_P(SimdSheenTest, CheckCharlieF64);
#endif
#if BRDFBAKE_WITH_DISNEY
HWY_EXPORT_AND_TEST_P(SimdSheenTest, CheckDisney);
#endif
}  // namespace brdfbake
#endif
