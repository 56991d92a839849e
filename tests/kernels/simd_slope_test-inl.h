// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Per-target helpers of the Beckmann and STD SIMD tests
// (simd_beckmann_test.cc, simd_student_t_test.cc): the documented bounds,
// the direction and uniform sweeps, and the checks both models share.

#if defined(BRDFBAKE_TESTS_KERNELS_SIMD_SLOPE_TEST_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef BRDFBAKE_TESTS_KERNELS_SIMD_SLOPE_TEST_INL_H_
#undef BRDFBAKE_TESTS_KERNELS_SIMD_SLOPE_TEST_INL_H_
#else
#define BRDFBAKE_TESTS_KERNELS_SIMD_SLOPE_TEST_INL_H_
#endif

#include <hwy/highway.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <random>
#include <vector>

#include "brdfbake/batch.h"
#include "brdfbake/models/beckmann.h"
#include "brdfbake/models/brdf.h"
#include "brdfbake/models/kernel_bounds.h"
#include "brdfbake/models/std_ndf.h"
#include "util/simd_test_util.h"

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;
namespace {  // internal linkage: each test file has its own copy

using test::MaxAbsDiff;

using test::Dirs;

// Documented bounds (src/kernels/math-inl.h, beckmann-inl.h, std-inl.h).
constexpr double kErfcRel = 3.5e-7;      // Erfc where erfc(x) >= FLT_MIN
constexpr double kErfcxRel = 3e-7;       // Erfcx on [0, inf)
constexpr double kIerfcRel = 3e-7;       // IerfcScaled
constexpr double kExpNegSqRel = 1.5e-7;  // ExpNegSquare where normal
// (bounds:: in include/brdfbake/models/kernel_bounds.h states them for the library.)
constexpr double kBeckDRel = 1e-6, kBeckLambda = 1e-6, kBeckBrdfRel = 2e-6;
constexpr double kStudentTDRel = 1e-6, kStudentTLambda = 1e-6, kStudentTBrdfRel = 2e-6;
// Relative error per unit of the exponent (Beckmann r2 and a^2, STD E).
constexpr double kExpSlope = bounds::kBeckmannExpSlope,
                 kStudentTExpSlope = bounds::kStudentTExpSlope;
constexpr double kBrdfExpSlope = bounds::kBeckmannBrdfExpSlope;
static_assert(kBeckDRel + kExpSlope == bounds::SlopeD(1, bounds::kBeckmannExpSlope) &&
                  kBeckBrdfRel + kBrdfExpSlope == bounds::SlopeBrdf(1, kBrdfExpSlope),
              "the test's bounds are the library's");
constexpr double kNdfSampleAbs = 1e-6;  // sampled normals, per component
constexpr double kInf = std::numeric_limits<double>::infinity();
// The batch calls flush subnormals to zero (src/kernels/batch.cc):
// results whose exponential factor exp(-E) is below FLT_MIN (E > 87.3, with
// some slack for the rounding of E) or whose value is below FLT_MIN may be 0.
constexpr double kFlushExponent = bounds::kFlushExponent;

// Directions with mu spread log-uniformly down to 1e-6 plus exact poles, then
// directions whose isotropic a = cot(theta) runs log-uniformly over
// [1e-7, 1e8] (dense around the form switch of the STD Lambda at a = 1.25).
inline Dirs TestDirs(size_t n, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  Dirs d;
  for (size_t i = 0; i < n; ++i) {
    double mu = i % 7 == 0 ? std::pow(10.0, -6 * uni(rng)) : uni(rng);
    if (i % 97 == 0) mu = 1.0;
    d.Push(FromMuPhi(mu, 2 * 3.141592653589793 * uni(rng)));
  }
  for (int i = 0; i <= 3000; ++i) {
    const double a = std::pow(10.0, -7.0 + 15.0 * i / 3000.0);
    const double phi = 2 * 3.141592653589793 * uni(rng);
    d.Push(FromMuPhi(a / std::sqrt(1 + a * a), phi));
  }
  for (int i = 0; i <= 1000; ++i) {
    const double a = 0.5 + 1.5 * i / 1000.0;
    d.Push(FromMuPhi(a / std::sqrt(1 + a * a), 0.3 * i));
  }
  return d;
}

// Applies a vector function to every element of x on this target.
template <class Fn>
inline std::vector<float> Map(const std::vector<float>& x, const Fn& fn, float pad = 0.0f) {
  const hn::ScalableTag<float> d;
  const size_t N = hn::Lanes(d);
  std::vector<float> in(x), out((x.size() + N - 1) / N * N);
  in.resize(out.size(), pad);
  for (size_t i = 0; i < in.size(); i += N) hn::StoreU(fn(d, hn::LoadU(d, &in[i])), d, &out[i]);
  out.resize(x.size());
  return out;
}

inline double RelErr(double got, double ref) {
  if (std::isinf(ref)) return std::isinf(got) ? 0.0 : 1.0;
  if (ref == 0) return got == 0 ? 0.0 : 1.0;
  return std::abs(got - ref) / std::abs(ref);
}

// Error of a value whose exact form carries a factor exp(-e): relative to
// (rel + slope e) |ref|, or flushed to 0 (see kFlushExponent). Returns
// err / allowed (<= 1 passes).
inline double ExpScaledRatio(double got, double ref, double e, double rel, double slope) {
  const double err = std::abs(got - ref);
  if (err == 0) return 0;
  double allowed = (rel + slope * e) * std::abs(ref) + FLT_MIN;
  if (e > kFlushExponent) allowed += std::abs(ref);
  return err / allowed;
}

// Exponent r2 of D at the (unnormalized) normal m, and the STD's E.
inline double SlopeR2(const Vec3<double>& m, double ax, double ay) {
  const double sx = m.x / ax, sy = m.y / ay;
  return (sx * sx + sy * sy) / (m.z * m.z);
}
inline double StudentTExponentE(double r2, double gamma) {
  if (std::isinf(gamma) || gamma >= 1e10) return r2;
  const double g = std::max(gamma, kMinStudentTGamma<double>);
  return g * std::log1p(r2 / (g - 1));
}
inline double LambdaA(const Vec3<double>& w, double ax, double ay) {
  return w.z / std::hypot(ax * w.x, ay * w.y);
}

using LambdaFn = std::function<double(const Vec3<double>&)>;
using DFn = std::function<double(const Vec3<double>&)>;

// D and Lambda of one model against the reference; returns the worst ratios.
inline void CheckDLambda(const Dirs& m, const std::vector<float>& d_out,
                         const std::vector<float>& l_out, const DFn& ref_d, const LambdaFn& ref_l,
                         double ax, double ay, double gamma, double d_rel, double slope,
                         double l_abs, double worst_d[2], double* worst_l, const char* what) {
  for (size_t i = 0; i < m.size(); ++i) {
    const Vec3<double> v = m.At(i);
    const double e = StudentTExponentE(SlopeR2(v, ax, ay), gamma);
    const double rd = ref_d(v);
    const double qd = ExpScaledRatio(d_out[i], rd, e, d_rel, slope);
    if (e <= kFlushExponent && rd > 1e-36) worst_d[0] = std::max(worst_d[0], RelErr(d_out[i], rd));
    if (e <= 1) worst_d[1] = std::max(worst_d[1], RelErr(d_out[i], rd));
    ASSERT_LE(qd, 1.0) << what << " D i=" << i << " got " << d_out[i] << " ref " << rd
                       << " exponent " << e << " m " << v.x << " " << v.y << " " << v.z;
    const double rl = ref_l(v);
    const double a = LambdaA(v, ax, ay);
    if (std::isinf(rl)) {
      ASSERT_TRUE(std::isinf(l_out[i])) << i;
      continue;
    }
    const double err = std::abs(l_out[i] - rl);
    const double allowed = l_abs * std::max(1.0, rl) + kExpSlope * std::min(a * a, 1e30) * rl;
    *worst_l = std::max(*worst_l, err / std::max(1.0, rl));
    ASSERT_LE(err, allowed) << what << " Lambda i=" << i << " a=" << a << " got " << l_out[i]
                            << " ref " << rl;
  }
}

const float kAlphas[][2] = {{1e-4f, 1e-4f}, {1e-3f, 1e-3f}, {0.05f, 0.05f}, {0.3f, 0.3f},
                            {1.0f, 1.0f},   {1.0f, 1e-3f},  {2e-3f, 0.8f}};

// 1.5000011f (1.50000107...) is the smallest float in the domain, >= 1.5 + 1e-6.
const float kGammas[] = {1.5000011f, 1.501f, 1.6f, 2.0f, 3.0f,  7.5f,
                         30.0f, 1e4f,   1e6f, 1e9f, 2e10f, std::numeric_limits<float>::infinity()};

// The BRDF of either model against Brdf(ndf, Schlick, ...) in double.
template <class Ndf, class Batch>
void CheckBrdf(const char* name, const Ndf& ndf, double gamma, const Batch& batch, const Dirs& wi,
               const Dirs& wo, double rel, double slope, double worst[2]) {
  std::vector<float> out(wi.size());
  for (Masking masking : {Masking::kHeightCorrelated, Masking::kSeparable}) {
    for (float f0 : {1.0f, 0.04f}) {
      batch(masking, f0, out.data());
      const Fresnel fr = Fresnel::Schlick({f0, f0, f0});
      for (size_t i = 0; i < wi.size(); ++i) {
        const Vec3<double> a = wi.At(i), b = wo.At(i);
        const double ref = Brdf(ndf, fr, a, b, masking);
        const Vec3<double> s = a + b;
        const double e = StudentTExponentE(SlopeR2(s, ndf.alpha_x(), ndf.alpha_y()), gamma);
        const double q = ExpScaledRatio(out[i], ref, e, rel, slope);
        if (e <= kFlushExponent && ref > 1e-36) worst[0] = std::max(worst[0], RelErr(out[i], ref));
        if (e <= 1) worst[1] = std::max(worst[1], RelErr(out[i], ref));
        ASSERT_LE(q, 1.0) << name << " gamma " << gamma << " alpha " << ndf.alpha_x() << ","
                          << ndf.alpha_y() << " " << MaskingName(masking) << " f0 " << f0
                          << " i=" << i << " got " << out[i] << " ref " << ref << " exponent " << e;
      }
    }
  }
}

// (u1, u2) pairs: a random cloud plus the corners (u2 up to 1 - 2^-24).
inline void SampleUs(size_t n, std::vector<float>* u1, std::vector<float>* u2) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<float> uni(0.0f, 1.0f);
  for (size_t i = 0; i < n; ++i) {
    u1->push_back(uni(rng));
    u2->push_back(i % 5 == 0 ? 1.0f - std::pow(10.0f, -7.0f * uni(rng)) : uni(rng));
  }
  for (float a : {0.0f, 0.25f, 0.5f, 0.75f, 0.99999994f}) {
    for (float b : {0.0f, 1e-7f, 0.5f, 0.9999f, 0.99999994f}) {
      u1->push_back(a);
      u2->push_back(b);
    }
  }
}

