// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The beckmann and std families' rules (azimuthal_slope.h with the
// azimuth of beckmann_azimuth.h or std_azimuth.h) in double SIMD lanes:
// each theta_i piece's 15 nodes together, then node by node the nodes of
// the numerical azimuthal integrals; the same pieces and nodes as the
// scalar references BeckmannAzimuthalAlbedo, StdAzimuthalAlbedo and
// SlopeAzimuthalDfg.

#ifndef BRDFBAKE_SRC_LANES_SLOPE_LANES_H_
#define BRDFBAKE_SRC_LANES_SLOPE_LANES_H_

#include "brdfbake/config.h"
#include "brdfbake/models/beckmann.h"
#include "brdfbake/models/brdf.h"
#include "brdfbake/models/std_ndf.h"
#include "rules/beckmann/beckmann_azimuth.h"
#include "rules/ggx/azimuthal.h"
#include "rules/slope/azimuthal_slope.h"
#include "rules/std/std_azimuth.h"

namespace brdfbake {

// BeckmannAzimuthalAlbedo with each theta_i piece's 15 nodes in lanes
// (angles, Lambda, G2, the closed-form azimuthal moments).
RuleResult SimdBeckmannAzimuthalAlbedo(double alpha, double mu, Masking masking, double tol,
                                            int max_pieces);

#if BRDFBAKE_WITH_STD
// StdAzimuthalAlbedo (finite gamma) with each theta_i piece's 15 nodes in
// lanes (angles, Lambda, G2, the tabulated azimuthal moments).
RuleResult SimdStdAzimuthalAlbedo(const StudentTNdf<double>& ndf, double mu, Masking masking,
                                       double tol, int max_pieces);
#endif

// SlopeAzimuthalDfg with each theta_i piece's 15 nodes in lanes, then the
// azimuthal integrals' nodes in lanes.
#if BRDFBAKE_WITH_BECKMANN
AzimuthalDfgResult SimdSlopeAzimuthalDfg(const BeckmannNdf<double>& ndf, double mu,
                                         Masking masking, bool with_bias, double tol,
                                         int max_pieces);
#endif
#if BRDFBAKE_WITH_STD
AzimuthalDfgResult SimdSlopeAzimuthalDfg(const StudentTNdf<double>& ndf, double mu, Masking masking,
                                         bool with_bias, double tol, int max_pieces);
#endif

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_LANES_SLOPE_LANES_H_
