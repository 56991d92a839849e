// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The catastrophic cancellations of the stiff corners, each at the input
// where a naive formula fails, against 50-digit values of the same
// quantity (Boost.Multiprecision, where a naive formula is exact enough):
//  - 1 - cos near 0: the specular peak of the azimuthally integrated GGX
//    (src/rules/ggx/azimuthal.h), where theta_i - theta_o ~ alpha; the half-angle
//    form sin^2((theta_i - theta_o)/2) replaces 1 - cos(theta_i - theta_o);
//  - tan^2 at grazing: Lambda from the tangential components, never from
//    1 - mu^2; and cos(theta) near pi/2 from the complement;
//  - (gamma - 1)^gamma overflow: the STD at gamma up to 1e15;
//  - 1 - E near 1: the complement channel keeps its relative precision;
//  - the half vector when wi = -wo: zero, never NaN, in every kernel.

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include <boost/multiprecision/cpp_bin_float.hpp>
#include <gtest/gtest.h>

#include "brdfbake/bake.h"
#include "brdfbake/batch.h"
#include "brdfbake/exr.h"
#include "brdfbake/models/beckmann.h"
#include "brdfbake/models/brdf.h"
#include "brdfbake/models/ggx.h"
#include "brdfbake/models/std_ndf.h"
#include "rules/ggx/azimuthal.h"

