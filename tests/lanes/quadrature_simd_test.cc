// The baker's one-dimensional rules with their azimuthal nodes in SIMD
// lanes (src/lanes/quadrature_simd.h) against their double scalar references
// (azimuthal.h, azimuthal_slope.h), texel by texel, on every compiled target
// the CPU runs: E, dfg.bias and the claims, every baked model, both
// maskings, from alpha = 1e-4 to 1 and from grazing (mu = 1e-7) to normal
// incidence. Both evaluate the same pieces and nodes; they differ only in
// the rounding of each term (Highway's Exp, Log1p, Sin and Cos, the order
// of the sums): measured within 1e-15 of each other.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "brdfbake/batch.h"
#include "brdfbake/targets.h"
#include "lanes/aniso_lanes.h"
#include "lanes/ellipsoid_lanes.h"
#include "lanes/ggx_lanes.h"
#include "lanes/sel_lanes.h"
#include "lanes/slope_lanes.h"
#include "rules/ellipsoid/ellipsoid_albedo.h"
#include "rules/ellipsoid/ellipsoid_albedo_rule.h"
#include "rules/ggx_aniso/aniso_ggx.h"
#include "util/poly_test_util.h"

namespace brdfbake {
namespace {

constexpr double kRoundingBound = 1e-13;

// A GGX rule with lanes against its scalar reference on every target, at
// alpha 1e-4 to 1 and mu 1e-7 to 1, both maskings: `compare(alpha, mu,
// masking, &claim_got, &claim_ref)` returns |simd - scalar| of the values
// and the two claims.
template <class Compare>
void CompareGgxRule(const char* rule, const Compare& compare) {
  const std::vector<std::string> targets = AvailableTargets();
  for (size_t k = 0; k < targets.size(); ++k) {
    ForceTarget(targets[k]);
    double worst = 0;
    for (Masking masking : {Masking::kHeightCorrelated, Masking::kSeparable}) {
      for (double alpha : {1e-4, 1e-3, 0.01, 0.1, 0.4, 1.0}) {
        for (double mu : {1e-7, 1e-3, 0.05, 0.3, 0.7, 1.0}) {
          double got_err, ref_err;
          const double d = compare(alpha, mu, masking, &got_err, &ref_err);
          EXPECT_LE(d, kRoundingBound) << targets[k] << " alpha " << alpha << " mu " << mu;
          EXPECT_NEAR(got_err, ref_err, 1e-3 * ref_err + 1e-15);
          worst = std::max(worst, d);
        }
      }
    }
    std::printf("%s: largest |simd - scalar| of the %s rule %.3g\n", targets[k].c_str(), rule,
                worst);
  }
  ForceTarget("best");
}

// The Schlick-weighted one-dimensional GGX rule with the azimuthal
// remainder's nodes in lanes against its scalar reference: the same pieces,
// the same nodes, rounding apart.
TEST(QuadratureSimdTest, AzimuthalDfgAgreesWithTheScalarReferenceOnEveryTarget) {
  CompareGgxRule(
      "dfg", [](double alpha, double mu, Masking masking, double* got_err, double* ref_err) {
        const AzimuthalDfgResult ref = GgxAzimuthalDfg(alpha, mu, masking, 1e-7, 512);
        const AzimuthalDfgResult got = SimdGgxAzimuthalDfg(alpha, mu, masking, 1e-7, 512);
        *got_err = got.err_bias;
        *ref_err = ref.err_bias;
        return std::max(std::abs(got.e - ref.e), std::abs(got.bias - ref.bias));
      });
}

// E's one-dimensional GGX rule (the azimuth in closed form) with its theta_i
// nodes in lanes against its scalar reference: the same pieces, rounding
// apart (hn::Sin and hn::Cos against the C library's).
TEST(QuadratureSimdTest, AzimuthalAlbedoAgreesWithTheScalarReferenceOnEveryTarget) {
  CompareGgxRule(
      "albedo", [](double alpha, double mu, Masking masking, double* got_err, double* ref_err) {
        const RuleResult ref = GgxAzimuthalAlbedo(alpha, mu, masking, 1e-7, 512);
        const RuleResult got = SimdGgxAzimuthalAlbedo(alpha, mu, masking, 1e-7, 512);
        *got_err = got.error;
        *ref_err = ref.error;
        return std::abs(got.value - ref.value);
      });
}

// Beckmann and STD: the same check for SlopeAzimuthalDfg.
template <class Ndf, class Make>
void CompareSlope(const char* name, const Make& make) {
  const std::vector<std::string> targets = AvailableTargets();
  for (size_t k = 0; k < targets.size(); ++k) {
    ForceTarget(targets[k]);
    double worst = 0;
    for (Masking masking : {Masking::kHeightCorrelated, Masking::kSeparable}) {
      for (double alpha : {1e-4, 1e-2, 0.1, 0.4, 1.0}) {
        const Ndf ndf = make(alpha);
        for (double mu : {1e-7, 1e-3, 0.05, 0.3, 0.7, 1.0}) {
          for (bool bias : {false, true}) {
            const AzimuthalDfgResult ref = SlopeAzimuthalDfg(ndf, mu, masking, bias, 1e-7, 512);
            const AzimuthalDfgResult got = SimdSlopeAzimuthalDfg(ndf, mu, masking, bias, 1e-7, 512);
            const double d = std::max(std::abs(got.e - ref.e), std::abs(got.bias - ref.bias));
            EXPECT_LE(d, kRoundingBound) << targets[k] << " " << name << " alpha " << alpha
                                         << " mu " << mu;
            EXPECT_NEAR(got.err_e, ref.err_e, 1e-3 * ref.err_e + 1e-15);
            worst = std::max(worst, d);
          }
        }
      }
    }
    std::printf("%s %s: largest |simd - scalar| %.3g\n", targets[k].c_str(), name, worst);
  }
  ForceTarget("best");
}

#if BRDFBAKE_WITH_BECKMANN
TEST(QuadratureSimdTest, BeckmannAgreesWithTheScalarReferenceOnEveryTarget) {
  CompareSlope<BeckmannNdf<double>>("beckmann", [](double a) { return BeckmannNdf<double>(a); });
}
#endif

#if BRDFBAKE_WITH_STD
TEST(QuadratureSimdTest, StudentTAgreesWithTheScalarReferenceOnEveryTarget) {
  for (double gamma : {1.6, 3.0, 1e6, std::numeric_limits<double>::infinity()}) {
    CompareSlope<StudentTNdf<double>>(
        ("std " + std::to_string(gamma)).c_str(),
        [gamma](double a) { return StudentTNdf<double>(a, a, gamma); });
  }
}
#endif

}  // namespace
}  // namespace brdfbake

