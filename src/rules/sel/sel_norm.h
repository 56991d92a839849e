// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The integral over the sphere of the squared ellipsoidal lobe K ([TokuyoshiHarada],
// sel.h), N(alpha_x, alpha_y) = int_{S^2} K dw: the normalization an engine
// needs to use K / N as a lobe. It does not depend on the lobe's rotation Q.
//
// With a = max(alpha_x, alpha_y), k = (a / alpha_x, a / alpha_y, 1) and
// v' = normalize(k o v), K(v) = K_SSL(v') / U^2 (U = |k o v|, K_SSL the
// squared spheroidal lobe of width a), and dw = U^3 / (k_x k_y) dw'. So
//   N = 1 / (k_x k_y) int K_SSL(v') g(v') dw',  g = 1 / |v' / k|,
// and K_SSL dw' = 4 pi a^2 D_GGX(h) cos(theta_h) dh over the half vector h of
// v' and the axis (theta' = 2 theta_h). In GGX's slope coordinates that
// density is uniform in x = 1 - u, u = rho^2 / (1 + rho^2), rho = tan(theta_h) / a:
//   N = 4 pi alpha_x alpha_y G,  G = (2 / pi) int_0^{pi/2} dphi int_0^1 dx g,
// with t = a^2 (1 - x) / x = tan^2(theta_h), sin^2 theta' = 4 t / (1 + t)^2,
// cos theta' = (1 - t) / (1 + t) and
//   g = 1 / sqrt(sin^2 theta' (cos^2 phi / k_x^2 + sin^2 phi / k_y^2) + cos^2 theta').
// Closed forms: alpha_x = alpha_y (g = 1) gives N = 4 pi alpha^2 (the
// squared spheroidal lobe: pi alpha^2 times the GGX normalization 4); as
// both alphas go to 0 the lobe is narrow, g -> 1 and N -> 4 pi alpha_x alpha_y.
// G >= 1 otherwise, and it is what the table stores beside N.
//
// Rule: Gauss-Kronrod 15 in x on pieces graded by 4 towards x = 0 down to
// a^2 / 4 (where theta' passes pi / 2), each node's integral over phi by
// Gauss-Kronrod 15 on pieces graded by 4 towards the axis along which g
// peaks (width min(k) / max(k) on the equator), the worst pieces of both
// bisected until the summed |K15 - G7| meets the tolerance.

#ifndef BRDFBAKE_SRC_RULES_SEL_SEL_NORM_H_
#define BRDFBAKE_SRC_RULES_SEL_SEL_NORM_H_

#include "rules/ggx/azimuthal.h"

namespace brdfbake {

struct SelIntegral {
  double n = 0;      // int K dw
  double ratio = 0;  // G = N / (4 pi alpha_x alpha_y)
  double n_error = 0, ratio_error = 0;
};

// alpha_x, alpha_y clamped to [1e-4, 1] ([TokuyoshiHarada]'s range of lobe
// roughness); `tol` is the absolute tolerance on G.
SelIntegral SelLobeIntegral(double alpha_x, double alpha_y, double tol);

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_RULES_SEL_SEL_NORM_H_