// An NDF sampler in double lanes, `sample(d, u1, u2, &mx, &my, &mz)`,
// against its scalar twin `ref(u1, u2)` (slope_ndf.h SampleNdf) at the
// SampleUs points with 30 more random low bits, plus u2 from 1 - 2^-53 to 1
// and u1 at the quadrant edges: returns the largest |m - m_ref| (max
// component) and asserts `bound` (kF64NdfSampleAbs unless stated).
constexpr double kF64NdfSampleAbs = 1e-14;
template <class Sample, class Ref>
double CheckNdfSamplerF64(const Sample& sample, const Ref& ref, const char* what,
                          double bound = kF64NdfSampleAbs) {
  using DD = hn::ScalableTag<double>;
  const DD dd;
  const size_t N = hn::Lanes(dd);
  std::vector<float> f1, f2;
  SampleUs(20000, &f1, &f2);
  std::vector<double> u1, u2;
  for (size_t i = 0; i < f1.size(); ++i) {
    u1.push_back(std::min(f1[i] + 0x1p-30 * f2[i], 1.0));
    u2.push_back(std::min(f2[i] + 0x1p-30 * f1[i], 1.0));
  }
  for (double a : {0.0, 0.125, 0.25, 0.5, 0.75, 1 - 0x1p-53}) {
    for (double b : {0.0, 1e-300, 0.5, 1 - 0x1p-40, 1 - 0x1p-53, 1.0}) {
      u1.push_back(a);
      u2.push_back(b);
    }
  }
  const size_t n = u1.size();
  while (u1.size() % N) u1.push_back(0.5), u2.push_back(0.5);
  double worst = 0;
  for (size_t i = 0; i < n; i += N) {
    hn::Vec<DD> x, y, z;
    sample(dd, hn::LoadU(dd, &u1[i]), hn::LoadU(dd, &u2[i]), &x, &y, &z);
    HWY_ALIGN double mx[HWY_MAX_BYTES / 8], my[HWY_MAX_BYTES / 8], mz[HWY_MAX_BYTES / 8];
    hn::Store(x, dd, mx);
    hn::Store(y, dd, my);
    hn::Store(z, dd, mz);
    for (size_t k = 0; k < N && i + k < n; ++k) {
      const Vec3<double> r = ref(u1[i + k], u2[i + k]);
      const double e = std::max({std::abs(mx[k] - r.x), std::abs(my[k] - r.y), std::abs(mz[k] - r.z)});
      worst = std::max(worst, e);
      EXPECT_LE(e, bound) << what << " u " << u1[i + k] << "," << u2[i + k];
    }
  }
  return worst;
}

