// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The directional albedo E(wo) of the rotated ellipsoid NDF ([Walter15],
// ellipsoid.h) with F = 1, for wo at any azimuth: the slope-plane rule of
// aniso_ggx.h generalized to a sheared and shifted slope density.
//
// With A = S R and B = A^-T (columns b1, b2, b3), D(m) = 1 / (pi |A| ||An||
// ||B m||^4) (seed eq. 1) becomes, for m = (-p, -q, 1) / N, the slope density
//   P22(s) = D m.z^4 = 1 / (pi |A| ||An|| Q(s)^2),  Q(s) = |b3 - p b1 - q b2|^2,
// a quadratic in s = (p, q): Q = Q_min + (s - s0)^T G (s - s0) with
// G = [b_i . b_j] (i, j = 1, 2), s0 = G^-1 (b1.b3, b2.b3) the slope of the
// distribution's peak (not 0 once the ellipsoid is tilted). With G = C^T C
// (Cholesky) and L = sqrt(Q_min) C^-1, s = s0 + L v makes P22 dp dq =
// dv / (pi (1 + |v|^2)^2): in polar coordinates v = rho (cos psi, sin psi)
// and u = rho^2 / (1 + rho^2) the density is uniform, du dpsi / (2 pi).
//
// As for GGX, E = int P22 G2 (1 + s.c) dp dq over the horizon disk
// |s - c| < 1 / wo.z, c = -wo_xy / wo.z. Along a ray s = s0 + rho e
// (e = L (cos psi, sin psi)) the disk is the interval (rho_-, rho_+) of the
// roots of |d + rho e|^2 = 1 / wo.z^2, d = s0 - c, with
// |d|^2 - 1 / wo.z^2 = |s0|^2 - 2 s0.c - 1 (no cancellation at grazing)
// and wi.z = wo.z |e|^2 (rho - rho_-) (rho_+ - rho) / N^2. When s0 lies
// outside the disk (a strongly tilted ellipsoid seen at grazing), rays
// cross it in a segment or miss it.
//
// G1 is [Walter15]'s (eq. 6, clamped at 1: Lambda = 0 where the clamp is
// active, ellipsoid.h); G2 height-correlated (brdfbake's extension) or
// separable ([Walter15] eq. 5). The clamp's edge is a closed curve in the
// slope plane where G2 has a kink.
//
// Rule (ellipsoid_albedo_rule.h): along each ray Gauss-Kronrod 15 in
// x = sqrt(u), each half of the ray that ends at a horizon crossing in
// tau = log1p(offset / c), c the width of G2's rise there (the map cancels
// G2's nearby pole, so one piece per 3 in tau replaces a geometric grading
// down to c), cut where the ray crosses the clamp's edge (the roots of a
// quartic in rho), the worst piece bisected until the ray meets a fifth of
// the tolerance. Over psi, Gauss-Kronrod 15 on
// segments: quarter turns from the rays where d.e = 0 when s0 is inside
// the disk, or the range between the two rays tangent to it when s0 is
// outside; each split again at the rays tangent to the clamp's edge. At a
// tangent ray the ray integral goes like |psi - tangent|^(3/2), and the
// segment is mapped (SegmentRule) so that it is smooth. Narrow smooth
// features (glancing rays, rays whose horizon end nears the clamp) get a
// cut and a grading towards them. The worst piece is
// bisected until the total meets the tolerance.

#ifndef BRDFBAKE_SRC_RULES_ELLIPSOID_ELLIPSOID_ALBEDO_H_
#define BRDFBAKE_SRC_RULES_ELLIPSOID_ELLIPSOID_ALBEDO_H_

#include "brdfbake/models/brdf.h"
#include "rules/ggx/azimuthal.h"

namespace brdfbake {

// E of the ellipsoid NDF with widths (alpha_x, alpha_y) (clamped to
// [1e-4, 1e4]) and rotation angles (radians, A = S Rx Ry Rz), for wo at
// cos(theta_o) = mu (at least 1e-7) and azimuth phi, within `tol`, with at
// most `max_pieces` pieces of the psi rule.
RuleResult EllipsoidAlbedo(double alpha_x, double alpha_y, double theta_x, double theta_y,
                                double theta_z, double mu, double phi, Masking masking,
                                double tol, int max_pieces);

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_RULES_ELLIPSOID_ELLIPSOID_ALBEDO_H_
