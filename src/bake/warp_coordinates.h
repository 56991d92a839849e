// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The coordinates the ior and exponent axes' warps are linear in (bake.h):
// the baker's axis map, the probe's inverse and the shader lookups share
// them.

#ifndef BRDFBAKE_SRC_BAKE_WARP_COORDINATES_H_
#define BRDFBAKE_SRC_BAKE_WARP_COORDINATES_H_

#include <cmath>

namespace brdfbake {

// fresnel-z: z = sqrt(|ior - 1| / (ior + 1)) = F0^(1/4), 1 at ior = inf.
inline double FresnelZOfIor(double ior) {
  return std::isinf(ior) ? 1.0 : std::sqrt(std::abs(ior - 1) / (ior + 1));
}

// schlick-z: z = 5 / (exponent + 5), 0 at exponent = inf.
inline double SchlickZOfExponent(double exponent) { return std::isinf(exponent) ? 0.0 : 5 / (exponent + 5); }

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_BAKE_WARP_COORDINATES_H_
