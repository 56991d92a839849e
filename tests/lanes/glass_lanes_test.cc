// The glass albedo rule with each ray piece's nodes in double SIMD lanes
// (SimdGlassAlbedo, src/lanes/glass_lanes.cc) against its double scalar
// reference (GlassAlbedo, whose nodes are ScalarGlassNodes), on every
// compiled target the CPU runs.
//  - Node by node: the integrand at the same angles differs by the
//    rounding of its terms only (polynomial sin and cos against the C
//    library's, products by 1 / eta for divisions, Lambda without the
//    division by the cosine, the microfacet unnormalized): stated bound kNodeBound absolute (the
//    integrand is at most about 1), except next to the critical angle,
//    where F has an infinite slope in the Fresnel cosine c and a rounding
//    of c moves F by up to sqrt of it: kCriticalNodeBound. At the rule's
//    nodes, which keep 0.4% of a piece's width from its ends (the lune's
//    edge and the curves where a mask flips); not at eta = 1, where both
//    form the straight-through refraction from the difference c -
//    sqrt(c^2) and differ at grazing views by their own rounding (the
//    texel test covers eta = 1).
//  - Piece by piece: the K15 and G7 sums of a piece of a mapped segment,
//    the nodes mapped and summed in lanes: the node bound times the
//    piece's width in theta, and the rounding of 16 terms.
//  - Texel by texel: the adaptive rules may then split a ray differently
//    where a piece's |K15 - G7| sits at a threshold, so the two albedos
//    agree within their claims, not to rounding: stated bound
//    |simd - scalar| <= kClaimShare (claim_simd + claim_scalar) + 1e-12;
//    each claim bounds its own distance to the true E
//    (tests/rules/glass_albedo_test.cc, tests/bake/glass_table_test.cc).

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "brdfbake/targets.h"
#include "lanes/glass_lanes.h"
#include "rules/glass/glass_albedo.h"
#include "rules/glass/glass_albedo_rule.h"
#include "quadrature/kronrod.h"

