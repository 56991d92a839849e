// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The Beckmann visible-normal sampler and the STD pseudo-VNIS
// (batch.h) against their double scalar references on every
// compiled target (one gtest case per target): for the same (u1, u2) the
// kernel must return the reference's normal, within the bound documented
// beside the kernel, over alpha from 1e-4 to 1, anisotropy 1000:1, views
// down to mu = 1e-4 and the pole, u near 0 and 1 (down to 2^-40 and 2^-24
// from the ends), gamma from 1.5 to 1e6 and +inf; the normal must be a unit
// vector facing the view; the densities at the sampled normals against the
// reference densities. Also erf^-1 (beckmann_sampling-inl.h) on a dense
// sweep of [0, 1]. Each check prints the observed maximum.

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <vector>

#include <boost/math/special_functions/erf.hpp>

#include "brdfbake/batch.h"
#include "brdfbake/targets.h"
#include "brdfbake/beckmann.h"
#include "brdfbake/kernel_bounds.h"
#include "brdfbake/std_ndf.h"

#include "simd_test_util.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "tests/simd_sampling_test.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>
#include <hwy/tests/hwy_gtest.h>

#include "simd/beckmann_sampling-inl.h"

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;
namespace {  // internal linkage: other test files define their own helpers

using test::Dirs;

// Documented bounds (src/simd/beckmann_sampling-inl.h, std_sampling-inl.h,
// and the kernels these reuse), against the double reference at the same
// float inputs.
constexpr double kErfInvRel = 3e-7;
constexpr double kSampleAbs = 2e-6;   // unit-roughness normal (VNDF) or m (NDF), max component
constexpr double kPdfRel = 2e-6;      // densities: plus kPdfDot / (w.m) for the visible ones
constexpr double kPdfDot = 2e-7;
// Relative error of D per unit of its exponent; the batch calls flush
// densities whose exponential factor is below FLT_MIN (kernel_bounds.h).
constexpr double kBeckSlope = bounds::kBeckmannExpSlope, kStudentTSlope = bounds::kStudentTExpSlope;
constexpr double kFlushExponent = bounds::kFlushExponent;

const char* Target() { return hwy::TargetName(HWY_TARGET); }


// Views: mu uniform, or log-uniform down to 1e-4 (grazing), or the pole.
Dirs Views(size_t n, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  Dirs d;
  for (size_t i = 0; i < n; ++i) {
    double mu = i % 3 == 0 ? std::pow(10.0, -4 * uni(rng)) : uni(rng);
    if (i % 97 == 0) mu = 1.0;
    d.Push(FromMuPhi(std::max(mu, 1e-4), 2 * 3.141592653589793 * uni(rng)));
  }
  return d;
}

// Uniforms: half uniform on [0, 1), a quarter log-uniform in distance from 0
// and a quarter from 1 (down to 2^-40 and 2^-24, the float spacing below 1),
// and the ends themselves now and then.
std::vector<float> Uniforms(size_t n, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  std::vector<float> u(n);
  for (size_t i = 0; i < n; ++i) {
    const double t = uni(rng);
    switch (i % 4) {
      case 2: u[i] = static_cast<float>(std::exp2(-40 * t)); break;
      case 3: u[i] = 1.0f - static_cast<float>(std::exp2(-1 - 23 * t)); break;
      default: u[i] = static_cast<float>(t);
    }
    if (i % 101 == 0) u[i] = 0.0f;
    if (i % 103 == 0) u[i] = 1.0f;
  }
  return u;
}

double MaxAbsDiff(const Vec3<double>& a, const Vec3<double>& b) {
  return std::max({std::abs(a.x - b.x), std::abs(a.y - b.y), std::abs(a.z - b.z)});
}

// The unit-roughness normal of seed 003 section 3.2, where the sampling map
// does not depend on alpha.
Vec3<double> Unstretch(const Vec3<double>& m, double ax, double ay) {
  return Normalize(Vec3<double>(m.x / ax, m.y / ay, m.z));
}

double RelErr(double got, double ref) {
  if (ref == 0) return got == 0 ? 0.0 : 1.0;
  return std::abs(got - ref) / std::abs(ref);
}

// Exponent of D at m: r2 for Beckmann, gamma log1p(r2 / (gamma - 1)) for STD.
double DExponent(const Vec3<double>& m, double ax, double ay, double gamma) {
  const double sx = m.x / ax, sy = m.y / ay;
  const double r2 = (sx * sx + sy * sy) / (m.z * m.z);
  if (std::isinf(gamma) || gamma >= 1e10) return r2;
  const double g = std::max(gamma, kMinStudentTGamma<double>);
  return g * std::log1p(r2 / (g - 1));
}

// Density error over its bound (<= 1 passes): relative rel + slope E, plus
// kPdfDot / (w.m) when `visible`; anything goes where the batch flushes.
double PdfRatio(double got, double ref, double e, double slope, double wm, bool visible) {
  const double err = std::abs(got - ref);
  if (err == 0) return 0;
  double allowed = (kPdfRel + slope * e + (visible ? kPdfDot / wm : 0.0)) * std::abs(ref) + FLT_MIN;
  if (e > kFlushExponent) allowed += std::abs(ref);
  return err / allowed;
}

// Checks one sampled normal: a unit vector, facing the view where the
// reference's does, within kSampleAbs of the reference (in the
// unit-roughness configuration for visible normals). Returns the error.
double CheckNormal(const Vec3<double>& wo, const Vec3<double>& got, const Vec3<double>& ref,
                   double ax, double ay, bool visible, double* worst_dot) {
  EXPECT_NEAR(Length(got), 1.0, 1e-6);
  const double err = visible ? MaxAbsDiff(Unstretch(got, ax, ay), Unstretch(ref, ax, ay))
                             : MaxAbsDiff(got, ref);
  if (visible && wo.z > 0) {
    // wo.m is exactly 0 at u1 = 1 (the edge of the visible slopes); elsewhere
    // it has the sign of the reference's, and never more than rounding below 0.
    const double d_got = Dot(wo, got), d_ref = Dot(wo, ref);
    *worst_dot = std::min(*worst_dot, d_got);
    EXPECT_GE(d_got, -2e-7);
    if (d_ref > 1e-6) {
      EXPECT_GT(d_got, 0.0);
    }
  }
  return err;
}

// Applies a vector function to every element of x on this target.
template <class Fn>
std::vector<float> Map(const std::vector<float>& x, const Fn& fn) {
  const hn::ScalableTag<float> d;
  const size_t N = hn::Lanes(d);
  std::vector<float> in(x), out((x.size() + N - 1) / N * N);
  in.resize(out.size(), 0.5f);
  for (size_t i = 0; i < in.size(); i += N) hn::StoreU(fn(d, hn::LoadU(d, &in[i])), d, &out[i]);
  out.resize(x.size());
  return out;
}

const float kAlphas[][2] = {{1e-4f, 1e-4f}, {1e-3f, 1e-3f}, {0.05f, 0.05f}, {0.3f, 0.3f},
                            {1.0f, 1.0f},   {1.0f, 1e-3f},  {1e-3f, 1.0f},  {2e-3f, 0.8f}};

}  // namespace

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
  const std::vector<float> y = Map(u, [](auto d, auto v) { return ErfInvCentered(d, v); });
  double worst = 0;
  for (size_t i = 0; i < u.size(); ++i) {
    const double q = std::max(std::min<double>(u[i], 1.0 - u[i]), 0x1p-53);
    const double mag = boost::math::erfc_inv(2 * q);
    const double ref = u[i] < 0.5f ? -mag : mag;
    const double e = ref == 0 ? std::abs(y[i]) : RelErr(y[i], ref);
    worst = std::max(worst, e);
    ASSERT_LE(e, kErfInvRel) << "u " << u[i] << " got " << y[i] << " ref " << ref;
  }
  std::printf("%s: erf^-1(2u - 1) max rel error %.3g (bound %.2g)\n", Target(), worst,
              kErfInvRel);
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
  for (const auto& a : kAlphas) {
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
      ASSERT_LE(err, kSampleAbs) << "alpha " << a[0] << "," << a[1] << " i=" << i << " wo "
                                 << w.x << "," << w.y << "," << w.z << " u " << u1[i] << ","
                                 << u2[i] << " got " << got.x << "," << got.y << "," << got.z
                                 << " ref " << ref.x << "," << ref.y << "," << ref.z;
      const double wm = Dot(w, got);
      if (!(wm > 0) || !(got.z > 0)) continue;
      const double pref = ndf.PdfVisible(w, got);
      const double q = PdfRatio(pdf[i], pref, DExponent(got, a[0], a[1], HUGE_VAL), kBeckSlope,
                                wm, true);
      worst_pdf = std::max(worst_pdf, q);
      ASSERT_LE(q, 1.0) << "pdf i=" << i << " got " << pdf[i] << " ref " << pref << " w.m " << wm;
    }
  }
  std::printf("%s: Beckmann SampleVisible max error %.3g (bound %.1g; raw m %.3g; min wo.m %.3g), "
              "PdfVisible error / bound %.3g\n",
              Target(), worst, kSampleAbs, worst_raw, worst_dot, worst_pdf);
}

