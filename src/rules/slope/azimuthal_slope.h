// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// E(mu) and the split-sum DFG terms of the isotropic Beckmann and STD
// BRDFs by the one-dimensional rule of azimuthal.h, with the azimuthal
// integral of D (and of D Fc) taken numerically.
//
// For a slope-space model D(h) = P22(r2) / (alpha^2 h.z^4) with
// r2 = tan^2(theta_h) / alpha^2 (slope_ndf.h). Over the azimuth of wi,
// with v = |wi + wo|^2 = 4 cos^2 A + t, t = 2 B sin^2(psi / 2),
// B = 2 sin(theta_i) sin(theta_o) and psi = pi - phi the azimuth from the
// specular plane, h.z^2 = s^2 / v with s = mu_i + mu_o = 2 cos A cos T and
//   tan^2(theta_h) = (v - s^2) / s^2 = (4 cos^2 A sin^2 T + t) / s^2,
// so (no cancellation anywhere)
//   r2 = sin^2 T / (alpha^2 cos^2 T) + t / (4 alpha^2 cos^2 A cos^2 T),
//   D = P22(r2) v^2 / (alpha^2 s^4),   wo.h = sqrt(v) / 2.
// Phi = int_0^{2 pi} D dphi = 2 int_0^pi D dpsi (and the same with
// Fc = (1 - wo.h)^5) by Gauss-Kronrod 15 on the ladder of azimuthal.h
// (AzimuthLadder), graded from the lobe's half width in psi,
// alpha cos A cos T sqrt(8 / B) (where r2 has grown by 1), and for Fc also
// from the branch point of wo.h at distance 2 cos A. Both integrands are
// positive and smooth on each piece: the lobe is Gaussian (Beckmann) or a
// power of a quadratic in sin(psi / 2) (STD), and the ladder's pieces
// resolve it at every scale. The ladder's ratio sets a floor under the
// pieces' |K15 - G7| (azimuthal.h: up to 5.4e-8 of the integral at the
// wider ratios, 1.2e-9 at 2), so from tolerance 1e-7 up (the default; 2e-7
// for dfg, whose scale claim carries the floors of both integrals) the
// rule takes ratio 3 for the STD up to gamma 4 (its heavier, algebraic
// tails, as GGX's in azimuthal.h) and 2.5 for the Gaussian and the STD
// beyond gamma 4, and ratio 2 below. Against ratio 2 at tolerance
// 1e-7 over the 32x32 E table: the same theta_i pieces within 1%, and
// 22-24% less time from gamma 1.501 to 4 (ratio 3; at gamma 6 ratio 3
// begins to cost theta_i bisections, at 10 five times the pieces), 13-16%
// from gamma 4.5 to inf (ratio 2.5). The error estimate is the sum of the
// pieces' |K15 - G7|. G2 depends on theta_i alone (isotropic Lambda), so
// Lambda(wi) is evaluated once per theta_i node, 15 at a time.

#ifndef BRDFBAKE_SRC_RULES_SLOPE_AZIMUTHAL_SLOPE_H_
#define BRDFBAKE_SRC_RULES_SLOPE_AZIMUTHAL_SLOPE_H_

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

#include "brdfbake/models/beckmann.h"
#include "brdfbake/models/brdf.h"
#include "brdfbake/models/std_ndf.h"
#include "rules/ggx/azimuthal.h"

