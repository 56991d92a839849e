// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The Beckmann and STD SIMD kernels (and the float special functions of
// src/simd/math-inl.h) against the double scalar references on every compiled
// target (one gtest case per target): dense sweeps including alpha 1e-4,
// anisotropy 1000:1, grazing directions down to mu = 1e-6, a dense sweep of
// the Lambda argument a from 1e-7 to 1e8, gamma from 1.501 to 1e6 and +inf;
// the NDF samplers against the scalar SampleNdf for the same (u1, u2). Each
// check asserts the bound documented beside the kernel and prints the
// observed maximum.

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <random>
#include <vector>

#include "brdfbake/batch.h"
#include "brdfbake/kernel_bounds.h"
#include "brdfbake/beckmann.h"
#include "brdfbake/brdf.h"
#include "brdfbake/std_ndf.h"

#include "simd_test_util.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "tests/simd_beckmann_std_test.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>
#include <hwy/tests/hwy_gtest.h>

#include "simd/math-inl.h"

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;
namespace {  // internal linkage: other test files define their own helpers

using test::Dirs;

// Documented bounds (src/simd/math-inl.h, beckmann-inl.h, std-inl.h).
constexpr double kErfcRel = 3.5e-7;     // Erfc where erfc(x) >= FLT_MIN
constexpr double kErfcxRel = 3e-7;      // Erfcx on [0, inf)
constexpr double kIerfcRel = 3e-7;     // IerfcScaled
constexpr double kExpNegSqRel = 1.5e-7; // ExpNegSquare where normal
// (bounds:: in include/brdfbake/kernel_bounds.h states them for the library.)
constexpr double kBeckDRel = 1e-6, kBeckLambda = 1e-6, kBeckBrdfRel = 2e-6;
constexpr double kStudentTDRel = 1e-6, kStudentTLambda = 1e-6, kStudentTBrdfRel = 2e-6;
// Relative error per unit of the exponent (Beckmann r2 and a^2, STD E).
constexpr double kExpSlope = bounds::kBeckmannExpSlope,
                 kStudentTExpSlope = bounds::kStudentTExpSlope;
constexpr double kBrdfExpSlope = bounds::kBeckmannBrdfExpSlope;
static_assert(kBeckDRel + kExpSlope == bounds::SlopeD(1, bounds::kBeckmannExpSlope) &&
                  kBeckBrdfRel + kBrdfExpSlope == bounds::SlopeBrdf(1, kBrdfExpSlope),
              "the test's bounds are the library's");
constexpr double kSampleAbs = 1e-6;     // sampled normals, per component
constexpr double kInf = std::numeric_limits<double>::infinity();
// The batch calls flush subnormals to zero (src/batch.cc):
// results whose exponential factor exp(-E) is below FLT_MIN (E > 87.3, with
// some slack for the rounding of E) or whose value is below FLT_MIN may be 0.
constexpr double kFlushExponent = bounds::kFlushExponent;


// Directions with mu spread log-uniformly down to 1e-6 plus exact poles, then
// directions whose isotropic a = cot(theta) runs log-uniformly over
// [1e-7, 1e8] (dense around the form switch of the STD Lambda at a = 1.25).
Dirs TestDirs(size_t n, uint64_t seed) {
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
std::vector<float> Map(const std::vector<float>& x, const Fn& fn) {
  const hn::ScalableTag<float> d;
  const size_t N = hn::Lanes(d);
  std::vector<float> in(x), out((x.size() + N - 1) / N * N);
  in.resize(out.size(), 0.0f);
  for (size_t i = 0; i < in.size(); i += N) hn::StoreU(fn(d, hn::LoadU(d, &in[i])), d, &out[i]);
  out.resize(x.size());
  return out;
}

double RelErr(double got, double ref) {
  if (std::isinf(ref)) return std::isinf(got) ? 0.0 : 1.0;
  if (ref == 0) return got == 0 ? 0.0 : 1.0;
  return std::abs(got - ref) / std::abs(ref);
}

// Error of a value whose exact form carries a factor exp(-e): relative to
// (rel + slope e) |ref|, or flushed to 0 (see kFlushExponent). Returns
// err / allowed (<= 1 passes).
double ExpScaledRatio(double got, double ref, double e, double rel, double slope) {
  const double err = std::abs(got - ref);
  if (err == 0) return 0;
  double allowed = (rel + slope * e) * std::abs(ref) + FLT_MIN;
  if (e > kFlushExponent) allowed += std::abs(ref);
  return err / allowed;
}

void CheckMath() {
  // erfc on [-10, 10.5]; erfcx and h on [0, 30] densely, then out to 1e30.
  std::vector<float> xs, ps;
  for (int i = 0; i <= 205000; ++i) xs.push_back(-10.0f + 1e-4f * i);
  for (int i = 0; i <= 300000; ++i) ps.push_back(1e-4f * i);
  for (int i = 0; i <= 2000; ++i) ps.push_back(static_cast<float>(std::pow(10.0, 1.5 + 28.5 * i / 2000)));
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
      ASSERT_LE(std::abs(ens[i] - ref_e), 4.5e-45) << "exp(-x^2) x=" << x << " got " << ens[i] << " ref " << ref_e;
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

// Exponent r2 of D at the (unnormalized) normal m, and the STD's E.
double SlopeR2(const Vec3<double>& m, double ax, double ay) {
  const double sx = m.x / ax, sy = m.y / ay;
  return (sx * sx + sy * sy) / (m.z * m.z);
}
double StudentTExponentE(double r2, double gamma) {
  if (std::isinf(gamma) || gamma >= 1e10) return r2;
  const double g = std::max(gamma, kMinStudentTGamma<double>);
  return g * std::log1p(r2 / (g - 1));
}
double LambdaA(const Vec3<double>& w, double ax, double ay) {
  return w.z / std::hypot(ax * w.x, ay * w.y);
}

using LambdaFn = std::function<double(const Vec3<double>&)>;
using DFn = std::function<double(const Vec3<double>&)>;

// D and Lambda of one model against the reference; returns the worst ratios.
void CheckDLambda(const Dirs& m, const std::vector<float>& d_out,
                  const std::vector<float>& l_out, const DFn& ref_d, const LambdaFn& ref_l,
                  double ax, double ay, double gamma, double d_rel, double slope, double l_abs,
                  double worst_d[2],
                  double* worst_l, const char* what) {
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
    CheckDLambda(m, d_out, l_out, [&](const Vec3<double>& v) { return ndf.D(v); },
                 [&](const Vec3<double>& v) { return ndf.Lambda(v); }, ndf.alpha_x(),
                 ndf.alpha_y(), kInf, kBeckDRel, kExpSlope, kBeckLambda, worst_d, &worst_l, "Beckmann");
    if (::testing::Test::HasFailure()) return;
  }
  std::printf("%s: Beckmann D max rel error %.3g at r2 <= 1, %.3g at r2 <= 87 (bound %.1g + %.2g r2), "
              "Lambda %.3g (bound %.1g)\n",
              hwy::TargetName(HWY_TARGET), worst_d[1], worst_d[0], kBeckDRel, kExpSlope, worst_l,
              kBeckLambda);
}

// 1.5 is clamped to 1.5 + 1e-6 (as the reference does); 1e9 is the largest STD
// proper tested, 2e10 already runs the Beckmann kernels.
const float kGammas[] = {1.5f, 1.501f, 1.6f, 2.0f, 3.0f, 7.5f, 30.0f, 1e4f, 1e6f, 1e9f, 2e10f,
                         std::numeric_limits<float>::infinity()};

#if BRDFBAKE_WITH_STD
void CheckStudentTDAndLambda() {
  const Dirs m = TestDirs(8000, 13);
  std::vector<float> d_out(m.size()), l_out(m.size());
  for (float gamma : kGammas) {
    double worst_d[2] = {0, 0}, worst_l = 0;
    for (const auto& al : kAlphas) {
      BatchModel p{ModelKind::kStudentT};
      p.alpha_x = al[0];
      p.alpha_y = al[1];
      p.gamma = gamma;
      const StudentTNdf<double> ndf(al[0], al[1], gamma);
      EvalBatch(p, Quantity::kD, {m.x.data(), m.y.data(), m.z.data()}, d_out.data(), m.size());
      EvalBatch(p, Quantity::kLambda, {m.x.data(), m.y.data(), m.z.data()}, l_out.data(), m.size());
      CheckDLambda(
          m, d_out, l_out, [&](const Vec3<double>& v) { return ndf.D(v); },
          [&](const Vec3<double>& v) { return ndf.Lambda(v); }, ndf.alpha_x(), ndf.alpha_y(), gamma,
          kStudentTDRel, kStudentTExpSlope, kStudentTLambda, worst_d, &worst_l, "STD");
      if (::testing::Test::HasFailure()) {
        std::printf("gamma %g alpha %g %g\n", gamma, al[0], al[1]);
        return;
      }
    }
    std::printf(
        "%s: STD gamma %g: D max rel error %.3g at E <= 1, %.3g at E <= 87 (bound %.1g + "
        "%.2g E), Lambda %.3g (bound %.1g)\n",
        hwy::TargetName(HWY_TARGET), gamma, worst_d[1], worst_d[0], kStudentTDRel,
        kStudentTExpSlope, worst_l, kStudentTLambda);
  }
}
#endif  // BRDFBAKE_WITH_STD

// The BRDF of either model against Brdf(ndf, Schlick, ...) in double.
template <class Ndf, class Batch>
void CheckBrdf(const char* name, const Ndf& ndf, double gamma, const Batch& batch,
               const Dirs& wi, const Dirs& wo, double rel, double slope, double worst[2]) {
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

void CheckBeckmannBrdf() {
  const Dirs wi = TestDirs(20000, 1), wo = TestDirs(20000, 2);
  double worst[2] = {0, 0};
  for (const auto& al : kAlphas) {
    const BeckmannNdf<double> ndf(al[0], al[1]);
    CheckBrdf("Beckmann", ndf, kInf, [&](Masking masking, float f0, float* out) {
      BatchModel p{ModelKind::kBeckmann};
      p.alpha_x = al[0];
      p.alpha_y = al[1];
      p.f0 = f0;
      p.masking = masking;
      EvalBatch(p, Quantity::kBrdf, {wi.x.data(), wi.y.data(), wi.z.data()},
                {wo.x.data(), wo.y.data(), wo.z.data()}, out, wi.size());
    }, wi, wo, kBeckBrdfRel, kBrdfExpSlope, worst);
    if (::testing::Test::HasFailure()) return;
  }
  std::printf(
      "%s: Beckmann BRDF max rel error %.3g at r2 <= 1, %.3g at r2 <= 87 (bound %.1g + %.2g r2)\n",
      hwy::TargetName(HWY_TARGET), worst[1], worst[0], kBeckBrdfRel, kBrdfExpSlope);
}

#if BRDFBAKE_WITH_STD
void CheckStudentTBrdf() {
  const Dirs wi = TestDirs(6000, 11), wo = TestDirs(6000, 12);
  for (float gamma : kGammas) {
    double worst[2] = {0, 0};
    for (const auto& al : kAlphas) {
      const StudentTNdf<double> ndf(al[0], al[1], gamma);
      CheckBrdf("STD", ndf, gamma, [&](Masking masking, float f0, float* out) {
        BatchModel p{ModelKind::kStudentT};
        p.alpha_x = al[0];
        p.alpha_y = al[1];
        p.gamma = gamma;
        p.f0 = f0;
        p.masking = masking;
        EvalBatch(p, Quantity::kBrdf, {wi.x.data(), wi.y.data(), wi.z.data()},
                  {wo.x.data(), wo.y.data(), wo.z.data()}, out, wi.size());
      }, wi, wo, kStudentTBrdfRel, kStudentTExpSlope, worst);
      if (::testing::Test::HasFailure()) return;
    }
    std::printf(
        "%s: STD gamma %g: BRDF max rel error %.3g at E <= 1, %.3g at E <= 87 (bound %.1g + "
        "%.2g E)\n",
        hwy::TargetName(HWY_TARGET), gamma, worst[1], worst[0], kStudentTBrdfRel,
        kStudentTExpSlope);
  }
}
#endif  // BRDFBAKE_WITH_STD

// (u1, u2) pairs: a random cloud plus the corners (u2 up to 1 - 2^-24).
void SampleUs(size_t n, std::vector<float>* u1, std::vector<float>* u2) {
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

void CheckSamplersMatchScalar() {
  std::vector<float> u1, u2;
  SampleUs(20000, &u1, &u2);
  const size_t n = u1.size();
  std::vector<float> mx(n), my(n), mz(n);
  double worst_b = 0, worst_s = 0;
  auto compare = [&](const Vec3<double>& ref, size_t i, double* worst) {
    const double e = std::max({std::abs(mx[i] - ref.x), std::abs(my[i] - ref.y),
                               std::abs(mz[i] - ref.z)});
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
      ASSERT_LE(compare(ref, i, &worst_b), kSampleAbs)
          << "Beckmann u=" << u1[i] << "," << u2[i] << " alpha " << al[0] << "," << al[1];
    }
#if BRDFBAKE_WITH_STD
    for (float gamma : kGammas) {
      BatchModel sp{ModelKind::kStudentT};
      sp.alpha_x = al[0];
      sp.alpha_y = al[1];
      sp.gamma = gamma;
      SampleBatch(sp, Sampler::kNdf, {}, u1.data(), u2.data(), {mx.data(), my.data(), mz.data()},
                  n);
      const StudentTNdf<double> sndf(al[0], al[1], gamma);
      for (size_t i = 0; i < n; ++i) {
        const Vec3<double> ref = sndf.SampleNdf(u1[i], u2[i]);
        ASSERT_LE(compare(ref, i, &worst_s), kSampleAbs)
            << "STD gamma " << gamma << " u=" << u1[i] << "," << u2[i] << " alpha " << al[0]
            << "," << al[1] << " got " << mx[i] << " " << my[i] << " " << mz[i] << " ref "
            << ref.x << " " << ref.y << " " << ref.z;
      }
    }
#endif
  }
  std::printf("%s: SampleNdf max abs error Beckmann %.3g, STD %.3g (bound %.2g)\n",
              hwy::TargetName(HWY_TARGET), worst_b, worst_s, kSampleAbs);
}

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
HWY_EXPORT_AND_TEST_P(SimdBeckmannTest, CheckSamplersMatchScalar);

#if BRDFBAKE_WITH_STD
HWY_BEFORE_TEST(SimdStudentTTest);
HWY_EXPORT_AND_TEST_P(SimdStudentTTest, CheckStudentTDAndLambda);
HWY_EXPORT_AND_TEST_P(SimdStudentTTest, CheckStudentTBrdf);
#endif
}  // namespace brdfbake
#endif
