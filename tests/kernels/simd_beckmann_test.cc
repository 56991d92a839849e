// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The Beckmann SIMD kernels (beckmann-inl.h, beckmann_sampling-inl.h and
// the float special functions of math-inl.h) against the double scalar
// references on every compiled target (one gtest case per target): dense
// sweeps including alpha 1e-4, anisotropy 1000:1, grazing directions down to
// mu = 1e-6 and the Lambda argument a from 1e-7 to 1e8; the NDF and
// visible-normal samplers against the scalar ones for the same (u1, u2),
// with u near 0 and 1; erf^-1 on a dense sweep of [0, 1]. Each check
// asserts the bound documented beside the kernel and prints the observed
// maximum.

#include <algorithm>
#include <boost/math/special_functions/erf.hpp>
#include <cmath>
#include <iomanip>
#include <random>
#include <cstdio>
#include <vector>

#include "brdfbake/batch.h"
#include "brdfbake/targets.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "tests/kernels/simd_beckmann_test.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>
#include <hwy/tests/hwy_gtest.h>

#include "kernels/beckmann_sampling-inl.h"
#include "kernels/math-inl.h"
#include "kernels/simd_slope_test-inl.h"

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace {

void CheckMath() {
  // erfc on [-10, 10.5]; erfcx and h on [0, 30] densely, then out to 1e30.
  std::vector<float> xs, ps;
  for (int i = 0; i <= 205000; ++i) xs.push_back(-10.0f + 1e-4f * i);
  for (int i = 0; i <= 300000; ++i) ps.push_back(1e-4f * i);
  for (int i = 0; i <= 2000; ++i)
    ps.push_back(static_cast<float>(std::pow(10.0, 1.5 + 28.5 * i / 2000)));
  ps.push_back(std::numeric_limits<float>::infinity());
  const auto erfc = Map(xs, [](auto d, auto v) { return Erfc(d, v); });
  const auto ens = Map(xs, [](auto d, auto v) { return ExpNegSquare(d, v); });
  const auto erfcx = Map(ps, [](auto d, auto v) { return Erfcx(d, v); });
  const auto ierfc = Map(ps, [](auto d, auto v) {
    decltype(v) num, den;
    IerfcScaled(d, v, &num, &den);
    return hn::Div(num, den);
  });
  const double sqrt_pi = 1.7724538509055159;
  double w_erfc = 0, w_ens = 0, w_erfcx = 0, w_h = 0;
  for (size_t i = 0; i < xs.size(); ++i) {
    const double x = xs[i];
    const double ref = std::erfc(x);
    if (ref >= FLT_MIN) {
      const double e = RelErr(erfc[i], ref);
      w_erfc = std::max(w_erfc, e);
      ASSERT_LE(e, kErfcRel) << "erfc x=" << x << " got " << erfc[i] << " ref " << ref;
    } else {
      ASSERT_LE(std::abs(erfc[i] - ref), 4.5e-45) << "erfc x=" << x;
    }
    const double ref_e = std::exp(-x * x);
    if (ref_e >= FLT_MIN) {
      const double e = RelErr(ens[i], ref_e);
      w_ens = std::max(w_ens, e);
      ASSERT_LE(e, kExpNegSqRel) << "exp(-x^2) x=" << x << " got " << ens[i] << " ref " << ref_e;
    } else {
      ASSERT_LE(std::abs(ens[i] - ref_e), 4.5e-45)
          << "exp(-x^2) x=" << x << " got " << ens[i] << " ref " << ref_e;
    }
  }
  for (size_t i = 0; i < ps.size(); ++i) {
    const double x = ps[i];
    double ref_x, ref_h;
    if (x <= 25) {
      ref_x = std::exp(x * x) * std::erfc(x);
      // 1 - sqrt(pi) x erfcx(x) cancels 2 x^2 digits: 1e-13 at x = 25.
      ref_h = 1 - sqrt_pi * x * ref_x;
    } else {
      const double t = 1 / (2 * x * x);  // asymptotic series, exact to double here
      ref_x = (1 - t * (1 - 3 * t * (1 - 5 * t * (1 - 7 * t)))) / (x * sqrt_pi);
      ref_h = t * (1 - 3 * t * (1 - 5 * t * (1 - 7 * t * (1 - 9 * t))));
    }
    const double ex = RelErr(erfcx[i], ref_x);
    // The quotient's denominator 1 + 2 a^2 overflows beyond a = 1.3e19.
    const double eh = x > 1e19 && !std::isinf(x) ? 0.0 : RelErr(ierfc[i], ref_h);
    w_erfcx = std::max(w_erfcx, ex);
    w_h = std::max(w_h, eh);
    ASSERT_LE(ex, kErfcxRel) << "erfcx x=" << x << " got " << erfcx[i] << " ref " << ref_x;
    ASSERT_LE(eh, kIerfcRel) << "h x=" << x << " got " << ierfc[i] << " ref " << ref_h;
  }
  std::printf("%s: max rel error erfc %.3g (bound %.2g), exp(-x^2) %.3g, erfcx %.3g, h %.3g\n",
              hwy::TargetName(HWY_TARGET), w_erfc, kErfcRel, w_ens, w_erfcx, w_h);
}

void CheckBeckmannDAndLambda() {
  const Dirs m = TestDirs(20000, 3);
  std::vector<float> d_out(m.size()), l_out(m.size());
  double worst_d[2] = {0, 0}, worst_l = 0;
  for (const auto& al : kAlphas) {
    BatchModel p{ModelKind::kBeckmann};
    p.alpha_x = al[0];
    p.alpha_y = al[1];
    const BeckmannNdf<double> ndf(al[0], al[1]);
    EvalBatch(p, Quantity::kD, {m.x.data(), m.y.data(), m.z.data()}, d_out.data(), m.size());
    EvalBatch(p, Quantity::kLambda, {m.x.data(), m.y.data(), m.z.data()}, l_out.data(), m.size());
    CheckDLambda(
        m, d_out, l_out, [&](const Vec3<double>& v) { return ndf.D(v); },
        [&](const Vec3<double>& v) { return ndf.Lambda(v); }, ndf.alpha_x(), ndf.alpha_y(), kInf,
        kBeckDRel, kExpSlope, kBeckLambda, worst_d, &worst_l, "Beckmann");
    if (::testing::Test::HasFailure()) return;
  }
  std::printf(
      "%s: Beckmann D max rel error %.3g at r2 <= 1, %.3g at r2 <= 87 (bound %.1g + %.2g r2), "
      "Lambda %.3g (bound %.1g)\n",
      hwy::TargetName(HWY_TARGET), worst_d[1], worst_d[0], kBeckDRel, kExpSlope, worst_l,
      kBeckLambda);
}

// 1.5 is clamped to 1.5 + 1e-6 (as the reference does); 1e9 is the largest STD
// proper tested, 2e10 already runs the Beckmann kernels.

void CheckBeckmannBrdf() {
  const Dirs wi = TestDirs(20000, 1), wo = TestDirs(20000, 2);
  double worst[2] = {0, 0};
  for (const auto& al : kAlphas) {
    const BeckmannNdf<double> ndf(al[0], al[1]);
    CheckBrdf(
        "Beckmann", ndf, kInf,
        [&](Masking masking, float f0, float* out) {
          BatchModel p{ModelKind::kBeckmann};
          p.alpha_x = al[0];
          p.alpha_y = al[1];
          p.f0 = f0;
          p.masking = masking;
          EvalBatch(p, Quantity::kBrdf, {wi.x.data(), wi.y.data(), wi.z.data()},
                    {wo.x.data(), wo.y.data(), wo.z.data()}, out, wi.size());
        },
        wi, wo, kBeckBrdfRel, kBrdfExpSlope, worst);
    if (::testing::Test::HasFailure()) return;
  }
  std::printf(
      "%s: Beckmann BRDF max rel error %.3g at r2 <= 1, %.3g at r2 <= 87 (bound %.1g + %.2g r2)\n",
      hwy::TargetName(HWY_TARGET), worst[1], worst[0], kBeckBrdfRel, kBrdfExpSlope);
}

void CheckBeckmannSampleNdf() {
  std::vector<float> u1, u2;
  SampleUs(20000, &u1, &u2);
  const size_t n = u1.size();
  std::vector<float> mx(n), my(n), mz(n);
  double worst_b = 0;
  auto compare = [&](const Vec3<double>& ref, size_t i, double* worst) {
    const double e =
        std::max({std::abs(mx[i] - ref.x), std::abs(my[i] - ref.y), std::abs(mz[i] - ref.z)});
    *worst = std::max(*worst, e);
    return e;
  };
  for (const auto& al : kAlphas) {
    BatchModel bp{ModelKind::kBeckmann};
    bp.alpha_x = al[0];
    bp.alpha_y = al[1];
    SampleBatch(bp, Sampler::kNdf, {}, u1.data(), u2.data(), {mx.data(), my.data(), mz.data()}, n);
    const BeckmannNdf<double> bndf(al[0], al[1]);
    for (size_t i = 0; i < n; ++i) {
      const Vec3<double> ref = bndf.SampleNdf(u1[i], u2[i]);
      ASSERT_LE(compare(ref, i, &worst_b), kNdfSampleAbs)
          << "Beckmann u=" << u1[i] << "," << u2[i] << " alpha " << al[0] << "," << al[1];
    }
  }
  std::printf("%s: Beckmann SampleNdf max abs error %.3g (bound %.2g)\n",
              hwy::TargetName(HWY_TARGET), worst_b, kNdfSampleAbs);
}

// erf^-1(2u - 1) on 2^20 + 1 points of [0, 1], the tails 2^-k and 1 - 2^-k,
// and below the clamp (q < 2^-53), against boost's erfc_inv in double.
void CheckErfInv() {
  std::vector<float> u;
  for (uint32_t i = 0; i <= (1u << 20); ++i) u.push_back(static_cast<float>(i) / (1u << 20));
  for (int k = 1; k <= 149; ++k) u.push_back(std::ldexp(1.0f, -k));
  for (int k = 1; k <= 24; ++k) u.push_back(1.0f - std::ldexp(1.0f, -k));
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  for (int i = 0; i < 100000; ++i) u.push_back(static_cast<float>(std::exp2(-60 * uni(rng))));
  const std::vector<float> y = Map(
      u, [](auto d, auto v) { return ErfInvCentered(d, v); }, 0.5f);
  double worst = 0;
  for (size_t i = 0; i < u.size(); ++i) {
    const double q = std::max(std::min<double>(u[i], 1.0 - u[i]), 0x1p-53);
    const double mag = boost::math::erfc_inv(2 * q);
    const double ref = u[i] < 0.5f ? -mag : mag;
    const double e = ref == 0 ? std::abs(y[i]) : RelErr(y[i], ref);
    worst = std::max(worst, e);
    ASSERT_LE(e, kErfInvRel) << "u " << u[i] << " got " << y[i] << " ref " << ref;
  }
  std::printf("%s: erf^-1(2u - 1) max rel error %.3g (bound %.2g)\n", Target(), worst, kErfInvRel);
}

void CheckBeckmannSampleVisible() {
  // The random set, then a grid: 100 views with mu log-spaced over [1e-4, 1]
  // times 100 values of u1 crowded at both ends (1 - u1 down to 2^-24).
  Dirs wo = Views(20000, 11);
  std::vector<float> u1 = Uniforms(20000, 12), u2 = Uniforms(20000, 13);
  for (int i = 0; i < 100; ++i) {
    for (int j = 0; j < 100; ++j) {
      wo.Push(FromMuPhi(std::pow(10.0, -4.0 + 4.0 * i / 99), 0.1 + 0.37 * j));
      const double t = std::exp2(-24.0 * std::abs(j - 49.5) / 49.5);
      u1.push_back(static_cast<float>(j < 50 ? t : 1 - t));
      u2.push_back(u2[i * 100 + j]);
    }
  }
  const size_t n = wo.size();
  std::vector<float> mx(n), my(n), mz(n), pdf(n);
  double worst = 0, worst_raw = 0, worst_pdf = 0, worst_dot = 1;
  for (const auto& a : kSamplingAlphas) {
    BatchModel p{ModelKind::kBeckmann};
    p.alpha_x = a[0];
    p.alpha_y = a[1];
    const BeckmannNdf<double> ndf(a[0], a[1]);
    SampleBatch(p, Sampler::kVisible, {wo.x.data(), wo.y.data(), wo.z.data()}, u1.data(), u2.data(),
                {mx.data(), my.data(), mz.data()}, n);
    EvalBatch(p, Quantity::kPdfVisible, {wo.x.data(), wo.y.data(), wo.z.data()},
              {mx.data(), my.data(), mz.data()}, pdf.data(), n);
    for (size_t i = 0; i < n; ++i) {
      const Vec3<double> w = wo.At(i), got(mx[i], my[i], mz[i]);
      const Vec3<double> ref = ndf.SampleVisible(w, u1[i], u2[i]);
      const double err = CheckNormal(w, got, ref, a[0], a[1], true, &worst_dot);
      worst = std::max(worst, err);
      worst_raw = std::max(worst_raw, MaxAbsDiff(got, ref));
      ASSERT_LE(err, kVisibleSampleAbs)
          << "alpha " << a[0] << "," << a[1] << " i=" << i << " wo " << w.x << "," << w.y << ","
          << w.z << " u " << u1[i] << "," << u2[i] << " got " << got.x << "," << got.y << ","
          << got.z << " ref " << ref.x << "," << ref.y << "," << ref.z;
      const double wm = Dot(w, got);
      if (!(wm > 0) || !(got.z > 0)) continue;
      const double pref = ndf.PdfVisible(w, got);
      const double q =
          PdfRatio(pdf[i], pref, DExponent(got, a[0], a[1], HUGE_VAL), kBeckSlope, wm, true);
      worst_pdf = std::max(worst_pdf, q);
      ASSERT_LE(q, 1.0) << "pdf i=" << i << " got " << pdf[i] << " ref " << pref << " w.m " << wm;
    }
  }
  std::printf(
      "%s: Beckmann SampleVisible max error %.3g (bound %.1g; raw m %.3g; min wo.m %.3g), "
      "PdfVisible error / bound %.3g\n",
      Target(), worst, kVisibleSampleAbs, worst_raw, worst_dot, worst_pdf);
}

// The same kernels in double lanes (the sampling integrators' samplers,
// src/sampling/slope_sampling_simd.cc): erf^-1 against boost's erfc_inv, and
// BeckmannSampleVisible and BeckmannPdfVisible against BeckmannNdf<double>
// for the same double (u1, u2), on the random views and the grid of
// CheckBeckmannSampleVisible with 1 - u1 and u1 down to 2^-50.
constexpr double kF64ErfInvRel = 1e-15;  // erf^-1: relative, + 4e-16 absolute
constexpr double kF64VisibleAbs = 1e-14;  // the unit-roughness normal, max component
constexpr double kF64PdfRel = 1e-13;      // + 2e-16 / (w.m), the rounding of w.m
void CheckBeckmannSamplingF64() {
  using DD = hn::ScalableTag<double>;
  const DD dd;
  const size_t N = hn::Lanes(dd);
  std::vector<double> u;
  for (uint32_t i = 0; i <= (1u << 18); ++i) u.push_back(static_cast<double>(i) / (1u << 18));
  for (int k = 1; k <= 60; ++k) {
    u.push_back(std::ldexp(1.0, -k));
    u.push_back(1.0 - std::ldexp(1.0, -std::min(k, 53)));
  }
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  for (int i = 0; i < 50000; ++i) u.push_back(uni(rng));
  while (u.size() % N) u.push_back(0.5);
  double worst_inv = 0;
  for (size_t i = 0; i < u.size(); i += N) {
    HWY_ALIGN double y[HWY_MAX_BYTES / 8];
    hn::Store(ErfInvCentered(dd, hn::LoadU(dd, u.data() + i)), dd, y);
    for (size_t k = 0; k < N; ++k) {
      const double q = std::max(std::min(u[i + k], 1.0 - u[i + k]), 0x1p-53);
      const double mag = boost::math::erfc_inv(2 * q);
      const double ref = u[i + k] < 0.5 ? -mag : mag;
      const double e = std::abs(y[k] - ref) / (kF64ErfInvRel * std::abs(ref) + 4e-16);
      worst_inv = std::max(worst_inv, e);
      ASSERT_LE(e, 1.0) << "u " << u[i + k] << " got " << y[k] << " ref " << ref;
    }
  }
  const Dirs views = Views(20000, 11);
  std::vector<double> wx, wy, wz, u1, u2;
  const std::vector<float> r1 = Uniforms(20000, 12), r2 = Uniforms(20000, 13);
  for (size_t i = 0; i < views.size(); ++i) {
    const Vec3<double> w = Normalize(views.At(i));
    wx.push_back(w.x), wy.push_back(w.y), wz.push_back(w.z);
    u1.push_back(std::min(r1[i] + 0x1p-30 * r2[i], 1.0));
    u2.push_back(std::min(r2[i] + 0x1p-30 * r1[i], 1.0));
  }
  for (int i = 0; i < 100; ++i) {
    for (int j = 0; j < 100; ++j) {
      const Vec3<double> w = FromMuPhi(std::pow(10.0, -4.0 + 4.0 * i / 99), 0.1 + 0.37 * j);
      wx.push_back(w.x), wy.push_back(w.y), wz.push_back(w.z);
      const double t = std::exp2(-50.0 * std::abs(j - 49.5) / 49.5);
      u1.push_back(j < 50 ? t : 1 - t);
      u2.push_back(u2[i * 100 + j]);
    }
  }
  const size_t n = wx.size();
  while (wx.size() % N) {
    wx.push_back(0), wy.push_back(0), wz.push_back(1), u1.push_back(0.5), u2.push_back(0.5);
  }
  std::vector<double> mx(wx.size()), my(wx.size()), mz(wx.size()), pdf(wx.size());
  double worst = 0, worst_pdf = 0;
  for (const auto& a : kSamplingAlphas) {
    const BeckmannNdf<double> ndf(a[0], a[1]);
    const BeckmannConsts<DD> c(dd, a[0], a[1], 1.0);
    for (size_t i = 0; i < wx.size(); i += N) {
      const auto x = hn::LoadU(dd, &wx[i]), y = hn::LoadU(dd, &wy[i]), z = hn::LoadU(dd, &wz[i]);
      hn::Vec<DD> ox, oy, oz;
      BeckmannSampleVisible(dd, c, x, y, z, hn::LoadU(dd, &u1[i]), hn::LoadU(dd, &u2[i]), &ox,
                            &oy, &oz);
      hn::StoreU(ox, dd, &mx[i]);
      hn::StoreU(oy, dd, &my[i]);
      hn::StoreU(oz, dd, &mz[i]);
      hn::StoreU(BeckmannPdfVisible(dd, c, x, y, z, ox, oy, oz), dd, &pdf[i]);
    }
    const double cax = std::max<double>(a[0], 1e-4), cay = std::max<double>(a[1], 1e-4);
    for (size_t i = 0; i < n; ++i) {
      const Vec3<double> w(wx[i], wy[i], wz[i]), got(mx[i], my[i], mz[i]);
      const Vec3<double> ref = ndf.SampleVisible(w, u1[i], u2[i]);
      const double e = MaxAbsDiff(Unstretch(got, cax, cay), Unstretch(ref, cax, cay));
      worst = std::max(worst, e);
      ASSERT_LE(e, kF64VisibleAbs) << "alpha " << a[0] << "," << a[1] << " i=" << i
                                   << std::setprecision(17) << " wo " << w.x << "," << w.y << ","
                                   << w.z << " u " << u1[i] << "," << u2[i] << " got " << got.x
                                   << "," << got.y << "," << got.z << " ref " << ref.x << ","
                                   << ref.y << "," << ref.z;
      const double wm = Dot(w, got);
      if (!(wm > 1e-300) || !(got.z > 0)) continue;
      const double pref = ndf.PdfVisible(w, got);
      if (!(pref > 1e-300)) continue;
      const double pe = std::abs(pdf[i] - pref) / pref / (kF64PdfRel + 2.2e-16 / wm);
      worst_pdf = std::max(worst_pdf, pe);
      ASSERT_LE(pe, 1.0) << "pdf i=" << i << " got " << pdf[i] << " ref " << pref;
    }
  }
  double worst_ndf = 0;
  for (const auto& a : kSamplingAlphas) {
    const BeckmannNdf<double> ndf(a[0], a[1]);
    const BeckmannConsts<DD> c(dd, a[0], a[1], 1.0);
    worst_ndf = std::max(
        worst_ndf, CheckNdfSamplerF64(
                       [&](DD d, auto v1, auto v2, auto* x, auto* y, auto* z) {
                         BeckmannSampleNdf(d, c, v1, v2, x, y, z);
                       },
                       [&](double v1, double v2) { return ndf.SampleNdf(v1, v2); },
                       "Beckmann SampleNdf, double lanes"));
  }
  std::printf("%s: double lanes: erf^-1 error / bound %.3g; Beckmann SampleVisible max error "
              "%.3g (bound %.0e), PdfVisible error / bound %.3g, SampleNdf max error %.3g "
              "(bound %.0e)\n",
              Target(), worst_inv, worst, kF64VisibleAbs, worst_pdf, worst_ndf, kF64NdfSampleAbs);
}

// Every branch of Algorithm 1: sigma <= 0.01 (NDF), gamma > 10 (Beckmann),
// the GGX, NDF and Beckmann bands between.

}  // namespace
}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace brdfbake {
HWY_BEFORE_TEST(SimdBeckmannTest);
HWY_EXPORT_AND_TEST_P(SimdBeckmannTest, CheckMath);
HWY_EXPORT_AND_TEST_P(SimdBeckmannTest, CheckBeckmannDAndLambda);
HWY_EXPORT_AND_TEST_P(SimdBeckmannTest, CheckBeckmannBrdf);
HWY_EXPORT_AND_TEST_P(SimdBeckmannTest, CheckBeckmannSampleNdf);
HWY_EXPORT_AND_TEST_P(SimdBeckmannTest, CheckErfInv);
HWY_EXPORT_AND_TEST_P(SimdBeckmannTest, CheckBeckmannSampleVisible);
HWY_EXPORT_AND_TEST_P(SimdBeckmannTest, CheckBeckmannSamplingF64);
}  // namespace brdfbake
#endif