namespace brdfbake {
namespace {

constexpr double kNodeBound = 5e-11;
constexpr double kCriticalNodeBound = 1e-7;
constexpr double kClaimShare = 0.25;
constexpr double kRoundingBound = 1e-12;

// Random rays over the lune (phi in [-pi/2, pi/2]) and the Kronrod nodes
// of random pieces along them, both sides of the interface, eta next to 1,
// alpha 1e-4 to 1, grazing to normal views; measured at most 9.1e-12 over
// several draws (AVX3 to SCALAR), none within 1e-6 of the critical
// cosine.
TEST(GlassLanesTest, NodesAgreeWithTheScalarReferenceOnEveryTarget) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double etas[] = {1.0 / 3, 1 / 1.5, 0.98, 1.02, 1.5, 3.0};
  const double alphas[] = {1e-4, 2e-3, 0.04, 0.3, 1.0};
  for (const std::string& target : AvailableTargets()) {
    ForceTarget(target);
    std::mt19937_64 rng(34);  // the same nodes on every target
    double worst = 0, worst_critical = 0;
    for (Masking masking : {Masking::kHeightCorrelated, Masking::kSeparable}) {
      for (double eta : etas) {
        for (double alpha : alphas) {
          const RoughDielectric<double, GgxNdf<double>> bsdf(GgxNdf<double>(alpha), eta, masking,
                                                             DielectricTransport::kImportance);
          for (int k = 0; k < 200; ++k) {
            const double mu = k % 3 == 0 ? std::pow(10.0, -7 * u(rng)) : u(rng);
            const double phi = kPi<double> * (u(rng) - 0.5);
            const GlassFrame frame(bsdf.ndf().alpha_x(), bsdf.eta(), mu);
            const double lambda_o = bsdf.Lambda(Vec3<double>{frame.so, 0, frame.mu});
            const ScalarGlassNodes ref_nodes{&bsdf, &frame, 1 + lambda_o, lambda_o};
            const double theta_max = frame.ThetaMax(std::sin(phi));
            // The Kronrod nodes of a piece of width 1e-8 to 1 times
            // theta_max, every third one ending on the lune's edge, where
            // the rule's pieces end (the integrand steps to 0 beyond it;
            // a node is never within 0.4% of a piece's width of its end).
            const double w = theta_max * std::pow(10.0, -8 * u(rng));
            const double a = k % 3 == 1 ? theta_max - w : (theta_max - w) * u(rng);
            double theta[15], got[15], want[15];
            for (int i = 0; i < 15; ++i) theta[i] = a + 0.5 * w * (1 + Kronrod15().x[i]);
            SimdGlassNodeValues(alpha, eta, masking, mu, phi, theta, got);
            ref_nodes(GlassRay{std::cos(phi), std::sin(phi)}, theta, want);
            for (int i = 0; i < 15; ++i) {
              // The Fresnel cosine of the node, and its distance to the
              // critical one sqrt(1 - eta^2) (eta < 1).
              const Vec3<double> m =
                  frame.M(std::cos(theta[i]), std::sin(theta[i]), std::cos(phi), std::sin(phi));
              const double len = std::sqrt(Dot(m, m));
              const double c = len > 0 ? (frame.so * m.x + frame.mu * m.z) / len : 0;
              const double cc = bsdf.eta() < 1 ? std::sqrt((1 - bsdf.eta()) * (1 + bsdf.eta())) : -1;
              const bool critical = std::abs(c - cc) < 1e-6;
              const double d = std::abs(got[i] - want[i]);
              ASSERT_TRUE(std::isfinite(got[i]));
              EXPECT_LE(d, critical ? kCriticalNodeBound : kNodeBound)
                  << target << " alpha " << alpha << " eta " << eta << " mu " << mu << " phi " << phi
                  << " theta " << theta[i] << " got " << got[i] << " want " << want[i];
              (critical ? worst_critical : worst) = std::max(critical ? worst_critical : worst, d);
            }
          }
        }
      }
    }
    std::printf("%s: largest |simd - scalar| of the glass nodes %.3g, within 1e-6 of the "
                "critical cosine %.3g\n",
                target.c_str(), worst, worst_critical);
  }
  ForceTarget("best");
}

// Pieces of random segments (each end singular or not, as the rule's maps)
// along random rays, random parts of them, both sides of the interface.
TEST(GlassLanesTest, PieceSumsAgreeWithTheScalarReferenceOnEveryTarget) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double etas[] = {1.0 / 3, 1 / 1.5, 1.02, 1.5, 3.0};
  const double alphas[] = {1e-4, 2e-3, 0.04, 0.3, 1.0};
  for (const std::string& target : AvailableTargets()) {
    ForceTarget(target);
    std::mt19937_64 rng(36);  // the same pieces on every target
    double worst = 0;
    for (Masking masking : {Masking::kHeightCorrelated, Masking::kSeparable}) {
      for (double eta : etas) {
        for (double alpha : alphas) {
          const RoughDielectric<double, GgxNdf<double>> bsdf(GgxNdf<double>(alpha), eta, masking,
                                                             DielectricTransport::kImportance);
          for (int k = 0; k < 100; ++k) {
            const double mu = k % 3 == 0 ? std::pow(10.0, -7 * u(rng)) : u(rng);
            const double phi = kPi<double> * (u(rng) - 0.5);
            const GlassFrame frame(bsdf.ndf().alpha_x(), bsdf.eta(), mu);
            const double lambda_o = bsdf.Lambda(Vec3<double>{frame.so, 0, frame.mu});
            const ScalarGlassNodes ref_nodes{&bsdf, &frame, 1 + lambda_o, lambda_o};
            const GlassRay ray{std::cos(phi), std::sin(phi)};
            const double theta_max = frame.ThetaMax(ray.sp);
            const double w = theta_max * std::pow(10.0, -6 * u(rng));
            const double a = (theta_max - w) * u(rng);
            const MappedSegment seg{a, a + w, k % 2 == 1, k % 4 >= 2};
            GlassPiece span{};
            span.a = 0.5 * u(rng);
            span.b = k % 5 == 0 ? 1.0 : span.a + (1 - span.a) * u(rng);
            span.segment = 0;
            GlassSums want;
            MappedPieceSums(&seg, &span, 1, &want, [&](const double* x, double* v, int n) { ref_nodes(ray, x, v, n); });
            double kron, gauss;
            SimdGlassPieceSums(alpha, eta, masking, mu, phi, seg.a, seg.b, seg.singular_a, seg.singular_b, span.a,
                               span.b, &kron, &gauss);
            // Within 1e-6 of the critical cosine anywhere on the piece:
            // its nodes' bound.
            bool critical = false;
            for (int i = 0; i <= 20 && bsdf.eta() < 1; ++i) {
              double x, jac;
              seg.Map(span.a + (span.b - span.a) * i / 20.0, &x, &jac);
              const Vec3<double> m = frame.M(std::cos(x), std::sin(x), ray.cp, ray.sp);
              const double c = (frame.so * m.x + frame.mu * m.z) / std::sqrt(Dot(m, m));
              critical = critical || std::abs(c - std::sqrt((1 - bsdf.eta()) * (1 + bsdf.eta()))) < 1e-3;
            }
            if (critical) continue;
            const double bound = kNodeBound * w + 1e-15 * (std::abs(want.kron) + std::abs(want.gauss));
            ASSERT_TRUE(std::isfinite(kron) && std::isfinite(gauss));
            EXPECT_LE(std::abs(kron - want.kron), bound) << target << " alpha " << alpha << " eta " << eta;
            EXPECT_LE(std::abs(gauss - want.gauss), bound) << target << " alpha " << alpha << " eta " << eta;
            worst = std::max(worst, std::max(std::abs(kron - want.kron), std::abs(gauss - want.gauss)) / bound);
          }
        }
      }
    }
    std::printf("%s: glass piece sums within %.3g of their bound\n", target.c_str(), worst);
  }
  ForceTarget("best");
}