namespace brdfbake {
namespace {

// A slope-plane rule (rule(simd, masking, case, mu, phi)) with each ray
// piece's nodes in lanes against its scalar reference on every target,
// grazing to normal incidence, wo at several azimuths. The two take the
// same pieces up to a bisection decision that rounding can flip; there
// they agree within their claims.
template <class Rule>
void CompareSlopePlane(const char* name, int cases, const Rule& rule) {
  const std::vector<std::string> targets = AvailableTargets();
  for (size_t k = 0; k < targets.size(); ++k) {
    ForceTarget(targets[k]);
    double worst = 0;
    for (Masking masking : {Masking::kHeightCorrelated, Masking::kSeparable}) {
      for (int c = 0; c < cases; ++c) {
        for (double mu : {1e-7, 0.05, 0.5, 1.0}) {
          for (double phi : {0.0, 0.6, 1.5, 4.5}) {
            const RuleResult ref = rule(false, masking, c, mu, phi);
            const RuleResult got = rule(true, masking, c, mu, phi);
            const double d = std::abs(got.value - ref.value);
            const double bound =
                got.pieces == ref.pieces ? kRoundingBound : got.error + ref.error;
            EXPECT_LE(d, bound) << targets[k] << " " << name << " case " << c << " mu " << mu
                                << " phi " << phi;
            worst = std::max(worst, d);
          }
        }
      }
    }
    std::printf("%s: largest |simd - scalar| of the %s rule %.3g\n", targets[k].c_str(), name,
                worst);
  }
  ForceTarget("best");
}

// ggx-aniso: anisotropic and isotropic widths up to 100 : 1.
TEST(QuadratureSimdTest, AnisoGgxAgreesWithTheScalarReferenceOnEveryTarget) {
  const double widths[][2] = {{1e-4, 1e-4}, {0.3, 0.3}, {1.0, 0.01}, {0.5, 0.1}, {0.05, 0.8}};
  CompareSlopePlane("ggx-aniso", 5, [&](bool simd, Masking m, int c, double mu, double phi) {
    const double ax = widths[c][0], ay = widths[c][1];
    return simd ? SimdAnisoGgxAlbedo(ax, ay, mu, phi, m, 1e-7, 512)
                : AnisoGgxAlbedo(ax, ay, mu, phi, m, 1e-7, 512);
  });
}

#if BRDFBAKE_WITH_ELLIPSOID
// The ellipsoid: aligned, tilted and 10^4 : 1 tilted.
TEST(QuadratureSimdTest, EllipsoidAgreesWithTheScalarReferenceOnEveryTarget) {
  const double cases[][5] = {{0.3, 0.6, 0, 0, 0}, {0.3, 0.6, 0.35, 0, 0.5}, {1, 1e-4, 1.5, -1.2, 0.3}};
  CompareSlopePlane("ellipsoid", 3, [&](bool simd, Masking m, int c, double mu, double phi) {
    const double* p = cases[c];
    return simd ? SimdEllipsoidAlbedo(p[0], p[1], p[2], p[3], p[4], mu, phi, m, 1e-7, 512)
                : EllipsoidAlbedo(p[0], p[1], p[2], p[3], p[4], mu, phi, m, 1e-7, 512);
  });
}

#endif  // BRDFBAKE_WITH_ELLIPSOID

#if BRDFBAKE_WITH_SEL
// The sel lobe's integral: the inner rule's nodes in lanes against the
// scalar reference on every target, widths from 1e-4 to 1 and 100 : 1.
TEST(QuadratureSimdTest, SelAgreesWithTheScalarReferenceOnEveryTarget) {
  const double widths[][2] = {{1e-4, 1e-4}, {0.3, 0.6}, {1.0, 0.01}, {0.05, 0.8}, {1.0, 1.0}};
  const std::vector<std::string> targets = AvailableTargets();
  for (size_t k = 0; k < targets.size(); ++k) {
    ForceTarget(targets[k]);
    double worst = 0;
    for (const auto& w : widths) {
      for (double tol : {1e-7, 1e-10}) {
        const SelIntegral ref = SelLobeIntegral(w[0], w[1], tol);
        const SelIntegral got = SimdSelLobeIntegral(w[0], w[1], tol);
        const double d = std::abs(got.ratio - ref.ratio);
        // The same pieces agree to rounding; a different bisection within
        // both claims.
        EXPECT_LE(d, got.ratio_error + ref.ratio_error)
            << targets[k] << " alpha " << w[0] << "," << w[1] << " tol " << tol;
        EXPECT_TRUE(std::isfinite(got.n) && got.n > 0);
        worst = std::max(worst, d);
      }
    }
    std::printf("%s: largest |simd - scalar| of the sel integral's ratio %.3g\n",
                targets[k].c_str(), worst);
  }
  ForceTarget("best");
}

#endif  // BRDFBAKE_WITH_SEL

#if BRDFBAKE_WITH_ELLIPSOID
// The kinks' root search in lanes against PolyRootsIn on every target:
// random polynomials of degree 0 to 4 (stored as quartics) with roots at
// least 1e-3 apart, batches of 1 to 40 (whole vectors and tails). The
// lanes' Horner steps use fused multiply-adds, so a root may differ from
// the scalar one, within the two searches' tolerances.
TEST(QuadratureSimdTest, PolyRootsInLanesAgreeWithTheScalarSearchOnEveryTarget) {
  const std::vector<std::string> targets = AvailableTargets();
  for (size_t k = 0; k < targets.size(); ++k) {
    ForceTarget(targets[k]);
    std::mt19937_64 rng(7);
    double worst = 0;
    int roots_seen = 0;
    for (int batch = 1; batch <= 40; ++batch) {
      std::vector<PolyRootsProblem> problems(batch);
      for (PolyRootsProblem& q : problems) q = RandomRootsProblem(rng, 1e-3);
      SimdPolyRootsInBatch(problems.data(), batch);
      for (const PolyRootsProblem& q : problems) {
        double want[kMaxPolyDegree];
        const int n = PolyRootsIn(q.c, q.n, q.lo, q.hi, q.tol, want);
        ASSERT_EQ(q.count, n) << targets[k];
        for (int i = 0; i < n; ++i) {
          EXPECT_NEAR(q.roots[i], want[i], 2 * q.tol) << targets[k];
          worst = std::max(worst, std::abs(q.roots[i] - want[i]) / q.tol);
        }
        roots_seen += n;
      }
    }
    EXPECT_GT(roots_seen, 100);
    std::printf("%s: largest |lanes - scalar| of the roots %.3g of their tolerance\n",
                targets[k].c_str(), worst);
  }
  ForceTarget("best");
}

// The ellipsoid rays set up in lanes (SimdSetUpEllipsoidRays) against
// EllipsoidRay::SetUp with the C library's cosine and sine, on every
// target: aligned, tilted, thin and 10^4 : 1 tilted materials, views from
// grazing to normal, rays all around. hn::Cos and hn::Sin are within 3 ulp
// of the C library's, so the fields agree to that rounding, amplified where
// they cancel: the roots rho_+- near a ray tangent to the horizon disk
// (disc small), the chord's length x_hi - x_lo of a short chord, omx2 at
// grazing (rho_+ large). Measured: 1.6e-13 relative at most for the
// geometry (with the halves' spans), 1.3e-13 for the maps' scales (a probe
// of Lambda), 2.5e-13 for the kinks' quartics relative to their largest
// coefficient; bound 1e-12.
TEST(QuadratureSimdTest, EllipsoidRaysSetUpInLanesAgreeWithTheScalarOnEveryTarget) {
  const double materials[][5] = {{0.3, 0.6, 0.35, 0, 0.52},
                                 {0.3, 0.6, 0, 0, 0},
                                 {0.05, 0.3, 1.22, 0, 0.35},
                                 {1, 1e-4, 1.5, -1.2, 0.3}};
  const std::vector<std::string> targets = AvailableTargets();
  for (size_t k = 0; k < targets.size(); ++k) {
    ForceTarget(targets[k]);
    double worst_geometry = 0, worst_scale = 0, worst_quartic = 0;
    int valid_rays = 0;
    for (const auto& m : materials) {
      for (double mu : {1e-6, 0.05, 0.4, 0.9, 1.0}) {
        for (double phi : {0.0, 1.0, 2.5, 4.0}) {
          const EllipsoidFrame f = MakeEllipsoidFrame(m[0], m[1], m[2], m[3], m[4], mu, phi,
                                                      Masking::kHeightCorrelated, 1e-7);
          std::vector<EllipsoidRay> want, got;
          for (int i = 0; i < 37; ++i) {
            const double psi = -2 * kPi<double> + 4 * kPi<double> * i / 36 + 0.01;
            want.emplace_back(f, psi);
            got.emplace_back(f, psi);
            want.back().SetUp(std::cos(psi), std::sin(psi));
          }
          SimdSetUpEllipsoidRays(got.data(), static_cast<int>(got.size()));
          for (size_t i = 0; i < want.size(); ++i) {
            const EllipsoidRay &w = want[i], &g = got[i];
            ASSERT_EQ(g.valid(), w.valid()) << targets[k] << " psi " << w.psi_;
            if (!w.valid()) continue;
            ++valid_rays;
            ASSERT_EQ(g.lo_edge_, w.lo_edge_);
            auto rel = [](double a, double b) {
              return std::abs(a - b) / std::max(std::abs(b), 1e-300);
            };
            for (auto field : {&EllipsoidRay::ex_, &EllipsoidRay::ey_, &EllipsoidRay::ee_,
                               &EllipsoidRay::rho_plus_, &EllipsoidRay::x_hi_,
                               &EllipsoidRay::omx2_hi_, &EllipsoidRay::len_, &EllipsoidRay::mid_}) {
              worst_geometry = std::max(worst_geometry, rel(g.*field, w.*field));
            }
            if (w.lo_edge_) {
              for (auto field : {&EllipsoidRay::rho_minus_, &EllipsoidRay::x_lo_,
                                 &EllipsoidRay::omx2_lo_}) {
                worst_geometry = std::max(worst_geometry, rel(g.*field, w.*field));
              }
              worst_scale = std::max(worst_scale, rel(g.c_lo_, w.c_lo_));
            }
            worst_scale = std::max(worst_scale, rel(g.c_hi_, w.c_hi_));
            worst_geometry = std::max(worst_geometry, rel(g.span_hi_, w.span_hi_));
            worst_geometry = std::max(worst_geometry, rel(g.span_lo_, w.span_lo_));
            // The kinks' quartic: its coefficients against their largest.
            ASSERT_EQ(g.kinks_, w.kinks_);
            if (!w.kinks_) continue;
            double big = 0, big_ah = 0;
            for (double c : w.kink_c_) big = std::max(big, std::abs(c));
            for (double c : w.kink_ah_) big_ah = std::max(big_ah, std::abs(c));
            for (int c = 0; c < 5; ++c) {
              worst_quartic = std::max(worst_quartic, std::abs(g.kink_c_[c] - w.kink_c_[c]) / big);
            }
            for (int c = 0; c < 3; ++c) {
              worst_quartic =
                  std::max(worst_quartic, std::abs(g.kink_ah_[c] - w.kink_ah_[c]) / big_ah);
            }
            worst_geometry = std::max(worst_geometry, rel(g.kink_lo_, w.kink_lo_));
          }
        }
      }
    }
    EXPECT_GT(valid_rays, 1000);
    EXPECT_LE(worst_geometry, 1e-12) << targets[k];
    EXPECT_LE(worst_scale, 1e-12) << targets[k];
    EXPECT_LE(worst_quartic, 1e-12) << targets[k];
    std::printf(
        "%s: ellipsoid rays in lanes: geometry within %.3g, maps' scales within %.3g, kinks' "
        "quartics within %.3g\n",
        targets[k].c_str(), worst_geometry, worst_scale, worst_quartic);
  }
  ForceTarget("best");
}

#endif  // BRDFBAKE_WITH_ELLIPSOID

}  // namespace
}  // namespace brdfbake
