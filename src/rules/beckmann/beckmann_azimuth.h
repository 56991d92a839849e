// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// E(mu) of the isotropic Beckmann BRDF by the one-dimensional rule of
// azimuthal.h with the azimuth of wi integrated in closed form.
//
// In azimuthal_slope.h's variables (psi = pi - phi, w = sin^2(psi / 2),
// t = 2B w, B = 2 sin(theta_i) sin(theta_o)) Beckmann's D is
//   D = exp(-r2_0 - r2_t t) (v_min + t)^2 / (pi alpha^2 s^4),
// so Phi = int_0^{2 pi} D dphi = 2 int_0^pi D dpsi is, with x = 2B r2_t,
//   Phi = 2 exp(-r2_0) / (pi alpha^2 s^4)
//         (v_min^2 M_0(x) + 2 v_min (2B) M_1(x) + (2B)^2 M_2(x)),
//   M_k(x) = int_0^pi exp(-x w) w^k dpsi = int_0^1 exp(-x w) w^(k-1/2) (1-w)^(-1/2) dw
//          = B(k + 1/2, 1/2) 1F1(k + 1/2; k + 1; -x)        (Kummer's function),
// three positive moments (no cancellation between the terms: v_min, 2B and
// the M_k are all >= 0). Equivalently M_0 = pi e^-y I0(y),
// M_1 = (pi/2) e^-y (I0 - I1), M_2 = (pi/4) e^-y (2 I0 - 2 I1 - I1 / y) with
// y = x / 2 (modified Bessel functions; tests/rules/beckmann_azimuth_test.cc checks
// the moments against these in 50 digits), but those differences cancel by
// a factor ~x for large x, so the moments are evaluated directly:
// - x < 40: Kummer's transformation 1F1(a; b; -x) = e^-x 1F1(b - a; b; x)
//   gives the positive series
//     M_k = e^-x sum_n B(k + 1/2, 1/2) (1/2)_n / ((k + 1)_n n!) x^n,
//   summed by Horner's rule from the term n = floor(x + 9 sqrt(x) + 12)
//   (the tail beyond it is below 1e-17 of the sum for x < 40; at most 109
//   terms).
// - x >= 40: the asymptotic expansion of 1F1 for large negative argument,
//     M_k = Gamma(k + 1/2) x^(-k - 1/2) sum_n (k + 1/2)_n (1/2)_n / n! x^-n,
//   to 38 terms from x = 40, 25 from 50, 16 from 80, 10 from 200, 7 from
//   1000 and 4 from 1e5 (each within 3e-16 of the limit at the start of its
//   range for k = 2, the slowest; the omitted exponentially small part,
//   Gamma(k + 1) / Gamma(k + 1/2) e^-x x^k relative, is below 1e-14 for
//   x >= 40).
// The coefficients are formed once in long double. Measured against the
// 50-digit Bessel forms: relative error <= 2e-15 over x in [0, 1e300]
// (measured 1.3e-15, next to x = 40, on every target)
// (tests/rules/beckmann_azimuth_test.cc prints the maximum).
//
// The integrand over theta_i, G2 Phi sin(theta_i) / (4 mu_o), is then the
// same kind of function as GGX's (a peak at theta_o of width ~alpha, the
// horizon's boundary layer), and AzimuthalMesh's breakpoints and the
// adaptive Gauss-Kronrod rule apply unchanged, with no azimuthal error.

#ifndef BRDFBAKE_SRC_RULES_BECKMANN_BECKMANN_AZIMUTH_H_
#define BRDFBAKE_SRC_RULES_BECKMANN_BECKMANN_AZIMUTH_H_

#include <cmath>
#include <limits>

#include "brdfbake/models/beckmann.h"
#include "brdfbake/models/brdf.h"
#include "rules/ggx/azimuthal.h"

namespace brdfbake {

// The coefficient tables of the moments M_0, M_1, M_2 (see the header),
// with B(k + 1/2, 1/2) and Gamma(k + 1/2) folded in.
struct BeckmannMomentTables {
  static constexpr int kSeriesTerms = 109;     // n = 0 .. 108
  static constexpr int kAsymptoticTerms = 38;  // n = 0 .. 37
  static constexpr double kAsymptoticFrom = 40;
  double series[3][kSeriesTerms];
  double asymptotic[3][kAsymptoticTerms];

  static const BeckmannMomentTables& Get() {
    static const BeckmannMomentTables t = [] {
      BeckmannMomentTables r;
      const long double pi = 3.141592653589793238462643383279502884L;
      const long double beta[3] = {pi, pi / 2, 3 * pi / 8};  // B(k + 1/2, 1/2)
      const long double gamma[3] = {std::sqrt(pi), std::sqrt(pi) / 2,
                                    3 * std::sqrt(pi) / 4};  // Gamma(k + 1/2)
      for (int k = 0; k < 3; ++k) {
        long double c = beta[k];
        for (int n = 0; n < kSeriesTerms; ++n) {
          r.series[k][n] = static_cast<double>(c);
          c *= (n + 0.5L) / ((k + 1.0L + n) * (n + 1.0L));
        }
        c = gamma[k];
        for (int n = 0; n < kAsymptoticTerms; ++n) {
          r.asymptotic[k][n] = static_cast<double>(c);
          c *= (k + 0.5L + n) * (n + 0.5L) / (n + 1.0L);
        }
      }
      return r;
    }();
    return t;
  }