namespace brdfbake {
namespace {

using Big = boost::multiprecision::number<boost::multiprecision::cpp_bin_float<50>>;

double RelErr(double got, const Big& ref) {
  return static_cast<double>(abs((Big(got) - ref) / ref));
}

// The azimuthal integral Phi(theta_i) of GGX's D in 50 digits from the
// textbook form (1 - cos differences and all): Phi = 2 alpha^2 (1 - 2k/R +
// k^2 C / R^3), R = sqrt(C^2 - B^2).
Big PhiNaive(double theta_i, double theta_o, double alpha) {
  const Big ti = theta_i, to = theta_o, a2 = Big(alpha) * alpha;
  const Big mi = cos(ti), mo = cos(to), si = sin(ti), so = sin(to);
  const Big s = mi + mo, k = (a2 - 1) * s * s;
  const Big c = k + 2 + 2 * mi * mo, b = 2 * si * so;
  const Big r = sqrt(c * c - b * b);
  return 2 * a2 * (1 - 2 * k / r + k * k * c / (r * r * r));
}

// GGX at tiny alpha with theta_i within 1e-9 .. 1e-5 of theta_o: the peak of
// height ~1/alpha^2 sits where C - B cancels to ~alpha^2 in the textbook
// form; the half-angle form keeps 1e-13.
TEST(CancellationTest, OneMinusCosAtTheSpecularPeak) {
  double worst = 0;
  for (double alpha : {1e-4, 1e-3}) {
    for (double theta_o : {1e-8, 0.3, 1.2, 1.5707}) {
      for (double d : {0.0, 1e-9, -1e-7, 1e-5, -3e-4}) {
        const double theta_i = theta_o + d;
        if (theta_i < 0 || theta_i > 1.5707963) continue;
        const double mu_o = std::cos(theta_o);
        const GgxAzimuthalE f(alpha, mu_o, Masking::kSeparable);
        // The integrand divided by G1(wi) G1(wo) sin(theta_i) / (4 mu_o) is Phi.
        const GgxNdf<double> ggx(alpha);
        const double g1i = ggx.G1(Vec3<double>(std::sin(theta_i), 0, std::cos(theta_i)));
        const double g1o = ggx.G1(Vec3<double>(std::sin(theta_o), 0, mu_o));
        const double phi = f(theta_i) / (g1i * g1o * std::sin(theta_i) / (4 * mu_o));
        // f takes theta_o from acos(mu_o): compare at that theta_o.
        const double err = RelErr(phi, PhiNaive(theta_i, std::acos(mu_o), alpha));
        worst = std::max(worst, err);
        EXPECT_LT(err, 1e-9) << "alpha " << alpha << " theta_o " << theta_o << " d " << d;
      }
    }
  }
  std::printf("Phi at the peak: max relative error %.3g\n", worst);
}

// Lambda at grazing (mu down to 1e-15, tan^2 up to 1e30) and at normal
// incidence (mu = 1 - 5e-19 .. 1, tan^2 down to 1e-18), from the direction's
// components as given, in double and in the SIMD kernels.
TEST(CancellationTest, TanSquaredAtGrazingAndNormalIncidence) {
  double worst_ggx = 0, worst_beck = 0, worst_simd = 0;
  for (double alpha : {1e-4, 0.1, 1.0}) {
    for (double s : {1.0, 1 - 1e-12, 0.5, 1e-3, 1e-9}) {
      // w = (s, 0, mu) with mu = sqrt(1 - s^2) formed stably.
      const double mu = std::sqrt((1 - s) * (1 + s));
      if (!(mu > 0)) continue;
      const Vec3<double> w(s, 0, mu);
      const Big t2 = (Big(s) * s) / (Big(mu) * mu);
      const Big a2 = Big(alpha) * alpha;
      // GGX: Lambda = (sqrt(1 + alpha^2 tan^2) - 1) / 2.
      const Big ggx_ref = (sqrt(1 + a2 * t2) - 1) / 2;
      const double e1 = RelErr(GgxNdf<double>(alpha).Lambda(w), ggx_ref);
      // Beckmann: (exp(-a^2) / (a sqrt(pi)) - erfc(a)) / 2, a = 1 / (alpha tan).
      const Big a = 1 / (Big(alpha) * sqrt(t2));
      const Big beck_ref =
          (exp(-a * a) / (a * sqrt(boost::math::constants::pi<Big>())) - erfc(a)) / 2;
      const double lb = BeckmannNdf<double>(alpha).Lambda(w);
      // Relative to max(1, Lambda) where Lambda underflows (a > 26).
      const double e2 = static_cast<double>(abs(Big(lb) - beck_ref) /
                                            (beck_ref > 1 ? beck_ref : Big(1)));
      worst_ggx = std::max(worst_ggx, e1);
      worst_beck = std::max(worst_beck, e2);
      EXPECT_LT(e1, 1e-14) << "alpha " << alpha << " s " << s;
      EXPECT_LT(e2, 1e-14) << "alpha " << alpha << " s " << s;
      // SIMD (float inputs: compare against the reference at those inputs).
      const float fx = static_cast<float>(s), fz = static_cast<float>(mu), fy = 0;
      if (!(fz > 0)) continue;
      const Big t2f = (Big(fx) * fx) / (Big(fz) * fz);
      const Big ggx_ref_f = (sqrt(1 + a2 * t2f) - 1) / 2;
      BatchModel gp{ModelKind::kGgx};
      gp.alpha_x = gp.alpha_y = static_cast<float>(alpha);
      float out = 0;
      EvalBatch(gp, Quantity::kLambda, {&fx, &fy, &fz}, &out, 1);
      // The kernel's alpha is the float one.
      const Big a2f = Big(gp.alpha_x) * gp.alpha_x;
      const Big ref_f = (sqrt(1 + a2f * t2f) - 1) / 2;
      (void)ggx_ref_f;
      const double e3 = static_cast<double>(abs(Big(out) - ref_f) / (1 + ref_f));
      worst_simd = std::max(worst_simd, e3);
      EXPECT_LT(e3, 2e-6) << "alpha " << alpha << " s " << s << " got " << out;
    }
  }
  std::printf("Lambda: GGX %.3g, Beckmann %.3g (double, relative), GGX SIMD %.3g (of 1 + L)\n",
              worst_ggx, worst_beck, worst_simd);
}

// cos(theta_i) near the horizon in the 1D albedo integrand: taken from the
// complement pi/2 - theta_i, so G2 ~ mu_i keeps its relative precision at
// mu_i ~ 1e-12 (the product of half-angle cosines lost 1e-4 there).
TEST(CancellationTest, CosineNearTheHorizon) {
  const double alpha = 0.3, mu_o = 1e-7;
  const GgxAzimuthalE f(alpha, mu_o, Masking::kHeightCorrelated);
  double worst = 0;
  for (double eps : {1e-12, 1e-9, 1e-6}) {
    const double theta_i = 1.5707963267948966 - eps;
    // The reference in 50 digits at the same double theta_i and theta_o.
    const Big ti = theta_i, a2 = Big(alpha) * alpha;
    const Big mi = cos(ti), si = sin(ti), mo = mu_o, so = sqrt(1 - mo * mo);
    auto lambda = [&](const Big& m, const Big& s) { return (sqrt(1 + a2 * s * s / (m * m)) - 1) / 2; };
    const Big g2 = 1 / (1 + lambda(mi, si) + lambda(mo, so));
    const Big ref = g2 * PhiNaive(theta_i, f.theta_o(), alpha) * si / (4 * mo);
    const double err = RelErr(f(theta_i), ref);
    worst = std::max(worst, err);
    EXPECT_LT(err, 1e-11) << "eps " << eps;
  }
  std::printf("1D integrand near the horizon: max relative error %.3g\n", worst);
}

// STD at very large gamma: (1 + r^2/(gamma-1))^-gamma and the constants of
// Lambda never form (gamma - 1)^gamma; D and Lambda stay finite and tend to
// Beckmann like 1/gamma.
TEST(CancellationTest, StudentTAtHugeGamma) {
  const double alpha = 0.4;
  const BeckmannNdf<double> beck(alpha);
  for (double gamma : {200.0, 1e3, 1e6, 1e9, 1e15}) {
    const StudentTNdf<double> sn(alpha, alpha, gamma);
    for (double mu : {1.0, 0.9, 0.5, 0.1, 1e-4}) {
      const Vec3<double> w = FromMuPhi(mu, 0.3);
      const double d = sn.D(w), l = sn.Lambda(w);
      ASSERT_TRUE(std::isfinite(d) && std::isfinite(l)) << gamma << " " << mu;
      // D in 50 digits from the textbook power (no overflow there).
      const Big r2 = (Big(w.x) * w.x + Big(w.y) * w.y) / (Big(alpha) * alpha * w.z * w.z);
      const Big p22 = pow(1 + r2 / (Big(gamma) - 1), -Big(gamma)) /
                      boost::math::constants::pi<Big>();
      const Big dref = p22 / (Big(alpha) * alpha * pow(Big(w.z), 4));
      if (dref > 1e-300) {
        EXPECT_LT(RelErr(d, dref), 1e-9) << gamma << " " << mu;
      }
      if (gamma >= 1e6) {
        // log D_std - log D_beckmann = (r^4/2 - r^2) / gamma + O(gamma^-2).
        const double db = beck.D(w), lb = beck.Lambda(w);
        const double r2d = static_cast<double>(r2);
        const double rel = 1.1 * (r2d * r2d / 2 + r2d) / gamma + 1e-12;
        EXPECT_NEAR(d, db, rel * db + 1e-300) << gamma << " " << mu;
        EXPECT_NEAR(l, lb, 1e-5 * (1 + lb)) << gamma << " " << mu;
      }
    }
  }
}

// 1 - E near 1: at small roughness E rounds to 1 in half precision, while
// the complement channel, formed in double before rounding, keeps the
// relative precision of half (2^-11) on 1 - E itself.
TEST(CancellationTest, ComplementKeepsRelativePrecisionNearOne) {
  BakeSpec spec;
  spec.mu.size = 5;
  spec.roughness.size = 5;
  spec.roughness.min = 0.02;
  spec.roughness.max = 0.2;
  spec.half = true;
  spec.complement = true;
  const Table t = Bake(spec);
  spec.complement = false;
  spec.half = false;
  const Table e = Bake(spec);
  const std::string path = ::testing::TempDir() + "/brdfbake_complement.exr";
  spec.complement = true;
  spec.half = true;
  WriteExr(t, path);
  const ExrContents c = ReadExr(path);
  const std::vector<float>* stored = c.ChannelData("1-E");
  ASSERT_NE(stored, nullptr);
  int checked = 0;
  for (size_t i = 0; i < stored->size(); ++i) {
    const double one_minus_e = 1.0 - e.channels[0].values[i];
    if (one_minus_e < 1e-4) continue;  // below half's normal range (6e-5)
    // E itself in half would be 1 (or off by 2^-11 absolute): useless for
    // 1 - E below 1e-3. The stored complement is within half's rounding.
    EXPECT_LT(std::abs((*stored)[i] - one_minus_e) / one_minus_e, 0x1p-11) << i;
    ++checked;
  }
  EXPECT_GT(checked, 10);
}

// wi = -wo: the half vector does not exist; every BRDF is 0, never NaN,
// including both directions on the horizon and the limit just off it.
TEST(CancellationTest, HalfVectorOfOppositeDirections) {
  const float tiny = 1e-30f;
  const std::vector<Vec3<float>> wis = {
      {1, 0, 0}, {0.6f, 0.8f, 0}, {1, 0, tiny}, {0, 1, -tiny}, {0, 0, 1}};
  Vec3<double> h;
  EXPECT_FALSE(HalfVector(Vec3<double>(0, 0, 1), Vec3<double>(0, 0, -1), &h));
  for (const Vec3<float>& wi : wis) {
    const Vec3<float> wo = -wi;
    const Vec3<double> wid(wi), wod(wo);
    EXPECT_EQ(Brdf(GgxNdf<double>(0.3), Fresnel::One(), wid, wod, Masking::kHeightCorrelated), 0.0);
    EXPECT_EQ(Brdf(BeckmannNdf<double>(0.3), Fresnel::One(), wid, wod, Masking::kSeparable), 0.0);
    EXPECT_EQ(Brdf(StudentTNdf<double>(0.3, 0.3, 1.8), Fresnel::One(), wid, wod,
                   Masking::kHeightCorrelated),
              0.0);
    float out[4] = {-1, -1, -1, -1};
    BatchModel gp{ModelKind::kGgx};
    EvalBatch(gp, Quantity::kBrdf, {&wi.x, &wi.y, &wi.z}, {&wo.x, &wo.y, &wo.z}, &out[0], 1);
    BatchModel bp{ModelKind::kBeckmann};
    EvalBatch(bp, Quantity::kBrdf, {&wi.x, &wi.y, &wi.z}, {&wo.x, &wo.y, &wo.z}, &out[1], 1);
    BatchModel sp{ModelKind::kStudentT};
    sp.gamma = 1.8f;
    EvalBatch(sp, Quantity::kBrdf, {&wi.x, &wi.y, &wi.z}, {&wo.x, &wo.y, &wo.z}, &out[2], 1);
    BatchModel ep{ModelKind::kEllipsoid};
    ep.theta_x = 0.5f;
    EvalBatch(ep, Quantity::kBrdf, {&wi.x, &wi.y, &wi.z}, {&wo.x, &wo.y, &wo.z}, &out[3], 1);
    for (int k = 0; k < 4; ++k) {
      EXPECT_EQ(out[k], 0.0f) << "kernel " << k << " wi " << wi.x << "," << wi.y << "," << wi.z;
    }
  }
}

}  // namespace
}  // namespace brdfbake
