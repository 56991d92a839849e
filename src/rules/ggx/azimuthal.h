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

#ifndef BRDFBAKE_SRC_RULES_GGX_AZIMUTHAL_H_
#define BRDFBAKE_SRC_RULES_GGX_AZIMUTHAL_H_

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "brdfbake/models/brdf.h"
#include "quadrature/kronrod.h"

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

// The values at theta_i of the integrands of E and of dfg.bias over
// theta_i, and the error estimates of the numerical azimuthal integrals
// inside them (0 where the azimuth is integrated in closed form).
struct AzimuthalValues {
  double e = 0, bias = 0, e_error = 0, bias_error = 0;
};

// The view wo = (sin theta_o, 0, mu_o) and the half angles
// A = (theta_i + theta_o) / 2, T = (theta_i - theta_o) / 2 of a light at
// theta_i, shared by the one-dimensional rules of every isotropic model.
class AzimuthalFrame {
 public:
  explicit AzimuthalFrame(double mu_o) {
    s_o_ = std::sqrt(std::max(0.0, (1 - mu_o) * (1 + mu_o)));
    theta_o_ = std::atan2(s_o_, mu_o);
    eps_o_ = std::atan2(mu_o, s_o_);
    grazing_o_ = mu_o < s_o_;
    scale_ = 1 / (4 * mu_o);
  }
  double theta_o() const { return theta_o_; }

  // pi/2 in two parts (kHalfPiHi + kHalfPiLo to 1e-32).
  static constexpr double kHalfPiHi = 1.5707963267948966;
  static constexpr double kHalfPiLo = 6.123233995736766e-17;  // pi/2 - kHalfPiHi

  // What AnglesAt reads, for its SIMD twin (lanes/lanes_common-inl.h).
  struct FrameConsts {
    double theta_o, eps_o, s_o, scale;
    bool grazing_o;
  };
  FrameConsts frame_consts() const { return {theta_o_, eps_o_, s_o_, scale_, grazing_o_}; }

 protected:
  // sin and cos of A and T, cos and sin of theta_i.
  struct Angles {
    double sa, ca, st, ct, mu_i, s_i;
  };
  Angles AnglesAt(double theta_i) const {
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
    Angles g;
    SinCosWithComplement(0.5 * (theta_i + theta_o_), 0.5 * (eps_i + eps_o_), &g.sa, &g.ca);
    SinCosWithComplement(theta_i, eps_i, &g.s_i, &g.mu_i);
    g.st = std::sin(ht);
    g.ct = std::cos(ht);
    g.mu_i = std::max(0.0, g.mu_i);
    return g;
  }

  double s_o_ = 0, scale_ = 0.25;  // scale: 1 / (4 mu_o)

 private:
  bool grazing_o_ = false;  // theta_o > pi/4
  double theta_o_ = 0, eps_o_ = 1.5707963267948966;
};

// The integrand G2 Phi sin(theta_i) / (4 mu_o) of E(mu_o) over theta_i.
class GgxAzimuthalE : public AzimuthalFrame {
 public:
  GgxAzimuthalE(double alpha, double mu_o, Masking masking)
      : AzimuthalFrame(mu_o), a2_(alpha * alpha), b_(1 - alpha * alpha),
        separable_(masking == Masking::kSeparable) {
    // Lambda(wo) = alpha^2 s^2 / (2 mu (mu + sqrt(mu^2 + alpha^2 s^2))).
    lambda_o_ = a2_ * s_o_ * s_o_ / (2 * mu_o * (mu_o + std::sqrt(mu_o * mu_o + a2_ * s_o_ * s_o_)));
  }

  double lambda_o() const { return lambda_o_; }

  // What EvalDfg reads besides the frame, for its SIMD twin.
  struct DfgConsts {
    double a2, b, lambda_o;
    bool separable;
  };
  DfgConsts dfg_consts() const { return {a2_, b_, lambda_o_, separable_}; }