  // The highest term of the series at x < 40 (0 <= x).
  static double SeriesTop(double x) { return std::floor(x + 9 * std::sqrt(x) + 12); }
  // The number of asymptotic terms at x >= 40.
  static int AsymptoticCount(double x) {
    return x >= 1e5 ? 4 : x >= 1000 ? 7 : x >= 200 ? 10 : x >= 80 ? 16 : x >= 50 ? 25 : 38;
  }
};

struct BeckmannMoments {
  double m0, m1, m2;
};

// M_0, M_1, M_2 at x >= 0 (the double scalar reference; see the header).
inline BeckmannMoments BeckmannAzimuthMoments(double x) {
  using T = BeckmannMomentTables;
  const T& t = T::Get();
  if (x < T::kAsymptoticFrom) {
    const int top = static_cast<int>(T::SeriesTop(x));
    double s0 = 0, s1 = 0, s2 = 0;
    for (int n = top; n >= 0; --n) {
      s0 = s0 * x + t.series[0][n];
      s1 = s1 * x + t.series[1][n];
      s2 = s2 * x + t.series[2][n];
    }
    const double e = std::exp(-x);
    return {e * s0, e * s1, e * s2};
  }
  const double y = 1 / x, r = std::sqrt(y);
  double s0 = 0, s1 = 0, s2 = 0;
  for (int n = T::AsymptoticCount(x) - 1; n >= 0; --n) {
    s0 = s0 * y + t.asymptotic[0][n];
    s1 = s1 * y + t.asymptotic[1][n];
    s2 = s2 * y + t.asymptotic[2][n];
  }
  return {r * s0, r * y * s1, r * y * y * s2};
}

// The integrand G2 Phi sin(theta_i) / (4 mu_o) of Beckmann's E(mu_o) over
// theta_i (alpha in [1e-4, 1], the header's closed-form Phi).
class BeckmannAzimuthalE : public MomentAzimuthalE {
 public:
  BeckmannAzimuthalE(double alpha, double mu_o, Masking masking)
      : MomentAzimuthalE(alpha, mu_o, masking), ndf_(alpha) {
    lambda_o_ = LambdaAt(mu_o, s_o_);
  }

  double operator()(double theta_i) const {
    const Angles g = AnglesAt(theta_i);
    Terms t;
    if (!TermsAt(g, LambdaAt(g.mu_i, g.s_i), &t)) return 0;
    const double x = t.two_b / (4 * t.a2 * t.cc * t.cc);  // 2B r2_t
    const BeckmannMoments m = BeckmannAzimuthMoments(x);
    const double moments[3] = {m.m0, m.m1, m.m2};
    return Integrand(t, moments, std::exp(-t.r2_0));
  }

 private:
  // Lambda of a direction at cos mu, sin s: +inf on the horizon, 0 along
  // the normal.
  double LambdaAt(double mu, double s) const {
    if (!(mu > 0)) return std::numeric_limits<double>::infinity();
    if (!(s > 0)) return 0.0;
    return ndf_.UnitLambda(mu / (alpha_ * s));
  }

  BeckmannNdf<double> ndf_;
};

// E(mu) of isotropic Beckmann by the adaptive rule over theta_i with the
// integrand at a piece's 15 nodes from `eval(f, theta, out)` (f's
// operator() node by node for the scalar reference; slope_lanes.h's
// lanes).
template <class Eval>
RuleResult BeckmannAzimuthalAlbedoWith(double alpha, double mu, Masking masking, double tol,
                                            int max_pieces, const Eval& eval) {
  const BeckmannAzimuthalE f(alpha, mu, masking);
  return AlbedoOnMesh(AzimuthalMesh(f.theta_o(), f.lambda_o(), alpha), tol, max_pieces,
                      [&](const double* theta, double* out) { eval(f, theta, out); });
}

// The double scalar reference.
inline RuleResult BeckmannAzimuthalAlbedo(double alpha, double mu, Masking masking, double tol,
                                               int max_pieces) {
  return BeckmannAzimuthalAlbedoWith(
      alpha, mu, masking, tol, max_pieces,
      [](const BeckmannAzimuthalE& f, const double* theta, double* out) {
        for (int i = 0; i < 15; ++i) out[i] = f(theta[i]);
      });
}

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_RULES_BECKMANN_BECKMANN_AZIMUTH_H_
