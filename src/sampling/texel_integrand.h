// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Per-texel integrators of the albedo E(mu) and the split-sum DFG terms of
// a microfacet BRDF with F = 1, generic over the distribution type.
//
// All integrators write the albedo as an integral over the unit square of
// the model's microfacet-normal sampler: with m = S(u1, u2) of density
// p(m) and wi = reflect(wo, m),
//   E = int f(wi, wo) cos(theta_i) dwi
//     = int_[0,1]^2 f cos_i 4 (wo.m) / p(m) du1 du2,
// whose integrand is G2 / G1(wo) in [0, 1] for exact visible-normal
// sampling ([Heitz18] eq. 19) and is zero where wi falls below the horizon.
// The DFG terms weight it with 1 - Fc and Fc, Fc = (1 - wo.m)^5.
// The QMC, MC and engine integrators use each model's own sampler; the
// deterministic quadrature uses the GGX visible-normal sampler with the
// model's alpha_x, alpha_y for GGX, Beckmann and STD alike (LineFamily),
// whose square is periodic in u2 and smooth in u1, with the weight
// f cos_i / pdf_ggx(wi) = D G2 (wo.m) / (wo.z PdfVisible_ggx(wo, m)).
//
// This file: the integrand over the unit square (each model's own
// visible-normal sampler and its weight), the two-value result of a rule,
// and the texel estimate from two rules. disk_quadrature.h holds the
// deterministic rule, sampling_integrators.h the QMC, MC and engine ones.

#ifndef BRDFBAKE_SRC_SAMPLING_TEXEL_INTEGRAND_H_
#define BRDFBAKE_SRC_SAMPLING_TEXEL_INTEGRAND_H_

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
#include "brdfbake/models/ggx.h"
#include "brdfbake/models/std_ndf.h"
#include "quadrature/gauss_legendre.h"

namespace brdfbake {

// Sampler and integrand weight per distribution type.
template <class Ndf>
struct VisibleSampler {
  static Vec3<double> Sample(const Ndf& ndf, const Vec3<double>& wo, double u1, double u2) {
    return ndf.SampleVisible(wo, u1, u2);
  }
  // f cos_i / pdf(wi) for F = 1; exact VNDF sampling makes it G2 / G1(wo).
  static double Weight(const Ndf& ndf, const Vec3<double>& wo, const Vec3<double>& m,
                       const Vec3<double>& wi, double g1_wo, Masking masking) {
    return G2(ndf, wi, wo, m, masking) / g1_wo;
  }
};

template <>
struct VisibleSampler<StudentTNdf<double>> {
  using Ndf = StudentTNdf<double>;
  static Vec3<double> Sample(const Ndf& ndf, const Vec3<double>& wo, double u1, double u2) {
    return ndf.SamplePseudoVnis(wo, u1, u2);
  }
  static double Weight(const Ndf& ndf, const Vec3<double>& wo, const Vec3<double>& m,
                       const Vec3<double>& wi, double, Masking masking) {
    const double pdf = ndf.PdfPseudoVnis(wo, m);
    if (!(pdf > 0)) return 0.0;
    const double g2 = G2(ndf, wi, wo, m, masking);
    // f cos_i / (pdf / (4 wo.m)) = D G2 (wo.m) / (wo.z pdf).
    return ndf.D(m) * g2 * Dot(wo, m) / (wo.z * pdf);
  }
};

// Accumulates (w, w Fc) for a sample of the unit square of the model's own
// visible-normal sampler (the sampling integrators).
template <class Ndf>
struct Integrand {
  const Ndf& ndf;
  Vec3<double> wo;
  Masking masking;
  double g1_wo;

  Integrand(const Ndf& n, const Vec3<double>& w, Masking mk)
      : ndf(n), wo(w), masking(mk), g1_wo(n.G1(w)) {}

  // Returns false when wi is below the horizon (zero contribution).
  bool Eval(double u1, double u2, double* w, double* w_fc) const {
    const Vec3<double> m = VisibleSampler<Ndf>::Sample(ndf, wo, u1, u2);
    const Vec3<double> wi = Reflect(wo, m);
    if (!(wi.z > 0)) {
      *w = *w_fc = 0;
      return false;
    }
    const double v = VisibleSampler<Ndf>::Weight(ndf, wo, m, wi, g1_wo, masking);
    const double fc = SchlickWeight(Dot(wo, m));
    *w = v;
    *w_fc = v * fc;
    return true;
  }
};


// E and the Fc-weighted part of one rule.
struct QuadratureResult {
  double e = 0, fc = 0;
};

inline TexelEstimate FromTwo(const QuadratureResult& fine, const QuadratureResult& coarse) {
  TexelEstimate v;
  v.e = fine.e;
  v.bias = fine.fc;
  v.scale = fine.e - fine.fc;
  v.err_e = std::abs(fine.e - coarse.e);
  v.err_bias = std::abs(fine.fc - coarse.fc);
  v.err_scale = std::abs((fine.e - fine.fc) - (coarse.e - coarse.fc));
  // Floor at a few ulps of the stored magnitude.
  v.err_e = std::max(v.err_e, 4e-16);
  v.err_bias = std::max(v.err_bias, 4e-16);
  v.err_scale = std::max(v.err_scale, 4e-16);
  return v;
}

// The grazing limit mu -> 0 is evaluated at mu = kMuMin (docs/format.md: mu = 0 is the
// grazing limit; E is continuous there).
inline constexpr double kMuMin = 1e-7;

// Mirror (alpha below the clamp): h = n, E = 1, Fc = (1 - mu)^5, with
// mu = 0 evaluated at kMuMin like every other texel.
inline TexelEstimate MirrorTexel(double mu) {
  TexelEstimate v;
  v.e = 1;
  v.bias = SchlickWeight(std::max(mu, kMuMin));
  v.scale = 1 - v.bias;
  return v;
}

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_SAMPLING_TEXEL_INTEGRAND_H_
