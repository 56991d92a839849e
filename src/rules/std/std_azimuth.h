// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// E(mu) of the isotropic STD (Student's t) BRDF by the one-dimensional rule
// of azimuthal.h with the azimuth of wi from tabulated moments.
//
// In azimuthal_slope.h's variables (w = sin^2(psi / 2), t = 2B w) the STD's
// P22 = (1 + r2 / (gamma - 1))^-gamma / pi ([Ribardiere17] eq. 13) with
// r2 = r2_0 + r2_t t is c0^-gamma (1 + y w)^-gamma / pi, where
// c0 = 1 + r2_0 / (gamma - 1) and y = 2B r2_t / ((gamma - 1) c0), so
//   Phi = 2 c0^-gamma / (pi alpha^2 s^4)
//         (v_min^2 N_0(y) + 2 v_min (2B) N_1(y) + (2B)^2 N_2(y)),
//   N_k(y) = int_0^pi (1 + y w)^-gamma w^k dpsi
//          = 2 int_0^{pi/2} (1 + y sin^2 th)^-gamma sin^2k(th) dth
//          = B(k + 1/2, 1/2) 2F1(gamma, k + 1/2; k + 1; -y),
// the same three positive moments as Beckmann's (beckmann_azimuth.h), of a
// Gauss hypergeometric function instead of Kummer's. 2F1 has no evaluation
// that is uniform in gamma: its large-y connection formula degenerates
// (log terms) wherever gamma - k - 1/2 is an integer, i.e. at every
// half-integer gamma. So for the bake's gamma the three functions of y are
// tabulated once (StdAzimuthMoments):
// - in t = log1p(z), z = gamma y, on [0, 60] (y up to 1e26; the rule's y
//   stays below 1e23: r2_t <= 1 / (4 alpha^2 cos^2 A cos^2 T) with
//   alpha >= 1e-4, mu >= 1e-7), as g_k(t) = N_k(y) (1 + z)^p_k,
//   p_k = min(k + 1/2, gamma) (the decay of N_k for large y, so g_k tends
//   to a constant, with corrections in powers of e^-t and t e^-t: smooth in
//   t). The singularities of N_k are on y <= -1, i.e. at Im t = +-pi
//   and beyond;
// - by Chebyshev interpolation on 30 pieces of width 2, of degree 20 up to
//   gamma 5 (the Bernstein ellipse of a piece reaching Im t = pi has
//   rho = 6.4: 1e-16) and 30 beyond: for large gamma (1 + y w)^-gamma
//   behaves like exp(-z w), which grows without bound where Re z < 0, i.e.
//   Im t > pi / 2, so the ellipse must stay within Im t < pi / 2 (rho = 3.5:
//   degree 30);
// - from values of N_k by Gauss-Legendre 20 on a mesh in th graded
//   geometrically (ratio 4) from the peak's width 1 / sqrt(z) and cut where
//   gamma log1p(y sin^2 th) reaches 1/2, 1, 2, ..., 64 (the integrand's
//   decay, which for large gamma is Gaussian, exp(-z sin^2 th)), ending
//   at 80 (e^-80 of the peak).
// Measured (tests/rules/std_azimuth_test.cc): the table against the direct
// values at random y, and the direct values against 2F1 in 50 digits.
//
// The integrand over theta_i is then the same kind of function as GGX's
// and Beckmann's: AzimuthalMesh's breakpoints (with the STD's horizon
// widening, azimuthal_slope.h) and the adaptive rule apply, with no
// azimuthal error.

#ifndef BRDFBAKE_SRC_RULES_STD_STD_AZIMUTH_H_
#define BRDFBAKE_SRC_RULES_STD_STD_AZIMUTH_H_

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "brdfbake/models/brdf.h"
#include "brdfbake/models/std_ndf.h"
#include "rules/ggx/azimuthal.h"

namespace brdfbake {

// N_0, N_1, N_2 of one gamma, tabulated (see the header).
class StdAzimuthMoments {
 public:
  static constexpr int kPieces = 30;
  static constexpr double kWidth = 2.0;  // of a piece in t (At assumes 2)
  static constexpr double kMaxT = kPieces * kWidth;

  explicit StdAzimuthMoments(double gamma);

  double gamma() const { return gamma_; }
  // SlopeAzimuthalE::horizon_widen of the STD at this gamma.
  double horizon_widen() const { return horizon_widen_; }
  // The Chebyshev degree: 20 up to gamma 5, 30 beyond (see the header).
  int degree() const { return degree_; }
  const double* p() const { return p_; }
  // Chebyshev coefficients: coef()[(piece * (degree() + 1) + j) * 3 + k].
  const double* coef() const { return coef_.data(); }

