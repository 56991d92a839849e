// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// An independent reference for the Schlick-weighted refraction albedo
// (DielectricPart::kTransmissionSchlick, EEVEE's btdf_ggx, [Blender]):
//   T(mu) = integral over the lower hemisphere of (1 - (1 - wo.h)^5)
//           D(h) G1(wo) G1(wi) eta^2 |wi.h| wo.h / (mu (wo.h + eta wi.h)^2) dwi,
// h = -normalize(wo + eta wi) ([Walter07] eq. 16, 17 and 21 without F, in
// the importance transport; G2 separable, or height-correlated), written out here from those equations, not
// from the model's BsdfCos (whose index is clamped at 100), so that it
// runs at any eta >= 1 (1e8 stands for inf). Nested adaptive Gauss-Kronrod
// (Boost.Math) in (|cos(theta_i)|, phi), cut at the refraction peak (graded
// towards it), at the cone wi.wo = -1 / eta where wo.h reaches 0, at the
// plane where h turns, and graded towards the horizon; it shares no code
// with the rule, which integrates over the visible normals.

#ifndef BRDFBAKE_TESTS_REFERENCE_SCHLICK_TRANSMISSION_REFERENCE_H_
#define BRDFBAKE_TESTS_REFERENCE_SCHLICK_TRANSMISSION_REFERENCE_H_

#include <algorithm>
#include <cmath>
#include <vector>

#include "reference/glass_reference.h"

namespace brdfbake {
namespace test {

// GGX's D and separable G1 at alpha, from their textbook forms.
inline double GgxD(double alpha, double nz) {
  const double a2 = alpha * alpha, c2 = nz * nz;
  const double t = c2 * (a2 - 1) + 1;
  return a2 / (kPi<double> * t * t);
}
inline double GgxLambda(double alpha, double z) {
  z = std::abs(z);
  const double t2 = (1 - z * z) / (z * z);
  return 0.5 * (std::sqrt(1 + alpha * alpha * t2) - 1);
}
// G2(wi, wo): G1(wo) G1(wi) (separable) or 1 / (1 + Lambda(wo) +
// Lambda(wi)) (height-correlated), Lambda = (sqrt(1 + alpha^2 tan^2) - 1) / 2.
inline double GgxG2(double alpha, double zo, double zi, bool separable) {
  const double lo = GgxLambda(alpha, zo), li = GgxLambda(alpha, zi);
  return separable ? 1 / ((1 + lo) * (1 + li)) : 1 / (1 + lo + li);
}

template <unsigned N>
double ReferenceSchlickT(double alpha, double eta, double mu, double tol, double* err, bool separable = true) {
  const double so = std::sqrt((1 - mu) * (1 + mu));
  const Vec3<double> wo{so, 0, mu};
  const double theta_o = std::acos(mu);
  auto integrand = [&](const Vec3<double>& wi) {
    Vec3<double> h = (wo + wi * eta) * -1.0;
    const double len = std::sqrt(Dot(h, h));
    if (!(len > 0)) return 0.0;
    h = h / len;
    if (h.z < 0) h = h * -1.0;
    const double oh = Dot(wo, h), ih = Dot(wi, h);
    if (!(oh > 0) || !(ih < 0)) return 0.0;
    const double den = oh + eta * ih;
    const double s = std::pow(1 - oh, 5);
    return (1 - s) * GgxD(alpha, h.z) * GgxG2(alpha, mu, wi.z, separable) * eta * eta * -ih * oh / (mu * den * den);
  };
  std::vector<double> x_cuts;
  auto cone_in_plane = [&](double k) {
    if (!(std::abs(k) < 1)) return;
    for (double beta : {theta_o + std::acos(k), theta_o - std::acos(k)}) {
      const double z = std::cos(beta);
      if (z < 0) x_cuts.push_back(-z);
    }
  };
  cone_in_plane(-1 / eta);
  const double finest = 1e-3 * alpha * alpha;
  const double st = so / eta;
  GradeTowards(std::sqrt((1 - st) * (1 + st)), 0, 1, finest, &x_cuts);
  if (mu / eta < 1) x_cuts.push_back(mu / eta);
  GradeTowards(0, 0, 1, 1e-3 * std::min(mu, alpha), &x_cuts);
  auto inner = [&](double x) {
    const double s = std::sqrt((1 - x) * (1 + x)), z = -x;
    std::vector<double> phis;
    if (so > 0) GradeTowards(kPi<double>, 0, kPi<double>, 1e-2 * alpha, &phis);
    const double c = so * s > 0 ? (-1 / eta - mu * z) / (so * s) : 2.0;
    if (std::abs(c) < 1) phis.push_back(std::acos(c));
    double e = 0;
    const double v = Adaptive<N>(
        [&](double phi) { return integrand(Vec3<double>(s * std::cos(phi), s * std::sin(phi), z)); }, phis, 0,
        kPi<double>, 0.01 * tol, &e);
    *err += 2 * e;
    return 2 * v;
  };
  double e = 0;
  const double v = Adaptive<N>(inner, x_cuts, 0, 1, tol, &e);
  *err += e;
  return v;
}

// The reference and its own error: the 61-point run, and its difference
// from the 31-point run.
inline double ReferenceSchlickTransmission(double alpha, double eta, double mu, double tol, double* ref_err,
                                           bool separable = true) {
  double e61 = 0, e31 = 0;
  const double ref = ReferenceSchlickT<61>(alpha, eta, mu, tol, &e61, separable);
  *ref_err = std::abs(ref - ReferenceSchlickT<31>(alpha, eta, mu, tol, &e31, separable));
  return ref;
}

}  // namespace test
}  // namespace brdfbake

#endif  // BRDFBAKE_TESTS_REFERENCE_SCHLICK_TRANSMISSION_REFERENCE_H_