namespace brdfbake {

// From this r2 on Beckmann's P22 = exp(-r2) / pi is below the smallest
// normal double (and outside Highway's Exp range): pieces of the azimuth
// that start there contribute nothing, in the scalar and the SIMD rules.
inline constexpr double kBeckmannNegligibleR2 = 706.0;

// The per-theta_i constants of the azimuthal integrand:
// r2 = r2_0 + r2_t t and v = v_min + t with t = two_b sin^2(psi / 2).
struct SlopeAzimuth {
  double r2_0, r2_t, v_min, two_b;
  bool with_bias;
};

// The unit-roughness Lambda of n arguments a (+inf for a <= 0, 0 for
// a = inf) and the azimuthal integrals piece by piece: the double scalar
// reference.
// ke/ge are the Kronrod/Gauss sums of P22(r2) v^2 of each piece (weights
// times integrand, without the half width), kb/gb those of P22(r2) v^2 Fc.
// `Ndf` provides UnitP22 (slope_ndf.h).
template <class Ndf>
struct ScalarSlopeNodes {
  // The STD's P22 decays like a power and is never negligible.
  static constexpr double kNegligibleR2 = std::is_same_v<Ndf, BeckmannNdf<double>>
                                              ? kBeckmannNegligibleR2
                                              : std::numeric_limits<double>::infinity();
  const Ndf* ndf;
  void Lambda(const double* a, int n, double* out) const {
    for (int k = 0; k < n; ++k) {
      out[k] = a[k] > 0 ? ndf->UnitLambda(a[k]) : std::numeric_limits<double>::infinity();
    }
  }
  void operator()(const SlopeAzimuth& az, const AzimuthLadder::Piece* const* pieces, int n,
                  double* ke, double* ge, double* kb, double* gb) const {
    const AzimuthLadder& rule = AzimuthLadder::Get(2);
    for (int p = 0; p < n; ++p) {
      double sums[4] = {0, 0, 0, 0};
      for (int i = 0; i < 15; ++i) {
        const double t = az.two_b * pieces[p]->s2[i];
        const double v = az.v_min + t;
        const double f = ndf->UnitP22(az.r2_0 + az.r2_t * t) * (v * v);
        sums[0] += rule.wk[i] * f;
        sums[1] += rule.wg[i] * f;
        if (az.with_bias) {
          const double m = std::max(0.0, 1 - 0.5 * std::sqrt(v)), m2 = m * m;
          sums[2] += rule.wk[i] * (f * (m2 * m2 * m));
          sums[3] += rule.wg[i] * (f * (m2 * m2 * m));
        }
      }
      ke[p] = sums[0];
      ge[p] = sums[1];
      kb[p] = sums[2];
      gb[p] = sums[3];
    }
  }
};

// One theta_i node's azimuthal integrals of D and D Fc on the ladder's
// pieces from `start`, times `scale`, with their error estimates (the sums
// of |K15 - G7|): the part of SlopeAzimuthalE's node that its SIMD twin
// (lanes/slope_lanes.cc) shares.
template <class Nodes>
AzimuthalValues SlopeAzimuthOnLadder(const AzimuthLadder& ladder, const SlopeAzimuth& az,
                                     double start, double scale, const Nodes& nodes) {
  const AzimuthLadder::Piece* used[AzimuthLadder::kMaxPieces];
  int pieces = ladder.Select(start, used);
  // r2 grows with psi: the pieces from the first one starting at
  // r2 >= nodes.kNegligibleR2 on (where a Gaussian P22 is below the
  // smallest double) contribute nothing.
  while (pieces > 1 &&
         az.r2_0 + az.r2_t * (az.two_b * used[pieces - 1]->s2_start) >= nodes.kNegligibleR2) {
    --pieces;
  }
  double ke[AzimuthLadder::kMaxPieces], ge[AzimuthLadder::kMaxPieces];
  double kb[AzimuthLadder::kMaxPieces], gb[AzimuthLadder::kMaxPieces];
  nodes(az, used, pieces, ke, ge, kb, gb);
  double phi_e = 0, err_e = 0, phi_b = 0, err_b = 0;
  for (int p = 0; p < pieces; ++p) {
    const double h = used[p]->half_width;
    phi_e += ke[p] * h;
    err_e += std::abs(ke[p] - ge[p]) * h;
    phi_b += kb[p] * h;
    err_b += std::abs(kb[p] - gb[p]) * h;
  }
  AzimuthalValues out;
  out.e = scale * phi_e;
  out.e_error = scale * err_e;
  out.bias = scale * phi_b;
  out.bias_error = scale * err_b;
  return out;
}

// What SlopeAzimuthalE::EvalPiece reads besides the frame, for its SIMD
// twin (lanes/slope_lanes.cc).
struct SlopeConsts {
  double alpha, lambda_o;
  bool separable;
  double ladder_ratio;
};

// The integrands over theta_i of E and dfg.bias for an isotropic
// slope-space model (BeckmannNdf, StudentTNdf: UnitLambda and UnitP22).
template <class Ndf>
class SlopeAzimuthalE : public AzimuthalFrame {
 public:
  // `tol`, the rule's tolerance, and `with_bias` pick the azimuth ladder
  // (see the header).
  SlopeAzimuthalE(const Ndf& ndf, double mu_o, Masking masking, double tol, bool with_bias)
      : AzimuthalFrame(mu_o), ndf_(&ndf), alpha_(ndf.alpha_x()),
        separable_(masking == Masking::kSeparable),
        ladder_ratio_(LadderRatio(ndf, with_bias ? 0.5 * tol : tol)) {
    lambda_o_ = LambdaAt(mu_o, s_o_);
    if constexpr (std::is_same_v<Ndf, StudentTNdf<double>>) {
      if (ndf.gamma() < 2) {
        normal_scale_ =
            NormalPoleScale([&](double a) { return ndf.UnitLambda(a); }, alpha_, lambda_o_);
      }
    }
  }

  double lambda_o() const { return lambda_o_; }
  double alpha() const { return alpha_; }

  // The factor on the theta_i mesh's horizon scale (HorizonWiden).
  double horizon_widen() const {
    if constexpr (std::is_same_v<Ndf, StudentTNdf<double>>) {
      return HorizonWiden([&](double a) { return ndf_->UnitLambda(a); });
    }
    return 1.0;
  }

  // The theta_i mesh's grading from the normal (NormalPoleScale; the STD
  // below gamma 2 only).
  double normal_scale() const { return normal_scale_; }

  SlopeConsts slope_consts() const {
    return {alpha_, lambda_o_, separable_, ladder_ratio_};
  }

