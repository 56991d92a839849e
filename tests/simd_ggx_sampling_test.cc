// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The GGX samplers (ggx_sampling-inl.h) against GgxNdf<double> on every
// compiled target: the same (u1, u2) must give the scalar sampler's normal,
// and the densities the scalar ones; alpha down to 1e-4 and anisotropy
// 1000:1. Each test asserts the documented bound and prints the maximum.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <vector>

#include "brdfbake/batch.h"
#include "brdfbake/kernel_bounds.h"
#include "brdfbake/targets.h"
#include "brdfbake/ggx.h"

#include "simd_test_util.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "tests/simd_ggx_sampling_test.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>
#include <hwy/tests/hwy_gtest.h>

#include "simd/ggx_sampling-inl.h"

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace {

using test::Dirs;
using test::RandomDirs;
using test::RelErr;

// Documented bounds (src/simd/ggx_sampling-inl.h), against the double
// reference at the same float inputs.
constexpr double kSinCosAbs = 2.5e-7;
constexpr double kGgxSampleAbs = 2e-6;        // unit-roughness normal, max component
constexpr double kGgxPdfRel = 2e-6;           // plus 2e-7 / (w.m) from the dot product
constexpr double kGgxPdfDot = 2e-7;

using test::MaxAbsDiff;
using test::RandomUniforms;

const char* Target() { return hwy::TargetName(HWY_TARGET); }

}  // namespace

// ---------------------------------------------------------- GGX sampling

void CheckSinCos2Pi() {
  namespace hn = hwy::HWY_NAMESPACE;
  const hn::ScalableTag<float> d;
  const size_t lanes = hn::Lanes(d);
  std::vector<float> u;
  for (uint32_t i = 0; i <= (1u << 20); ++i) u.push_back(static_cast<float>(i) / (1u << 20));
  for (float x : {1e-30f, 1e-8f, 0.125f, 0.375f, 0.625f, 0.875f, 1 - 0x1p-24f, 2.5f, -0.3f}) {
    u.push_back(x);
  }
  while (u.size() % lanes) u.push_back(0.5f);
  std::vector<float> s(u.size()), c(u.size());
  for (size_t i = 0; i < u.size(); i += lanes) {
    hn::Vec<decltype(d)> vs, vc;
    SinCos2Pi(d, hn::LoadU(d, u.data() + i), &vs, &vc);
    hn::StoreU(vs, d, s.data() + i);
    hn::StoreU(vc, d, c.data() + i);
  }
  double worst = 0;
  for (size_t i = 0; i < u.size(); ++i) {
    const double phi = 2 * 3.141592653589793 * static_cast<double>(u[i]);
    const double err = std::max(std::abs(s[i] - std::sin(phi)), std::abs(c[i] - std::cos(phi)));
    worst = std::max(worst, err);
    ASSERT_LE(err, kSinCosAbs) << "u " << u[i] << " sin " << s[i] << " cos " << c[i];
  }
  std::printf("%s: SinCos2Pi max abs error %.3g (bound %.2g)\n", Target(), worst, kSinCosAbs);
}

namespace {

const float kGgxAlphas[][2] = {{1e-4f, 1e-4f}, {1e-3f, 1e-3f}, {0.05f, 0.05f}, {0.3f, 0.3f},
                               {1.0f, 1.0f},   {1.0f, 1e-3f},  {1e-3f, 1.0f},  {2e-3f, 0.8f}};

// The unit-roughness normal of seed 003 section 3.2.
Vec3<double> Unstretch(const Vec3<double>& m, double ax, double ay) {
  return Normalize(Vec3<double>(m.x / ax, m.y / ay, m.z));
}

}  // namespace

void CheckGgxSampleVisible() {
  const size_t n = 20000;
  const Dirs wo = RandomDirs(n, 11);
  const std::vector<float> u1 = RandomUniforms(n, 12), u2 = RandomUniforms(n, 13);
  std::vector<float> mx(n), my(n), mz(n), pdf(n);
  double worst = 0, worst_raw = 0, worst_pdf = 0;
  for (const auto& a : kGgxAlphas) {
    BatchModel p{ModelKind::kGgx};
    p.alpha_x = a[0];
    p.alpha_y = a[1];
    const GgxNdf<double> ndf(a[0], a[1]);
    SampleBatch(p, Sampler::kVisible, {wo.x.data(), wo.y.data(), wo.z.data()}, u1.data(), u2.data(),
                {mx.data(), my.data(), mz.data()}, n);
    EvalBatch(p, Quantity::kPdfVisible, {wo.x.data(), wo.y.data(), wo.z.data()},
              {mx.data(), my.data(), mz.data()}, pdf.data(), n);
    for (size_t i = 0; i < n; ++i) {
      const Vec3<double> ref = ndf.SampleVisible(wo.At(i), u1[i], u2[i]);
      const Vec3<double> got(mx[i], my[i], mz[i]);
      const double err = MaxAbsDiff(Unstretch(got, a[0], a[1]), Unstretch(ref, a[0], a[1]));
      worst = std::max(worst, err);
      worst_raw = std::max(worst_raw, MaxAbsDiff(got, ref));
      ASSERT_LE(err, kGgxSampleAbs) << "alpha " << a[0] << "," << a[1] << " i=" << i << " u "
                                    << u1[i] << "," << u2[i] << " got " << got.x << ","
                                    << got.y << "," << got.z << " ref " << ref.x << ","
                                    << ref.y << "," << ref.z;
      // The density at the sampled normal.
      const double wm = Dot(wo.At(i), got);
      if (!(wm > 1e-6) || !(got.z > 0)) continue;
      const double pref = ndf.PdfVisible(wo.At(i), got);
      const double perr = RelErr(pdf[i], pref);
      worst_pdf = std::max(worst_pdf, perr / (kGgxPdfRel + kGgxPdfDot / wm));
      ASSERT_LE(perr, kGgxPdfRel + kGgxPdfDot / wm) << "i=" << i << " got " << pdf[i] << " ref "
                                                    << pref;
    }
  }
  std::printf("%s: GGX SampleVisible max error %.3g (bound %.1g; raw m %.3g), PdfVisible "
              "error / bound %.3g\n",
              Target(), worst, kGgxSampleAbs, worst_raw, worst_pdf);
}

