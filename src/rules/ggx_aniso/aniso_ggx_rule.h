// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The slope-plane rule of aniso_ggx.h as a template over its node
// evaluator: `Nodes` integrates one piece of a ray, given the piece's
// centre c and half width h in x = sqrt(u_b) - sqrt(u), returning the
// Kronrod 15 and Gauss 7 sums of AnisoRay::Eval(x (2 v_b - x)) 2 (v_b - x)
// (the weights on [-1, 1], without h). ScalarAnisoNodes is the double
// reference; lanes/aniso_lanes.cc evaluates the 15 nodes in lanes.

#ifndef BRDFBAKE_SRC_RULES_GGX_ANISO_ANISO_GGX_RULE_H_
#define BRDFBAKE_SRC_RULES_GGX_ANISO_ANISO_GGX_RULE_H_

#include <algorithm>
#include <cmath>
#include <vector>

#include "brdfbake/models/ggx.h"
#include "quadrature/adaptive_rule.h"
#include "rules/ggx/azimuthal.h"
#include "rules/ggx_aniso/aniso_ggx.h"

namespace brdfbake {

// Each ray's pieces shrink by this factor towards the disk's edge.
inline constexpr double kAnisoRayGrading = 0.25;

struct AnisoFrame : SlopeView {
  AnisoFrame(double mu, double phi) : SlopeView(mu, phi) {}
  double ax, ay, lambda_o;
  bool separable;
  // Eval's G2 = 2 Z / (z_weight Z + sqrt(Z^2 + P)) g_scale.
  double z_weight, g_scale;
};

// One ray m = rho e from the origin of the slope plane to the disk's edge.
struct AnisoRay {
  double ex, ey, ce, ee, rho_b, u_b, one_minus_ub, inv_s_plus_ce;

  AnisoRay(const AnisoFrame& f, double psi) {
    ex = f.ax * std::cos(psi);
    ey = f.ay * std::sin(psi);
    ce = f.cx * ex + f.cy * ey;
    ee = ex * ex + ey * ey;
    const double s = std::sqrt(ce * ce + ee);
    inv_s_plus_ce = 1 / (s + ce);
    rho_b = ce >= 0 ? (s + ce) / ee : 1 / (s - ce);
    one_minus_ub = 1 / (1 + rho_b * rho_b);
    u_b = rho_b * rho_b * one_minus_ub;
  }

  // G2 (1 + rho c.e) at u = u_b - w. With M = (1 - u_b) (1 - u) (rho_b + rho)
  // (rho_b - rho = w / M) and N^2 = 1 + rho^2 |e|^2, wi scaled by N^2 M is
  //   Z  = wo.z |e|^2 w (rho + 1 / (S + c.e))           (its z, >= 0)
  //   XY = -(2 wo.z lin m + wo_xy N^2) M                (m = rho e)
  // and 1 + Lambda(wi) = (1 + sqrt(1 + P / Z^2)) / 2, P = |alpha o XY|^2, so
  //   height-correlated: G2 = 2 Z / ((1 + 2 Lambda(wo)) Z + sqrt(Z^2 + P)),
  //   separable:         G2 = 2 Z / (Z + sqrt(Z^2 + P)) / (1 + Lambda(wo)):
  // one division and one square root besides rho's.
  double Eval(const AnisoFrame& f, double w) const {
    const double u = std::max(0.0, u_b - w);
    const double omu = one_minus_ub + w;  // 1 - u
    const double rho = std::sqrt(u / omu);
    const double p = rho * ex, q = rho * ey;
    const double n2 = 1 + p * p + q * q;
    const double lin = 1 + rho * ce;
    const double m = one_minus_ub * omu * (rho_b + rho);
    const double z = f.wz * ee * w * (rho + inv_s_plus_ce);
    if (!(z > 0) || !(lin > 0)) return 0;
    const double k = 2 * f.wz * lin;
    const double x = -(k * p + f.wx * n2) * m, y = -(k * q + f.wy * n2) * m;
    const double ax = f.ax * x, ay = f.ay * y;
    const double root = std::sqrt(z * z + (ax * ax + ay * ay));
    return 2 * z * lin / (f.z_weight * z + root) * f.g_scale;
  }