  double operator()(double theta_i) const {
    const Angles g = AnglesAt(theta_i);
    return scale_ * G2(g.mu_i, g.s_i) * PhiAt(g).phi * g.s_i;
  }

  // The integrands of E and of dfg.bias at theta_i, and the error estimate
  // of the numerical part of the latter's azimuthal integral ("The
  // Schlick-weighted azimuthal integral" below). `nodes(rem, pieces, n, k,
  // g)` integrates the remainder's integrand over the n pieces
  // (ScalarRemainderNodes below).
  template <class Nodes>
  AzimuthalValues EvalDfg(double theta_i, const Nodes& nodes) const;

 private:
  // X, Y (the header's) and Phi = int D dphi at the angles g.
  struct PhiTerms {
    double x, y, xy, phi;
  };
  PhiTerms PhiAt(const Angles& g) const {
    PhiTerms p;
    p.x = a2_ * g.ct * g.ct + g.st * g.st;
    p.y = a2_ * g.ca * g.ca + g.sa * g.sa;
    p.xy = p.x * p.y;
    const double q = b_ * g.ca * g.ct / std::sqrt(p.xy);
    p.phi = 2 * a2_ * (1 + q * (2 + b_ * (g.ca * g.ca * p.x + g.ct * g.ct * p.y) / (2 * p.xy)));
    return p;
  }

  // G2 of the pair (theta_i, theta_o): Lambda(wi) = a2 s_i^2 / n with
  // n = 2 mu_i (mu_i + sqrt(mu_i^2 + a2 s_i^2)), so G1(wi) = n / (n + a2 s_i^2):
  // 0 on the horizon, no division by zero.
  double G2(double mu_i, double s_i) const {
    const double a2s2 = a2_ * s_i * s_i;
    const double n = 2 * mu_i * (mu_i + std::sqrt(mu_i * mu_i + a2s2));
    return separable_ ? n / ((n + a2s2) * (1 + lambda_o_)) : n / (n * (1 + lambda_o_) + a2s2);
  }

  double a2_, b_;
  bool separable_;
  double lambda_o_ = 0;
};

// The common part of the integrands G2 Phi sin(theta_i) / (4 mu_o) whose
// Phi = int D dphi comes from three moments of the azimuth
// (beckmann_azimuth.h in closed form, std_azimuth.h tabulated):
//   Phi = norm c(r2_0) ((v_min M_0 + 2 (2B) M_1) v_min + (2B)^2 M_2),
// norm = 2 / (pi alpha^2 s^4), s / 2 = cc = cos A cos T, 2B = 4 sin(theta_i)
// sin(theta_o), v_min = 4 cos^2 A, r2_0 = tan^2 T / alpha^2, with the
// model's M_k and c(r2_0) (exp(-r2_0) for Beckmann).
class MomentAzimuthalE : public AzimuthalFrame {
 public:
  double lambda_o() const { return lambda_o_; }
  double alpha() const { return alpha_; }

  // What the common part reads besides the frame, for its SIMD twin.
  struct Consts {
    double alpha, lambda_o;
    bool separable;
  };
  Consts consts() const { return {alpha_, lambda_o_, separable_}; }

 protected:
  MomentAzimuthalE(double alpha, double mu_o, Masking masking)
      : AzimuthalFrame(mu_o), alpha_(alpha), separable_(masking == Masking::kSeparable) {}