void CheckGgxPdfVisibleRandom() {
  const size_t n = 20000;
  const Dirs wo = RandomDirs(n, 14), m = RandomDirs(n, 15);
  std::vector<float> out(n);
  double worst = 0;
  for (const auto& a : kGgxAlphas) {
    BatchModel p{ModelKind::kGgx};
    p.alpha_x = a[0];
    p.alpha_y = a[1];
    const GgxNdf<double> ndf(a[0], a[1]);
    EvalBatch(p, Quantity::kPdfVisible, {wo.x.data(), wo.y.data(), wo.z.data()},
              {m.x.data(), m.y.data(), m.z.data()}, out.data(), n);
    for (size_t i = 0; i < n; ++i) {
      const double wm = Dot(wo.At(i), m.At(i));
      if (std::abs(wm) < 1e-6) continue;
      const double ref = ndf.PdfVisible(wo.At(i), m.At(i));
      const double allowed = kGgxPdfRel + kGgxPdfDot / std::abs(wm);
      const double err = RelErr(out[i], ref);
      worst = std::max(worst, err / allowed);
      ASSERT_LE(err, allowed) << "i=" << i << " got " << out[i] << " ref " << ref;
    }
  }
  std::printf("%s: GGX PdfVisible (random m) error / bound %.3g\n", Target(), worst);
}

void CheckGgxSampleNdf() {
  const size_t n = 20000;
  const std::vector<float> u1 = RandomUniforms(n, 16), u2 = RandomUniforms(n, 17);
  std::vector<float> mx(n), my(n), mz(n), pdf(n);
  double worst = 0, worst_raw = 0, worst_pdf = 0;
  for (const auto& a : kGgxAlphas) {
    BatchModel p{ModelKind::kGgx};
    p.alpha_x = a[0];
    p.alpha_y = a[1];
    const GgxNdf<double> ndf(a[0], a[1]);
    SampleBatch(p, Sampler::kNdf, {}, u1.data(), u2.data(), {mx.data(), my.data(), mz.data()}, n);
    EvalBatch(p, Quantity::kPdfNdf, {mx.data(), my.data(), mz.data()}, pdf.data(), n);
    for (size_t i = 0; i < n; ++i) {
      const Vec3<double> ref = ndf.SampleNdf(u1[i], u2[i]);
      const Vec3<double> got(mx[i], my[i], mz[i]);
      const double err = MaxAbsDiff(Unstretch(got, a[0], a[1]), Unstretch(ref, a[0], a[1]));
      worst = std::max(worst, err);
      worst_raw = std::max(worst_raw, MaxAbsDiff(got, ref));
      ASSERT_LE(err, kGgxSampleAbs) << "alpha " << a[0] << "," << a[1] << " u " << u1[i] << ","
                                    << u2[i];
      if (!(got.z > 0)) continue;
      const double perr = RelErr(pdf[i], ndf.PdfNdf(got));
      worst_pdf = std::max(worst_pdf, perr);
      ASSERT_LE(perr, kGgxPdfRel) << i;
    }
  }
  std::printf("%s: GGX SampleNdf max error %.3g (bound %.1g; raw m %.3g), PdfNdf max rel %.3g\n",
              Target(), worst, kGgxSampleAbs, worst_raw, worst_pdf);
}

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace brdfbake {
HWY_BEFORE_TEST(SimdGgxSamplingTest);
HWY_EXPORT_AND_TEST_P(SimdGgxSamplingTest, CheckSinCos2Pi);
HWY_EXPORT_AND_TEST_P(SimdGgxSamplingTest, CheckGgxSampleVisible);
HWY_EXPORT_AND_TEST_P(SimdGgxSamplingTest, CheckGgxPdfVisibleRandom);
HWY_EXPORT_AND_TEST_P(SimdGgxSamplingTest, CheckGgxSampleNdf);
}  // namespace brdfbake
#endif
