// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Beckmann distribution, isotropic and anisotropic, with exact visible-normal
// sampling by inversion of the visible-slope CDF.

#ifndef BRDFBAKE_MODELS_BECKMANN_H_
#define BRDFBAKE_MODELS_BECKMANN_H_

#include <algorithm>
#include <cmath>

#include <boost/math/special_functions/erf.hpp>

#include "brdfbake/models/slope_ndf.h"
#include "brdfbake/models/vec3.h"

namespace brdfbake {

template <typename T>
class BeckmannNdf : public SlopeNdf<T, BeckmannNdf<T>> {
  using Base = SlopeNdf<T, BeckmannNdf<T>>;

 public:
  explicit BeckmannNdf(T alpha) : Base(alpha, alpha) {}
  BeckmannNdf(T alpha_x, T alpha_y) : Base(alpha_x, alpha_y) {}

  // Standard slopes: P22 = exp(-r^2) / pi.
  T UnitP22(T r2) const { return kInvPi<T> * std::exp(-r2); }
  // Lambda = (exp(-a^2) / (a sqrt(pi)) - erfc(a)) / 2 ([Ribardiere17] Table 1,
  // gamma -> inf, with erf(a) - 1 written as -erfc(a) so that the small
  // tail keeps its relative precision).
  T UnitLambda(T a) const {
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
  T UnitSampleR2(T u) const {
    return -std::log1p(-std::min(u, T(1) - std::numeric_limits<T>::epsilon() / 2));
  }

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
    // y = erf^-1(2 u2 - 1) = -+erfc^-1(2 q), q = min(u2, 1 - u2) (exact; 2 u2 - 1
    // would round away the tail's precision), clamped at 2^-53 as 2 u2 - 1
    // at +-(1 - 2^-52).
    const T q = std::max(std::min(u2, T(1) - u2), std::numeric_limits<T>::epsilon() / 2);
    const T y_mag = boost::math::erfc_inv(T(2) * q);
    const T y = u2 < T(0.5) ? -y_mag : y_mag;
    // Rotate back to the view azimuth, unstretch, slope -> normal.
    const T sx = ax * (cos_phi * x - sin_phi * y);
    const T sy = ay * (sin_phi * x + cos_phi * y);
    return Normalize(Vec3<T>(-sx, -sy, T(1)));
  }
  T PdfVisible(const Vec3<T>& w, const Vec3<T>& m) const { return this->DVisible(w, m); }

