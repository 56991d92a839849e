// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The directional albedo E(wo) of the anisotropic GGX BRDF (F = 1), for wo
// at any azimuth, by a rule over the slope plane (the double reference the
// ggx-aniso tables are baked with).
//
// With the slope m = (p, q) of the half vector, h = (-p, -q, 1) / N,
// N^2 = 1 + p^2 + q^2, and P22 the slope density (D(h) dh = P22 dp dq / h.z),
//   E = int f cos(theta_i) dwi = int P22(p, q) G2(wi, wo) (wo.h) / (wo.z h.z) dp dq
// with (wo.h) / h.z = wo.z - p wo.x - q wo.y. The condition wi.z > 0 is
//   2 (wo.h) h.z > wo.z  <=>  |m - c|^2 < 1 / wo.z^2,  c = -(wo.x, wo.y) / wo.z,
// a disk that contains m = 0 (and on which wo.h > 0), and 1 / wo.z^2 - |c|^2 = 1.
// In the stretched polar coordinates m = rho (alpha_x cos psi, alpha_y sin psi)
// the GGX slope density is uniform: P22 dp dq = du dpsi / (2 pi) with
// u = rho^2 / (1 + rho^2). So
//   E = 1 / (2 pi) int_0^{2 pi} dpsi int_0^{u_b(psi)} G2 (1 + rho c.e) du,
// e = (alpha_x cos psi, alpha_y sin psi), where the ray leaves the disk at
//   rho_b = 1 / (S - c.e) = (S + c.e) / |e|^2,  S = sqrt((c.e)^2 + |e|^2).
// The integrand is smooth inside; G2 falls to 0 at the disk's edge over a
// layer where wi.z is about |alpha o wi_xy|. wi.z is taken without
// cancellation from the factored form
//   wi.z = wo.z |e|^2 (rho_b - rho) (rho + 1 / (S + c.e)) / N^2.
//
// Rule: over psi, Gauss-Kronrod 15 on pieces (first cut where c.e = 0, the
// rays along which the edge comes nearest at grazing, and where G2's rise
// at the rays' horizon end is narrowest), the worst bisected until the
// summed error estimate meets the tolerance; along each ray,
// Gauss-Kronrod 15 on pieces in w = u_b - u graded geometrically (ratio 4)
// from u_b down to the edge layer, whose width is estimated from wi.z's
// slope at the edge, then the ray's worst piece bisected until the ray
// meets a fifth of the tolerance; the last piece next to the edge is left
// out where its contribution is bounded below 1/20 of the tolerance, and
// its bound added to the error. The psi rule is SegmentRule
// (adaptive_rule.h).

#ifndef BRDFBAKE_SRC_RULES_GGX_ANISO_ANISO_GGX_H_
#define BRDFBAKE_SRC_RULES_GGX_ANISO_ANISO_GGX_H_

#include "brdfbake/models/brdf.h"
#include "rules/ggx/azimuthal.h"

namespace brdfbake {

// E of GGX with widths (alpha_x, alpha_y) (each clamped to [1e-4, 1e4]),
// for wo at cos(theta_o) = mu (at least 1e-7) and azimuth phi (radians,
// from the x axis), within `tol` (the sum of the rules' |K15 - G7| and of
// the bounds of what was left out), with at most `max_pieces` pieces of
// the psi rule.
RuleResult AnisoGgxAlbedo(double alpha_x, double alpha_y, double mu, double phi,
                               Masking masking, double tol, int max_pieces);

// The glTF KHR_materials_anisotropy widths from roughness r and strength s:
// alpha_t = mix(r^2, 1, s^2) along the tangent (x), alpha_b = r^2 (y).
inline double AnisotropyAlphaT(double r, double s) {
  const double a = AlphaFromRoughness(r);
  return a + (1 - a) * s * s;
}

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_RULES_GGX_ANISO_ANISO_GGX_H_
