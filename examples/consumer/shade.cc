// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The evaluator embedded in a renderer: a batch of GGX BRDF values and
// visible-normal samples through brdfbake::core, checked against the scalar
// reference in double. Exits non-zero on any disagreement.

#include <cmath>
#include <cstdio>
#include <vector>

#include "brdfbake/batch.h"
#include "brdfbake/models/ggx.h"
#include "brdfbake/targets.h"

int main() {
  using namespace brdfbake;
  constexpr int kN = 37;  // not a whole number of vectors
  std::vector<float> ix(kN), iy(kN), iz(kN), ox(kN), oy(kN), oz(kN), f(kN);
  for (int i = 0; i < kN; ++i) {
    const double ti = 1.4 * i / kN, to = 0.3 + 0.02 * i, phi = 0.1 * i;
    ix[i] = float(std::sin(ti) * std::cos(phi));
    iy[i] = float(std::sin(ti) * std::sin(phi));
    iz[i] = float(std::cos(ti));
    ox[i] = float(std::sin(to));
    oy[i] = 0;
    oz[i] = float(std::cos(to));
  }
  BatchModel model;  // GGX, height-correlated, F = 1
  model.alpha_x = model.alpha_y = 0.3f;
  EvalBatch(model, Quantity::kBrdf, {ix.data(), iy.data(), iz.data()},
            {ox.data(), oy.data(), oz.data()}, f.data(), kN);

  const GgxNdf<double> ndf(0.3);
  double worst = 0;
  for (int i = 0; i < kN; ++i) {
    const Vec3<double> wi(ix[i], iy[i], iz[i]), wo(ox[i], oy[i], oz[i]);
    const Vec3<double> h = Normalize(wi + wo);
    const double g2 = 1 / (1 + ndf.Lambda(wi) + ndf.Lambda(wo));
    const double ref = ndf.D(h) * g2 / (4 * wi.z * wo.z);
    worst = std::fmax(worst, std::abs(f[i] - ref) / std::fmax(ref, 1e-30));
  }

  std::vector<float> u1(kN), u2(kN), mx(kN), my(kN), mz(kN);
  for (int i = 0; i < kN; ++i) {
    u1[i] = (i + 0.5f) / kN;
    u2[i] = std::fmod(0.618034f * i, 1.0f);
  }
  SampleBatch(model, Sampler::kVisible, {ox.data(), oy.data(), oz.data()}, u1.data(), u2.data(),
              {mx.data(), my.data(), mz.data()}, kN);
  int bad_samples = 0;
  for (int i = 0; i < kN; ++i) {
    const double len = std::sqrt(double(mx[i]) * mx[i] + double(my[i]) * my[i] + double(mz[i]) * mz[i]);
    const double wo_m = ox[i] * mx[i] + oy[i] * my[i] + oz[i] * mz[i];
    if (!(std::abs(len - 1) < 1e-5) || !(mz[i] > 0) || !(wo_m > 0)) ++bad_samples;
  }
  std::printf("target %s: brdf max rel error %.3g over %d values, %d bad samples\n",
              BatchTarget().c_str(), worst, kN, bad_samples);
  return worst < 1e-5 && bad_samples == 0 ? 0 : 1;
}
