// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The sel lobe's integral (sel_norm.h) in double SIMD lanes.

#ifndef BRDFBAKE_SRC_LANES_SEL_LANES_H_
#define BRDFBAKE_SRC_LANES_SEL_LANES_H_

#include "rules/sel/sel_norm.h"

namespace brdfbake {

// SelLobeIntegral (sel_norm.h) with the inner rule's nodes in lanes.
SelIntegral SimdSelLobeIntegral(double alpha_x, double alpha_y, double tol);

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_LANES_SEL_LANES_H_
