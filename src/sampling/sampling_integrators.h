// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The sampling integrators of the texel integral (texel_integrand.h):
// randomized QMC, plain MC and the engine setting (Hammersley points and
// NDF sampling, as engines bake their tables).

#ifndef BRDFBAKE_SRC_SAMPLING_SAMPLING_INTEGRATORS_H_
#define BRDFBAKE_SRC_SAMPLING_SAMPLING_INTEGRATORS_H_

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <memory>
#include <type_traits>
#include <vector>

#include "brdfbake/estimate.h"
#include "brdfbake/models/beckmann.h"
#include "brdfbake/models/brdf.h"
#include "brdfbake/models/disney_diffuse.h"
#include "brdfbake/models/ggx.h"
#include "brdfbake/models/sheen.h"
#include "brdfbake/models/std_ndf.h"
#include "quadrature/gauss_legendre.h"
#include "sampling/texel_integrand.h"

namespace brdfbake {

// The sums over a point set that the integrators below take: sum(u1, u2,
// n, &acc, &acc_fc) adds up w and w Fc at the n points (u1[i], u2[i]).
// The scalar one evaluates `Integrand` (the model's visible-normal
// sampler) point by point in order; <family>_sampling_simd.h have the lanes twins.
template <class Ndf>
auto ScalarVisibleSum(const Ndf& ndf, const Vec3<double>& wo, Masking masking) {
  return [f = Integrand<Ndf>(ndf, wo, masking)](const double* u1, const double* u2, int n,
                                                double* acc, double* acc_fc) {
    double e = 0, fc = 0;
    for (int i = 0; i < n; ++i) {
      double w, wfc;
      f.Eval(u1[i], u2[i], &w, &wfc);
      e += w;
      fc += wfc;
    }
    *acc = e;
    *acc_fc = fc;
  };
}

// Points per call of a sum (QmcTexelWith, EngineRuleWith).
inline constexpr int kSamplingBlock = 2048;

// The view of the sampling integrators: azimuth 0, mu at least kMuMin.
inline Vec3<double> SamplingView(double mu) { return FromMuPhi(std::max(mu, kMuMin), 0.0); }

// Randomized QMC: `replicas` Cranley-Patterson rotations of an
// n-point Hammersley set; the estimate is their mean and the error 4 times
// the standard error of the mean. Plain MC draws the points from the
// texel's SplitMix64 stream instead (u1 then u2 per point). `sum` adds up
// one replica's points (ScalarVisibleSum).
template <class Sum>
TexelEstimate QmcTexelWith(int samples, uint64_t seed, bool plain_mc, const Sum& sum) {
  constexpr int replicas = 8;
  const int n = std::max(1, samples / replicas);
  Rng rng(seed);
  // The points go to `sum` in blocks of kSamplingBlock (memory bounded at
  // any sample count and thread count), in the order drawn.
  double u1[kSamplingBlock], u2[kSamplingBlock];
  double e[replicas], b[replicas], s[replicas];
  for (int r = 0; r < replicas; ++r) {
    const double shift1 = rng.Uniform(), shift2 = rng.Uniform();
    double acc = 0, acc_fc = 0;
    for (int i0 = 0; i0 < n; i0 += kSamplingBlock) {
      const int m = std::min(kSamplingBlock, n - i0);
      if (plain_mc) {
        for (int k = 0; k < m; ++k) {
          u1[k] = rng.Uniform();
          u2[k] = rng.Uniform();
        }
      } else {
        for (int k = 0; k < m; ++k) {
          const int i = i0 + k;
          const double a = (i + 0.5) / n + shift1;
          const double c = RadicalInverse2(static_cast<uint32_t>(i)) + shift2;
          // x - floor(x) for x in [0, 2): a subtraction of 1 at most.
          u1[k] = a >= 1 ? a - 1 : a;
          u2[k] = c >= 1 ? c - 1 : c;
        }
      }
      double block = 0, block_fc = 0;
      sum(u1, u2, m, &block, &block_fc);
      acc += block;
      acc_fc += block_fc;
    }
    e[r] = acc / n;
    b[r] = acc_fc / n;
    s[r] = e[r] - b[r];
  }
  // The mean, and 4 standard errors from the squared deviations from it
  // (two passes: sum x^2 - R mean^2 would cancel to rounding noise where
  // the replicas agree to 1e-8 of their value).
  auto mean = [&](const double* x) {
    double m = 0;
    for (int r = 0; r < replicas; ++r) m += x[r];
    return m / replicas;
  };
  auto err = [&](const double* x, double m) {
    double ss = 0;
    for (int r = 0; r < replicas; ++r) ss += (x[r] - m) * (x[r] - m);
    return 4.0 * std::sqrt(ss / (replicas - 1) / replicas);
  };
  TexelEstimate v;
  v.e = mean(e);
  v.bias = mean(b);
  v.scale = mean(s);
  v.err_e = err(e, v.e);
  v.err_bias = err(b, v.bias);
  v.err_scale = err(s, v.scale);
  return v;
}

template <class Ndf>
TexelEstimate QmcTexel(const Ndf& ndf, double mu, Masking masking, int samples, uint64_t seed,
                       bool plain_mc) {
  return QmcTexelWith(samples, seed, plain_mc, ScalarVisibleSum(ndf, SamplingView(mu), masking));
}

// The engine setting: an N-point Hammersley set (no randomization) driving
// NDF sampling of the half vector, pdf(wi) = D(h) h.z / (4 wo.h), so the
// weight is G2 (wo.h) / (wo.z h.z). `sum` as for QmcTexelWith, with
// u1 = i / N the azimuth's and u2 the radius's variable of SampleNdf.
template <class Sum>
QuadratureResult EngineRuleWith(int samples, const Sum& sum) {
  double u1[kSamplingBlock], u2[kSamplingBlock];
  QuadratureResult r;
  for (int i0 = 0; i0 < samples; i0 += kSamplingBlock) {
    const int m = std::min(kSamplingBlock, samples - i0);
    for (int k = 0; k < m; ++k) {
      u1[k] = static_cast<double>(i0 + k) / samples;
      u2[k] = RadicalInverse2(static_cast<uint32_t>(i0 + k));
    }
    double block = 0, block_fc = 0;
    sum(u1, u2, m, &block, &block_fc);
    r.e += block;
    r.fc += block_fc;
  }
  r.e /= samples;
  r.fc /= samples;
  return r;
}

template <class Ndf>
QuadratureResult EngineRule(const Ndf& ndf, double mu, Masking masking, int samples) {
  const Vec3<double> wo = SamplingView(mu);
  return EngineRuleWith(samples, [&](const double* u1, const double* u2, int n, double* acc,
                                     double* acc_fc) {
    double e = 0, fc = 0;
    for (int i = 0; i < n; ++i) {
      const Vec3<double> h = ndf.SampleNdf(u1[i], u2[i]);
      const Vec3<double> wi = Reflect(wo, h);
      const double wo_h = Dot(wo, h);
      if (!(wi.z > 0) || !(wo_h > 0) || !(h.z > 0)) continue;
      const double w = G2(ndf, wi, wo, h, masking) * wo_h / (wo.z * h.z);
      e += w;
      fc += w * SchlickWeight(wo_h);
    }
    *acc = e;
    *acc_fc = fc;
  });
}

// The sums of the lobes without a Fresnel factor (acc_fc = 0), for
// QmcTexelWith and EngineRuleWith. The Charlie sheen draws its half vector
// from its NDF (CharlieSheen::SampleNdf, pdf(wi) = D(h) h.z / (4 wo.h)):
// the weight f wi.z / pdf is 4 V wi.z (wo.h) / h.z. The Disney lobe draws
// the light by the cosine (pdf wi.z / pi): the weight is pi f.
inline auto CharlieSum(const CharlieSheen<double>& sheen, const Vec3<double>& wo) {
  return [sheen, wo](const double* u1, const double* u2, int n, double* acc, double* acc_fc) {
    double e = 0;
    for (int i = 0; i < n; ++i) {
      const Vec3<double> h = sheen.SampleNdf(u1[i], u2[i]);
      const Vec3<double> wi = Reflect(wo, h);
      const double wo_h = Dot(wo, h);
      if (!(wi.z > 0) || !(wo_h > 0) || !(h.z > 0)) continue;
      e += 4 * sheen.Visibility(std::min(wi.z, 1.0), std::min(wo.z, 1.0)) * wi.z * wo_h / h.z;
    }
    *acc = e;
    *acc_fc = 0;
  };
}

inline auto DisneySum(const DisneyDiffuse<double>& f, const Vec3<double>& wo) {
  return [f, wo](const double* u1, const double* u2, int n, double* acc, double* acc_fc) {
    double e = 0;
    for (int i = 0; i < n; ++i) {
      const double s = std::sqrt(u2[i]), phi = 2 * kPi<double> * u1[i];
      const Vec3<double> wi{s * std::cos(phi), s * std::sin(phi), std::sqrt(std::max(0.0, 1 - u2[i]))};
      if (!(wi.z > 0)) continue;
      e += kPi<double> * f.Brdf(wi, wo);
    }
    *acc = e;
    *acc_fc = 0;
  };
}

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_SAMPLING_SAMPLING_INTEGRATORS_H_