// Entering and leaving the medium (eta < 1 with total internal reflection,
// eta next to 1), tiny to unit roughness, grazing to normal views, both
// maskings, at the bake's default tolerance and a tighter one.
TEST(GlassLanesTest, AgreesWithTheScalarReferenceOnEveryTarget) {
  const std::vector<std::string> targets = AvailableTargets();
  const double etas[] = {1.0 / 3, 1 / 1.5, 0.98, 1.0, 1.02, 1.5, 3.0};
  const double alphas[] = {1e-4, 2e-3, 0.04, 0.2066, 0.5, 1.0};
  const double mus[] = {1e-7, 1e-3, 0.05, 0.3, 0.745356, 0.932809, 1.0};
  // The references once, for every target to meet.
  struct Case {
    double alpha, eta, mu, tol;
    Masking masking;
    RuleResult ref;
  };
  std::vector<Case> cases;
  for (Masking masking : {Masking::kHeightCorrelated, Masking::kSeparable}) {
    for (double eta : etas) {
      for (double alpha : alphas) {
        for (double mu : mus) {
          // Separable masking and the tight tolerance on a subset.
          if (masking == Masking::kSeparable && (alpha == 2e-3 || mu == 0.05)) continue;
          const double tol = alpha == 0.2066 ? 1e-9 : 1e-7;
          cases.push_back({alpha, eta, mu, tol, masking, GlassAlbedo(alpha, eta, masking, mu, tol, 512)});
        }
      }
    }
  }
  for (const std::string& target : targets) {
    ForceTarget(target);
    double worst = 0, worst_ratio = 0;
    for (const Case& c : cases) {
      const RuleResult got = SimdGlassAlbedo(c.alpha, c.eta, c.masking, c.mu, c.tol, 512);
      const double d = std::abs(got.value - c.ref.value);
      ASSERT_TRUE(std::isfinite(got.value) && std::isfinite(got.error));
      const double bound = kClaimShare * (got.error + c.ref.error) + kRoundingBound;
      EXPECT_LE(d, bound) << target << " alpha " << c.alpha << " eta " << c.eta << " mu " << c.mu;
      worst = std::max(worst, d);
      worst_ratio = std::max(worst_ratio, d / bound);
    }
    std::printf("%s: %zu texels, largest |simd - scalar| %.3g, at most %.3g of the stated bound\n",
                target.c_str(), cases.size(), worst, worst_ratio);
  }
  ForceTarget("best");
}

