// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The energy albedo of the rough dielectric over GGX ([Walter07],
// models/dielectric.h), reflection and refraction, for the baker:
//   E(mu) = integral over the sphere of f*(wi, wo) |wi.n| dwi
// with wo above the surface at cos(theta_o) = mu and f* the importance
// transport (the adjoint of [Walter07] eq. 21). A smooth interface gives
// exactly 1; 1 - E is what single scattering loses.
//
// The integral is taken over the visible normals h of wo ([Heitz18] eq. 3),
// where the half-vector Jacobians of [Walter07] eq. 14 and 17 cancel the
// BSDF's denominators:
//   E = integral D_wo(h) [F(wo.h) G2(wo, r) / G1(wo) 1{r.z > 0}
//                         + (1 - F) G2(wo, t) / G1(wo) 1{t.z < 0}] dh,
// r the reflection of wo about h, t its refraction (F = 1 beyond the
// critical angle, eta < 1). In the stretched configuration of [Heitz18]
// (section 3.2: h = normalize(alpha n.x, alpha n.y, n.z), n on the unit
// hemisphere) the visible normals are uniform over the area the lune
// {n.z > 0, n.v > 0} projects onto the plane normal to v = normalize(alpha
// wo.x, alpha wo.y, wo.z): D_wo(h) dh = (n.v) dn / A, A = pi (1 + v.z) / 2.
// In polar angles (theta, phi) of n about v the measure is cos(theta)
// sin(theta) dtheta dphi / A with theta from 0 to the lune's edge
// theta_max(phi) (where n.z = 0), smooth in both angles; the features in h
// scale with alpha there as D does.
//
// The integrand changes form on three curves, each the zero set of a
// quadratic form in m = (alpha n.x, alpha n.y, n.z), so that along a ray
// phi it is a quadratic in (cos(theta), sin(theta)) solved in closed form:
//  - the reflection's horizon r.z = 0: 2 (wo.m) m.z = mu |m|^2;
//  - the refraction's horizon t.z = 0 (eta < 1; from Snell's law,
//    squared): mu^2 |m|^2 - 2 mu (wo.m) m.z = (eta^2 - 1) m.z^2 (the
//    squaring adds roots where the refraction does not cross; a cut there
//    costs a piece, never accuracy);
//  - the critical angle (eta < 1): (wo.m)^2 = (1 - eta^2) |m|^2, where F
//    reaches 1 as the square root of the distance.
// Each ray is cut at these roots; pieces ending on the critical curve are
// mapped by theta = a + (b - a) t^2 (3 - 2 t), smooth in t. Over phi
// (taken on [-pi/2, pi/2] and doubled: the integrand is even about the
// plane of wo) the ray integral is cut at phi = 0 (the lune's edge has a
// kink there) and wherever the sequence of roots along the ray changes (a
// root appears, leaves through the lune's edge, or two curves cross),
// located by a scan of 128 rays per half and bisection; those segments
// are mapped the same way at both ends. Gauss-Kronrod 15 everywhere, the
// worst pieces bisected; the error is the outer |K15 - G7| plus the rays'
// own sums carried through the Kronrod weights.

#ifndef BRDFBAKE_SRC_RULES_GLASS_GLASS_ALBEDO_H_
#define BRDFBAKE_SRC_RULES_GLASS_GLASS_ALBEDO_H_

#include <algorithm>

#include "brdfbake/models/brdf.h"
#include "brdfbake/models/dielectric.h"
#include "brdfbake/models/ggx.h"
#include "quadrature/kronrod.h"

namespace brdfbake {

// E(mu) of the rough dielectric `bsdf` (its alpha, eta and masking; the
// transport is always the importance one, the energy albedo) to the
// absolute tolerance `tol`, at most `max_pieces` pieces over phi; mu is
// taken at least 1e-7. At eta = 1 (no interface) the value is the limit
// eta -> 1: the refraction straight through, weighted by G2 / G1(wo).
// `part` keeps the reflection or the refraction term of the bracket alone
// (the rule, its cuts and pieces are the same; each part is as accurate as
// the sum). kTransmissionSchlick's weight is smooth in wo.h and has no
// critical angle (eta >= 1): the same cuts serve it. `eta`, when given,
// replaces the bsdf's clamped index in the rule (kTransmissionSchlick
// only, eta >= 1 up to inf).
RuleResult GlassAlbedo(const RoughDielectric<double, GgxNdf<double>>& bsdf, double mu, double tol, int max_pieces,
                       DielectricPart part = DielectricPart::kBoth, double eta = 0);

// The albedo of the smooth interface (alpha = 0): exactly 1, with no
// error; its reflection F(eta, mu) and its refraction 1 - F.
inline RuleResult SmoothGlassAlbedo(double eta = 1, double mu = 1, DielectricPart part = DielectricPart::kBoth) {
  RuleResult out;
  out.pieces = 1;
  if (part == DielectricPart::kTransmissionSchlick) {
    // h = n: 1 - (1 - mu)^5, whatever eta >= 1.
    const double m = 1 - std::clamp(mu, 0.0, 1.0);
    out.value = 1 - m * m * m * m * m;
    return out;
  }
  const double f = part == DielectricPart::kBoth ? 0 : FresnelDielectric(eta, std::clamp(mu, 0.0, 1.0));
  out.value = part == DielectricPart::kBoth ? 1 : part == DielectricPart::kReflection ? f : 1 - f;
  out.pieces = 1;
  return out;
}

// The same from the parameters; alpha = 0 is the smooth interface
// (SmoothGlassAlbedo; the rough model's smallest alpha is 1e-4).
RuleResult GlassAlbedo(double alpha, double eta, Masking masking, double mu, double tol, int max_pieces,
                       DielectricPart part = DielectricPart::kBoth);

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_RULES_GLASS_GLASS_ALBEDO_H_
