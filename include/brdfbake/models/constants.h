// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The constants and the one parameter mapping every model shares.

#ifndef BRDFBAKE_MODELS_CONSTANTS_H_
#define BRDFBAKE_MODELS_CONSTANTS_H_

namespace brdfbake {

template <typename T>
inline constexpr T kPi = T(3.141592653589793238462643383279502884L);
template <typename T>
inline constexpr T kTwoPi = T(6.283185307179586476925286766559005768L);
template <typename T>
inline constexpr T kInvPi = T(0.318309886183790671537767526745028724L);

// The NDF width from the perceptual roughness r: alpha = r^2 (the
// convention of every table's roughness axis).
template <typename T>
constexpr T AlphaFromRoughness(T r) {
  return r * r;
}

}  // namespace brdfbake

#endif  // BRDFBAKE_MODELS_CONSTANTS_H_
