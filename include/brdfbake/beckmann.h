// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Beckmann distribution, isotropic and anisotropic, with exact visible-normal
// sampling by inversion of the visible-slope CDF.

#ifndef BRDFBAKE_BECKMANN_H_
#define BRDFBAKE_BECKMANN_H_

#include <algorithm>
#include <cmath>

#include <boost/math/special_functions/erf.hpp>

#include "brdfbake/slope_ndf.h"
#include "brdfbake/vec3.h"

namespace brdfbake {

template <typename T>
class BeckmannNdf : public SlopeNdf<T, BeckmannNdf<T>> {
  using Base = SlopeNdf<T, BeckmannNdf<T>>;

 public:
  explicit BeckmannNdf(T alpha) : Base(alpha, alpha) {}
  BeckmannNdf(T alpha_x, T alpha_y) : Base(alpha_x, alpha_y) {}

  // Standard slopes: P22 = exp(-r^2) / pi.
  T StdP22(T r2) const { return kInvPi<T> * std::exp(-r2); }
  // Lambda = (exp(-a^2) / (a sqrt(pi)) - erfc(a)) / 2 (seed 004 Table 1,
  // gamma -> inf, with erf(a) - 1 written as -erfc(a) so that the small
  // tail keeps its relative precision).
  T StdLambda(T a) const {
    if (a > T(26)) return T(0);  // exp(-a^2) underflows double here
    return T(0.5) * (std::exp(-a * a) / (a * kSqrtPi<T>) - std::erfc(a));
  }
  // D = exp(-r^2 - log(ax ay z2^2)) / pi: one exponential of the whole
  // exponent, so D is accurate wherever it is representable (the quotient
  // form underflows exp(-r^2) first at tiny alpha).
  T DFromStretched(T s2, T z2) const {
    return kInvPi<T> * std::exp(-s2 / z2 - this->LogAreaScale(z2));
  }
  // Radial CDF 1 - exp(-r^2)  =>  r^2 = -log(1 - u).
  T StdSampleR2(T u) const { return -std::log1p(-std::min(u, T(1) - std::numeric_limits<T>::epsilon() / 2)); }

  // Visible-normal sampling (Heitz and d'Eon 2014 stretch, exact inversion).
  // In the unit-roughness configuration with the view at cot(theta) = mu,
  // the visible slope x (along the view azimuth) has density
  // (mu - x)^+ exp(-x^2) / sqrt(pi), whose CDF up to normalization is
  //   N(x) = mu erfc(-x) / 2 + exp(-x^2) / (2 sqrt(pi)),  x <= mu,
  // and y given x is N(0, 1/2). N is inverted by safeguarded Newton.
  Vec3<T> SampleVisible(const Vec3<T>& w, T u1, T u2) const {
    const T ax = this->ax_, ay = this->ay_;
    const Vec3<T> ws = Normalize(Vec3<T>(ax * w.x, ay * w.y, w.z));
    const T sin_t = std::sqrt(ws.x * ws.x + ws.y * ws.y);
    T cos_phi = T(1), sin_phi = T(0);
    if (sin_t > T(0)) {
      cos_phi = ws.x / sin_t;
      sin_phi = ws.y / sin_t;
    }
    const T x = SampleVisibleSlopeX(ws.z, sin_t, u1);
    const T uy = std::clamp(T(2) * u2 - T(1), -T(1) + std::numeric_limits<T>::epsilon(),
                            T(1) - std::numeric_limits<T>::epsilon());
    const T y = boost::math::erf_inv(uy);
    // Rotate back to the view azimuth, unstretch, slope -> normal.
    const T sx = ax * (cos_phi * x - sin_phi * y);
    const T sy = ay * (sin_phi * x + cos_phi * y);
    return Normalize(Vec3<T>(-sx, -sy, T(1)));
  }
  T PdfVisible(const Vec3<T>& w, const Vec3<T>& m) const { return this->DVisible(w, m); }

 private:
  // Solves N(x) = u N(mu) for the visible slope; mu = cos_t / sin_t.
  static T SampleVisibleSlopeX(T cos_t, T sin_t, T u) {
    const T inv_sqrt_pi = T(1) / kSqrtPi<T>;
    // Work with sin_t * N(x) = cos_t erfc(-x)/2 + sin_t exp(-x^2)/(2 sqrt pi),
    // which stays finite at normal incidence (sin_t = 0).
    auto n = [&](T x) {
      return T(0.5) * (cos_t * std::erfc(-x) + sin_t * std::exp(-x * x) * inv_sqrt_pi);
    };
    const T hi_limit = T(9);
    const T mu_hi = sin_t > T(0) ? std::min(cos_t / sin_t, hi_limit) : hi_limit;
    T lo = -T(9), hi = mu_hi;
    const T target = u * n(mu_hi);
    T x = T(0.5) * (lo + hi);
    for (int i = 0; i < 100; ++i) {
      const T f = n(x) - target;
      if (f > T(0)) hi = x; else lo = x;
      const T df = (cos_t - x * sin_t) * std::exp(-x * x) * inv_sqrt_pi;
      T next = df > T(0) ? x - f / df : T(0.5) * (lo + hi);
      if (!(next > lo && next < hi)) next = T(0.5) * (lo + hi);
      if (std::abs(next - x) <= T(4) * std::numeric_limits<T>::epsilon() * (T(1) + std::abs(x))) {
        x = next;
        break;
      }
      x = next;
    }
    return x;
  }
};

}  // namespace brdfbake

#endif  // BRDFBAKE_BECKMANN_H_
