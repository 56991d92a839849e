// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The microfacet BRDF of every model: the exact value E = 1 - ln 2 (GGX,
// alpha = 1, mu = 1), reciprocity, energy never above one with F = 1, the
// ordering of the two masking variants, and agreement between deterministic
// quadrature of E and the importance-sampled estimator of each model's own
// sampler and pdf.

#include <cmath>
#include <cstdio>
#include <memory>
#include <random>

#include <gtest/gtest.h>

#include "brdfbake/model.h"
#include "brdfbake/models/brdf.h"
#include "brdfbake/models/ggx.h"
#include "util/test_util.h"

namespace brdfbake {
namespace {

std::vector<ModelParams> AllModels() {
  std::vector<ModelParams> out;
  auto add = [&](const char* name, double ax, double ay, double gamma = 2, double tx = 0,
                 double ty = 0, double tz = 0) {
    ModelParams p;
    p.kind = ParseModelKind(name);
    p.alpha_x = ax;
    p.alpha_y = ay;
    p.gamma = gamma;
    p.theta_x = tx;
    p.theta_y = ty;
    p.theta_z = tz;
    out.push_back(p);
  };
  add("ggx", 0.5, 0.5);
  add("ggx", 0.7, 0.15);
  add("beckmann", 0.4, 0.4);
  add("beckmann", 0.2, 0.6);
  add("std", 0.5, 0.5, 1.7);
  add("std", 0.3, 0.6, 3.5);
  add("std", 0.4, 0.4, std::numeric_limits<double>::infinity());
  add("ellipsoid", 0.5, 0.5);
  add("ellipsoid", 0.6, 0.25, 2, 0.2, -0.3, 0.8);
  return out;
}

// E(wo) = int f(wi, wo) cos(theta_i) dwi over the upper hemisphere, in
// (mu_i, phi_i); the integrand is smooth inside the domain for reflection.
double AlbedoQuadrature(const Model& model, const Vec3<double>& wo, Masking masking,
                        const Fresnel& fresnel = Fresnel::One()) {
  return test::IntegrateDirections(
      [&](const test::Dir& wi) { return model.Brdf(wi, wo, fresnel, masking, 0) * wi.z; },
      0.0, 1.0, 1e-10, 15);
}

TEST(BrdfTest, GgxAlphaOneNormalIncidenceIsOneMinusLn2) {
  // docs/format.md: GGX, height-correlated, alpha = 1, mu = 1, F = 1.
  const GgxNdf<double> ndf(1.0);
  const Vec3<double> wo(0, 0, 1);
  const double e = test::IntegrateDirections(
      [&](const test::Dir& wi) {
        return Brdf(ndf, Fresnel::One(), wi, wo, Masking::kHeightCorrelated) * wi.z;
      },
      0.0, 1.0, 1e-13);
  std::printf("E(ggx, alpha=1, mu=1) = %.15f, 1 - ln 2 = %.15f\n", e, 1 - std::log(2.0));
  EXPECT_NEAR(e, 1.0 - std::log(2.0), 1e-11);
}

TEST(BrdfTest, Reciprocity) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  const Fresnel fresnels[] = {Fresnel::One(), Fresnel::Schlick({0.9, 0.5, 0.1}),
                              Fresnel::Dielectric(1.5),
                              Fresnel::Conductor({0.2, 0.9, 1.1}, {3.9, 2.4, 2.1})};
  for (const ModelParams& p : AllModels()) {
    const auto model = MakeModel(p);
    for (Masking masking : {Masking::kHeightCorrelated, Masking::kSeparable}) {
      for (const Fresnel& fr : fresnels) {
        for (int i = 0; i < 200; ++i) {
          const Vec3<double> a = FromMuPhi(uni(rng), 2 * kPi<double> * uni(rng));
          const Vec3<double> b = FromMuPhi(uni(rng), 2 * kPi<double> * uni(rng));
          const double fab = model->Brdf(a, b, fr, masking, i % 3);
          const double fba = model->Brdf(b, a, fr, masking, i % 3);
          ASSERT_TRUE(std::isfinite(fab));
          EXPECT_NEAR(fab, fba, 1e-12 * std::max(1.0, std::abs(fab))) << p.ToJson();
        }
      }
    }
  }
}

TEST(BrdfTest, MaskingOrdering) {
  // 1/(1+a+b) >= 1/((1+a)(1+b)), and both <= min(G1(wi), G1(wo)).
  std::mt19937_64 rng(6);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  for (const ModelParams& p : AllModels()) {
    const auto model = MakeModel(p);
    for (int i = 0; i < 300; ++i) {
      const Vec3<double> a = FromMuPhi(uni(rng), 2 * kPi<double> * uni(rng));
      const Vec3<double> b = FromMuPhi(uni(rng), 2 * kPi<double> * uni(rng));
      const double hc = model->G2(a, b, Masking::kHeightCorrelated);
      const double sep = model->G2(a, b, Masking::kSeparable);
      EXPECT_GE(hc + 1e-15, sep) << p.ToJson();
      EXPECT_LE(hc, std::min(model->G1(a), model->G1(b)) + 1e-15) << p.ToJson();
      EXPECT_GE(sep, 0.0);
    }
  }
}

// Energy is never above one with F = 1, and the importance-sampled estimate
// with each model's own sampler and pdf agrees with the quadrature.
TEST(BrdfTest, AlbedoBoundedAndSamplerConsistent) {
  const double mus[] = {1.0, 0.6, 0.15};
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  for (const ModelParams& p : AllModels()) {
    const auto model = MakeModel(p);
    for (double mu : mus) {
      const Vec3<double> wo = FromMuPhi(mu, 0.4);
      for (Masking masking : {Masking::kHeightCorrelated, Masking::kSeparable}) {
        const double e = AlbedoQuadrature(*model, wo, masking);
        EXPECT_LE(e, 1.0 + 1e-7) << p.ToJson() << " mu=" << mu;
        EXPECT_GT(e, 0.0);
        // Importance-sampled estimate: f cos / pdf(wi), pdf(wi) = pdf(m) / (4 wo.m).
        const int n = 40000;
        double sum = 0, sum2 = 0;
        for (int i = 0; i < n; ++i) {
          const Vec3<double> m = model->Sample(wo, uni(rng), uni(rng));
          const Vec3<double> wi = Reflect(wo, m);
          double w = 0;
          const double pdf = model->Pdf(wo, m);
          if (wi.z > 0 && pdf > 0) {
            w = model->Brdf(wi, wo, Fresnel::One(), masking, 0) * wi.z * 4 * Dot(wo, m) / pdf;
          }
          sum += w;
          sum2 += w * w;
        }
        const double mean = sum / n;
        const double sigma = std::sqrt(std::max(0.0, sum2 / n - mean * mean) / n);
        EXPECT_NEAR(mean, e, 5 * sigma + 1e-9) << p.ToJson() << " mu=" << mu;
      }
    }
  }
}

}  // namespace
}  // namespace brdfbake