  // The integral over [0, u_b] and its error estimate. The slope rho is
  // sqrt(u / (1 - u)), so the integrand has a square-root branch at u = 0:
  // the rule runs in x = sqrt(u_b) - sqrt(u) (du = 2 sqrt(u) dx), Gauss-Kronrod
  // 15 on pieces graded by 4 from x = sqrt(u_b) down to the edge layer.
  template <class Nodes>
  void Integrate(const AnisoFrame& f, double skip_eps, double ray_tol, const Nodes& nodes,
                 double* value, double* error) const {
    *value = *error = 0;
    if (!(u_b > 0)) return;
    // The edge layer: wi.z ~ K w for small w, K = wo.z |e|^2 (rho_b + 1/(S + c.e)) /
    // (N_b^2 2 rho_b (1 - u_b)^2). Lambda(wi) ~ |alpha o wi_xy| / (2 wi.z) (wi a
    // unit vector in the plane at the edge), and G2 changes where Lambda(wi)
    // reaches 1 + Lambda(wo) (height-correlated) or 1 (separable).
    const double pb = rho_b * ex, qb = rho_b * ey;
    const double n2b = 1 + pb * pb + qb * qb;
    const double lin_b = 1 + rho_b * ce;
    const double kb = 2 * f.wz * lin_b / n2b;
    const double wxb = -kb * pb - f.wx, wyb = -kb * qb - f.wy;
    const double a_b = std::sqrt((f.ax * wxb) * (f.ax * wxb) + (f.ay * wyb) * (f.ay * wyb));
    const double slope =
        f.wz * ee * (rho_b + inv_s_plus_ce) / (n2b * 2 * rho_b * one_minus_ub * one_minus_ub);
    const double lambda_scale = f.separable ? 1.0 : 1 + f.lambda_o;
    const double w_layer = slope > 0 ? a_b / (2 * lambda_scale * slope) : u_b;
    // The integrand is at most G2(0) (1 + rho_b max(c.e, 0)) <= that / (1 + Lambda(wo)).
    const double bound = (1 + rho_b * std::max(ce, 0.0)) / (1 + f.lambda_o);
    // w = u_b - u = x (2 v_b - x); the piece [0, x] covers w <= 2 v_b x.
    const double v_b = std::sqrt(u_b);
    const double x_stop = std::max(0.25 * w_layer, skip_eps / bound) / (2 * v_b);
    struct Piece {
      double a, b, value, err;
    };
    auto piece = [&](double a, double b) {
      const double c = 0.5 * (a + b), h = 0.5 * (b - a);
      double k, g;
      nodes(f, *this, v_b, c, h, &k, &g);
      return Piece{a, b, k * h, std::abs(k - g) * h};
    };
    constexpr int kMaxPieces = 96;
    Piece pieces[kMaxPieces];
    int n = 0;
    double hi = v_b;
    for (int level = 0; level < 60 && hi > x_stop; ++level) {
      const double lo = kAnisoRayGrading * hi;
      pieces[n++] = piece(lo, hi);
      hi = lo;
    }
    double left = hi * (2 * v_b - hi) * bound;
    if (left > skip_eps) {
      pieces[n++] = piece(0, hi);
      left = 0;
    }
    // Where the grading has not resolved the ray (a layer narrower than
    // estimated), the worst piece is bisected until the ray meets ray_tol.
    auto sum_err = [&] {
      double e = left;
      for (int i = 0; i < n; ++i) e += pieces[i].err;
      return e;
    };
    while (sum_err() > ray_tol && n < kMaxPieces) {
      int worst = 0;
      for (int i = 1; i < n; ++i) {
        if (pieces[i].err > pieces[worst].err) worst = i;
      }
      const Piece p = pieces[worst];
      const double m = 0.5 * (p.a + p.b);
      pieces[worst] = piece(p.a, m);
      pieces[n++] = piece(m, p.b);
    }
    for (int i = 0; i < n; ++i) *value += pieces[i].value;
    *error = sum_err();
  }
};

struct ScalarAnisoNodes {
  void operator()(const AnisoFrame& f, const AnisoRay& ray, double v_b, double c, double h,
                  double* k, double* g) const {
    const KronrodRule& r = Kronrod15();
    *k = *g = 0;
    for (int i = 0; i < 15; ++i) {
      const double x = c + h * r.x[i];
      const double v = ray.Eval(f, x * (2 * v_b - x)) * (2 * (v_b - x));
      *k += r.wk[i] * v;
      *g += r.wg[i] * v;
    }
  }
};

// HorizonApproaches (ellipsoid_albedo_rule.h) for GGX, in closed form: at
// the ray's horizon end G2 rises over a width proportional to N of the
// ellipsoid's eq. 6, which on the horizon (u = (cos b, sin b, 0)) is
// ||(alpha_x cos b, alpha_y sin b)||: smallest, a_min, along the narrower
// axis (two opposite b*), with curvature (a_max^2 - a_min^2) / a_min
// there. A strongly anisotropic lobe makes it a narrow feature over psi:
// at alpha 1 x 0.04, mu 0.66667, phi 1.46608 the psi rule without these
// cuts missed by 1.0e-5 against a claim of 8.9e-8.
inline std::vector<HorizonApproach> GgxHorizonApproaches(const AnisoFrame& f) {
  const double a_min = std::min(f.ax, f.ay), a_max = std::max(f.ax, f.ay);
  const double m2 = (a_max - a_min) * (a_max + a_min) / a_min;
  std::vector<HorizonApproach> out;
  if (!(m2 > 0)) return out;
  const double d = std::sqrt(2 * a_min / m2);
  if (!(d < 0.5)) return out;  // as HorizonApproaches
  // The ray through the horizon point wi(b): its half vector's slope s, in
  // the stretched frame (s_x / alpha_x, s_y / alpha_y).
  auto psi_at = [&](double b) {
    const double mx = std::cos(b) + f.wx, my = std::sin(b) + f.wy;
    return std::atan2(-my / (f.wz * f.ay), -mx / (f.wz * f.ax));
  };
  const double b0 = f.ay < f.ax ? 0.5 * kPi<double> : 0.0;
  for (double b : {b0, b0 + kPi<double>}) {
    const double w = 0.5 * std::abs(WrapAngle(psi_at(b + d) - psi_at(b - d)));
    out.push_back({psi_at(b), w});
  }
  return out;
}

template <class Nodes>
RuleResult AnisoGgxAlbedoWith(double alpha_x, double alpha_y, double mu, double phi,
                                   Masking masking, double tol, int max_pieces,
                                   const Nodes& nodes) {
  AnisoFrame f(mu, phi);
  f.ax = std::clamp(alpha_x, 1e-4, 1e4);
  f.ay = std::clamp(alpha_y, 1e-4, 1e4);
  f.separable = masking == Masking::kSeparable;
  f.lambda_o = GgxNdf<double>(f.ax, f.ay).Lambda(Vec3<double>(f.wx, f.wy, f.wz));
  f.z_weight = f.separable ? 1 : 1 + 2 * f.lambda_o;
  f.g_scale = f.separable ? 1 / (1 + f.lambda_o) : 1;
  // A ray's part next to the edge is left out where its bound is below
  // skip_eps (the bound is added to the ray's error).
  const double skip_eps = 0.05 * tol;
  // Each ray's error enters E with the psi rule's weights (summing to 1):
  // a ray within a fifth of the tolerance leaves the rest to the psi rule.
  const double ray_tol = 0.2 * tol;
  // First cuts where c.e = 0 (cos psi alpha_x c_x + sin psi alpha_y c_y = 0).
  // Near those two rays the edge's distance 1 / (S - c.e) turns from about
  // 1 / |e| to 1 / (2 |c.e|) over delta = |e| / |d(c.e)/dpsi| (about mu at
  // grazing), to which the psi rule grades its first pieces.
  const double psi0 = std::atan2(f.cx * f.ax, -f.cy * f.ay);
  const double e0x = f.ax * std::cos(psi0), e0y = f.ay * std::sin(psi0);
  const double dce = std::abs(-f.cx * f.ax * std::sin(psi0) + f.cy * f.ay * std::cos(psi0));
  const double delta = dce > 0 ? std::sqrt(e0x * e0x + e0y * e0y) / dce : 4 * kPi<double>;
  auto rays = [&](const double* psi, int n, double* value, double* err) {
    for (int i = 0; i < n; ++i) {
      AnisoRay(f, psi[i]).Integrate(f, skip_eps, ray_tol, nodes, &value[i], &err[i]);
    }
  };
  // Quarter turns from psi0, graded towards the two feature rays down to
  // delta / 4 (`feature` delta / 2, SegmentRule), and cut where the rise
  // of G2 at the rays' horizon end is narrowest (GgxHorizonApproaches).
  std::vector<PsiSegment> segments;
  for (int k = 0; k < 4; ++k) {
    PsiSegment g{psi0 + k * 0.25 * kTwoPi<double>, psi0 + (k + 1) * 0.25 * kTwoPi<double>};
    (k % 2 == 0 ? g.feature_a : g.feature_b) = 0.5 * delta;
    segments.push_back(g);
  }
  for (const HorizonApproach& h : GgxHorizonApproaches(f)) {
    CutAtNarrowFeature(&segments, psi0, h.psi, h.width);
  }
  return SegmentRule(rays, segments, tol, max_pieces);
}

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_RULES_GGX_ANISO_ANISO_GGX_RULE_H_