  // The factors above at the angles g, with Lambda(wi) = lambda_i, and the
  // weight w = G2 sin(theta_i) / (4 mu_o); false where the node adds
  // nothing (w = 0, or cos A <= 0).
  struct Terms {
    double w, a2, cc, two_b, v_min, r2_0;
  };
  bool TermsAt(const Angles& g, double lambda_i, Terms* t) const {
    const double g2 =
        separable_ ? 1 / ((1 + lambda_i) * (1 + lambda_o_)) : 1 / (1 + lambda_i + lambda_o_);
    t->w = scale_ * g2 * g.s_i;
    if (!(t->w > 0) || !(g.ca > 0)) return false;
    t->a2 = alpha_ * alpha_;
    t->cc = g.ca * g.ct;  // s / 2
    t->two_b = 4 * g.s_i * s_o_;
    t->v_min = 4 * g.ca * g.ca;
    t->r2_0 = g.st * g.st / (t->a2 * g.ct * g.ct);
    return true;
  }
  // The integrand from the terms, the moments m and c = c(r2_0).
  static double Integrand(const Terms& t, const double* m, double c) {
    const double sum = (t.v_min * m[0] + 2 * t.two_b * m[1]) * t.v_min + t.two_b * t.two_b * m[2];
    // 2 / (pi alpha^2 s^4), s^4 = 16 (cos A cos T)^4.
    const double norm = 2 / (3.141592653589793 * t.a2 * 16 * (t.cc * t.cc) * (t.cc * t.cc));
    return t.w * (norm * c * sum);
  }

  double alpha_;
  bool separable_;
  double lambda_o_ = 0;
};

// E(mu) of isotropic GGX (alpha in [1e-4, 1], mu in (0, 1]) to within `tol`
// (sum of the per-piece |K15 - G7|), with at most `max_pieces` pieces.
RuleResult GgxAzimuthalAlbedo(double alpha, double mu, Masking masking, double tol,
                                   int max_pieces);

// The breakpoints of the theta_i rule (see the header): the specular peak
// at theta_o graded from 2 alpha, the horizon from alpha / (2 (1 + Lambda(wo)))
// times `horizon_widen` (>= 1; azimuthal_slope.h), and where G2 has a pole
// at theta_i = -`normal_scale` (NormalPoleScale), pieces graded from the
// normal: each piece [a, b] ends at b <= 3 a + 2 normal_scale (0, 2 s, 8 s,
// 26 s, ... where the other breakpoints leave wider gaps), so the pole lies
// at least half a piece's width beyond it.
std::vector<double> AzimuthalMesh(double theta_o, double lambda_o, double alpha,
                                  double horizon_widen = 1,
                                  double normal_scale = std::numeric_limits<double>::infinity());

// AzimuthalMesh's horizon_widen for a slope distribution whose unit
// Lambda(a) -> c / a near the horizon (a -> 0): max(1, 2 c), c taken as
// 1e-9 Lambda(1e-9). Near the horizon G2's pole lies at pi/2 - theta_i ~
// -alpha c / (1 + Lambda(wo)) and the mesh's scale assumes GGX's c = 1/2.
// The STD's c grows without bound as gamma -> 1.5 (2.52 at 1.55, 112.8 at
// 1.501), where that scale would start the grading up to 225 times too
// fine. (Below 1/2, gamma > 2 and Beckmann's 0.282, the mesh keeps GGX's
// finer start.)
template <class UnitLambda>
double HorizonWiden(const UnitLambda& unit_lambda) {
  return std::max(1.0, 2 * 1e-9 * unit_lambda(1e-9));
}

