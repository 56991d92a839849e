// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The ggx family's rules (azimuthal.h) in double SIMD lanes: each theta_i
// piece's 15 nodes together (angles, Lambda, G2, the azimuth's closed form
// or moments), then node by node the nodes of the numerical azimuthal
// remainder; dispatched once per texel to the best Highway target (or the
// one ForceTarget chose). The same pieces and nodes as the scalar
// references GgxAzimuthalAlbedo and GgxAzimuthalDfg.

#ifndef BRDFBAKE_SRC_LANES_GGX_LANES_H_
#define BRDFBAKE_SRC_LANES_GGX_LANES_H_

#include "brdfbake/models/brdf.h"
#include "rules/ggx/azimuthal.h"

namespace brdfbake {

// GgxAzimuthalAlbedo with each theta_i piece's 15 nodes in lanes.
RuleResult SimdGgxAzimuthalAlbedo(double alpha, double mu, Masking masking, double tol,
                                       int max_pieces);

// GgxAzimuthalDfg with each theta_i piece's 15 nodes in lanes (angles, Phi,
// G2, the closed-form moments) and then, node by node, the azimuthal
// remainder's nodes in lanes.
AzimuthalDfgResult SimdGgxAzimuthalDfg(double alpha, double mu, Masking masking, double tol,
                                       int max_pieces);

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_LANES_GGX_LANES_H_
