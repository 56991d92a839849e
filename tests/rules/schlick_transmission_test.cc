// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The Schlick-weighted refraction albedo (DielectricPart::
// kTransmissionSchlick, EEVEE's btdf_ggx, [Blender]): the glass rule
// (rules/glass/glass_albedo.h) with the refraction weighted by 1 - (1 -
// wo.h)^5 and no F, against an independent integration over the light
// direction written from [Walter07]'s equations
// (tests/reference/schlick_transmission_reference.h), at grazing views,
// narrow lobes and ior from 1.1 to 19999 and inf (the reference at 1e8):
// the claimed error bounds the true one. The rule at the table's
// tolerance against itself converged over EEVEE's range, and the smooth
// limit 1 - (1 - mu)^5.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "reference/schlick_transmission_reference.h"
#include "rules/glass/glass_albedo.h"

namespace brdfbake {
namespace {

constexpr DielectricPart kPart = DielectricPart::kTransmissionSchlick;
const double kInf = std::numeric_limits<double>::infinity();

TEST(SchlickTransmissionTest, AgreesWithIndependentIntegration) {
  struct Case {
    double alpha, eta, mu;
    Masking masking;
  };
  std::vector<Case> cases;
  // (Near eta = 1 the refraction lobe over wi narrows like (eta - 1)
  // alpha, which the reference does not resolve in reasonable time: ior
  // 1.0002 is checked against the converged rule in the grid below.)
  for (double alpha : {0.1, 0.5, 1.0}) {
    for (double eta : {1.1, 1.5, 19999.0}) {
      for (double mu : {1e-3, 0.2, 1.0}) cases.push_back({alpha, eta, mu, Masking::kSeparable});
    }
  }
  // inf (the reference at 1e8), a narrow lobe, height-correlated masking.
  for (double mu : {1e-2, 0.5}) cases.push_back({0.3, kInf, mu, Masking::kSeparable});
  cases.push_back({0.02, 1.5, 0.5, Masking::kSeparable});
  cases.push_back({0.02, 19999.0, 0.05, Masking::kSeparable});
  cases.push_back({0.3, 1.5, 0.1, Masking::kHeightCorrelated});
  cases.push_back({0.3, kInf, 0.9, Masking::kHeightCorrelated});
  double worst = 0, worst_ref = 0;
  for (const Case& c : cases) {
    const RuleResult rule = GlassAlbedo(c.alpha, c.eta, c.masking, c.mu, 1e-7, 256, kPart);
    double ref_err = 0;
    const double ref = test::ReferenceSchlickTransmission(c.alpha, std::isinf(c.eta) ? 1e8 : c.eta, c.mu, 1e-7,
                                                          &ref_err, c.masking == Masking::kSeparable);
    worst_ref = std::max(worst_ref, ref_err);
    const double d = std::abs(rule.value - ref);
    worst = std::max(worst, d / rule.error);
    std::printf("%s alpha %g eta %.6g mu %g: rule %.12f +- %.2g, reference %.12f +- %.2g\n", MaskingName(c.masking),
                c.alpha, c.eta, c.mu, rule.value, rule.error, ref, ref_err);
    std::fflush(stdout);
    EXPECT_LE(ref_err, 1e-8) << "alpha " << c.alpha << " eta " << c.eta << " mu " << c.mu;
    // 1e-8: the reference's eta = 1e8 for inf moves T by O(1 / eta).
    EXPECT_LE(d, rule.error + ref_err + (std::isinf(c.eta) ? 1e-8 : 0.0))
        << "alpha " << c.alpha << " eta " << c.eta << " mu " << c.mu;
    EXPECT_LE(rule.error, 1.5e-7);
    EXPECT_GE(rule.value, 0.0);
    EXPECT_LE(rule.value, 1.0);
  }
  std::printf("schlick transmission: max |rule - reference| / claim %.3g, reference error at most %.3g\n", worst,
              worst_ref);
}

// The rule at the tolerance of EEVEE's preset (1e-6) and at 1e-7 against
// itself converged (1e-11), over EEVEE's roughness slices, grazing views
// and ior 1 to inf: the claim bounds the difference.
TEST(SchlickTransmissionTest, ClaimsBoundTheErrorOverAGrid) {
  double worst = 0;
  int n = 0;
  for (double eta : {1.0, 1.0002, 1.5, 3.0, 19999.0, kInf}) {
    for (double r : {1.0 / 16, 0.25, 0.5, 15.0 / 16}) {
      for (double mu : {1e-7, 1e-4, 0.02, 0.5, 1.0}) {
        const RuleResult b = GlassAlbedo(r * r, eta, Masking::kSeparable, mu, 1e-11, 4096, kPart);
        for (double tol : {1e-6, 1e-7}) {
          const RuleResult a = GlassAlbedo(r * r, eta, Masking::kSeparable, mu, tol, 256, kPart);
          const double d = std::abs(a.value - b.value);
          worst = std::max(worst, d / (a.error + b.error));
          ++n;
          EXPECT_LE(d, a.error + b.error) << "r " << r << " eta " << eta << " mu " << mu << " tol " << tol;
          EXPECT_LE(a.error, 1.5 * tol) << "r " << r << " eta " << eta << " mu " << mu;
        }
      }
    }
  }
  std::printf("schlick transmission grid: %d texels, max |T(tol) - T(1e-11)| / claims %.3g\n", n, worst);
}

// alpha = 0 is the smooth interface: h = n, T = 1 - (1 - mu)^5 for every
// eta >= 1, exactly; a rough T is finite and in [0, 1] up to eta = inf,
// and eta = inf is the limit of large eta.
TEST(SchlickTransmissionTest, SmoothLimitAndInfiniteIndex) {
  for (double eta : {1.0, 1.5, 19999.0, kInf}) {
    for (double mu : {0.0, 0.3, 0.9, 1.0}) {
      const RuleResult t = GlassAlbedo(0.0, eta, Masking::kSeparable, mu, 1e-7, 64, kPart);
      EXPECT_EQ(t.value, 1 - std::pow(1 - mu, 5));
      EXPECT_EQ(t.error, 0.0);
    }
  }
  for (double mu : {1e-7, 0.3, 1.0}) {
    const RuleResult inf = GlassAlbedo(0.09, kInf, Masking::kSeparable, mu, 1e-9, 1024, kPart);
    const RuleResult big = GlassAlbedo(0.09, 1e7, Masking::kSeparable, mu, 1e-9, 1024, kPart);
    EXPECT_LE(std::abs(inf.value - big.value), inf.error + big.error + 1e-6) << mu;
    EXPECT_GT(inf.value, 0.0);
    EXPECT_LE(inf.value, 1.0);
  }
  // A small roughness approaches the smooth value.
  const RuleResult t = GlassAlbedo(1e-4, 1.5, Masking::kSeparable, 0.5, 1e-9, 1024, kPart);
  EXPECT_NEAR(t.value, 1 - std::pow(0.5, 5), 1e-3);
}

}  // namespace
}  // namespace brdfbake