// AzimuthalMesh's normal_scale for a slope distribution whose Lambda(a)
// decays more slowly than a^-2 for large a (the STD below gamma 2:
// Lambda ~ a^-(2 gamma - 2), its marginal slope density falling like
// q^(1 - 2 gamma)). Lambda(wi) then rises from the normal like
// theta_i^(2 gamma - 2), not theta_i^2 (GGX, Beckmann: G2 is flat there),
// and as gamma -> 1.5 steeply: Lambda(wi) ~ k alpha theta_i with k ~
// 1 / (2 gamma - 3) (1.1e5 at gamma 1.500001). G2 = 1 / (1 + Lambda(wo) +
// Lambda(wi)) halves within theta_i = s, where Lambda(wi) = 1 + Lambda(wo),
// and has its pole at theta_i ~ -s: at mu_o = 1 (Lambda(wo) = 0) and
// gamma 1.500001, s = 9e-6 / alpha. A Kronrod piece from 0 much wider than
// s misses that layer in G7 and K15 alike: at roughness 1, without this
// grading, the mesh is one piece over [0, pi/2], whose |K15 - G7| of
// 7.3e-11 is 2.75 times below its true error 2.0e-10. Returns s, where Lambda(cot(s) / alpha) =
// 1 + lambda_o (bisection on log theta_i, to 0.3%), or +inf where
// Lambda(wi) stays below that up to theta_i = 1 rad (no layer narrower
// than the mesh's pieces).
template <class UnitLambda>
double NormalPoleScale(const UnitLambda& unit_lambda, double alpha, double lambda_o) {
  const double target = 1 + lambda_o;
  const auto rises_past = [&](double log_theta) {
    return unit_lambda(1 / (alpha * std::tan(std::exp(log_theta)))) > target;
  };
  double lo = -46, hi = 0;  // log theta_i: 1e-20 to 1 rad
  if (!rises_past(hi)) return std::numeric_limits<double>::infinity();
  if (rises_past(lo)) return std::exp(lo);
  for (int i = 0; i < 14; ++i) {
    const double mid = 0.5 * (lo + hi);
    (rises_past(mid) ? hi : lo) = mid;
  }
  return std::exp(hi);
}

// The Schlick-weighted azimuthal integral. With v = |wi + wo|^2 = 2 + 2 wi.wo
// and u = v + k (azimuthal.h: D = (alpha^2 / pi) v^2 / u^2, k = (alpha^2 - 1)
// s^2 = -kappa), wo.h = sqrt(v) / 2, so over the azimuth both D and
// Fc = (1 - wo.h)^5 are functions of v = kappa + u alone, and
//   Psi = int_0^{2 pi} D Fc dphi = (alpha^2 / pi) int g(v) / u^2 dphi,
//   g(v) = v^2 (1 - sqrt(v) / 2)^5 = q(v) - p(v),
// q (the even powers of wo.h) = v^2 + (5/2) v^3 + (5/16) v^4, a polynomial,
// p (the odd powers) = v^(5/2) (5/2 + (5/4) v + v^2 / 32).
// u = C + B cos(phi) (B = 2 sin(theta_i) sin(theta_o)) has the moments
//   I_-2 = 2 pi C / R^3, I_-1 = 2 pi / R, I_0 = 2 pi, I_1 = 2 pi C,
//   I_2 = 2 pi (C^2 + B^2 / 2),  R^2 = C^2 - B^2,
// with C - B = 4 cos^2 A X and C + B = 4 cos^2 T Y as for Phi, so
//   Psi (pi / alpha^2) = g(kappa) I_-2 + g'(kappa) I_-1 + c2 I_0 + c3 I_1 + c4 I_2 - Rem,
// where c2 = 1 + (15/2) kappa + (15/8) kappa^2, c3 = 5/2 + (5/4) kappa and
// c4 = 5/16 are the Taylor coefficients of q at kappa (q is exact in them),
// g(kappa) and g'(kappa) are formed directly (no cancellation of q and p near
// wo.h = 1), and Rem = int (p(v) - p(kappa) - p'(kappa) u) / u^2 dphi is
// the odd part with its Taylor terms at the pole u = 0 taken out. Its
// integrand, the second divided difference p[kappa, kappa, v], is formed
// without cancellation: with a = sqrt(kappa), b = sqrt(v) and
// v - kappa = (b - a)(b + a), for each odd power b^n
//   (b^n - a^n - (n/2) a^(n-2) (v - kappa)) / (v - kappa)^2 = S_n(a, b) / (a + b)^2,
//   S_n = sum_{k=0}^{n-3} (k + 1) a^k b^(n-2-k) + (n/2 - 1) a^(n-2),
// all terms positive (synthetic division of the numerator by (b - a)^2), so
// the integrand is T(b) / (a + b)^2 with T = (5/2) S_5 + (5/4) S_7 + S_9 / 32,
// a polynomial in b whose coefficients are set once per theta_i. It is smooth
// in phi (the double pole of D near the specular azimuth is gone) except for
// the branch point of b = sqrt(v) at v = 0, which lies at a distance ~2 cos A
// from the specular azimuth (v >= 4 cos^2 A; both directions grazing). Rem is
// integrated over psi = pi - phi in [0, pi] (twice, by symmetry) with
// v = 4 cos^2 A + 2 B sin^2(psi/2), by Gauss-Kronrod 15 on pieces graded
// geometrically (ratio 3) from psi = 2 cos A; its error estimate is the sum
// of |K15 - G7|.