  // The AzimuthalValues at the 15 nodes of a piece of the theta_i rule:
  // Lambda(wi) of all 15 at once (nodes.Lambda), then each node's azimuth.
  template <class Nodes>
  void EvalPiece(const double* theta, bool with_bias, const Nodes& nodes,
                 AzimuthalValues* out) const {
    Angles g[15];
    double a[15], lambda_i[15];
    for (int k = 0; k < 15; ++k) {
      g[k] = AnglesAt(theta[k]);
      // a = cot(theta_i) / alpha: 0 (Lambda = inf) on the horizon, inf along
      // the normal.
      a[k] = g[k].mu_i > 0 ? g[k].mu_i / (alpha_ * g[k].s_i) : 0.0;
    }
    nodes.Lambda(a, 15, lambda_i);
    for (int k = 0; k < 15; ++k) out[k] = Azimuth(g[k], lambda_i[k], with_bias, nodes);
  }

 private:
  template <class Nodes>
  AzimuthalValues Azimuth(const Angles& g, double lambda_i, bool with_bias,
                          const Nodes& nodes) const {
    AzimuthalValues out;
    const double g2 = separable_ ? 1 / ((1 + lambda_i) * (1 + lambda_o_))
                                 : 1 / (1 + lambda_i + lambda_o_);
    const double w = scale_ * g2 * g.s_i;
    if (!(w > 0) || !(g.ca > 0)) return out;
    const double a2 = alpha_ * alpha_;
    const double cc = g.ca * g.ct;  // s / 2
    const double two_b = 4 * g.s_i * s_o_;
    SlopeAzimuth az;
    az.r2_0 = g.st * g.st / (a2 * g.ct * g.ct);
    az.r2_t = 1 / (4 * a2 * cc * cc);
    az.v_min = 4 * g.ca * g.ca;
    az.two_b = two_b;
    az.with_bias = with_bias;
    // The ladder starts at the lobe's half width (and at the branch point
    // of wo.h for Fc); with B = 0 (normal incidence) the integrand is
    // constant in psi.
    const double b = 0.5 * two_b;
    double start = b > 0 ? alpha_ * cc * std::sqrt(8 / b) : std::numeric_limits<double>::infinity();
    if (with_bias) start = std::min(start, 2 * g.ca);
    // D = P22 v^2 / (alpha^2 s^4), s^4 = 16 (cos A cos T)^4; Phi = 2 int_0^pi.
    const double norm = 2 / (a2 * 16 * (cc * cc) * (cc * cc));
    return SlopeAzimuthOnLadder(AzimuthLadder::Get(ladder_ratio_), az, start, w * norm, nodes);
  }

  // Lambda of a direction at cos mu, sin s: UnitLambda(mu / (alpha s)); +inf
  // on the horizon, 0 along the normal.
  double LambdaAt(double mu, double s) const {
    if (!(mu > 0)) return std::numeric_limits<double>::infinity();
    if (!(s > 0)) return 0.0;
    return ndf_->UnitLambda(mu / (alpha_ * s));
  }

  // The azimuth ladder's ratio for a budget `tol` of each azimuthal
  // integral's floor (see the header).
  static double LadderRatio(const Ndf& ndf, double tol) {
    if (!(tol >= 1e-7)) return 2;
    if constexpr (std::is_same_v<Ndf, StudentTNdf<double>>) {
      if (ndf.gamma() <= 4) return 3;
    }
    return 2.5;
  }

  const Ndf* ndf_;
  double alpha_;
  bool separable_;
  double ladder_ratio_;
  double lambda_o_ = 0;
  double normal_scale_ = std::numeric_limits<double>::infinity();
};

// E (and with `with_bias` dfg.bias and scale) of an isotropic slope-space
// model at mu by the adaptive rule over theta_i.
template <class Ndf, class Nodes>
AzimuthalDfgResult SlopeAzimuthalDfgWith(const Ndf& ndf, double mu, Masking masking,
                                         bool with_bias, double tol, int max_pieces,
                                         const Nodes& nodes) {
  const SlopeAzimuthalE<Ndf> f(ndf, mu, masking, tol, with_bias);
  return AdaptiveAzimuthalRule(
      AzimuthalMesh(f.theta_o(), f.lambda_o(), f.alpha(), f.horizon_widen(), f.normal_scale()),
      [&](const double* theta, AzimuthalValues* out) {
        f.EvalPiece(theta, with_bias, nodes, out);
      },
      tol, max_pieces);
}

// The double scalar reference.
template <class Ndf>
AzimuthalDfgResult SlopeAzimuthalDfg(const Ndf& ndf, double mu, Masking masking, bool with_bias,
                                     double tol, int max_pieces) {
  return SlopeAzimuthalDfgWith(ndf, mu, masking, with_bias, tol, max_pieces,
                               ScalarSlopeNodes<Ndf>{&ndf});
}

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_RULES_SLOPE_AZIMUTHAL_SLOPE_H_
