// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Shape-invariant microfacet distributions defined by a distribution of
// slopes (GGX, Beckmann, STD). Each is fully described by its unit-roughness
// ("standard", alpha = 1) isotropic slope density P22(r^2) and Smith Lambda
// at a = cot(theta); anisotropy is a stretch of the slope space by
// (alpha_x, alpha_y) (Heitz 2014, the "shape invariance" cited in [Ribardiere17]
// section 1.1 and eq. 10):
//
//   D(m)      = P22((m.x^2/ax^2 + m.y^2/ay^2) / m.z^2) / (ax ay m.z^4)
//   Lambda(w) = Lambda_std(a),   a = w.z / sqrt(ax^2 w.x^2 + ay^2 w.y^2)
//
// NDF sampling draws a standard radial slope r^2 by inverting its radial CDF,
// an azimuth phi0 = 2 pi u1, and stretches: slope = r (ax cos phi0,
// ay sin phi0). This is [Ribardiere17] eq. 11-12 / 40-42 with the quadrant of
// eq. 40 resolved (arctan(ay/ax tan(2 pi u)) alone only covers half the
// circle; atan2 of the stretched vector is the intended map).

#ifndef BRDFBAKE_MODELS_SLOPE_NDF_H_
#define BRDFBAKE_MODELS_SLOPE_NDF_H_

#include <algorithm>
#include <cmath>
#include <limits>

#include "brdfbake/models/vec3.h"

namespace brdfbake {

// Clamp policy shared by every model: alpha is clamped once, in the
// constructor, to [kMinAlpha, +inf). alpha below 1e-4 behaves as 1e-4.
template <typename T>
inline constexpr T kMinAlpha = T(1e-4);

template <typename T>
T ClampAlpha(T alpha) {
  return std::max(alpha, kMinAlpha<T>);
}

// CRTP base: Derived provides
//   T UnitP22(T r2) const       standard isotropic slope density
//   T UnitLambda(T a) const     Smith Lambda at a = cot(theta), a > 0
//   T UnitSampleR2(T u) const   inverse radial CDF of the standard slopes
// and may shadow DFromStretched (below) with a form that keeps D's range.
template <typename T, class Derived>
class SlopeNdf {
 public:
  SlopeNdf(T alpha_x, T alpha_y)
      : ax_(ClampAlpha(alpha_x)), ay_(ClampAlpha(alpha_y)) {}

  T alpha_x() const { return ax_; }
  T alpha_y() const { return ay_; }

  // NDF D(m), per steradian; zero on the lower hemisphere.
  T D(const Vec3<T>& m) const {
    if (!(m.z > T(0))) return T(0);
    const T z2 = m.z * m.z;
    if (!(z2 > T(0))) return T(0);
    const T sx = m.x / ax_, sy = m.y / ay_;
    return self().DFromStretched(sx * sx + sy * sy, z2);
  }

  // D from the stretched tangential length s2 = (m.x/ax)^2 + (m.y/ay)^2 and
  // z2 = m.z^2 > 0: P22(s2 / z2) / (ax ay z2^2). A model overrides this when
  // the quotient form loses range: P22 can underflow (float: below 1e-38)
  // where D itself, divided by a tiny ax ay z2^2, is still representable.
  T DFromStretched(T s2, T z2) const {
    return self().UnitP22(s2 / z2) / (ax_ * ay_ * z2 * z2);
  }

  // Smith Lambda; +inf for directions on or below the horizon.
  T Lambda(const Vec3<T>& w) const {
    if (!(w.z > T(0))) return std::numeric_limits<T>::infinity();
    const T px = ax_ * w.x, py = ay_ * w.y;
    const T proj = std::sqrt(px * px + py * py);
    if (!(proj > T(0))) return T(0);
    return self().UnitLambda(w.z / proj);
  }

  // Smith G1(w) = 1 / (1 + Lambda(w)), independent of the microfacet normal.
  T G1(const Vec3<T>& w) const {
    if (!(w.z > T(0))) return T(0);
    return T(1) / (T(1) + Lambda(w));
  }

  // G1 with the back-facing test against the microfacet normal m.
  T G1(const Vec3<T>& w, const Vec3<T>& m) const {
    return Dot(w, m) > T(0) ? G1(w) : T(0);
  }

  // Distribution of visible normals D_w(m) = G1(w) max(0, w.m) D(m) / w.z
  // ([Heitz18] eq. 3); integrates to 1 over m for every w above the horizon.
  T DVisible(const Vec3<T>& w, const Vec3<T>& m) const {
    const T wm = Dot(w, m);
    if (!(wm > T(0)) || !(w.z > T(0))) return T(0);
    return G1(w) * wm * D(m) / w.z;
  }

  // Sampling of m with density D(m) m.z per steradian.
  Vec3<T> SampleNdf(T u1, T u2) const {
    const T r = std::sqrt(self().UnitSampleR2(u2));
    const T phi = T(2) * kPi<T> * u1;
    const T px = r * ax_ * std::cos(phi), py = r * ay_ * std::sin(phi);
    return Normalize(Vec3<T>(-px, -py, T(1)));
  }
  T PdfNdf(const Vec3<T>& m) const { return m.z > T(0) ? D(m) * m.z : T(0); }

 protected:
  // log(ax ay z2^2) as a sum of logs: finite even where the product
  // underflows (z2 > 0 is denormal-safe).
  T LogAreaScale(T z2) const {
    return std::log(ax_) + std::log(ay_) + T(2) * std::log(z2);
  }
  const Derived& self() const { return static_cast<const Derived&>(*this); }

  T ax_, ay_;
};

}  // namespace brdfbake

#endif  // BRDFBAKE_MODELS_SLOPE_NDF_H_