 private:
  // Solves N(x) = u N(mu) for the visible slope; mu = cos_t / sin_t (capped
  // at 9, as the search interval [-9, 9]). With f(x) = (cos_t - x sin_t)
  // exp(-x^2) / sqrt(pi), the density times sin_t, and
  //   n(x) = sin_t N(x) = (cos_t erfc(-x) + sin_t exp(-x^2) / sqrt(pi)) / 2,
  //   U(x) = n(mu) - n(x) = int_x^mu f,
  // the equation is solved as log n(x) = log(u n(mu)) for u <= 1/2 and as
  // log U(x) = log((1 - u) n(mu)) for u > 1/2 (1 - u is exact there). Both
  // n and U are log-concave in x (the CDF and survival function of a
  // log-concave density), so Newton on their logs converges from any start;
  // a bracket with a bisection fallback guards it anyway. U is formed
  // without cancellation: from erfc(x) - erfc(mu) and exp(-x^2) -
  // exp(-mu^2) when mu - x >= 1/4, else by 16-point Gauss-Legendre of f over
  // [x, mu] (f > 0 there; the difference of n values would be below double
  // rounding near mu, where U is of second order in mu - x). Start: the
  // empirical fit of the inverse that pbrt-v3 uses for Beckmann sampling,
  // erf(x0) = erf(mu) - (1 + erf(mu)) (1 - u)^p(theta), p(theta) = 1 -
  // 0.876 theta + 0.4265 theta^2 - 0.0594 theta^3, written with erfc_inv so
  // that small u keeps its precision; a few Newton steps finish it.
  static T SampleVisibleSlopeX(T cos_t, T sin_t, T u) {
    using std::exp;
    using std::log;
    const T inv_sqrt_pi = T(1) / kSqrtPi<T>;
    const T lo_limit = -T(9), hi_limit = T(9);
    const T mu_hi = sin_t > T(0) ? std::min(cos_t / sin_t, hi_limit) : hi_limit;
    if (!(u > T(0))) return lo_limit;
    if (!(u < T(1))) return mu_hi;
    auto n = [&](T x) {
      return T(0.5) * (cos_t * std::erfc(-x) + sin_t * exp(-x * x) * inv_sqrt_pi);
    };
    auto f = [&](T x) { return (cos_t - x * sin_t) * exp(-x * x) * inv_sqrt_pi; };
    auto upper = [&](T x) {
      if (mu_hi - x >= T(0.25)) {
        return T(0.5) * (cos_t * (std::erfc(x) - std::erfc(mu_hi)) -
                         sin_t * (exp(-x * x) - exp(-mu_hi * mu_hi)) * inv_sqrt_pi);
      }
      // 16-point Gauss-Legendre on [x, mu_hi] (nodes and weights on [-1, 1]).
      static constexpr double kX[8] = {0.0950125098376374, 0.2816035507792589,
                                       0.4580167776572274, 0.6178762444026438,
                                       0.7554044083550030, 0.8656312023878318,
                                       0.9445750230732326, 0.9894009349916499};
      static constexpr double kW[8] = {0.1894506104550685, 0.1826034150449236,
                                       0.1691565193950025, 0.1495959888165767,
                                       0.1246289712555339, 0.0951585116824928,
                                       0.0622535239386479, 0.0271524594117541};
      const T c = T(0.5) * (x + mu_hi), h = T(0.5) * (mu_hi - x);
      T acc = 0;
      for (int i = 0; i < 8; ++i) {
        acc += T(kW[i]) * (f(c - h * T(kX[i])) + f(c + h * T(kX[i])));
      }
      return acc * h;
    };
    const T total = n(mu_hi);
    const bool low_half = u <= T(0.5);
    const T log_target = low_half ? log(u * total) : log((T(1) - u) * total);
    // The start (pbrt-v3's fit), clamped into the interval.
    const T theta = std::atan2(sin_t, cos_t);
    const T p = T(1) - theta * (T(0.876) - theta * (T(0.4265) - T(0.0594) * theta));
    // v = erfc(-mu) / 2 (1 - (1 - u)^p); x0 = erf^-1(2 v - 1) = -erfc^-1(2 v).
    const T v = T(0.5) * std::erfc(-mu_hi) * -std::expm1(p * std::log1p(-u));
    T x = v > T(0) && v < T(1) ? -boost::math::erfc_inv(T(2) * v) : T(0);
    T lo = lo_limit, hi = mu_hi;
    x = std::clamp(x, lo + (hi - lo) * T(1e-6), hi - (hi - lo) * T(1e-6));
    for (int i = 0; i < 60; ++i) {
      // g(x) = log n(x) - log target (increasing) or log U(x) - log target
      // (decreasing); g' = f / n or -f / U.
      const T val = low_half ? n(x) : upper(x);
      const T g = log(val) - log_target;
      const bool above = low_half ? g > T(0) : g < T(0);  // x above the root
      if (above) hi = x; else lo = x;
      const T dg = (low_half ? f(x) : -f(x)) / val;
      T next = dg != T(0) && std::isfinite(g) ? x - g / dg : T(0.5) * (lo + hi);
      if (!(next > lo && next < hi)) next = T(0.5) * (lo + hi);
      const bool done =
          std::abs(next - x) <= T(4) * std::numeric_limits<T>::epsilon() * (T(1) + std::abs(x));
      x = next;
      if (done || !(hi - lo > T(0))) break;
    }
    return x;
  }
};

}  // namespace brdfbake

#endif  // BRDFBAKE_MODELS_BECKMANN_H_
