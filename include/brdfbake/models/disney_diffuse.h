// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The Disney diffuse BRDF of [Burley12] (section 5.3), with base colour 1:
//   f(wi, wo) = (1 / pi) (1 + (F_D90 - 1) (1 - NoL)^5) (1 + (F_D90 - 1) (1 - NoV)^5),
//   F_D90 = 1/2 + 2 r (L.H)^2 = 1/2 + r (1 + L.V),
// r the perceptual roughness as the paper and the engines pass it (not
// alpha = r^2; 2 (L.H)^2 = 1 + L.V for the half vector H of L and V).
//
// Its directional albedo has a closed azimuth: with g = F_D90 - 1 =
// (r - 1/2) + r L.V, P = (1 - NoL)^5 and Q = (1 - NoV)^5, the product is
// 1 + g (P + Q) + g^2 P Q, and over the azimuth phi between wi and wo
// (L.V = NoL NoV + sin_l sin_v cos phi) the means are
//   <g>   = (r - 1/2) + r NoL NoV,
//   <g^2> = (r - 1/2)^2 + 2 (r - 1/2) r NoL NoV + r^2 (NoL^2 NoV^2 + sin_l^2 sin_v^2 / 2),
// so E(NoV) = 2 integral_0^1 NoL (1 + <g> (P + Q) + <g^2> P Q) dNoL, the
// integral of a polynomial of degree 8 in NoL (DisneyAzimuthMean below).

#ifndef BRDFBAKE_MODELS_DISNEY_DIFFUSE_H_
#define BRDFBAKE_MODELS_DISNEY_DIFFUSE_H_

#include <algorithm>
#include <cmath>

#include "brdfbake/models/constants.h"
#include "brdfbake/models/vec3.h"

namespace brdfbake {

template <typename T>
class DisneyDiffuse {
 public:
  // r in [0, 1] (the perceptual roughness).
  explicit DisneyDiffuse(T r) : r_(std::clamp(r, T(0), T(1))) {}

  T roughness() const { return r_; }

  // pi f at cosines nol, nov and L.V: the two Schlick-like factors.
  T PiF(T nol, T nov, T lov) const {
    const T g = (r_ - T(0.5)) + r_ * lov;
    return (T(1) + g * Pow5(T(1) - nol)) * (T(1) + g * Pow5(T(1) - nov));
  }

  T Brdf(const Vec3<T>& wi, const Vec3<T>& wo) const {
    if (!(wi.z > T(0)) || !(wo.z > T(0))) return T(0);
    return kInvPi<T> * PiF(std::min(wi.z, T(1)), std::min(wo.z, T(1)), Dot(wi, wo));
  }

  // The mean of pi f over the azimuth between wi and wo at cosines nol, nov
  // (the header comment).
  T AzimuthMean(T nol, T nov) const {
    const T c = r_ - T(0.5);
    const T x = nol * nov;
    const T s2 = (T(1) - nol) * (T(1) + nol) * (T(1) - nov) * (T(1) + nov);
    const T g1 = c + r_ * x;
    const T g2 = c * c + T(2) * c * r_ * x + r_ * r_ * (x * x + T(0.5) * s2);
    const T p = Pow5(T(1) - nol), q = Pow5(T(1) - nov);
    return T(1) + g1 * (p + q) + g2 * p * q;
  }

 private:
  static T Pow5(T x) {
    const T x2 = x * x;
    return x2 * x2 * x;
  }
  T r_;
};

}  // namespace brdfbake

#endif  // BRDFBAKE_MODELS_DISNEY_DIFFUSE_H_
