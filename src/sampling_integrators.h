// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The sampling integrators of the texel integral (texel_integrand.h):
// randomized QMC, plain MC and the engine setting (Hammersley points and
// NDF sampling, as engines bake their tables).

#ifndef BRDFBAKE_SRC_SAMPLING_INTEGRATORS_H_
#define BRDFBAKE_SRC_SAMPLING_INTEGRATORS_H_

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <memory>
#include <type_traits>
#include <vector>

#include "brdfbake/bake.h"
#include "brdfbake/beckmann.h"
#include "brdfbake/brdf.h"
#include "brdfbake/ggx.h"
#include "brdfbake/std_ndf.h"
#include "quadrature.h"
#include "texel_integrand.h"

namespace brdfbake {

// Randomized QMC: `replicas` Cranley-Patterson rotations of an
// n-point Hammersley set; the estimate is their mean and the error 4 times
// the standard error of the mean.
template <class Ndf>
TexelEstimate QmcTexel(const Ndf& ndf, double mu, Masking masking, int samples, uint64_t seed,
                    bool plain_mc) {
  const Vec3<double> wo = FromMuPhi(std::max(mu, kMuMin), 0.0);
  const Integrand<Ndf> f(ndf, wo, masking);
  const int replicas = 8;
  const int n = std::max(1, samples / replicas);
  Rng rng(seed);
  double sum_e = 0, sum_e2 = 0, sum_b = 0, sum_b2 = 0, sum_s = 0, sum_s2 = 0;
  for (int r = 0; r < replicas; ++r) {
    const double shift1 = rng.Uniform(), shift2 = rng.Uniform();
    double acc = 0, acc_fc = 0;
    for (int i = 0; i < n; ++i) {
      double u1, u2;
      if (plain_mc) {
        u1 = rng.Uniform();
        u2 = rng.Uniform();
      } else {
        u1 = (i + 0.5) / n + shift1;
        u2 = RadicalInverse2(static_cast<uint32_t>(i)) + shift2;
        u1 -= std::floor(u1);
        u2 -= std::floor(u2);
      }
      double w, wfc;
      f.Eval(u1, u2, &w, &wfc);
      acc += w;
      acc_fc += wfc;
    }
    const double e = acc / n, b = acc_fc / n, s = e - b;
    sum_e += e; sum_e2 += e * e;
    sum_b += b; sum_b2 += b * b;
    sum_s += s; sum_s2 += s * s;
  }
  auto err = [&](double sum, double sum2) {
    const double mean = sum / replicas;
    const double var = std::max(0.0, (sum2 - replicas * mean * mean) / (replicas - 1));
    return 4.0 * std::sqrt(var / replicas);
  };
  TexelEstimate v;
  v.e = sum_e / replicas;
  v.bias = sum_b / replicas;
  v.scale = sum_s / replicas;
  v.err_e = err(sum_e, sum_e2);
  v.err_bias = err(sum_b, sum_b2);
  v.err_scale = err(sum_s, sum_s2);
  return v;
}

// The engine setting: an N-point Hammersley set (no randomization) driving
// NDF sampling of the half vector, pdf(wi) = D(h) h.z / (4 wo.h), so the
// weight is G2 (wo.h) / (wo.z h.z).
template <class Ndf>
QuadratureResult EngineRule(const Ndf& ndf, double mu, Masking masking, int samples) {
  const Vec3<double> wo = FromMuPhi(std::max(mu, kMuMin), 0.0);
  QuadratureResult r;
  for (int i = 0; i < samples; ++i) {
    const double u1 = static_cast<double>(i) / samples;
    const double u2 = RadicalInverse2(static_cast<uint32_t>(i));
    const Vec3<double> h = ndf.SampleNdf(u1, u2);
    const Vec3<double> wi = Reflect(wo, h);
    const double wo_h = Dot(wo, h);
    if (!(wi.z > 0) || !(wo_h > 0) || !(h.z > 0)) continue;
    const double w = G2(ndf, wi, wo, h, masking) * wo_h / (wo.z * h.z);
    r.e += w;
    r.fc += w * SchlickWeight(wo_h);
  }
  r.e /= samples;
  r.fc /= samples;
  return r;
}

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_SAMPLING_INTEGRATORS_H_
