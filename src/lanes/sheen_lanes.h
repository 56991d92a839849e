// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The charlie and disney families' rules (sheen_albedo.h) in double SIMD
// lanes.

#ifndef BRDFBAKE_SRC_LANES_SHEEN_LANES_H_
#define BRDFBAKE_SRC_LANES_SHEEN_LANES_H_

#include "brdfbake/models/sheen.h"
#include "rules/sheen/sheen_albedo.h"

namespace brdfbake {

// CharlieAlbedo, DisneyAlbedo and DisneyEavg (sheen_albedo.h) with their
// nodes in lanes.
RuleResult SimdCharlieAlbedo(double alpha, SheenVisibility visibility, double mu, double tol,
                             int max_pieces);
RuleResult SimdDisneyAlbedo(double r, double mu);
RuleResult SimdDisneyEavg(double r);

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_LANES_SHEEN_LANES_H_
