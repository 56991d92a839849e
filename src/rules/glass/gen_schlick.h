// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The interpolation factor of the generalized Schlick Fresnel over a GGX
// reflection lobe, as Cycles tabulates it ([Cycles], cycles_precompute's
// gen_schlick terms and bsdf_microfacet.h's microfacet_fresnel):
//   F(wo.h) = mix(F0, F90, s_h(wo.h)),
//   s(mu) = integral D_wo(h) clamp(s_h(wo.h), 0, 1) 1{r.z > 0} dh,
// the mean of s_h over the visible normals h of wo ([Heitz18] eq. 3), r
// the reflection of wo about h, reflections below the surface counting 0.
// The renderer then takes the lobe's albedo as mix(F0, F90, s) E. The
// masking weight G2 / G1 of each visible normal is not in s: the
// generator averages the ratio of two colour channels (F0, F90) = (0, 1)
// and (1, 1) sample by sample, in which it cancels. s_h is either
//  - (1 - c)^exponent (exponent >= 0; Schlick's weight at 5), or
//  - (F(eta, c) - F0) / (1 - F0), F the exact dielectric Fresnel and F0
//    = ((eta - 1) / (eta + 1))^2 (the "dielectric Fresnel" mode, eta >
//    1; for large eta F dips below F0 near Brewster's angle, where the
//    clamp holds s_h at 0).
// The integral runs over the same lune of visible normals and ray
// segments as the glass albedo (glass_albedo.h), cut at the reflection's
// horizon.

#ifndef BRDFBAKE_SRC_RULES_GLASS_GEN_SCHLICK_H_
#define BRDFBAKE_SRC_RULES_GLASS_GEN_SCHLICK_H_

#include "brdfbake/models/brdf.h"
#include "quadrature/kronrod.h"

namespace brdfbake {

// The shape of s_h: exponent >= 0 is (1 - c)^exponent; exponent < 0 is the
// dielectric mode at `eta` (> 1).
struct GenSchlickShape {
  double exponent = 5;
  double eta = 1.5;
};

// s_h at c = wo.h in [0, 1], clamped to [0, 1].
double GenSchlickWeight(const GenSchlickShape& shape, double c);

// s(mu) of GGX at width alpha (> 0) to the absolute tolerance `tol`, at
// most `max_pieces` pieces over the rays' angle; mu is taken at least
// 1e-7.
RuleResult GenSchlickFactor(double alpha, const GenSchlickShape& shape, double mu, double tol,
                            int max_pieces);

// The F82-tint term of a GGX reflection lobe with F = 1: the energy its
// facets reflect weighted by b(wo.h) = wo.h (1 - wo.h)^6, the shape of the
// F82 correction of [Hoffman19] (Schlick's Fresnel at the metal's
// measured reflectance at 82 degrees), as Blender EEVEE's brdf_ggx stores
// it in its third channel ([Blender], eevee_lut_comp.glsl's metal_bias):
//   b(mu) = integral of (f / F)(wi, wo) b(wo.h) cos(theta_i) dwi
//         = integral D_wo(h) b(wo.h) G2(wo, r) / G1(wo) 1{r.z > 0} dh,
// f the GGX BRDF of width `alpha` (> 0) with `masking`, over the same
// rays as s above (their pieces graded to the reflection's horizon, where
// G2 falls to 0). To the absolute tolerance `tol`, at most `max_pieces`
// pieces over the rays' angle; mu is taken at least 1e-7.
RuleResult F82TintBias(double alpha, Masking masking, double mu, double tol, int max_pieces);

// b(wo.h) = c (1 - c)^6 at c = wo.h clamped to [0, 1]; the mirror's b(mu).
double F82TintWeight(double c);

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_RULES_GLASS_GEN_SCHLICK_H_