// T(b) = (5/2) S_5 + (5/4) S_7 + S_9 / 32 (coefficients t[m] of b^m) for
// a = sqrt(kappa), and the remainder's integrand T(b) / (a + b)^2 at psi,
// b = sqrt(vmin + two_b sin^2(psi / 2)).
struct OddRemainder {
  double a, vmin, two_b;
  double t[8];
  OddRemainder(double a_, double vmin_, double two_b_) : a(a_), vmin(vmin_), two_b(two_b_) {
    const double a2 = a * a, a3 = a2 * a, a4 = a2 * a2, a5 = a4 * a, a6 = a3 * a3, a7 = a6 * a;
    t[7] = 1.0 / 32;
    t[6] = 2 * a / 32;
    t[5] = 1.25 + 3 * a2 / 32;
    t[4] = 2.5 * a + 4 * a3 / 32;
    t[3] = 2.5 + 3.75 * a2 + 5 * a4 / 32;
    t[2] = 5 * a + 5 * a3 + 6 * a5 / 32;
    t[1] = 7.5 * a2 + 6.25 * a4 + 7 * a6 / 32;
    t[0] = 3.75 * a3 + 3.125 * a5 + 3.5 * a7 / 32;
  }
  // At s2 = sin^2(psi / 2).
  double At(double s2) const {
    const double b = std::sqrt(vmin + two_b * s2);
    double acc = t[7];
    for (int m = 6; m >= 0; --m) acc = acc * b + t[m];
    const double ab = a + b;
    return acc / (ab * ab);
  }
};

// The pieces of a rule over psi in [0, pi] (an azimuth measured from the
// specular plane) graded geometrically towards psi = 0, from one fixed
// ladder so that sin^2(psi / 2) at their Kronrod nodes is tabulated once:
// [0, d_J], [d_J, d_(J-1)], ..., [d_1, d_0], [pi/2, pi] with
// d_j = (pi / 2) ratio^-j and J the first j >= 0 with d_j <= `start`, so
// the innermost piece is within a factor `ratio` of the scale of the
// feature at psi = 0. (With [0, pi] as one piece where the integrand is
// smooth, G7 is only good to ~1e-9 and |K15 - G7| would stop the theta_i
// rule short of tolerances below that; halves bring it to ~1e-13.)
// Ratio 3 serves GGX's remainder (algebraic near psi = 0). For a lobe at
// psi = 0 of half width s the worst |G7 - I| of the pieces [0, d], [d, r d],
// ..., [r^3 d, r^4 d] (ratio r), relative to the whole integral, over s / d
// = 1, 1.25, 1.5, 2, 2.5, 3 (up to r; mpmath 1.3, 30 digits): for the
// Gaussian (Beckmann) 1.2e-9 at ratio 2, 5.4e-8 at 2.5, 3.5e-7 at 3 (K15:
// 2e-17, 1.2e-14, 6e-13); for the STD's lobe (1 + (psi/s)^2 / (gamma -
// 1))^-gamma at ratio 3 4.1e-8 (gamma 1.501), 2.3e-8 (2), 4.9e-8 (4); at
// ratio 2.5 4.2e-9 (4.5), 4.7e-9 (6), 2.9e-8 (30); at ratio 2 7e-11
// (4), 1.2e-10 (6). That floor bounds the |K15 - G7| claims from below, so
// the wider ladders serve only tolerances above it (azimuthal_slope.h).
struct AzimuthLadder {
  struct Piece {
    double half_width;
    double s2[16];  // sin^2(psi / 2) at the nodes; the 16th pads (weight 0)
    double s2_start;  // sin^2(psi / 2) at the piece's start
  };
  int levels = 0;
  Piece outer;              // [pi/2, pi]
  std::vector<Piece> ring;  // ring[j], j >= 1: [d_j, d_(j-1)]
  std::vector<Piece> core;  // core[j]: [0, d_j]
  // The Kronrod and Gauss weights of the 15 nodes and a 16th of weight 0,
  // which pads each piece to whole vectors of 2, 4, 8 or 16.
  double wk[16], wg[16];

