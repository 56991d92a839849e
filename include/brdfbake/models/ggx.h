// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// GGX / Trowbridge-Reitz distribution, isotropic and anisotropic.

#ifndef BRDFBAKE_MODELS_GGX_H_
#define BRDFBAKE_MODELS_GGX_H_

#include <cmath>

#include "brdfbake/models/slope_ndf.h"
#include "brdfbake/models/vec3.h"

namespace brdfbake {

// GGX Lambda from 1/a^2 = alpha^2 tan^2(theta) (the stretched frame's):
// (sqrt(1 + 1/a^2) - 1) / 2, written as (1/a^2) / (2 (1 + sqrt(1 + 1/a^2)))
// to avoid cancellation when a >> 1. (azimuthal.h uses the form in mu and
// sin(theta), which has no division on the horizon.)
template <typename T>
T GgxLambdaOfInvA2(T inv_a2) {
  return inv_a2 / (T(2) * (T(1) + std::sqrt(T(1) + inv_a2)));
}

template <typename T>
class GgxNdf : public SlopeNdf<T, GgxNdf<T>> {
  using Base = SlopeNdf<T, GgxNdf<T>>;

 public:
  explicit GgxNdf(T alpha) : Base(alpha, alpha) {}
  GgxNdf(T alpha_x, T alpha_y) : Base(alpha_x, alpha_y) {}

  // Standard slopes: P22 = 1 / (pi (1 + r^2)^2) ([Ribardiere17] eq. 3, C = 2, B = 1).
  T UnitP22(T r2) const {
    const T q = T(1) + r2;
    return kInvPi<T> / (q * q);
  }
  // Lambda = (sqrt(1 + 1/a^2) - 1) / 2 ([Ribardiere17] Table 1, gamma = 2).
  T UnitLambda(T a) const { return GgxLambdaOfInvA2(T(1) / (a * a)); }
  // D = 1 / (pi ax ay z2^2 (1 + s2/z2)^2) = 1 / (pi ax ay (z2 + s2)^2): no
  // division by z2, no overflow of (1 + r^2)^2 at grazing normals.
  T DFromStretched(T s2, T z2) const {
    const T q = z2 + s2;
    return kInvPi<T> / (this->ax_ * this->ay_ * q * q);
  }
  // Radial CDF 1 - 1/(1 + r^2)  =>  r^2 = u / (1 - u).
  T UnitSampleR2(T u) const { return u / std::max(T(1) - u, std::numeric_limits<T>::min()); }

  // Exact visible-normal sampling, [Heitz18] Listing 1; density DVisible(w, m).
  Vec3<T> SampleVisible(const Vec3<T>& w, T u1, T u2) const {
    const T ax = this->ax_, ay = this->ay_;
    // Section 3.2: to the hemisphere (unit roughness) configuration.
    const Vec3<T> vh = Normalize(Vec3<T>(ax * w.x, ay * w.y, w.z));
    // Section 4.1: orthonormal basis, special case when vh is the pole.
    const T lensq = vh.x * vh.x + vh.y * vh.y;
    const Vec3<T> t1 = lensq > T(0)
                           ? Vec3<T>(-vh.y, vh.x, T(0)) / std::sqrt(lensq)
                           : Vec3<T>(T(1), T(0), T(0));
    const Vec3<T> t2 = Cross(vh, t1);
    // Section 4.2: uniform point on the projected area (disk squeezed and
    // sheared onto the projected half-sphere).
    const T r = std::sqrt(u1);
    const T phi = T(2) * kPi<T> * u2;
    const T p1 = r * std::cos(phi);
    T p2 = r * std::sin(phi);
    const T s = T(0.5) * (T(1) + vh.z);
    p2 = (T(1) - s) * std::sqrt(std::max(T(0), T(1) - p1 * p1)) + s * p2;
    // Section 4.3: reprojection onto the hemisphere, back to the ellipsoid.
    const Vec3<T> nh =
        t1 * p1 + t2 * p2 + vh * std::sqrt(std::max(T(0), T(1) - p1 * p1 - p2 * p2));
    return Normalize(Vec3<T>(ax * nh.x, ay * nh.y, std::max(T(0), nh.z)));
  }
  T PdfVisible(const Vec3<T>& w, const Vec3<T>& m) const { return this->DVisible(w, m); }
};

}  // namespace brdfbake

#endif  // BRDFBAKE_MODELS_GGX_H_
