// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// What an integrator returns for one texel of the E / dfg tables.

#ifndef BRDFBAKE_ESTIMATE_H_
#define BRDFBAKE_ESTIMATE_H_

namespace brdfbake {

// E, dfg.scale and dfg.bias at one (roughness, mu), and the integrator's own
// error estimate of each.
struct TexelEstimate {
  double e = 0, scale = 0, bias = 0;
  double err_e = 0, err_scale = 0, err_bias = 0;
};

}  // namespace brdfbake

#endif  // BRDFBAKE_ESTIMATE_H_
