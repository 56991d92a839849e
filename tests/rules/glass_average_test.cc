// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The rough dielectric's E_avg rule (rules/glass/glass_average.h), which
// integrates over the view about each microfacet normal, against E_avg
// the other way round: the visible-normal rule for E (glass_albedo.h)
// integrated over mu (reference/glass_eavg_reference.h). Stiff views:
// alpha 1e-4 (the tilted facets' tail), eta next to 1 from both sides
// (the critical angle at grazing), eta 1/100 and 100, every part, both
// maskings. Then identities the rule does not build in: the refraction's
// average from inside is the one from outside over eta^2 (reciprocity of
// refraction, [Walter07] eq. 21); the parts sum to the whole; the smooth
// interface's parts are the hemispherical averages of F and 1 - F.

#include "rules/glass/glass_average.h"

#include <gtest/gtest.h>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <cstdio>
#include <vector>

#include "brdfbake/models/fresnel.h"
#include "reference/glass_eavg_reference.h"

namespace brdfbake {
namespace {

struct Case {
  double alpha, eta;
  DielectricPart part;
  Masking masking;
};

TEST(GlassAverageTest, AgreesWithTheMuIntegralOfE) {
  const Masking hc = Masking::kHeightCorrelated, sep = Masking::kSeparable;
  const DielectricPart both = DielectricPart::kBoth;
  const std::vector<Case> cases = {
      {1e-4, 1.5, both, hc},
      {1e-4, 1 / 1.5, both, hc},
      {1.0 / 225, 0.99, both, hc},
      {1.0 / 225, 1.01, both, sep},
      {0.02, 0.5, DielectricPart::kReflection, hc},
      {0.02, 0.5, DielectricPart::kTransmission, hc},
      {0.2, 100, DielectricPart::kTransmissionSchlick, hc},
      {0.2, 0.01, both, sep},
      {1.0, 2.4, both, sep},
      {1.0, 1.0, both, hc},
  };
  double worst = 0;
  for (const Case& c : cases) {
    const RuleResult ref = test::GlassEavgOverMu(c.alpha, c.eta, c.masking, 1e-10, c.part);
    for (double tol : {1e-6, 1e-7}) {
      const RuleResult r = GlassAlbedoAverage(c.alpha, c.eta, c.masking, tol, 64, c.part);
      const double d = std::abs(r.value - ref.value);
      EXPECT_LE(d, r.error + ref.error) << "alpha " << c.alpha << " eta " << c.eta << " part "
                                        << DielectricPartName(c.part) << " tol " << tol;
      EXPECT_LE(r.error, tol) << "alpha " << c.alpha << " eta " << c.eta;
      EXPECT_TRUE(std::isfinite(r.value));
      worst = std::max(worst, d / (r.error + ref.error));
    }
    EXPECT_LE(ref.error, 1e-9);
  }
  std::printf("glass E_avg: max |rule - mu integral of E| / claims %.3g\n", worst);
}

// T_avg(1 / eta) = T_avg(eta) / eta^2: the refraction's average seen from
// inside the medium is the one from outside over eta^2 (the two are the
// same double integral, [Walter07] eq. 21's reciprocity of f_t with the
// importance transport's eta^2).
TEST(GlassAverageTest, RefractionFromInsideIsFromOutsideOverEtaSquared) {
  for (Masking masking : {Masking::kHeightCorrelated, Masking::kSeparable}) {
    for (double alpha : {1e-3, 0.05, 0.5, 1.0}) {
      for (double eta : {1.01, 1.5, 3.0, 50.0}) {
        const RuleResult out = GlassAlbedoAverage(alpha, eta, masking, 1e-8, 64, DielectricPart::kTransmission);
        const RuleResult in = GlassAlbedoAverage(alpha, 1 / eta, masking, 1e-8, 64, DielectricPart::kTransmission);
        EXPECT_NEAR(in.value, out.value / (eta * eta), in.error + out.error / (eta * eta))
            << "alpha " << alpha << " eta " << eta;
      }
    }
  }
}

TEST(GlassAverageTest, PartsSumToTheWhole) {
  for (double alpha : {1e-3, 0.1, 1.0}) {
    for (double eta : {0.3, 0.95, 1.0, 1.05, 2.0}) {
      const double tol = 1e-7;
      const Masking m = Masking::kHeightCorrelated;
      const RuleResult b = GlassAlbedoAverage(alpha, eta, m, tol, 64);
      const RuleResult r = GlassAlbedoAverage(alpha, eta, m, tol, 64, DielectricPart::kReflection);
      const RuleResult t = GlassAlbedoAverage(alpha, eta, m, tol, 64, DielectricPart::kTransmission);
      EXPECT_NEAR(r.value + t.value, b.value, r.error + t.error + b.error) << alpha << " " << eta;
      EXPECT_LE(b.value, 1 + b.error);
    }
  }
}

// alpha = 0: 2 integral c w(c) dc, w = F, 1 - F or 1 - (1 - c)^5, against
// Boost's Gauss-Kronrod cut at the critical cosine; the whole is 1.
TEST(GlassAverageTest, SmoothInterfaceIsTheAverageOfFresnel) {
  using boost::math::quadrature::gauss_kronrod;
  for (double eta : {0.4, 1 / 1.5, 1.0, 1.5, 3.0}) {
    const double crit = eta < 1 ? std::sqrt((1 - eta) * (1 + eta)) : 0;
    auto avg = [&](auto w) {
      auto f = [&](double c) { return 2 * c * w(c); };
      return gauss_kronrod<double, 61>::integrate(f, 0, crit, 15, 1e-14) +
             gauss_kronrod<double, 61>::integrate(f, crit, 1, 15, 1e-14);
    };
    const double fr = avg([&](double c) { return FresnelDielectric(eta, c); });
    const Masking hc = Masking::kHeightCorrelated;
    const RuleResult r = GlassAlbedoAverage(0, eta, hc, 1e-9, 64, DielectricPart::kReflection);
    const RuleResult t = GlassAlbedoAverage(0, eta, hc, 1e-9, 64, DielectricPart::kTransmission);
    const RuleResult b = GlassAlbedoAverage(0, eta, hc, 1e-9, 64);
    EXPECT_NEAR(r.value, fr, 1e-9) << eta;
    EXPECT_NEAR(t.value, 1 - fr, 1e-9) << eta;
    EXPECT_NEAR(b.value, 1, 1e-15);
    if (eta >= 1) {
      const double s = avg([&](double c) { return 1 - std::pow(1 - c, 5); });
      const RuleResult rs = GlassAlbedoAverage(0, eta, hc, 1e-9, 64, DielectricPart::kTransmissionSchlick);
      EXPECT_NEAR(rs.value, s, 1e-9);
      EXPECT_NEAR(s, 20.0 / 21, 1e-14);  // 1 - 2 B(2, 6) = 1 - 1/21
    }
  }
}

}  // namespace
}  // namespace brdfbake
