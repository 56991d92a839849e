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
#include <iomanip>
#include <random>
#include <vector>

#include "brdfbake/batch.h"
#include "brdfbake/models/ggx.h"
#include "brdfbake/models/kernel_bounds.h"
#include "brdfbake/targets.h"

#include "util/simd_test_util.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "tests/kernels/simd_ggx_sampling_test.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>
#include <hwy/tests/hwy_gtest.h>

#include "kernels/ggx_sampling-inl.h"

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace {

using test::Dirs;
using test::RandomDirs;
using test::RelErr;

// Documented bounds (src/kernels/ggx_sampling-inl.h), against the double
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

// The unit-roughness normal of [Heitz18] section 3.2.
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

// The samplers and pdfs in double lanes (ggx_sampling-inl.h is generic over
// the lane type) against the double reference at the same inputs:
// SinCos2Pi within 4e-16 absolute, the unit-roughness normals of
// SampleVisible within 1e-14 plus the reference's own rim error (below)
// and SampleNdf within 1e-14 (max component), PdfVisible
// within 1e-14 + 1e-15 / (w.m) relative and PdfNdf within 1e-14 relative.
constexpr double kF64SinCosAbs = 4e-16, kF64SampleAbs = 1e-14, kF64PdfRel = 1e-14,
                 kF64PdfDot = 1e-15;

void CheckGgxSamplingF64() {
  namespace hn = hwy::HWY_NAMESPACE;
  using DD = hn::ScalableTag<double>;
  const DD dd;
  const size_t N = hn::Lanes(dd);
  // SinCos2Pi on 2^20 + 1 points of [0, 1] and a few awkward ones.
  std::vector<double> u;
  for (uint32_t i = 0; i <= (1u << 20); ++i) u.push_back(static_cast<double>(i) / (1u << 20));
  for (double x : {1e-300, 1e-17, 0.125, 0.375, 0.625, 0.875, 1 - 0x1p-53, 0.3 + 1e-12, 2.5, -0.3}) {
    u.push_back(x);
  }
  while (u.size() % N) u.push_back(0.5);
  double worst_sc = 0;
  for (size_t i = 0; i < u.size(); i += N) {
    hn::Vec<DD> vs, vc;
    SinCos2Pi(dd, hn::LoadU(dd, u.data() + i), &vs, &vc);
    HWY_ALIGN double s[HWY_MAX_BYTES / 8], c[HWY_MAX_BYTES / 8];
    hn::Store(vs, dd, s);
    hn::Store(vc, dd, c);
    for (size_t k = 0; k < N; ++k) {
      // sin(2 pi u) from the exact reduction u = q / 4 + r / 4 (libm's
      // sin(2 pi u) would carry the rounding of 2 pi u).
      const double x = 4 * u[i + k], q = std::nearbyint(x), r = x - q;
      const double sr = std::sin(1.5707963267948966 * r), cr = std::cos(1.5707963267948966 * r);
      const int qm = static_cast<int>(((static_cast<long long>(q) % 4) + 4) % 4);
      const double rs = qm == 0 ? sr : qm == 1 ? cr : qm == 2 ? -sr : -cr;
      const double rc = qm == 0 ? cr : qm == 1 ? -sr : qm == 2 ? -cr : sr;
      const double err = std::max(std::abs(s[k] - rs), std::abs(c[k] - rc));
      worst_sc = std::max(worst_sc, err);
      ASSERT_LE(err, kF64SinCosAbs) << "u " << u[i + k];
    }
  }
  // The samplers.
  const size_t n = 20000, padded = (n + N - 1) / N * N;
  const Dirs wo32 = RandomDirs(n, 61);
  const std::vector<float> u1f = RandomUniforms(n, 62), u2f = RandomUniforms(n, 63);
  std::vector<double> wx(padded, 0), wy(padded, 0), wz(padded, 1), u1(padded, 0.5),
      u2(padded, 0.5);
  for (size_t i = 0; i < n; ++i) {
    const Vec3<double> w = Normalize(wo32.At(i));
    wx[i] = w.x, wy[i] = w.y, wz[i] = w.z;
    // Uniforms with all 53 bits in play.
    u1[i] = std::min(u1f[i] + 0x1p-30 * u2f[i], 1.0);
    u2[i] = std::min(u2f[i] + 0x1p-30 * u1f[i], 1.0);
  }
  std::vector<double> mx(padded), my(padded), mz(padded), pv(padded), nx(padded), ny(padded),
      nz(padded), pn(padded);
  double worst_v = 0, worst_n = 0, worst_pv = 0, worst_pn = 0;
  for (const auto& a : kGgxAlphas) {
    const GgxNdf<double> ndf(a[0], a[1]);
    const GgxSamplingConsts<DD> c(dd, a[0], a[1]);
    // The widths as both clamp them (at 1e-4 in double; a[] holds floats).
    const double cax = std::max<double>(a[0], 1e-4), cay = std::max<double>(a[1], 1e-4);
    for (size_t i = 0; i < padded; i += N) {
      const auto x = hn::LoadU(dd, &wx[i]), y = hn::LoadU(dd, &wy[i]), z = hn::LoadU(dd, &wz[i]);
      const auto v1 = hn::LoadU(dd, &u1[i]), v2 = hn::LoadU(dd, &u2[i]);
      hn::Vec<DD> ox, oy, oz;
      GgxSampleVisible(dd, c, x, y, z, v1, v2, &ox, &oy, &oz);
      hn::StoreU(ox, dd, &mx[i]);
      hn::StoreU(oy, dd, &my[i]);
      hn::StoreU(oz, dd, &mz[i]);
      hn::StoreU(GgxPdfVisible(dd, c, x, y, z, ox, oy, oz), dd, &pv[i]);
      GgxSampleNdf(dd, c, v1, v2, &ox, &oy, &oz);
      hn::StoreU(ox, dd, &nx[i]);
      hn::StoreU(oy, dd, &ny[i]);
      hn::StoreU(oz, dd, &nz[i]);
      hn::StoreU(GgxPdfNdf(dd, c, ox, oy, oz), dd, &pn[i]);
    }
    for (size_t i = 0; i < n; ++i) {
      const Vec3<double> w(wx[i], wy[i], wz[i]);
      const Vec3<double> got(mx[i], my[i], mz[i]), ref = ndf.SampleVisible(w, u1[i], u2[i]);
      // The reference's lift sqrt(1 - p1^2 - p2^2) cancels at the rim
      // (u1 -> 1), by about eps / lift with lift = nh.vh; the kernel's does
      // not (at alpha 1e-4, u1 = 1 - 1.2e-7, at the pole, the reference is
      // 5.6e-14 off the 50-digit value, the kernel within 1e-16 of it).
      const Vec3<double> nh_ref = Unstretch(ref, cax, cay);
      const Vec3<double> vh = Normalize(Vec3<double>(cax * w.x, cay * w.y, w.z));
      const double lift = std::max(Dot(nh_ref, vh), 1e-300);
      const double ev = MaxAbsDiff(Unstretch(got, cax, cay), nh_ref) /
                        (kF64SampleAbs + 2.220446049250313e-16 / lift);
      worst_v = std::max(worst_v, ev);
      ASSERT_LE(ev, 1.0) << "SampleVisible alpha " << a[0] << "," << a[1] << " i=" << i
                         << std::setprecision(17) << " w " << w.x << "," << w.y << "," << w.z
                         << " u " << u1[i] << "," << u2[i] << " lift " << lift << " got "
                         << got.x << "," << got.y << "," << got.z << " ref " << ref.x << ","
                         << ref.y << "," << ref.z;
      const double wm = Dot(w, got);
      if (wm > 1e-6 && got.z > 0) {
        const double pe = RelErr(pv[i], ndf.PdfVisible(w, got)) / (kF64PdfRel + kF64PdfDot / wm);
        worst_pv = std::max(worst_pv, pe);
        ASSERT_LE(pe, 1.0) << "PdfVisible i=" << i;
      }
      const Vec3<double> gn(nx[i], ny[i], nz[i]), rn = ndf.SampleNdf(u1[i], u2[i]);
      const double en = MaxAbsDiff(Unstretch(gn, cax, cay), Unstretch(rn, cax, cay));
      worst_n = std::max(worst_n, en);
      ASSERT_LE(en, kF64SampleAbs) << "SampleNdf alpha " << a[0] << "," << a[1] << " i=" << i;
      if (gn.z > 0) {
        const double pe = RelErr(pn[i], ndf.PdfNdf(gn));
        worst_pn = std::max(worst_pn, pe);
        ASSERT_LE(pe, kF64PdfRel) << "PdfNdf i=" << i << " got " << pn[i];
      }
    }
  }
  std::printf("%s: GGX sampling in double lanes: SinCos2Pi max abs error %.3g (bound %.0e), "
              "SampleVisible error / bound %.3g, SampleNdf %.3g (bound %.0e), PdfVisible error / bound %.3g, "
              "PdfNdf max rel %.3g (bound %.0e)\n",
              Target(), worst_sc, kF64SinCosAbs, worst_v, worst_n, kF64SampleAbs, worst_pv,
              worst_pn, kF64PdfRel);
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
HWY_EXPORT_AND_TEST_P(SimdGgxSamplingTest, CheckGgxSamplingF64);
}  // namespace brdfbake
#endif
