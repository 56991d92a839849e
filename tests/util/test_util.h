// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Shared test machinery: adaptive hemisphere/sphere quadrature (Boost.Math
// Gauss-Kronrod, nested) and a chi-square goodness-of-fit test for samplers
// of directions (bins in cos(theta) x phi, expected counts from the pdf
// integrated per bin, sparse bins pooled, p-value from the chi-square law).

#ifndef BRDFBAKE_TESTS_UTIL_TEST_UTIL_H_
#define BRDFBAKE_TESTS_UTIL_TEST_UTIL_H_

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <random>
#include <vector>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/special_functions/gamma.hpp>

#include "brdfbake/models/vec3.h"

namespace brdfbake {
namespace test {

using Dir = Vec3<double>;

// Integral of f over the directions with cos(theta) in [mu_lo, mu_hi], in
// (mu, phi) coordinates (dw = dmu dphi), nested adaptive Gauss-Kronrod.
inline double IntegrateDirections(const std::function<double(const Dir&)>& f,
                                  double mu_lo = 0.0, double mu_hi = 1.0,
                                  double tol = 1e-10, unsigned depth = 18) {
  using GK = boost::math::quadrature::gauss_kronrod<double, 31>;
  auto inner = [&](double mu) {
    auto g = [&](double phi) { return f(FromMuPhi(mu, phi)); };
    return GK::integrate(g, 0.0, 2.0 * kPi<double>, depth, tol);
  };
  return GK::integrate(inner, mu_lo, mu_hi, depth, tol);
}

// Same, but in (theta, phi) with dw = sin(theta) dtheta dphi; resolves
// functions concentrated near the pole better than the mu parameterization.
inline double IntegrateHemisphereTheta(const std::function<double(const Dir&)>& f,
                                       double theta_lo = 0.0,
                                       double theta_hi = kPi<double> / 2,
                                       double tol = 1e-10, unsigned depth = 18) {
  using GK = boost::math::quadrature::gauss_kronrod<double, 31>;
  auto inner = [&](double theta) {
    const double mu = std::cos(theta), s = std::sin(theta);
    auto g = [&](double phi) {
      return f(Dir(s * std::cos(phi), s * std::sin(phi), mu));
    };
    return s * GK::integrate(g, 0.0, 2.0 * kPi<double>, depth, tol);
  };
  return GK::integrate(inner, theta_lo, theta_hi, depth, tol);
}

// Integral over the upper hemisphere of f(m) max(0, v.m) dm, for f smooth.
// For each theta the phi range where v.m > 0 is found in closed form and
// only that arc is integrated, so the kink of max(0, .) never sits inside a
// quadrature panel; this is orders of magnitude faster than adaptive
// quadrature of the kinked integrand.
inline double IntegrateVisibleHemisphere(const std::function<double(const Dir&)>& f,
                                         const Dir& v, double tol = 1e-10,
                                         unsigned depth = 15) {
  using GK = boost::math::quadrature::gauss_kronrod<double, 31>;
  const double sin_v = std::sqrt(std::max(0.0, 1.0 - v.z * v.z));
  const double phi_v = sin_v > 0 ? std::atan2(v.y, v.x) : 0.0;
  auto inner = [&](double theta) {
    const double mu = std::cos(theta), s = std::sin(theta);
    auto g = [&](double phi) {
      const Dir m(s * std::cos(phi), s * std::sin(phi), mu);
      return f(m) * std::max(0.0, Dot(v, m));
    };
    // v.m = s sin_v cos(phi - phi_v) + mu v.z > 0.
    const double a = s * sin_v, b = mu * v.z;
    if (a <= std::abs(b)) {
      if (b <= 0) return 0.0;
      return s * GK::integrate(g, 0.0, 2.0 * kPi<double>, depth, tol);
    }
    const double half = std::acos(std::clamp(-b / a, -1.0, 1.0));
    return s * GK::integrate(g, phi_v - half, phi_v + half, depth, tol);
  };
  return GK::integrate(inner, 0.0, kPi<double> / 2, depth, tol);
}

struct ChiSquareResult {
  double p_value = 0;
  double chi2 = 0;
  int dof = 0;
  double pdf_mass = 0;  // integral of the pdf over the binned domain
};

// Chi-square test of a direction sampler against its density (per sr).
// `sample(u1, u2, &dir)` returns false when it produced no sample (that
// sample then counts as mass outside the histogram). The histogram covers
// cos(theta) in [mu_lo, 1] with n_mu x n_phi cells.
inline ChiSquareResult ChiSquareDirections(
    const std::function<bool(double, double, Dir*)>& sample,
    const std::function<double(const Dir&)>& pdf, int n_mu = 40, int n_phi = 80,
    int n_samples = 1000000, uint64_t seed = 1, double mu_lo = 0.0) {
  std::vector<double> observed(n_mu * n_phi, 0.0), expected(n_mu * n_phi, 0.0);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  const double dmu = (1.0 - mu_lo) / n_mu, dphi = 2.0 * kPi<double> / n_phi;
  for (int i = 0; i < n_samples; ++i) {
    const double u1 = uni(rng), u2 = uni(rng);
    Dir d;
    if (!sample(u1, u2, &d)) continue;
    if (!std::isfinite(d.x) || !std::isfinite(d.y) || !std::isfinite(d.z)) continue;
    const double len = Length(d);
    if (std::abs(len - 1.0) > 1e-6) continue;  // not a unit vector: a failure
    if (d.z < mu_lo) continue;
    double phi = std::atan2(d.y, d.x);
    if (phi < 0) phi += 2.0 * kPi<double>;
    const int im = std::clamp(static_cast<int>((d.z - mu_lo) / dmu), 0, n_mu - 1);
    const int ip = std::clamp(static_cast<int>(phi / dphi), 0, n_phi - 1);
    observed[im * n_phi + ip] += 1.0;
  }
  // Expected counts: 6x6 Gauss-Legendre per cell.
  static const double kX[6] = {-0.9324695142031521, -0.6612093864662645,
                               -0.2386191860831969, 0.2386191860831969,
                               0.6612093864662645,  0.9324695142031521};
  static const double kW[6] = {0.1713244923791704, 0.3607615730481386,
                               0.4679139345726910, 0.4679139345726910,
                               0.3607615730481386, 0.1713244923791704};
  double mass = 0;
  for (int im = 0; im < n_mu; ++im) {
    for (int ip = 0; ip < n_phi; ++ip) {
      double acc = 0;
      for (int a = 0; a < 6; ++a) {
        const double mu = mu_lo + (im + 0.5 + 0.5 * kX[a]) * dmu;
        for (int b = 0; b < 6; ++b) {
          const double phi = (ip + 0.5 + 0.5 * kX[b]) * dphi;
          acc += kW[a] * kW[b] * pdf(FromMuPhi(mu, phi));
        }
      }
      acc *= 0.25 * dmu * dphi;
      mass += acc;
      expected[im * n_phi + ip] = acc * n_samples;
    }
  }
  // Pool cells with expected count < 5 (sorted ascending) into one cell.
  std::vector<int> order(observed.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return expected[a] < expected[b]; });
  double pooled_o = 0, pooled_e = 0, chi2 = 0;
  int dof = 0;
  for (int idx : order) {
    if (expected[idx] == 0) {
      if (observed[idx] > n_samples * 1e-5) {
        // Samples where the pdf is zero: fail decisively.
        return {0.0, 1e30, dof, mass};
      }
      continue;
    }
    if (expected[idx] < 5) {
      pooled_o += observed[idx];
      pooled_e += expected[idx];
      continue;
    }
    const double diff = observed[idx] - expected[idx];
    chi2 += diff * diff / expected[idx];
    ++dof;
  }
  if (pooled_e > 0) {
    const double diff = pooled_o - pooled_e;
    chi2 += diff * diff / pooled_e;
    ++dof;
  }
  --dof;
  ChiSquareResult r;
  r.chi2 = chi2;
  r.dof = dof;
  r.pdf_mass = mass;
  r.p_value = dof > 0 ? boost::math::gamma_q(0.5 * dof, 0.5 * chi2) : 0.0;
  return r;
}

// Significance level for one of `n_tests` chi-square tests at overall 1%
// (Sidak correction).
inline double ChiSquareAlpha(int n_tests) {
  return 1.0 - std::pow(1.0 - 0.01, 1.0 / n_tests);
}

}  // namespace test
}  // namespace brdfbake

#endif  // BRDFBAKE_TESTS_UTIL_TEST_UTIL_H_