  // N_0, N_1, N_2 at y >= 0 from the table (the double scalar reference).
  // Clenshaw's recurrence for the three at once, each step as
  // b_j = 2x b_(j+1) + (c_j - b_(j+2)) (one fused multiply-add on the
  // chain). The factor e^(-p_k t) = (1 + z)^-p_k is r (1 + z)^-k,
  // r = 1 / sqrt(1 + z), where p_k = k + 1/2, and exp(-gamma t) otherwise.
  void At(double y, double* n) const {
    const double z = gamma_ * y, t = std::min(std::log1p(z), kMaxT);
    const int piece = std::min(static_cast<int>(t * (1 / kWidth)), kPieces - 1);
    const double x = (t - piece * kWidth) - 1;  // in [-1, 1] (kWidth = 2)
    const double inv = 1 / (1 + z), r = std::sqrt(inv);
    const double half_powers[3] = {r, r * inv, r * inv * inv};
    const double* c = coef_.data() + piece * (degree_ + 1) * 3;
    const double x2 = 2 * x;
    double b1[3] = {0, 0, 0}, b2[3] = {0, 0, 0};
    for (int j = degree_; j >= 1; --j) {
      for (int k = 0; k < 3; ++k) {
        const double b0 = x2 * b1[k] + (c[j * 3 + k] - b2[k]);
        b2[k] = b1[k];
        b1[k] = b0;
      }
    }
    for (int k = 0; k < 3; ++k) {
      const double decay = p_[k] < k + 0.5 ? std::exp(-p_[k] * t) : half_powers[k];
      n[k] = (x * b1[k] + (c[k] - b2[k])) * decay;
    }
  }

  // N_0, N_1, N_2 at y >= 0 by direct quadrature (see the header).
  static void Direct(double gamma, double y, double* n);

 private:
  double gamma_;
  double horizon_widen_;
  int degree_;
  double p_[3];
  std::vector<double> coef_;
};

// The table of `gamma` (> 1.5, finite), built on first use and kept for the
// process (the few gammas a process bakes; each table is 15 KB).
const StdAzimuthMoments& StdAzimuthMomentsFor(double gamma);
// Forgets the tables (for benchmarks that time the whole bake, building
// included).
void ClearStdAzimuthMoments();

// The integrand over theta_i of the STD's E(mu_o) (gamma finite; the header's
// Phi).
class StdAzimuthalE : public MomentAzimuthalE {
 public:
  StdAzimuthalE(const StudentTNdf<double>& ndf, double mu_o, Masking masking)
      : MomentAzimuthalE(ndf.alpha_x(), mu_o, masking),
        ndf_(&ndf),
        moments_(&StdAzimuthMomentsFor(ndf.gamma())) {
    lambda_o_ = LambdaAt(mu_o, s_o_);
    if (ndf.gamma() < 2) {
      normal_scale_ =
          NormalPoleScale([&](double a) { return ndf.UnitLambda(a); }, alpha_, lambda_o_);
    }
  }

  const StdAzimuthMoments& moments() const { return *moments_; }

  // The factor on the theta_i mesh's horizon scale: SlopeAzimuthalE's
  // (kept with the table: a property of gamma).
  double horizon_widen() const { return moments_->horizon_widen(); }

  // The theta_i mesh's grading from the normal (NormalPoleScale; below
  // gamma 2 only, where Lambda(wi) rises more steeply than theta_i^2).
  double normal_scale() const { return normal_scale_; }

  double gamma() const { return ndf_->gamma(); }

  double operator()(double theta_i) const {
    const Angles g = AnglesAt(theta_i);
    Terms t;
    if (!TermsAt(g, LambdaAt(g.mu_i, g.s_i), &t)) return 0;
    const double gamma = ndf_->gamma(), gm1 = gamma - 1;
    const double l0 = std::log1p(t.r2_0 / gm1);  // log c0
    // y = 2B r2_t / ((gamma - 1) c0), r2_t = 1 / (4 alpha^2 cc^2).
    const double y = t.two_b / (4 * t.a2 * t.cc * t.cc * gm1) * std::exp(-l0);
    double n[3];
    moments_->At(y, n);
    return Integrand(t, n, std::exp(-gamma * l0));
  }

 private:
  double LambdaAt(double mu, double s) const {
    if (!(mu > 0)) return std::numeric_limits<double>::infinity();
    if (!(s > 0)) return 0.0;
    return ndf_->UnitLambda(mu / (alpha_ * s));
  }

  const StudentTNdf<double>* ndf_;
  const StdAzimuthMoments* moments_;
  double normal_scale_ = std::numeric_limits<double>::infinity();
};

// E(mu) of the isotropic STD at finite gamma by the adaptive rule over
// theta_i with the integrand at a piece's 15 nodes from `eval(f, theta,
// out)`.
template <class Eval>
RuleResult StdAzimuthalAlbedoWith(const StudentTNdf<double>& ndf, double mu, Masking masking,
                                       double tol, int max_pieces, const Eval& eval) {
  const StdAzimuthalE f(ndf, mu, masking);
  return AlbedoOnMesh(
      AzimuthalMesh(f.theta_o(), f.lambda_o(), f.alpha(), f.horizon_widen(), f.normal_scale()), tol,
      max_pieces, [&](const double* theta, double* out) { eval(f, theta, out); });
}

// The double scalar reference.
inline RuleResult StdAzimuthalAlbedo(const StudentTNdf<double>& ndf, double mu,
                                          Masking masking, double tol, int max_pieces) {
  return StdAzimuthalAlbedoWith(ndf, mu, masking, tol, max_pieces,
                                [](const StdAzimuthalE& f, const double* theta, double* out) {
                                  for (int i = 0; i < 15; ++i) out[i] = f(theta[i]);
                                });
}

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_RULES_STD_STD_AZIMUTH_H_
