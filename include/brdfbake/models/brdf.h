// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The microfacet BRDF over any distribution (docs/format.md):
//   f(wi, wo) = F(wo.h) D(h) G2(wi, wo, h) / (4 |wi.n| |wo.n|),
//   h = normalize(wi + wo).
// A distribution provides D(m), Lambda(w) and G1(w).

#ifndef BRDFBAKE_MODELS_BRDF_H_
#define BRDFBAKE_MODELS_BRDF_H_

#include <cmath>
#include <string>

#include "brdfbake/models/fresnel.h"
#include "brdfbake/models/vec3.h"

namespace brdfbake {

enum class Masking { kHeightCorrelated, kSeparable };

inline const char* MaskingName(Masking m) {
  return m == Masking::kHeightCorrelated ? "height-correlated" : "separable";
}

// G2(wi, wo, m): height-correlated 1 / (1 + Lambda(wi) + Lambda(wo)) or
// separable G1(wi) G1(wo); zero when wi.m or wo.m is not positive.
template <typename T, class Ndf>
T G2(const Ndf& ndf, const Vec3<T>& wi, const Vec3<T>& wo, const Vec3<T>& m,
     Masking masking) {
  if (!(Dot(wi, m) > T(0)) || !(Dot(wo, m) > T(0))) return T(0);
  if (!(wi.z > T(0)) || !(wo.z > T(0))) return T(0);
  if (masking == Masking::kSeparable) return ndf.G1(wi) * ndf.G1(wo);
  return T(1) / (T(1) + ndf.Lambda(wi) + ndf.Lambda(wo));
}

// The half vector of a reflection pair; false when wi = -wo.
template <typename T>
bool HalfVector(const Vec3<T>& wi, const Vec3<T>& wo, Vec3<T>* h) {
  const Vec3<T> s = wi + wo;
  const T len2 = Dot(s, s);
  if (!(len2 > T(0))) return false;
  *h = s / std::sqrt(len2);
  return true;
}

// The BRDF for one colour channel; zero unless both directions are above
// the horizon.
template <typename T, class Ndf>
T Brdf(const Ndf& ndf, const Fresnel& fresnel, const Vec3<T>& wi,
       const Vec3<T>& wo, Masking masking, int channel = 0) {
  if (!(wi.z > T(0)) || !(wo.z > T(0))) return T(0);
  Vec3<T> h;
  if (!HalfVector(wi, wo, &h)) return T(0);
  const T g2 = G2(ndf, wi, wo, h, masking);
  if (!(g2 > T(0))) return T(0);
  const T f = fresnel.Eval(Dot(wo, h), channel);
  return f * ndf.D(h) * g2 / (T(4) * wi.z * wo.z);
}

}  // namespace brdfbake

#endif  // BRDFBAKE_MODELS_BRDF_H_
