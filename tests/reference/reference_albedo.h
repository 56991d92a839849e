// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The tests' independent reference for the directional albedo E(mu): an
// integral over the half vector with Boost.Math's tanh-sinh quadrature,
// sharing no code with the baker's rules.

#ifndef BRDFBAKE_TESTS_REFERENCE_REFERENCE_ALBEDO_H_
#define BRDFBAKE_TESTS_REFERENCE_REFERENCE_ALBEDO_H_

#include <algorithm>
#include <cmath>
#include <vector>

#include <boost/math/quadrature/tanh_sinh.hpp>

#include "brdfbake/models/brdf.h"
#include "brdfbake/models/ggx.h"
#include "brdfbake/models/vec3.h"

namespace brdfbake {

// Independent reference: E(mu) as an integral over the half vector,
//   E = int D(h) G2(wi, wo, h) (wo.h) / wo.z dh,  wi = reflect(wo, h),
// adaptive Gauss-Kronrod (Boost.Math) in (theta_h, phi_h), in double. For wo
// at azimuth 0 and a given theta_h, both wo.h > 0 and wi.z > 0 are of the
// form cos(phi_h) > c, so the valid azimuths are one arc |phi_h| < phi_max
// found in closed form, and the integrand is smooth on it.
// `phi_o` turns wo (and the half vectors with it) about the normal: the
// arc conditions depend only on the azimuth relative to wo.
// Not smooth everywhere for the STD below gamma 2: Lambda(wi) has a cusp
// at wi = n (it rises like theta_i^(2 gamma - 2)), which for mu < 1 lies
// inside the (theta_h, phi_h) domain, at theta_h = theta_o / 2 (for
// mu = 1 at its end, theta_h = 0). Near gamma = 1.5 the cusp is steep and
// the result is off there: at gamma 1.500001, alpha 0.25, mu 0.984375 by
// 5.7e-6 of E (the baker's rules and a product Gauss-Legendre rule in
// (theta_i, phi_i) agree to 1e-15). Use it there at mu = 1 only.
// The same integral over the half vector of any integrand g(h, wo, wi, wo.h)
// (0 outside the arc), E's being D G2 (wo.h) / wo.z; `extra_cuts` in
// theta_h split the outer integral where g has a feature of its own.
template <class G>
inline double ReferenceHalfVectorIntegral(double mu, double tol, double phi_o, const G& g,
                                          const std::vector<double>& extra_cuts = {}) {
  const double mu_o = std::max(mu, 1e-7);
  const Vec3<double> wo = FromMuPhi(mu_o, phi_o);
  const double so = std::sqrt(std::max(0.0, 1 - mu_o * mu_o));
  // The arc is cos(phi_h) > c(theta_h).
  auto ArcCos = [&](double th) {
    const double ch = std::cos(th), sh = std::sin(th);
    const double denom = so * sh;
    if (denom <= 0) return (2 * ch * ch * mu_o - mu_o > 0) ? -2.0 : 2.0;
    const double c1 = -mu_o * ch / denom;                           // wo.h > 0
    const double c2 = mu_o * (1 - 2 * ch * ch) / (2 * ch * denom);  // wi.z > 0
    return std::max(c1, c2);
  };
  auto inner = [&](double th) {
    const double ch = std::cos(th), sh = std::sin(th);
    const double c = ArcCos(th);
    if (c >= 1) return 0.0;
    auto f = [&](double phi) {
      const Vec3<double> h(sh * std::cos(phi + phi_o), sh * std::sin(phi + phi_o), ch);
      const double wo_h = Dot(wo, h);
      const Vec3<double> wi = Reflect(wo, h);
      if (!(wo_h > 0) || !(wi.z > 0)) return 0.0;
      return g(h, wo, wi, wo_h);
    };
    const double phi_max = c <= -1 ? kPi<double> : std::acos(c);
    // tanh-sinh: the integrand can have square-root behaviour at the arc's ends.
    static thread_local boost::math::quadrature::tanh_sinh<double> ts(12);
    if (phi_o == 0.0) return sh * 2 * ts.integrate(f, 0.0, phi_max, tol);
    // Without the mirror symmetry of an isotropic model about wo's plane.
    auto both = [&](double phi) { return f(phi) + f(-phi); };
    return sh * ts.integrate(both, 0.0, phi_max, tol);
  };
  // Split theta_h where the arc becomes full (c = -1) or empty (c = 1): the
  // outer integrand has square-root behaviour there.
  std::vector<double> cuts = {0.0};
  const int probes = 2000;
  double prev = ArcCos(0.0);
  for (int k = 1; k <= probes; ++k) {
    const double th = (kPi<double> / 2) * k / probes;
    const double cur = ArcCos(th);
    for (double level : {-1.0, 1.0}) {
      if ((prev > level) != (cur > level)) {
        double lo = (kPi<double> / 2) * (k - 1) / probes, hi = th;
        for (int it = 0; it < 60; ++it) {
          const double mid = 0.5 * (lo + hi);
          if ((ArcCos(mid) > level) == (prev > level)) lo = mid; else hi = mid;
        }
        cuts.push_back(0.5 * (lo + hi));
      }
    }
    prev = cur;
  }
  for (double c : extra_cuts) {
    if (c > 0 && c < kPi<double> / 2) cuts.push_back(c);
  }
  cuts.push_back(kPi<double> / 2);
  std::sort(cuts.begin(), cuts.end());
  boost::math::quadrature::tanh_sinh<double> outer(12);
  double total = 0;
  for (size_t i = 0; i + 1 < cuts.size(); ++i) {
    if (cuts[i + 1] > cuts[i]) total += outer.integrate(inner, cuts[i], cuts[i + 1], tol);
  }
  return total;
}

template <class Ndf>
inline double ReferenceEFor(const Ndf& ndf, double mu, Masking masking, double tol,
                            double phi_o = 0.0) {
  return ReferenceHalfVectorIntegral(
      mu, tol, phi_o, [&](const Vec3<double>& h, const Vec3<double>& wo, const Vec3<double>& wi, double wo_h) {
        return ndf.D(h) * G2(ndf, wi, wo, h, masking) * wo_h / wo.z;
      });
}

inline double ReferenceE(double alpha, double mu, Masking masking = Masking::kHeightCorrelated,
                  double tol = 1e-10) {
  return ReferenceEFor(GgxNdf<double>(alpha), mu, masking, tol);
}

}  // namespace brdfbake

#endif  // BRDFBAKE_TESTS_REFERENCE_REFERENCE_ALBEDO_H_
