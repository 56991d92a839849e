// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The albedo E(mu) of the isotropic GGX BRDF as a one-dimensional integral:
// the azimuth of wi is integrated in closed form, the polar angle by an
// adaptive Gauss-Kronrod rule on a mesh graded towards the specular peak
// and the horizon.
//
// With wo = (s_o, 0, mu_o), wi = (s_i cos phi, s_i sin phi, mu_i) and F = 1,
// f cos_i = D(h) G2 / (4 mu_o), and for an isotropic model G2 depends on
// theta_i and theta_o only (wi.h = wo.h > 0 for every reflection), so
//   E(mu_o) = 1 / (4 mu_o) int_0^{pi/2} G2(theta_i) Phi(theta_i) sin(theta_i) dtheta_i,
//   Phi = int_0^{2 pi} D(h(phi)) dphi.
// Derivation of Phi for GGX, D = alpha^2 / (pi (1 + (alpha^2 - 1) h.z^2)^2):
// with 2x = |wi + wo|^2 = 2 + 2 wi.wo and h.z^2 = s^2 / (2x), s = mu_i + mu_o,
// D = (alpha^2 / pi) (u - k)^2 / u^2 where k = (alpha^2 - 1) s^2 and
// u = 2x + k = C + B cos(phi) with B = 2 s_i s_o. The two integrals
//   int dphi / u = 2 pi / R,  int dphi / u^2 = 2 pi C / R^3,  R^2 = C^2 - B^2,
// give Phi = 2 alpha^2 (1 - 2k / R + k^2 C / R^3). In the half angles
// A = (theta_i + theta_o) / 2 and T = (theta_i - theta_o) / 2 the factors are
// free of cancellation:
//   C - B = 4 cos^2 A X,  X = alpha^2 cos^2 T + sin^2 T,
//   C + B = 4 cos^2 T Y,  Y = alpha^2 cos^2 A + sin^2 A,
// and with b = 1 - alpha^2 >= 0 and q = b cos A cos T / sqrt(X Y) (>= 0),
//   Phi = 2 alpha^2 (1 + q (2 + b (cos^2 A X + cos^2 T Y) / (2 X Y))),
// a sum of non-negative terms for alpha <= 1. (Checked against direct
// numerical integration over phi to 1e-17; at alpha = 1, mu_o = 1 it gives
// E = 1 - ln 2.)
//
// The integrand is analytic on (0, pi/2) with its singularities off the real
// axis: branch points of sqrt(X) at theta_i = theta_o +- 2i atanh(alpha)
// (the specular peak, width ~2 alpha), of sqrt(Y) at -theta_o +- 2i
// atanh(alpha), and near the horizon the branch points of Lambda(wi) at
// pi/2 - theta_i = +-i alpha and a pole of G2 at pi/2 - theta_i ~
// -alpha / (2 (1 + Lambda(wo))) (~ -mu_o at grazing: the boundary layer of
// E). The mesh is graded geometrically (ratio 3) from these scales, so the
// nearest singularity of every piece lies at least half the piece's width
// beyond its ends (Bernstein ellipse parameter >= 2 + sqrt 3): the 7-point
// Gauss rule embedded in the 15-point Kronrod rule is then accurate to
// ~1e-8 of the piece's mass and the Kronrod rule to ~1e-13. Pieces are
// bisected, worst first, until the sum of |K15 - G7| over the pieces is
// within the tolerance; that sum is the claimed error of the K15 value.
// (Ratio 2 costs 30% more evaluations for nothing; ratio 4 leaves G7 at
// ~1e-6 and the refinement then costs more than it saves.)

#ifndef BRDFBAKE_SRC_AZIMUTHAL_H_
#define BRDFBAKE_SRC_AZIMUTHAL_H_

#include <algorithm>
#include <cmath>
#include <vector>

#include "brdfbake/brdf.h"