// Documented bounds (src/kernels/beckmann_sampling-inl.h, std_sampling-inl.h,
// and the kernels these reuse), against the double reference at the same
// float inputs.
constexpr double kErfInvRel = 3e-7;
constexpr double kVisibleSampleAbs =
    2e-6;                         // unit-roughness normal (VNDF) or m (NDF), max component
constexpr double kPdfRel = 2e-6;  // densities: plus kPdfDot / (w.m) for the visible ones
constexpr double kPdfDot = 2e-7;
// Relative error of D per unit of its exponent; the batch calls flush
// densities whose exponential factor is below FLT_MIN (kernel_bounds.h).
constexpr double kBeckSlope = bounds::kBeckmannExpSlope, kStudentTSlope = bounds::kStudentTExpSlope;

inline const char* Target() { return hwy::TargetName(HWY_TARGET); }

// Views: mu uniform, or log-uniform down to 1e-4 (grazing), or the pole.
inline Dirs Views(size_t n, uint64_t seed) {
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
inline std::vector<float> Uniforms(size_t n, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  std::vector<float> u(n);
  for (size_t i = 0; i < n; ++i) {
    const double t = uni(rng);
    switch (i % 4) {
      case 2:
        u[i] = static_cast<float>(std::exp2(-40 * t));
        break;
      case 3:
        u[i] = 1.0f - static_cast<float>(std::exp2(-1 - 23 * t));
        break;
      default:
        u[i] = static_cast<float>(t);
    }
    if (i % 101 == 0) u[i] = 0.0f;
    if (i % 103 == 0) u[i] = 1.0f;
  }
  return u;
}

// The unit-roughness normal of [Heitz18] section 3.2, where the sampling map
// does not depend on alpha.
inline Vec3<double> Unstretch(const Vec3<double>& m, double ax, double ay) {
  return Normalize(Vec3<double>(m.x / ax, m.y / ay, m.z));
}

// Exponent of D at m: r2 for Beckmann, gamma log1p(r2 / (gamma - 1)) for STD.
inline double DExponent(const Vec3<double>& m, double ax, double ay, double gamma) {
  const double sx = m.x / ax, sy = m.y / ay;
  const double r2 = (sx * sx + sy * sy) / (m.z * m.z);
  if (std::isinf(gamma) || gamma >= 1e10) return r2;
  const double g = std::max(gamma, kMinStudentTGamma<double>);
  return g * std::log1p(r2 / (g - 1));
}

// Density error over its bound (<= 1 passes): relative rel + slope E, plus
// kPdfDot / (w.m) when `visible`; anything goes where the batch flushes.
inline double PdfRatio(double got, double ref, double e, double slope, double wm, bool visible) {
  const double err = std::abs(got - ref);
  if (err == 0) return 0;
  double allowed = (kPdfRel + slope * e + (visible ? kPdfDot / wm : 0.0)) * std::abs(ref) + FLT_MIN;
  if (e > kFlushExponent) allowed += std::abs(ref);
  return err / allowed;
}

// Checks one sampled normal: a unit vector, facing the view where the
// reference's does, within kSampleAbs of the reference (in the
// unit-roughness configuration for visible normals). Returns the error.
inline double CheckNormal(const Vec3<double>& wo, const Vec3<double>& got, const Vec3<double>& ref,
                          double ax, double ay, bool visible, double* worst_dot) {
  EXPECT_NEAR(Length(got), 1.0, 1e-6);
  const double err =
      visible ? MaxAbsDiff(Unstretch(got, ax, ay), Unstretch(ref, ax, ay)) : MaxAbsDiff(got, ref);
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

const float kSamplingAlphas[][2] = {{1e-4f, 1e-4f}, {1e-3f, 1e-3f}, {0.05f, 0.05f}, {0.3f, 0.3f},
                                    {1.0f, 1.0f},   {1.0f, 1e-3f},  {1e-3f, 1.0f},  {2e-3f, 0.8f}};

}  // namespace
}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#endif  // BRDFBAKE_TESTS_KERNELS_SIMD_SLOPE_TEST_INL_H_
