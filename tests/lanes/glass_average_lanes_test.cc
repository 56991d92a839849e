// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The glass E_avg rule with each psi piece's nodes in double SIMD lanes
// (SimdGlassAlbedoAverage, src/lanes/glass_lanes.cc) against its double
// scalar reference (GlassAlbedoAverage, whose nodes are
// ScalarAverageLines), on every compiled target the CPU runs.
//  - Node by node: the line's value jac(w) G2 at the same w differs by the
//    rounding of its terms (fused multiply-adds) only, which the cosines
//    next to a horizon (z ~ alpha, formed by cancellation) carry into G1 as
//    a relative error ~ 1e-16 / z: stated bound kNodeBound absolute (jac
//    is at most 2, G2 at most 1), over random lines of both kinds (the
//    reflection's cosines cc -+ k x, the refraction's cc - k x and ct
//    cos(theta_h) - k x / eta), pieces from 1e-8 to 1 wide, every third
//    ending on the horizon.
//  - Piece by piece: the K15 and G7 sums of the same pieces, the nodes
//    formed in lanes and summed in another order: within kNodeBound times
//    the piece's width (the weights sum to 2, times the half width) and
//    the rounding of 16 terms.
//  - Texel by texel: the adaptive levels may split a piece differently
//    where a |K15 - G7| sits at a threshold, so the two averages agree
//    within their claims: |simd - scalar| <= kClaimShare (claim_simd +
//    claim_scalar) + kRoundingBound; each claim bounds its own distance to
//    the true E_avg (tests/rules/glass_average_test.cc).

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "brdfbake/targets.h"
#include "lanes/glass_lanes.h"
#include "quadrature/kronrod.h"
#include "rules/glass/glass_average.h"
#include "rules/glass/glass_average_rule.h"

namespace brdfbake {
namespace {

constexpr double kNodeBound = 1e-11;
constexpr double kClaimShare = 0.25;
constexpr double kRoundingBound = 1e-13;

TEST(GlassAverageLanesTest, LineNodesAndSumsAgreeWithTheScalarReferenceOnEveryTarget) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (const std::string& target : AvailableTargets()) {
    ForceTarget(target);
    std::mt19937_64 rng(35);  // the same lines on every target
    double worst = 0, worst_sum = 0;
    for (Masking masking : {Masking::kHeightCorrelated, Masking::kSeparable}) {
      for (double alpha : {1e-4, 2e-3, 0.04, 0.3, 1.0}) {
        const AverageModel m = AverageModelOf(alpha, 1.5, masking, DielectricPart::kBoth);
        for (int k = 0; k < 300; ++k) {
          // theta_h, c and eta at random; the line's coefficients as the
          // rule forms them.
          const double th = 0.5 * kPi<double> * u(rng), c = u(rng), eta = std::pow(10.0, 2 * u(rng) - 1);
          const double s = std::sqrt((1 - c) * (1 + c)), cc = c * std::cos(th), kk = s * std::sin(th);
          const double st = s / eta, ct = std::sqrt(std::max((1 - st) * (1 + st), 0.0));
          const bool refraction = k % 2 == 1;
          const AverageLine line = refraction ? AverageLine{cc, -kk, ct * std::cos(th), -kk / eta}
                                              : AverageLine{cc, -kk, cc, kk};
          const double coef[4] = {line.a0, line.a1, line.b0, line.b1};
          // A piece of w in [0, 2] (the horizon at its lower end every
          // third line).
          const double horizon = kk > 0 ? WOfCos(std::min(cc / kk, 1.0)) : 0.0;
          const double width = (2 - horizon) * std::pow(10.0, -8 * u(rng));
          const double a = k % 3 == 0 ? horizon : horizon + (2 - horizon - width) * u(rng);
          double w[15], got[15], want[15];
          for (int i = 0; i < 15; ++i) w[i] = a + 0.5 * width * (1 + Kronrod15().x[i]);
          SimdGlassAverageLineValues(alpha, masking, coef, w, got);
          ScalarAverageLines{&m}(line, w, want);
          double kron, gauss;
          SimdGlassAverageLineSums(alpha, masking, coef, a, a + width, &kron, &gauss);
          GlassSums ref;
          const double b = a + width;
          ScalarAverageLines{&m}.Pieces(line, &a, &b, 1, &ref);
          const double sum_bound = kNodeBound * width + 1e-15 * std::abs(ref.kron);
          EXPECT_LE(std::abs(kron - ref.kron), sum_bound) << target << " alpha " << alpha << " piece " << a;
          EXPECT_LE(std::abs(gauss - ref.gauss), sum_bound) << target << " alpha " << alpha << " piece " << a;
          worst_sum = std::max(worst_sum, std::abs(kron - ref.kron) / sum_bound);
          for (int i = 0; i < 15; ++i) {
            ASSERT_TRUE(std::isfinite(got[i])) << target << " w " << w[i];
            EXPECT_LE(std::abs(got[i] - want[i]), kNodeBound)
                << target << " alpha " << alpha << " w " << w[i] << " want " << want[i];
            worst = std::max(worst, std::abs(got[i] - want[i]));
          }
        }
      }
    }
    std::printf("%s: largest |simd - scalar| of the E_avg line nodes %.3g; of the sums, %.3g of their bound\n",
                target.c_str(), worst, worst_sum);
  }
  ForceTarget("best");
}

// Both sides of the interface (eta < 1 with the critical angle, eta next
// to 1, eta = 1), tiny to unit roughness, every part, both maskings.
TEST(GlassAverageLanesTest, AgreesWithTheScalarReferenceOnEveryTarget) {
  struct Case {
    double alpha, eta;
    DielectricPart part;
    Masking masking;
    RuleResult ref;
  };
  std::vector<Case> cases;
  for (double alpha : {1e-4, 2e-3, 0.04, 0.3, 1.0}) {
    for (double eta : {1.0 / 3, 1 / 1.5, 0.98, 1.0, 1.02, 1.5, 3.0}) {
      for (int p = 0; p < 4; ++p) {
        const DielectricPart part = DielectricPart(p);
        if (part == DielectricPart::kTransmissionSchlick && eta < 1) continue;
        for (Masking masking : {Masking::kHeightCorrelated, Masking::kSeparable}) {
          if (masking == Masking::kSeparable && part != DielectricPart::kBoth) continue;
          cases.push_back({alpha, eta, part, masking, GlassAlbedoAverage(alpha, eta, masking, 1e-7, 64, part)});
        }
      }
    }
  }
  for (const std::string& target : AvailableTargets()) {
    ForceTarget(target);
    double worst = 0, worst_ratio = 0;
    for (const Case& c : cases) {
      const RuleResult got = SimdGlassAlbedoAverage(c.alpha, c.eta, c.masking, 1e-7, 64, c.part);
      ASSERT_TRUE(std::isfinite(got.value) && std::isfinite(got.error));
      const double d = std::abs(got.value - c.ref.value);
      const double bound = kClaimShare * (got.error + c.ref.error) + kRoundingBound;
      EXPECT_LE(d, bound) << target << " alpha " << c.alpha << " eta " << c.eta << " part "
                          << DielectricPartName(c.part);
      worst = std::max(worst, d);
      worst_ratio = std::max(worst_ratio, d / bound);
    }
    std::printf("%s: %zu E_avg texels, largest |simd - scalar| %.3g, at most %.3g of the stated bound\n",
                target.c_str(), cases.size(), worst, worst_ratio);
  }
  ForceTarget("best");
}

}  // namespace
}  // namespace brdfbake
