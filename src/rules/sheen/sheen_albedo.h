// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The directional albedo of the Charlie sheen ([EstevezKulla17],
// models/sheen.h) and of the Disney diffuse BRDF ([Burley12],
// models/disney_diffuse.h), F = 1, for the baker.
//
// Charlie: both visibility terms depend on the cosines alone, so with wi at
// cosine x and azimuth phi from wo,
//   E(mu) = integral_0^1 2 x V(x, mu) I(x) dx,   I(x) = integral_0^pi D(h) dphi,
//   cos^2(theta_h) = (x + mu)^2 / (2 (1 + wi.wo)),
//   1 + wi.wo = (x + mu)^2 / (1 + x mu + s_x s_mu) + s_x s_mu (1 + cos phi)
// (the second form has no cancellation where wi and wo both graze; s the
// sines). The rule: Gauss-Kronrod 15 in x on [0, mu] and [mu, 1] (I has a
// kink at x = mu, where h reaches the normal at phi = pi and D has its cusp
// sin^(1/alpha)), the part below mu graded by 4 towards x = 0 down to the
// width 1 / (q mu), q = 1 / (2 alpha), of the grazing peak of a narrow
// lobe; each node's I by Gauss-Kronrod 15 on [0, pi/2], [pi/2, pi], its
// worst piece bisected until the summed |K15 - G7| is a tenth of the texel
// tolerance over 2 x V; then the worst x piece bisected until the outer
// |K15 - G7| plus the inner errors carried through the Kronrod weights meet
// the tolerance.
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
