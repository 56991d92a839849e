// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// E_avg = 2 integral_0^1 E(mu) mu dmu of the rough dielectric over GGX
// (glass_albedo.h) as one integral over the microfacet normal h and the
// view wo, instead of a rule over mu of the 2D rule for E.
//
// With E(wo) = integral D(h) (wo.h) / mu [F G2(wo, r) 1{r.z > 0} + (1 - F)
// G2(wo, t) 1{t.z < 0}] dh (glass_albedo.h: D_wo = G1(wo) (wo.h) D / mu,
// [Heitz18] eq. 3, times G2 / G1(wo)), the cosine mu cancels:
//   E_avg = 1/pi integral over wo above, h integral D(h) (wo.h)_+ [...] dh dwo.
// Taken in the other order, about each h: wo at the angle b from h, cos(b)
// = c = wo.h, and the azimuth psi about h measured from the plane of h
// and n, dwo = dc dpsi. The Fresnel factor depends on c alone, so the
// critical angle is the line c = sqrt(1 - eta^2). With h at theta_h from
// n and s = sin(b), the cosines to n of wo, of its reflection r = 2 c h -
// wo and of its refraction t are linear in cos(psi):
//   wo.n = c cos(theta_h) - s sin(theta_h) cos(psi),
//   r.n  = c cos(theta_h) + s sin(theta_h) cos(psi),
//   t.n  = s sin(theta_h) cos(psi) / eta - c_t cos(theta_h),
// c_t = sqrt(1 - s^2 / eta^2) ([Walter07] eq. 40 in h's frame). So each
// horizon bounds psi in closed form: the reflection keeps |cos(psi)| < A,
// A = c cos(theta_h) / (s sin(theta_h)) (an interval symmetric about pi/2,
// where swapping psi and pi - psi swaps wo and r and leaves G2 alone); the
// refraction keeps cos(psi) < min(A, B), B = eta c_t cos(theta_h) / (s
// sin(theta_h)) (B < A exactly when eta < 1). G2 depends on the two
// cosines only (isotropic Smith). With the azimuth of h giving 2 pi and
// u = tan^2 / (alpha^2 + tan^2) of theta_h (GGX's radial CDF, d u = 2 pi D
// cos sin dtheta_h):
//   E_avg = 1/pi integral_0^1 du / cos(theta_h) integral_0^1 c dc
//           [F(c) 4 integral_{psi_r}^{pi/2} G2(wo, r) dpsi
//            + (1 - F(c)) 2 integral_{psi_t}^{pi} G2(wo, t) dpsi],
// psi_r = acos(min(A, 1)), psi_t = acos(min(A, B, 1)). A smooth interface
// (theta_h = 0, G2 = 1) gives F_avg + (1 - F)_avg = 1.
//
// The outer variable is q with u = q^2 (2 - q^2): theta_h ~ alpha q near
// h = n, and 1 / cos(theta_h) du stays bounded at the horizon (where the
// refraction of a grazing facet keeps a share ~ alpha^2). The innermost
// is w = sqrt(1 - cos(psi)) up to psi = pi/2 and 2 - sqrt(1 + cos(psi))
// beyond: cos(psi) = +-(1 - y^2), y = w or 2 - w, dpsi = 2 dy / sqrt(2 -
// y^2), so a node needs no cosine and a horizon reaching psi = 0 leaves no
// square-root edge. Each level is Gauss-Kronrod 15 with the worst pieces
// bisected (GlassSegmentsRule), the inner levels' errors carried through
// the outer weights. Where the integrands change form:
//  - over c: at sin(theta_h) (A = 1: the reflection's and, for eta >= 1,
//    the refraction's psi interval reaches psi = 0), at the critical
//    cosine sqrt(1 - eta^2) (F reaches 1 as a square root) and at sqrt(1
//    - eta^2 cos^2(theta_h)) (B = 1), eta < 1: cut there, mapped t^2
//    towards each cut (the square-root edges become smooth in t);
//  - G2 of a direction at the cosine z to n turns on over z ~ alpha: over
//    w towards each interval's horizon end, and over c towards those cuts
//    and c = 0, the pieces are graded (ratio kGlassGrading) down to alpha
//    in z; w is also cut at 1 (psi = pi/2), where its map's second
//    derivative jumps;
//  - over q: at cos(theta_h) = eta (eta < 1), where sin(theta_h) meets the
//    critical cosine, and beyond q = 1/2 where tan(theta_h) passes 16, 4,
//    1, 1/4, ... down to 4 alpha (the facets tilted far beyond alpha lie
//    within ~alpha / tan(theta_h) of q = 1).

#ifndef BRDFBAKE_SRC_RULES_GLASS_GLASS_AVERAGE_H_
#define BRDFBAKE_SRC_RULES_GLASS_GLASS_AVERAGE_H_

#include "brdfbake/models/brdf.h"
#include "brdfbake/models/dielectric.h"
#include "quadrature/kronrod.h"

namespace brdfbake {

// E_avg of the rough dielectric at `alpha` (at least 1e-4; 0 is the
// smooth interface, exactly 1 or F_avg or 1 - F_avg), `eta` (clamped to
// [0.01, 100] as the BSDF clamps it; kTransmissionSchlick takes eta >= 1
// up to inf as is) and `masking`, to the absolute tolerance `tol`, with at
// most `max_pieces` pieces over q. `part` as for GlassAlbedo.
RuleResult GlassAlbedoAverage(double alpha, double eta, Masking masking, double tol, int max_pieces,
                              DielectricPart part = DielectricPart::kBoth);

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_RULES_GLASS_GLASS_AVERAGE_H_