namespace brdfbake {

// sin and cos of t in [0, pi/2] given with its complement c = pi/2 - t,
// both from the smaller of the two, so each keeps its relative accuracy.
inline void SinCosWithComplement(double t, double c, double* sin_t, double* cos_t) {
  if (t <= c) {
    *sin_t = std::sin(t);
    *cos_t = std::cos(t);
  } else {
    *sin_t = std::cos(c);
    *cos_t = std::sin(c);
  }
}

// The integrand G2 Phi sin(theta_i) / (4 mu_o) of E(mu_o) over theta_i.
class GgxAzimuthalE {
 public:
  GgxAzimuthalE(double alpha, double mu_o, Masking masking)
      : a2_(alpha * alpha), b_(1 - alpha * alpha), separable_(masking == Masking::kSeparable) {
    const double s_o = std::sqrt(std::max(0.0, (1 - mu_o) * (1 + mu_o)));
    theta_o_ = std::atan2(s_o, mu_o);
    eps_o_ = std::atan2(mu_o, s_o);
    grazing_o_ = mu_o < s_o;
    // Lambda(wo) = alpha^2 s^2 / (2 mu (mu + sqrt(mu^2 + alpha^2 s^2))).
    lambda_o_ = a2_ * s_o * s_o / (2 * mu_o * (mu_o + std::sqrt(mu_o * mu_o + a2_ * s_o * s_o)));
    scale_ = 1 / (4 * mu_o);
  }

  double theta_o() const { return theta_o_; }
  double lambda_o() const { return lambda_o_; }

  double operator()(double theta_i) const {
    // Near the horizon (theta_i, theta_o -> pi/2) cos(theta_i) and cos(A)
    // are small: they are taken from the complements eps = pi/2 - theta,
    // which carry their full relative accuracy there (eps_o from atan2, and
    // eps_i from theta_i with pi/2 in two parts), and sin(A) from theta;
    // each factor is then accurate to a few ulps in its own regime (a
    // difference of 1e-9 relative near grazing otherwise).
    const double eps_i = (kHalfPiHi - theta_i) + kHalfPiLo;
    // T = (theta_i - theta_o) / 2 sets the peak's width (X ~ alpha^2 + T^2),
    // so it is formed from the operands that are exact on its side:
    // theta_o rounded near pi/2 would shift it by 1e-16 absolute.
    const double ht = grazing_o_ ? 0.5 * (eps_o_ - eps_i) : 0.5 * (theta_i - theta_o_);
    double sa, ca, st, ct, mu_i, s_i;
    SinCosWithComplement(0.5 * (theta_i + theta_o_), 0.5 * (eps_i + eps_o_), &sa, &ca);
    SinCosWithComplement(theta_i, eps_i, &s_i, &mu_i);
    st = std::sin(ht);
    ct = std::cos(ht);
    mu_i = std::max(0.0, mu_i);
    const double x = a2_ * ct * ct + st * st;
    const double y = a2_ * ca * ca + sa * sa;
    const double xy = x * y;
    const double q = b_ * ca * ct / std::sqrt(xy);
    const double phi = 2 * a2_ * (1 + q * (2 + b_ * (ca * ca * x + ct * ct * y) / (2 * xy)));
    // Lambda(wi) = a2 s_i^2 / n with n = 2 mu_i (mu_i + sqrt(mu_i^2 + a2 s_i^2)),
    // so G1(wi) = n / (n + a2 s_i^2): 0 on the horizon, no division by zero.
    const double a2s2 = a2_ * s_i * s_i;
    const double n = 2 * mu_i * (mu_i + std::sqrt(mu_i * mu_i + a2s2));
    const double g2 = separable_ ? n / ((n + a2s2) * (1 + lambda_o_))
                                 : n / (n * (1 + lambda_o_) + a2s2);
    return scale_ * g2 * phi * s_i;
  }

 private:
  double a2_, b_;
  bool separable_;
  bool grazing_o_ = false;  // theta_o > pi/4
  static constexpr double kHalfPiHi = 1.5707963267948966;
  static constexpr double kHalfPiLo = 6.123233995736766e-17;  // pi/2 - kHalfPiHi
  double theta_o_ = 0, eps_o_ = 1.5707963267948966, lambda_o_ = 0, scale_ = 0.25;
};

// The 15-point Kronrod rule on [-1, 1] with its embedded 7-point Gauss rule
// (Gauss weight 0 at the Kronrod-only nodes).
struct KronrodRule {
  double x[15], wk[15], wg[15];
};
const KronrodRule& Kronrod15();

struct AzimuthalResult {
  double value = 0, error = 0;
  int pieces = 0;
};

// E(mu) of isotropic GGX (alpha in [1e-4, 1], mu in (0, 1]) to within `tol`
// (sum of the per-piece |K15 - G7|), with at most `max_pieces` pieces.
AzimuthalResult GgxAzimuthalAlbedo(double alpha, double mu, Masking masking, double tol,
                                   int max_pieces);

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_AZIMUTHAL_H_