  static constexpr int kMaxPieces = 66;
  // Ratio 3 (40 levels, d_40 = 1.3e-19), 2.5 (48 levels, d_48 = 1.2e-19)
  // or 2 (62 levels, d_62 = 3.4e-19).
  static const AzimuthLadder& Get(double ratio);
  // d_j for j = 0..levels, by repeated division (Select's thresholds).
  std::vector<double> d;
  // The pieces for a feature of scale `start` at psi = 0; returns their count.
  int Select(double start, const Piece** used) const {
    int level = 0;
    while (level < levels && d[level] > start) ++level;
    int n = 0;
    used[n++] = &core[level];
    for (int j = level; j >= 1; --j) used[n++] = &ring[j];
    used[n++] = &outer;
    return n;
  }
};

// The remainder's pieces node by node: the double scalar reference.
// k[p] and g[p] are the Kronrod and Gauss sums of piece p (weights times
// integrand, without the half width).
struct ScalarRemainderNodes {
  void operator()(const OddRemainder& rem, const AzimuthLadder::Piece* const* pieces, int n,
                  double* k, double* g) const {
    const AzimuthLadder& rule = AzimuthLadder::Get(3);
    for (int p = 0; p < n; ++p) {
      double ks = 0, gs = 0;
      for (int i = 0; i < 15; ++i) {
        const double v = rem.At(pieces[p]->s2[i]);
        ks += rule.wk[i] * v;
        gs += rule.wg[i] * v;
      }
      k[p] = ks;
      g[p] = gs;
    }
  }
};

template <class Nodes>
AzimuthalValues GgxAzimuthalE::EvalDfg(double theta_i, const Nodes& nodes) const {
  const Angles g = AnglesAt(theta_i);
  const PhiTerms pt = PhiAt(g);
  const double w = scale_ * G2(g.mu_i, g.s_i) * g.s_i;
  AzimuthalValues out;
  out.e = w * pt.phi;
  const double r = 4 * g.ca * g.ct * std::sqrt(pt.xy);
  if (!(r > 0) || !(w > 0)) return out;
  const double cmb = 4 * g.ca * g.ca * pt.x, cpb = 4 * g.ct * g.ct * pt.y;
  const double c = 0.5 * (cmb + cpb);
  const double bb = 2 * g.s_i * s_o_;
  const double i_m2 = kTwoPi<double> * c / (r * r * r), i_m1 = kTwoPi<double> / r;
  const double i_1 = kTwoPi<double> * c, i_2 = kTwoPi<double> * (c * c + 0.5 * bb * bb);
  // kappa = (1 - alpha^2) s^2 with s = mu_i + mu_o = 2 cos A cos T.
  const double kappa = b_ * 4 * g.ca * g.ca * g.ct * g.ct;
  const double sk = std::sqrt(kappa);
  const double f = 1 - 0.5 * sk, f2 = f * f, f4 = f2 * f2;
  const double g_k = kappa * kappa * f4 * f;
  const double gp_k = kappa * f4 * (2 * f - 1.25 * sk);
  const double c2 = 1 + kappa * (7.5 + kappa * 1.875), c3 = 2.5 + 1.25 * kappa;
  const double closed = g_k * i_m2 + gp_k * i_m1 + c2 * kTwoPi<double> + c3 * i_1 + 0.3125 * i_2;
  // Rem over psi in [0, pi], on pieces graded from 2 cos A (ratio 3): the
  // nodes of every piece, evaluated together, then each piece's K15 and G7.
  const OddRemainder rem(sk, 4 * g.ca * g.ca, 2 * bb);
  const AzimuthLadder::Piece* used[AzimuthLadder::kMaxPieces];
  const int pieces = AzimuthLadder::Get(3).Select(2 * g.ca, used);
  double k[AzimuthLadder::kMaxPieces], gs[AzimuthLadder::kMaxPieces];
  nodes(rem, used, pieces, k, gs);
  double rem_k = 0, rem_err = 0;
  for (int p = 0; p < pieces; ++p) {
    rem_k += k[p] * used[p]->half_width;
    rem_err += std::abs(k[p] - gs[p]) * used[p]->half_width;
  }
  const double norm = a2_ / 3.141592653589793;
  out.bias = w * norm * (closed - 2 * rem_k);
  out.bias_error = w * norm * 2 * rem_err;
  return out;
}

