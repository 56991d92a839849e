// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The generalized Schlick factor and the F82-tint term
// (rules/glass/gen_schlick.h) against an
// independent integration over the half vector (tests/reference/
// reference_albedo.h, tanh-sinh over theta_h and the arc of valid
// azimuths, sharing no code with the rule, which integrates over the
// visible normals' lune), its claimed error bounding the true error.
// Cycles' shipped gen_schlick tables are compared with the cycles preset's
// in tests/bake/glass_table_test.cc.

#include "rules/glass/gen_schlick.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "brdfbake/models/ggx.h"
#include "reference/reference_albedo.h"

namespace brdfbake {
namespace {

// s(mu) = integral over h of G1(wo) D(h) (wo.h) / mu s_h(wo.h) on the arc
// where wo.h > 0 and the reflection is above the surface ([Heitz18] eq. 3
// for D_wo), cut at theta_h = theta_o, where h = wo and (1 - wo.h)^e of a
// small exponent has a cusp.
double ReferenceS(double alpha, const GenSchlickShape& shape, double mu, double tol) {
  const GgxNdf<double> ndf(alpha);
  const double mu_o = std::max(mu, 1e-7);
  const Vec3<double> wo = FromMuPhi(mu_o, 0.0);
  const double g1 = ndf.G1(wo);
  return ReferenceHalfVectorIntegral(
      mu, tol, 0.0,
      [&](const Vec3<double>& h, const Vec3<double>&, const Vec3<double>&, double wo_h) {
        return g1 * ndf.D(h) * wo_h / mu_o * GenSchlickWeight(shape, wo_h);
      },
      {std::acos(mu_o)});
}

TEST(GenSchlickTest, WeightIsTheSchlickPowerOrTheDielectricShape) {
  EXPECT_DOUBLE_EQ(GenSchlickWeight({5, 1}, 0.3), std::pow(0.7, 5));
  EXPECT_DOUBLE_EQ(GenSchlickWeight({0, 1}, 0.3), 1.0);
  EXPECT_DOUBLE_EQ(GenSchlickWeight({5, 1}, 1.0), 0.0);
  // Dielectric mode: 0 at normal incidence, 1 at grazing.
  EXPECT_NEAR(GenSchlickWeight({-1, 1.5}, 1.0), 0.0, 1e-15);
  EXPECT_NEAR(GenSchlickWeight({-1, 1.5}, 0.0), 1.0, 1e-15);
  // At eta 1.5, c = 0.5: F = 0.0891763 (Fresnel equations by hand).
  const double f0 = 0.04, f = 0.5 * (std::pow((1.5 * 0.5 - std::sqrt(1 - 0.75 / 2.25)) /
                                                  (1.5 * 0.5 + std::sqrt(1 - 0.75 / 2.25)),
                                              2) +
                                     std::pow((0.5 - 1.5 * std::sqrt(1 - 0.75 / 2.25)) /
                                                  (0.5 + 1.5 * std::sqrt(1 - 0.75 / 2.25)),
                                              2));
  EXPECT_NEAR(GenSchlickWeight({-1, 1.5}, 0.5), (f - f0) / (1 - f0), 1e-15);
}

TEST(GenSchlickTest, AgreesWithIndependentIntegration) {
  const std::vector<GenSchlickShape> shapes = {{5, 1}, {0.357, 1}, {70, 1}, {-1, 1.5}, {-1, 3}};
  double worst = 0;
  for (double alpha : {0.0225, 0.3, 1.0}) {
    for (double mu : {0.01, 0.3, 0.8, 1.0}) {
      for (const GenSchlickShape& shape : shapes) {
        const RuleResult got = GenSchlickFactor(alpha, shape, mu, 1e-7, 4000);
        const double ref = ReferenceS(alpha, shape, mu, 1e-11);
        const double err = std::abs(got.value - ref);
        worst = std::max(worst, err / got.error);
        EXPECT_LE(err, got.error + 1e-10)
            << "alpha " << alpha << " mu " << mu << " exponent " << shape.exponent << " eta "
            << shape.eta << ": rule " << got.value << " (claim " << got.error << ") reference "
            << ref;
        EXPECT_GE(got.value, 0);
        EXPECT_LE(got.value, 1 + got.error);
      }
    }
  }
  std::printf("worst true error / claim %.3g\n", worst);
}

// Over a grid reaching Cycles' ends (the exponents 0.05 and 5e4, ior 99.5,
// grazing views, narrow lobes), the claim at the tables' tolerance bounds
// the distance to the rule converged at 1e-11.
TEST(GenSchlickTest, ClaimsBoundTheErrorOverAGrid) {
  const std::vector<GenSchlickShape> shapes = {{0.0505, 1}, {0.357, 1}, {5, 1},     {70, 1},
                                               {1000, 1},   {49995, 1}, {-1, 1.01}, {-1, 1.5},
                                               {-1, 7},     {-1, 99.5}};
  double worst = 0;
  for (double r : {0.05, 0.2, 0.5, 0.9}) {
    for (double mu : {1e-4, 0.02, 0.2, 0.6, 0.999}) {
      for (const GenSchlickShape& shape : shapes) {
        const RuleResult got = GenSchlickFactor(r * r, shape, mu, 1e-7, 4000);
        const RuleResult fine = GenSchlickFactor(r * r, shape, mu, 1e-11, 20000);
        const double err = std::abs(got.value - fine.value);
        worst = std::max(worst, err / got.error);
        EXPECT_LE(err, got.error + fine.error)
            << "r " << r << " mu " << mu << " exponent " << shape.exponent << " eta " << shape.eta;
        EXPECT_TRUE(std::isfinite(got.value));
      }
    }
  }
  std::printf("worst true error / claim %.3g\n", worst);
}

// The F82-tint term b(mu) = integral D G2 (wo.h) / mu b(wo.h) over the
// half vector, both maskings: the same independent integration, cut at h =
// wo where b's factor (1 - wo.h)^6 is smooth but its derivative scale is.
double ReferenceF82(double alpha, Masking masking, double mu, double tol) {
  const GgxNdf<double> ndf(alpha);
  const double mu_o = std::max(mu, 1e-7);
  return ReferenceHalfVectorIntegral(
      mu_o, tol, 0.0,
      [&](const Vec3<double>& h, const Vec3<double>& wo, const Vec3<double>& wi, double wo_h) {
        return ndf.D(h) * G2(ndf, wi, wo, h, masking) * wo_h / wo.z * F82TintWeight(wo_h);
      },
      {std::acos(mu_o)});
}

TEST(F82TintTest, WeightIsCTimesOneMinusCToTheSixth) {
  EXPECT_DOUBLE_EQ(F82TintWeight(0.3), 0.3 * std::pow(0.7, 6));
  EXPECT_EQ(F82TintWeight(0.0), 0.0);
  EXPECT_EQ(F82TintWeight(1.0), 0.0);
  // Its largest value, at c = 1/7: (1/7) (6/7)^6.
  EXPECT_NEAR(F82TintWeight(1.0 / 7), std::pow(6.0 / 7, 6) / 7, 1e-16);
}

// The rule against the independent integration, both maskings, narrow to
// wide lobes, grazing to normal views; its claim bounds the true error.
TEST(F82TintTest, AgreesWithIndependentIntegration) {
  double worst = 0;
  for (Masking masking : {Masking::kSeparable, Masking::kHeightCorrelated}) {
    for (double alpha : {0.0225, 0.09, 0.3, 1.0}) {
      for (double mu : {0.01, 0.1, 0.3, 0.8, 1.0}) {
        const RuleResult got = F82TintBias(alpha, masking, mu, 1e-7, 4000);
        const double ref = ReferenceF82(alpha, masking, mu, 1e-11);
        const double err = std::abs(got.value - ref);
        worst = std::max(worst, err / got.error);
        EXPECT_LE(err, got.error + 1e-10) << MaskingName(masking) << " alpha " << alpha << " mu " << mu << ": rule "
                                          << got.value << " (claim " << got.error << ") reference " << ref;
        // Below the largest weight (1/7) (6/7)^6 times E <= 1.
        EXPECT_GE(got.value, 0);
        EXPECT_LE(got.value, std::pow(6.0 / 7, 6) / 7 + got.error);
      }
    }
  }
  std::printf("worst true error / claim %.3g\n", worst);
}

// At the grid's stiff ends (narrow lobes, grazing views) the claim at the
// tables' tolerance bounds the distance to the rule converged at 1e-11.
TEST(F82TintTest, ClaimsBoundTheErrorOverAGrid) {
  double worst = 0;
  for (Masking masking : {Masking::kSeparable, Masking::kHeightCorrelated}) {
    for (double r : {0.011, 0.05, 0.2, 0.5, 0.9}) {
      for (double mu : {1e-4, 0.02, 0.2, 0.6, 0.999}) {
        const RuleResult got = F82TintBias(r * r, masking, mu, 1e-7, 4000);
        const RuleResult fine = F82TintBias(r * r, masking, mu, 1e-11, 20000);
        const double err = std::abs(got.value - fine.value);
        worst = std::max(worst, err / got.error);
        EXPECT_LE(err, got.error + fine.error) << MaskingName(masking) << " r " << r << " mu " << mu;
        EXPECT_TRUE(std::isfinite(got.value));
      }
    }
  }
  std::printf("worst true error / claim %.3g\n", worst);
}

}  // namespace
}  // namespace brdfbake
