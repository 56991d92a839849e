// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// An independent reference for the rough dielectric's energy albedo E(mu)
// (rules/glass/glass_albedo.h): nested adaptive Gauss-Kronrod (Boost.Math)
// in (cos(theta_i), phi) over both hemispheres of the model's own BsdfCos
// (importance transport), cut at the specular and refraction peaks, at the
// cones where the refraction half vector's chi+ factor and the critical
// angle end a lobe, and graded towards the peaks. It shares no code with
// the rule, which integrates over the visible normals.

#ifndef BRDFBAKE_TESTS_REFERENCE_GLASS_REFERENCE_H_
#define BRDFBAKE_TESTS_REFERENCE_GLASS_REFERENCE_H_

#include <algorithm>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <vector>

#include "brdfbake/models/dielectric.h"
#include "brdfbake/models/ggx.h"

namespace brdfbake {
namespace test {

using GlassRef = RoughDielectric<double, GgxNdf<double>>;

// Cuts graded by 4 from `from` towards `to` (both sides of `to` when it is
// inside [lo, hi]) down to the distance `finest`.
inline void GradeTowards(double to, double lo, double hi, double finest, std::vector<double>* cuts) {
  if (!(to >= lo && to <= hi)) return;
  cuts->push_back(to);
  for (double w = 0.25 * (hi - lo); w > finest; w *= 0.25) {
    if (to - w > lo) cuts->push_back(to - w);
    if (to + w < hi) cuts->push_back(to + w);
  }
}

// Adaptive Gauss-Kronrod of N points on each interval between the sorted
// cuts in [lo, hi], to the relative tolerance `tol`; the error estimates
// summed into *err.
template <unsigned N, class F>
double Adaptive(const F& f, std::vector<double> cuts, double lo, double hi, double tol, double* err) {
  cuts.push_back(lo);
  cuts.push_back(hi);
  std::sort(cuts.begin(), cuts.end());
  double s = 0;
  for (size_t k = 0; k + 1 < cuts.size(); ++k) {
    const double a = std::max(lo, cuts[k]), b = std::min(hi, cuts[k + 1]);
    if (!(b > a)) continue;
    double e = 0;
    s += boost::math::quadrature::gauss_kronrod<double, N>::integrate(f, a, b, 12, tol, &e);
    *err += e;
  }
  return s;
}

// E(mu) = integral over the sphere of BsdfCos(wi, wo), wo = (so, 0, mu):
// for each hemisphere, x = |wi.z| outside and phi in [0, pi] inside (the
// integrand is even in phi), both cut where the BSDF has a peak, a kink or
// an edge. `part` keeps the upper hemisphere (the reflection) or the lower
// one (the refraction) alone.
template <unsigned N>
double ReferenceE(const GlassRef& m, double mu, double tol, double* err, DielectricPart part = DielectricPart::kBoth) {
  const double eta = m.eta(), alpha = m.ndf().alpha_x();
  const double so = std::sqrt((1 - mu) * (1 + mu));
  const Vec3<double> wo{so, 0, mu};
  const double theta_o = std::acos(mu);
  // The cones wi.wo = k where a lobe ends or kinks: the refraction pair's
  // chi+ edges wi.wo = -eta and -1/eta (wi.h = 0 or wo.h = 0, the critical
  // angle of the refraction from the dense side), and for eta < 1 the
  // reflection's critical angle wo.h = sqrt(1 - eta^2), wi.wo = 2 (1 -
  // eta^2) - 1 = 1 - 2 eta^2.
  std::vector<double> cones_below = {-eta, -1 / eta};
  std::vector<double> cones_above;
  if (eta < 1) cones_above.push_back(1 - 2 * eta * eta);
  std::vector<double> x_above, x_below;
  // Where a cone meets the plane of wo (the inner phi range changes form).
  auto cone_in_plane = [&](double k, bool above) {
    if (!(std::abs(k) < 1)) return;
    for (double beta : {theta_o + std::acos(k), theta_o - std::acos(k)}) {
      const double z = std::cos(beta);
      if (above && z > 0) x_above.push_back(z);
      if (!above && z < 0) x_below.push_back(-z);
    }
  };
  for (double k : cones_below) cone_in_plane(k, false);
  for (double k : cones_above) cone_in_plane(k, true);
  // The peaks: the mirror direction (x = mu) and the refracted one.
  const double finest = 1e-3 * alpha * alpha;
  GradeTowards(mu, 0, 1, finest * std::max(mu, 1e-3), &x_above);
  const double st = so / eta;
  if (st < 1) GradeTowards(std::sqrt((1 - st) * (1 + st)), 0, 1, finest, &x_below);
  // Where the refraction half vector lies in the plane (s.z = mu - eta x = 0).
  if (mu / eta < 1) x_below.push_back(mu / eta);
  // The horizon's boundary layer.
  GradeTowards(0, 0, 1, 1e-3 * std::min(mu, alpha), &x_above);
  GradeTowards(0, 0, 1, 1e-3 * std::min(mu, alpha), &x_below);
  auto hemisphere = [&](bool above, const std::vector<double>& xcuts, const std::vector<double>& cones) {
    auto inner = [&](double x) {
      const double s = std::sqrt((1 - x) * (1 + x)), z = above ? x : -x;
      std::vector<double> phis;
      if (so > 0) GradeTowards(kPi<double>, 0, kPi<double>, 1e-2 * alpha, &phis);
      for (double k : cones) {
        // so s cos(phi) + mu z = k.
        const double c = so * s > 0 ? (k - mu * z) / (so * s) : 2.0;
        if (std::abs(c) < 1) phis.push_back(std::acos(c));
      }
      double e = 0;
      const double v = Adaptive<N>([&](double phi) { return m.BsdfCos(Vec3<double>(s * std::cos(phi), s * std::sin(phi), z), wo); },
                                   phis, 0, kPi<double>, 0.01 * tol, &e);
      *err += 2 * e;  // an upper bound of the inner errors' share (weights sum to 1)
      return 2 * v;
    };
    double e = 0;
    const double v = Adaptive<N>(inner, xcuts, 0, 1, tol, &e);
    *err += e;
    return v;
  };
  const double up = part == DielectricPart::kTransmission ? 0.0 : hemisphere(true, x_above, cones_above);
  return up + (part == DielectricPart::kReflection ? 0.0 : hemisphere(false, x_below, cones_below));
}

// The reference and its own error: the 61-point run, and its difference
// from the 31-point run (Boost's |K - G| estimates are far too pessimistic
// next to the square-root edges of the lobes for eta < 1).
inline double ReferenceGlassE(const GlassRef& m, double mu, double tol, double* ref_err,
                              DielectricPart part = DielectricPart::kBoth) {
  double e61 = 0, e31 = 0;
  const double ref = ReferenceE<61>(m, mu, tol, &e61, part);
  *ref_err = std::abs(ref - ReferenceE<31>(m, mu, tol, &e31, part));
  return ref;
}

}  // namespace test
}  // namespace brdfbake

#endif  // BRDFBAKE_TESTS_REFERENCE_GLASS_REFERENCE_H_