// E, dfg.bias and dfg.scale = E - bias of isotropic GGX by the same rule
// over theta_i (one mesh for all three), each with its error estimate: the
// sum of the per-piece |K15 - G7| of its integrand, plus (bias, scale) the
// error estimates of the numerical part of the azimuthal integral carried
// through the Kronrod weights. Pieces are bisected until all three are
// within `tol`.
struct AzimuthalDfgResult {
  double e = 0, bias = 0, err_e = 0, err_bias = 0, err_scale = 0;
  int pieces = 0;
};
// The adaptive rule over theta_i for E, bias and scale = E - bias:
// Gauss-Kronrod 15 on the pieces of `mesh`, the worst piece bisected until
// the claims of all three meet `tol` (or `max_pieces`). `eval(theta, out)`
// gives the AzimuthalValues at a piece's 15 nodes; their azimuthal error
// estimates are carried through the Kronrod weights into the claims.
template <class Eval>
AzimuthalDfgResult AdaptiveAzimuthalRule(const std::vector<double>& mesh, const Eval& eval,
                                         double tol, int max_pieces) {
  struct Piece {
    double a, b, e, bias, err_e, err_bias, err_scale, az_e, az_bias;
    double Worst() const {
      return std::max(err_e + az_e, std::max(err_bias, err_scale) + az_bias + az_e);
    }
  };
  const KronrodRule& r = Kronrod15();
  auto kronrod = [&](double a, double b) {
    const double c = 0.5 * (a + b), h = 0.5 * (b - a);
    double theta[15];
    AzimuthalValues values[15];
    for (int i = 0; i < 15; ++i) theta[i] = c + h * r.x[i];
    eval(theta, values);
    double ke = 0, ge = 0, kb = 0, gb = 0, aze = 0, azb = 0;
    for (int i = 0; i < 15; ++i) {
      const AzimuthalValues& v = values[i];
      ke += r.wk[i] * v.e;
      ge += r.wg[i] * v.e;
      kb += r.wk[i] * v.bias;
      gb += r.wg[i] * v.bias;
      aze += r.wk[i] * v.e_error;
      azb += r.wk[i] * v.bias_error;
    }
    return Piece{a,  b,  ke * h, kb * h, std::abs(ke - ge) * h, std::abs(kb - gb) * h,
                 std::abs((ke - kb) - (ge - gb)) * h, aze * h, azb * h};
  };
  std::vector<Piece> pieces;
  pieces.reserve(mesh.size() + 64);
  for (size_t i = 0; i + 1 < mesh.size(); ++i) pieces.push_back(kronrod(mesh[i], mesh[i + 1]));
  double err_e = 0, err_b = 0, err_s = 0;
  auto totals = [&] {
    err_e = err_b = err_s = 0;
    for (const Piece& p : pieces) {
      err_e += p.err_e + p.az_e;
      err_b += p.err_bias + p.az_bias;
      err_s += p.err_scale + p.az_bias + p.az_e;
    }
  };
  totals();
  while (std::max(err_e, std::max(err_b, err_s)) > tol &&
         static_cast<int>(pieces.size()) < max_pieces) {
    size_t worst = 0;
    for (size_t i = 1; i < pieces.size(); ++i) {
      if (pieces[i].Worst() > pieces[worst].Worst()) worst = i;
    }
    const Piece p = pieces[worst];
    const double m = 0.5 * (p.a + p.b);
    if (!(m > p.a && m < p.b)) break;  // down to adjacent doubles
    pieces[worst] = kronrod(p.a, m);
    pieces.push_back(kronrod(m, p.b));
    totals();
  }
  AzimuthalDfgResult out;
  for (const Piece& p : pieces) {
    out.e += p.e;
    out.bias += p.bias;
  }
  // Plus the rounding of the sums (a few ulps of the values).
  out.err_e = err_e + 4e-16 * std::abs(out.e);
  out.err_bias = err_b + 4e-16 * std::abs(out.bias);
  out.err_scale = err_s + 4e-16 * std::abs(out.e);
  out.pieces = static_cast<int>(pieces.size());
  return out;
}

