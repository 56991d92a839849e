// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// ggx-aniso's slope-plane rule (aniso_ggx.h) in double SIMD lanes.

#ifndef BRDFBAKE_SRC_LANES_ANISO_LANES_H_
#define BRDFBAKE_SRC_LANES_ANISO_LANES_H_

#include "brdfbake/models/brdf.h"
#include "rules/ggx_aniso/aniso_ggx.h"

namespace brdfbake {

// AnisoGgxAlbedo (aniso_ggx.h) with each ray piece's nodes in lanes.
RuleResult SimdAnisoGgxAlbedo(double alpha_x, double alpha_y, double mu, double phi,
                                   Masking masking, double tol, int max_pieces);

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_LANES_ANISO_LANES_H_