// Every branch of Algorithm 1: sigma <= 0.01 (NDF), gamma > 10 (Beckmann),
// the GGX, NDF and Beckmann bands between.
#if BRDFBAKE_WITH_STD
void CheckStudentTPseudoVnis() {
  const size_t n = 4000;
  const Dirs wo = Views(n, 21);
  const std::vector<float> u1 = Uniforms(n, 22), u2 = Uniforms(n, 23);
  std::vector<float> mx(n), my(n), mz(n), pdf(n);
  const float gammas[] = {1.5f, 1.501f, 2.0f, 3.0f, 4.5f, 6.0f, 7.5f, 9.0f, 12.0f, 30.0f,
                          1e4f, 1e6f,   2e10f, HUGE_VALF};
  const float alphas[][2] = {{1e-4f, 1e-4f}, {0.01f, 0.01f}, {0.05f, 0.05f}, {0.15f, 0.15f},
                             {0.25f, 0.25f}, {0.3f, 0.3f},   {0.6f, 0.6f},   {1.0f, 1.0f},
                             {1.0f, 1e-3f},  {2e-3f, 0.8f}};
  double worst[3] = {0, 0, 0}, worst_pdf[3] = {0, 0, 0}, worst_dot = 1;
  int cases[3] = {0, 0, 0};
  for (float gamma : gammas) {
    for (const auto& a : alphas) {
      BatchModel p{ModelKind::kStudentT};
      p.alpha_x = a[0];
      p.alpha_y = a[1];
      p.gamma = gamma;
      const StudentTNdf<double> ndf(a[0], a[1], gamma);
      const int branch = ndf.PseudoVnisBranch();
      ++cases[branch];
      SampleBatch(p, Sampler::kVisible, {wo.x.data(), wo.y.data(), wo.z.data()}, u1.data(),
                  u2.data(), {mx.data(), my.data(), mz.data()}, n);
      EvalBatch(p, Quantity::kPdfVisible, {wo.x.data(), wo.y.data(), wo.z.data()},
                {mx.data(), my.data(), mz.data()}, pdf.data(), n);
      const bool visible = branch != 0;
      const double slope = branch == 1 ? 0.0 : branch == 2 ? kBeckSlope : kStudentTSlope;
      for (size_t i = 0; i < n; ++i) {
        const Vec3<double> w = wo.At(i), got(mx[i], my[i], mz[i]);
        // u2 = 1 is outside the NDF sampler's [0, 1) (StudentTSampleNdf clamps it
        // to 1 - 2^-24, the reference to 1 - 2^-53).
        if (branch == 0 && u2[i] == 1.0f) continue;
        const Vec3<double> ref = ndf.SamplePseudoVnis(w, u1[i], u2[i]);
        const double err = CheckNormal(w, got, ref, a[0], a[1], visible, &worst_dot);
        worst[branch] = std::max(worst[branch], err);
        ASSERT_LE(err, kSampleAbs) << "gamma " << gamma << " alpha " << a[0] << "," << a[1]
                                   << " branch " << branch << " i=" << i << " u " << u1[i]
                                   << "," << u2[i] << " got " << got.x << "," << got.y << ","
                                   << got.z << " ref " << ref.x << "," << ref.y << "," << ref.z;
        const double wm = Dot(w, got);
        if (!(got.z > 0) || (visible && !(wm > 0))) continue;
        const double pref = ndf.PdfPseudoVnis(w, got);
        const double e = branch == 1 ? 0.0 : DExponent(got, a[0], a[1], branch == 2 ? HUGE_VAL : gamma);
        const double q = PdfRatio(pdf[i], pref, e, slope, wm, visible);
        worst_pdf[branch] = std::max(worst_pdf[branch], q);
        ASSERT_LE(q, 1.0) << "gamma " << gamma << " alpha " << a[0] << "," << a[1] << " branch "
                          << branch << " pdf i=" << i << " got " << pdf[i] << " ref " << pref;
      }
    }
  }
  EXPECT_GT(cases[0], 0);
  EXPECT_GT(cases[1], 0);
  EXPECT_GT(cases[2], 0);
  std::printf("%s: STD pseudo-VNIS max error (bound %.1g) NDF %.3g, GGX %.3g, Beckmann %.3g; "
              "min wo.m %.3g; pdf error / bound %.3g, %.3g, %.3g (%d, %d, %d materials)\n",
              Target(), kSampleAbs, worst[0], worst[1], worst[2], worst_dot, worst_pdf[0],
              worst_pdf[1], worst_pdf[2], cases[0], cases[1], cases[2]);
}
#endif  // BRDFBAKE_WITH_STD

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace brdfbake {
HWY_BEFORE_TEST(SimdBeckmannSamplingTest);
HWY_EXPORT_AND_TEST_P(SimdBeckmannSamplingTest, CheckErfInv);
HWY_EXPORT_AND_TEST_P(SimdBeckmannSamplingTest, CheckBeckmannSampleVisible);

#if BRDFBAKE_WITH_STD
HWY_BEFORE_TEST(SimdStudentTSamplingTest);
HWY_EXPORT_AND_TEST_P(SimdStudentTSamplingTest, CheckStudentTPseudoVnis);
#endif
}  // namespace brdfbake
#endif
