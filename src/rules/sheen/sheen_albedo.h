// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The directional albedo of the Charlie sheen ([EstevezKulla17],
// models/sheen.h) and of the Disney diffuse BRDF ([Burley12],
// models/disney_diffuse.h), F = 1, for the baker.
//
// Charlie: both visibility terms depend on the cosines alone and D on
// theta_h alone, so E is integrated over the half vector,
//   E(mu) = integral D(theta_h) sin(theta_h) J(theta_h) dtheta_h,
//   J = 2 integral_0^phi_max V NoL 4 (wo.h) dphi_h,
// the light's azimuth phi_h on the arc where NoL > 0, found in closed
// form: Gauss-Kronrod 15 over theta_h in s, theta_h = theta_max (1 -
// s^2), on pieces graded towards the peak and cut where J changes form;
// each node's J by Gauss-Kronrod 15 in phi_h, its end part in a variable
// in which the visibility's change near NoL ~ mu is smooth
// (sheen_albedo_rule.h, docs/integrators.md); the worst pieces bisected,
// the inner errors carried through the Kronrod weights.
//
// Disney diffuse: E(mu) = 2 integral_0^1 x M(x, mu) dx with M the azimuthal
// mean of pi f (DisneyDiffuse<T>::AzimuthMean), a polynomial of degree 8 in
// x: the 8-point Gauss-Legendre rule is exact, and so is E_avg =
// 2 integral_0^1 E(mu) mu dmu (degree 8 in mu) as an 8 x 8 rule; the error
// is the difference from the 6-point rule (also exact: rounding only) plus
// the rounding of the sums.

#ifndef BRDFBAKE_SRC_RULES_SHEEN_SHEEN_ALBEDO_H_
#define BRDFBAKE_SRC_RULES_SHEEN_SHEEN_ALBEDO_H_

#include "brdfbake/models/disney_diffuse.h"
#include "brdfbake/models/sheen.h"
#include "quadrature/kronrod.h"

namespace brdfbake {

// E(mu) of the Charlie sheen to the absolute tolerance `tol`, at most
// `max_pieces` x pieces; mu is taken at least 1e-7.
RuleResult CharlieAlbedo(const CharlieSheen<double>& sheen, double mu, double tol, int max_pieces);

// E(mu) and E_avg of the Disney diffuse BRDF at roughness r.
RuleResult DisneyAlbedo(double r, double mu);
RuleResult DisneyEavg(double r);

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_RULES_SHEEN_SHEEN_ALBEDO_H_
