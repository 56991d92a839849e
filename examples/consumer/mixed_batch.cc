// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// A path tracer's shading batch through brdfbake::core: every element has
// its own material (GGX roughness and Schlick F0), evaluated in one call
// and sampled in one call for light directions with their weight
// f cos / pdf and their pdf. Checked against the double reference; the
// library's domain check is shown on a material with roughness 0. Exits
// non-zero on any disagreement.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "brdfbake/batch.h"
#include "brdfbake/models/ggx.h"
#include "brdfbake/targets.h"

int main() {
  using namespace brdfbake;
  constexpr int kN = 53;  // not a whole number of vectors
  // The batch: a view per element and a material per element.
  std::vector<float> ox(kN), oy(kN), oz(kN), alpha(kN), f0(kN);
  for (int i = 0; i < kN; ++i) {
    const double to = 0.05 + 1.4 * i / kN, phi = 0.37 * i;
    ox[i] = float(std::sin(to) * std::cos(phi));
    oy[i] = float(std::sin(to) * std::sin(phi));
    oz[i] = float(std::cos(to));
    const float roughness = 0.1f + 0.8f * float((i * 7) % kN) / kN;
    alpha[i] = roughness * roughness;
    f0[i] = i % 3 == 0 ? 0.9f : 0.04f;  // a metal, then two dielectrics
  }
  BatchModel ggx;  // GGX, height-correlated, Schlick Fresnel
  const BatchElements materials{alpha.data(), nullptr, f0.data()};  // isotropic

  // Light directions for every element, with weight and pdf.
  std::vector<float> u1(kN), u2(kN), ix(kN), iy(kN), iz(kN), weight(kN), pdf(kN);
  for (int i = 0; i < kN; ++i) {
    u1[i] = (i + 0.5f) / kN;
    u2[i] = std::fmod(0.618034f * i, 1.0f);
  }
  SampleLightBatch(ggx, materials, {ox.data(), oy.data(), oz.data()}, u1.data(), u2.data(),
                   {ix.data(), iy.data(), iz.data(), weight.data(), pdf.data()}, kN);

  // The BRDF of each element's own material at the sampled directions.
  std::vector<float> f(kN);
  EvalBatch(ggx, materials, Quantity::kBrdf, {ix.data(), iy.data(), iz.data()},
            {ox.data(), oy.data(), oz.data()}, f.data(), kN);

  double worst_f = 0, worst_weight = 0;
  for (int i = 0; i < kN; ++i) {
    const GgxNdf<double> ndf(alpha[i]);
    const Vec3<double> wi(ix[i], iy[i], iz[i]), wo(ox[i], oy[i], oz[i]);
    if (!(wi.z > 0)) {
      worst_weight = std::max(worst_weight, double(weight[i]));  // must be 0
      continue;
    }
    const Vec3<double> h = Normalize(wi + wo);
    const double oh = Dot(wo, h);
    const double fresnel = f0[i] + (1 - f0[i]) * std::pow(1 - oh, 5);
    const double g2 = 1 / (1 + ndf.Lambda(wi) + ndf.Lambda(wo));
    const double ref = fresnel * ndf.D(h) * g2 / (4 * wi.z * wo.z);
    worst_f = std::max(worst_f, std::abs(f[i] - ref) / ref);
    // Visible-normal sampling: f cos / pdf = F G2 / G1(wo).
    const double ref_weight = fresnel * g2 * (1 + ndf.Lambda(wo));
    worst_weight = std::max(worst_weight, std::abs(weight[i] - ref_weight) / ref_weight);
    // pdf = D(h) G1(wo) (wo.h) / wo.z / (4 wo.h).
    if (!(std::abs(pdf[i] * 4 * wo.z * (1 + ndf.Lambda(wo)) / ndf.D(h) - 1) < 1e-4)) {
      std::printf("element %d: pdf %g disagrees\n", i, pdf[i]);
      return 1;
    }
  }

  // Roughness 0 is outside the batch API's domain (alpha in (0, 1e4]):
  // refused in one line before anything is written.
  alpha[5] = 0;
  bool refused = false;
  try {
    EvalBatch(ggx, materials, Quantity::kBrdf, {ix.data(), iy.data(), iz.data()},
              {ox.data(), oy.data(), oz.data()}, f.data(), kN);
  } catch (const std::invalid_argument& e) {
    std::printf("refused: %s\n", e.what());
    refused = true;
  }
  std::printf("target %s: %d mixed materials, brdf within %.2g, light weights within %.2g\n",
              BatchTarget().c_str(), kN, worst_f, worst_weight);
  return worst_f < 1e-5 && worst_weight < 1e-4 && refused ? 0 : 1;
}