// The albedo rule of the models whose azimuth is integrated in closed form
// (no azimuthal error): AdaptiveAzimuthalRule with E alone (its bias and
// scale claims then equal E's) on `mesh`, with the integrand at a piece's
// 15 nodes from `eval(theta, out)`.
template <class Eval>
RuleResult AlbedoOnMesh(const std::vector<double>& mesh, double tol, int max_pieces,
                             const Eval& eval) {
  const AzimuthalDfgResult r = AdaptiveAzimuthalRule(
      mesh,
      [&](const double* theta, AzimuthalValues* out) {
        double v[15];
        eval(theta, v);
        for (int i = 0; i < 15; ++i) {
          out[i] = AzimuthalValues();
          out[i].e = v[i];
        }
      },
      tol, max_pieces);
  RuleResult out;
  out.value = r.e;
  out.error = r.err_e;
  out.pieces = r.pieces;
  return out;
}

// GgxAzimuthalAlbedo's rule, with the integrand at a piece's 15 nodes from
// `eval(f, theta, out)` (f's operator() node by node for the scalar
// reference; ggx_lanes.h's lanes).
template <class Eval>
RuleResult GgxAzimuthalAlbedoWith(double alpha, double mu, Masking masking, double tol,
                                       int max_pieces, const Eval& eval) {
  const GgxAzimuthalE f(alpha, mu, masking);
  return AlbedoOnMesh(AzimuthalMesh(f.theta_o(), f.lambda_o(), alpha), tol, max_pieces,
                      [&](const double* theta, double* out) { eval(f, theta, out); });
}

template <class Nodes>
AzimuthalDfgResult GgxAzimuthalDfgWith(double alpha, double mu, Masking masking, double tol,
                                       int max_pieces, const Nodes& nodes) {
  const GgxAzimuthalE f(alpha, mu, masking);
  return AdaptiveAzimuthalRule(
      AzimuthalMesh(f.theta_o(), f.lambda_o(), alpha),
      [&](const double* theta, AzimuthalValues* out) {
        for (int i = 0; i < 15; ++i) out[i] = f.EvalDfg(theta[i], nodes);
      },
      tol, max_pieces);
}

// The double scalar reference.
inline AzimuthalDfgResult GgxAzimuthalDfg(double alpha, double mu, Masking masking, double tol,
                                          int max_pieces) {
  return GgxAzimuthalDfgWith(alpha, mu, masking, tol, max_pieces, ScalarRemainderNodes());
}

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_RULES_GGX_AZIMUTHAL_H_