// The reflection and the refraction alone (DielectricPart), node by node
// and texel by texel, with the same bounds as the sum: both sides of the
// interface, next to the critical cosine of eta = 1/1.5 (0.745356),
// grazing and tiny roughness, both maskings.
TEST(GlassLanesTest, EachPartAgreesWithTheScalarReferenceOnEveryTarget) {
  const double etas[] = {0.4, 1 / 1.5, 1.0, 1.5, 2.5};
  const double alphas[] = {1e-4, 0.04, 0.3, 1.0};
  const double mus[] = {1e-7, 1e-3, 0.3, 0.745356, 1.0};
  struct Case {
    double alpha, eta, mu;
    Masking masking;
    DielectricPart part;
    RuleResult ref;
  };
  std::vector<Case> cases;
  for (Masking masking : {Masking::kHeightCorrelated, Masking::kSeparable}) {
    for (DielectricPart part : {DielectricPart::kReflection, DielectricPart::kTransmission}) {
      for (double eta : etas) {
        for (double alpha : alphas) {
          for (double mu : mus) {
            cases.push_back({alpha, eta, mu, masking, part, GlassAlbedo(alpha, eta, masking, mu, 1e-7, 512, part)});
          }
        }
      }
    }
  }
  std::mt19937_64 rng(35);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (const std::string& target : AvailableTargets()) {
    ForceTarget(target);
    double worst = 0, worst_ratio = 0, worst_node = 0;
    for (const Case& c : cases) {
      const RuleResult got = SimdGlassAlbedo(c.alpha, c.eta, c.masking, c.mu, 1e-7, 512, c.part);
      ASSERT_TRUE(std::isfinite(got.value) && std::isfinite(got.error));
      const double d = std::abs(got.value - c.ref.value);
      if (c.eta == 1.0 && c.part == DielectricPart::kReflection) {
        // F = 0 without an interface; both paths hold their rounding of
        // it (the lanes' cos_t = sqrt(1 - (1 - c^2)) loses c below 1e-8),
        // measured at most 2.6e-12 here.
        EXPECT_LE(std::abs(got.value), 1e-10) << target << " mu " << c.mu;
        EXPECT_LE(std::abs(c.ref.value), 1e-10) << target << " mu " << c.mu;
        continue;
      }
      const double bound = kClaimShare * (got.error + c.ref.error) + kRoundingBound;
      EXPECT_LE(d, bound) << target << " " << DielectricPartName(c.part) << " alpha " << c.alpha << " eta " << c.eta
                          << " mu " << c.mu;
      worst = std::max(worst, d);
      worst_ratio = std::max(worst_ratio, d / bound);
      // The nodes of one random ray piece, away from eta = 1 and the
      // critical cosine (the sum's node test says why).
      if (c.eta == 1.0 || c.mu == 0.745356) continue;
      const double phi = (u(rng) - 0.5) * kPi<double>;
      const GlassFrame frame(c.alpha, c.eta, c.mu);
      const double tmax = frame.ThetaMax(std::sin(phi));
      double theta[15], v[15], w[15];
      const double a = u(rng) * tmax, b = a + (tmax - a) * u(rng);
      for (int i = 0; i < 15; ++i) theta[i] = a + (b - a) * 0.5 * (1 + std::cos(kPi<double> * (i + 0.5) / 15));
      SimdGlassNodeValues(c.alpha, c.eta, c.masking, c.mu, phi, theta, v, c.part);
      const RoughDielectric<double, GgxNdf<double>> bsdf(GgxNdf<double>(c.alpha), c.eta, c.masking,
                                                         DielectricTransport::kImportance);
      const double lambda_o = bsdf.Lambda(Vec3<double>{frame.so, 0, frame.mu});
      const ScalarGlassNodes nodes{&bsdf, &frame, 1 + lambda_o, lambda_o, c.part};
      nodes(GlassRay{std::cos(phi), std::sin(phi)}, theta, w);
      for (int i = 0; i < 15; ++i) {
        EXPECT_LE(std::abs(v[i] - w[i]), kNodeBound) << target << " node " << i;
        worst_node = std::max(worst_node, std::abs(v[i] - w[i]));
      }
    }
    std::printf("%s: %zu part texels, largest |simd - scalar| %.3g (%.3g of the bound), nodes %.3g\n", target.c_str(),
                cases.size(), worst, worst_ratio, worst_node);
  }
  ForceTarget("best");
}

