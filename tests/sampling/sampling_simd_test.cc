// The sampling integrators with their points in double SIMD lanes
// (src/sampling/*_sampling_simd.h) against their double scalar references
// (src/sampling/sampling_integrators.h), texel by texel, on every compiled target
// the CPU runs. Both draw the same points in the same order; they differ
// only in the rounding of each sample's normal and weight (the GGX and
// Beckmann visible-normal samplers are within 1e-14 of the reference,
// CheckGgxSamplingF64 and CheckBeckmannSamplingF64; Lambda within 2e-15,
// simd_math_f64_test and simd_std_f64_test) and in the order of the sums.
// The NDF samplers of Beckmann and STD and the STD's D in double lanes
// (slope_sampling_simd.cc) are checked through these sums: a sampler or a
// density off by more than rounding moves them far beyond the bound here.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "brdfbake/targets.h"
#include "sampling/sampling_integrators.h"
#include "sampling/ggx_sampling_simd.h"
#include "sampling/slope_sampling_simd.h"

namespace brdfbake {
namespace {

// |lanes - scalar| of a texel value in [0, 1] (a sum of up to 2^20 terms
// of at most 1 in the lanes' order against the scalar order, plus each
// weight's rounding): measured below 8e-15 on every target.
constexpr double kRoundingBound = 1e-13;

const std::vector<double> kAlphas = {1e-4, 1e-3, 0.02, 0.1, 0.4, 1.0};
const std::vector<double> kMus = {1e-7, 1e-3, 0.05, 0.3, 0.7, 1.0};

// Runs `check(masking, alpha, mu) -> |lanes - scalar|` on every target and
// prints the largest difference.
template <class Check>
void OnEveryTarget(const char* what, const Check& check) {
  const std::vector<std::string> targets = AvailableTargets();
  for (const std::string& target : targets) {
    ForceTarget(target);
    double worst = 0;
    for (Masking masking : {Masking::kHeightCorrelated, Masking::kSeparable}) {
      for (double alpha : kAlphas) {
        for (double mu : kMus) {
          const double d = check(masking, alpha, mu);
          EXPECT_LE(d, kRoundingBound) << target << " " << what << " alpha " << alpha << " mu "
                                       << mu << " masking " << MaskingName(masking);
          worst = std::max(worst, d);
        }
      }
    }
    std::printf("%s: largest |lanes - scalar| of %s %.3g\n", target.c_str(), what, worst);
  }
  ForceTarget("best");
}

double Differs(const TexelEstimate& a, const TexelEstimate& b) {
  return std::max({std::abs(a.e - b.e), std::abs(a.bias - b.bias), std::abs(a.scale - b.scale)});
}

// QMC and MC (the same estimator over other points) with the model's
// visible-normal sampler; 8 x 125 points leave a tail of 5 lanes on AVX3
// and 1 on AVX2, 8 x 128 none.
template <class Ndf>
void CheckQmc(const char* model, const std::function<Ndf(double)>& make) {
  for (bool plain_mc : {false, true}) {
    for (int samples : {1000, 1024}) {
      const std::string what = std::string(model) + (plain_mc ? " mc" : " qmc");
      OnEveryTarget(what.c_str(), [&](Masking masking, double alpha, double mu) {
        const Ndf ndf = make(alpha);
        const TexelEstimate ref = QmcTexel(ndf, mu, masking, samples, 77, plain_mc);
        const TexelEstimate got = SimdQmcTexel(ndf, mu, masking, samples, 77, plain_mc);
        // The error estimates, 4 standard errors of the 8 replicas, move by
        // at most 4 sqrt(8 / 7) / sqrt(8) < 1.6 times the replicas' largest
        // difference.
        EXPECT_NEAR(got.err_e, ref.err_e, 2 * kRoundingBound);
        EXPECT_NEAR(got.err_bias, ref.err_bias, 2 * kRoundingBound);
        EXPECT_NEAR(got.err_scale, ref.err_scale, 2 * kRoundingBound);
        return Differs(got, ref);
      });
    }
  }
}

TEST(SamplingSimdTest, GgxQmcAndMcAgreeWithTheScalarReferenceOnEveryTarget) {
  CheckQmc<GgxNdf<double>>("ggx", [](double a) { return GgxNdf<double>(a); });
}

#if BRDFBAKE_WITH_BECKMANN
TEST(SamplingSimdTest, BeckmannQmcAndMcAgreeWithTheScalarReferenceOnEveryTarget) {
  CheckQmc<BeckmannNdf<double>>("beckmann", [](double a) { return BeckmannNdf<double>(a); });
}
#endif

#if BRDFBAKE_WITH_STD
// Every branch of the pseudo visible-normal sampler (alpha 1e-4 and 1e-3:
// NDF sampling; gamma 1.501 and 2: GGX's visible normals; 30 and inf:
// Beckmann's; 7 at alpha 0.02 and 0.1: NDF sampling between the bands).
TEST(SamplingSimdTest, StdQmcAndMcAgreeWithTheScalarReferenceOnEveryTarget) {
  for (double gamma : {1.501, 2.0, 7.0, 30.0, std::numeric_limits<double>::infinity()}) {
    const std::string what = "std, gamma " + std::to_string(gamma);
    CheckQmc<StudentTNdf<double>>(what.c_str(),
                                  [&](double a) { return StudentTNdf<double>(a, a, gamma); });
  }
}
#endif

// Every count of points per replica from 1 to 2 vectors and a few more:
// each tail length of every target, against the scalar sum; and counts
// across the blocks of kSamplingBlock points.
TEST(SamplingSimdTest, EveryTailLengthSumsTheSamePoints) {
  const GgxNdf<double> ndf(0.3);
  std::vector<int> counts;
  for (int n = 1; n <= 20; ++n) counts.push_back(n);
  for (int n : {kSamplingBlock - 1, kSamplingBlock, kSamplingBlock + 5, 3 * kSamplingBlock + 7}) {
    counts.push_back(n);
  }
  for (int n : counts) {
    const TexelEstimate ref = QmcTexel(ndf, 0.4, Masking::kHeightCorrelated, 8 * n, 5, false);
    const TexelEstimate got = SimdQmcTexel(ndf, 0.4, Masking::kHeightCorrelated, 8 * n, 5, false);
    EXPECT_LE(Differs(got, ref), kRoundingBound) << n << " points per replica";
    const QuadratureResult er = EngineRule(ndf, 0.4, Masking::kSeparable, n);
    const QuadratureResult eg = SimdEngineRule(ndf, 0.4, Masking::kSeparable, n);
    EXPECT_NEAR(eg.e, er.e, kRoundingBound) << n << " engine points";
    EXPECT_NEAR(eg.fc, er.fc, kRoundingBound) << n << " engine points";
  }
}

// The engine rule (NDF sampling of the half vector, Hammersley points) of
// every sampled model.
template <class Ndf>
void CheckEngine(const char* what, const std::function<Ndf(double)>& make) {
  OnEveryTarget(what, [&](Masking masking, double alpha, double mu) {
    const Ndf ndf = make(alpha);
    const QuadratureResult ref = EngineRule(ndf, mu, masking, 1000);
    const QuadratureResult got = SimdEngineRule(ndf, mu, masking, 1000);
    EXPECT_GT(ref.e, 0) << what << " alpha " << alpha << " mu " << mu;
    return std::max(std::abs(got.e - ref.e), std::abs(got.fc - ref.fc));
  });
}

TEST(SamplingSimdTest, GgxEngineAgreesWithTheScalarReferenceOnEveryTarget) {
  CheckEngine<GgxNdf<double>>("ggx engine", [](double a) { return GgxNdf<double>(a); });
}

#if BRDFBAKE_WITH_BECKMANN
TEST(SamplingSimdTest, BeckmannEngineAgreesWithTheScalarReferenceOnEveryTarget) {
  CheckEngine<BeckmannNdf<double>>("beckmann engine",
                                   [](double a) { return BeckmannNdf<double>(a); });
}
#endif

#if BRDFBAKE_WITH_STD
// From the heavy-tailed end (gamma 1.501, whose radial slope
// (gamma - 1) expm1(e / (gamma - 1)) reaches 1e15 at u = 1 - 2^-53) to
// Beckmann (gamma = inf).
TEST(SamplingSimdTest, StdEngineAgreesWithTheScalarReferenceOnEveryTarget) {
  for (double gamma : {1.501, 2.0, 3.7, 30.0, std::numeric_limits<double>::infinity()}) {
    const std::string what = "std engine, gamma " + std::to_string(gamma);
    CheckEngine<StudentTNdf<double>>(
        what.c_str(), [&](double a) { return StudentTNdf<double>(a, a, gamma); });
  }
}
#endif

}  // namespace
}  // namespace brdfbake