// The Schlick-weighted refraction (EEVEE's btdf_ggx), node by node and
// texel by texel with the same bounds: ior 1 to inf (where 1 / eta = 0 and
// the lanes form no F), grazing and tiny roughness, both maskings.
TEST(GlassLanesTest, SchlickTransmissionAgreesWithTheScalarReferenceOnEveryTarget) {
  const double inf = std::numeric_limits<double>::infinity();
  const double etas[] = {1.0, 1.0002, 1.5, 100, 19999, inf};
  const double alphas[] = {1e-4, 1.0 / 256, 0.04, 0.3, 1.0};
  const double mus[] = {1e-7, 1e-3, 0.3, 0.9999, 1.0};
  struct Case {
    double alpha, eta, mu;
    Masking masking;
    RuleResult ref;
  };
  const DielectricPart part = DielectricPart::kTransmissionSchlick;
  std::vector<Case> cases;
  for (Masking masking : {Masking::kSeparable, Masking::kHeightCorrelated}) {
    for (double eta : etas) {
      for (double alpha : alphas) {
        for (double mu : mus) {
          cases.push_back({alpha, eta, mu, masking, GlassAlbedo(alpha, eta, masking, mu, 1e-7, 512, part)});
        }
      }
    }
  }
  std::mt19937_64 rng(36);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (const std::string& target : AvailableTargets()) {
    ForceTarget(target);
    double worst = 0, worst_ratio = 0, worst_node = 0;
    for (const Case& c : cases) {
      const RuleResult got = SimdGlassAlbedo(c.alpha, c.eta, c.masking, c.mu, 1e-7, 512, part);
      ASSERT_TRUE(std::isfinite(got.value) && std::isfinite(got.error)) << target << " eta " << c.eta;
      ASSERT_TRUE(std::isfinite(c.ref.value) && std::isfinite(c.ref.error)) << "eta " << c.eta;
      const double d = std::abs(got.value - c.ref.value);
      const double bound = kClaimShare * (got.error + c.ref.error) + kRoundingBound;
      EXPECT_LE(d, bound) << target << " alpha " << c.alpha << " eta " << c.eta << " mu " << c.mu;
      worst = std::max(worst, d);
      worst_ratio = std::max(worst_ratio, d / bound);
      // The nodes of one random ray piece, away from eta = 1, where both
      // paths form cos_t = sqrt(1 - (1 - c^2)) with a cancellation of
      // their own (the texels above agree; measured 3.3e-10 per node).
      if (c.eta == 1.0) continue;
      const double phi = (u(rng) - 0.5) * kPi<double>;
      const GlassFrame frame(c.alpha, c.eta, c.mu);
      const double tmax = frame.ThetaMax(std::sin(phi));
      double theta[15], v[15], w[15];
      const double a = u(rng) * tmax, b = a + (tmax - a) * u(rng);
      for (int i = 0; i < 15; ++i) theta[i] = a + (b - a) * 0.5 * (1 + std::cos(kPi<double> * (i + 0.5) / 15));
      SimdGlassNodeValues(c.alpha, c.eta, c.masking, c.mu, phi, theta, v, part);
      const RoughDielectric<double, GgxNdf<double>> bsdf(GgxNdf<double>(c.alpha), c.eta, c.masking,
                                                         DielectricTransport::kImportance);
      const double lambda_o = bsdf.Lambda(Vec3<double>{frame.so, 0, frame.mu});
      const ScalarGlassNodes nodes{&bsdf, &frame, 1 + lambda_o, lambda_o, part};
      nodes(GlassRay{std::cos(phi), std::sin(phi)}, theta, w);
      for (int i = 0; i < 15; ++i) {
        EXPECT_LE(std::abs(v[i] - w[i]), kNodeBound) << target << " node " << i << " eta " << c.eta;
        worst_node = std::max(worst_node, std::abs(v[i] - w[i]));
      }
    }
    std::printf("%s: %zu schlick-transmission texels, largest |simd - scalar| %.3g (%.3g of the bound), nodes %.3g\n",
                target.c_str(), cases.size(), worst, worst_ratio, worst_node);
  }
  ForceTarget("best");
  // The smooth interface: 1 - (1 - mu)^5 on both paths.
  EXPECT_EQ(SimdGlassAlbedo(0.0, inf, Masking::kSeparable, 0.5, 1e-7, 512, part).value, 1 - std::pow(0.5, 5));
}

// alpha = 0 is the smooth interface, as in GlassAlbedo: E = 1, its
// reflection F(eta, mu) and its refraction 1 - F.
TEST(GlassLanesTest, SmoothInterfaceIsOne) {
  const RuleResult r = SimdGlassAlbedo(0.0, 1.5, Masking::kHeightCorrelated, 0.5, 1e-7, 512);
  EXPECT_EQ(r.value, 1.0);
  EXPECT_EQ(r.error, 0.0);
  const double f = FresnelDielectric(1.5, 0.5);
  EXPECT_EQ(SimdGlassAlbedo(0.0, 1.5, Masking::kSeparable, 0.5, 1e-7, 512, DielectricPart::kReflection).value, f);
  EXPECT_EQ(SimdGlassAlbedo(0.0, 1.5, Masking::kSeparable, 0.5, 1e-7, 512, DielectricPart::kTransmission).value, 1 - f);
}

}  // namespace
}  // namespace brdfbake
