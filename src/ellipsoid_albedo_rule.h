// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The slope-plane rule of ellipsoid_albedo.h as a template over its node
// evaluator: `Nodes` integrates one piece of a ray, given its centre c and
// half width h in the signed offset (>= 0: y = x_hi - x; <= 0: -(x - x_lo))
// and the ray's length len in x = sqrt(u), returning the Kronrod 15 and
// Gauss 7 sums (weights on [-1, 1], without h) of EllipsoidRay::Eval.
// ScalarEllipsoidNodes is the double reference; quadrature_simd.cc
// evaluates the 15 nodes in lanes.

#ifndef BRDFBAKE_SRC_ELLIPSOID_ALBEDO_RULE_H_
#define BRDFBAKE_SRC_ELLIPSOID_ALBEDO_RULE_H_

#include <algorithm>
#include <cmath>
#include <vector>

#include "adaptive_rule.h"
#include "brdfbake/ellipsoid.h"
#include "ellipsoid_albedo.h"
#include "integrate.h"

namespace brdfbake {

// Initial grading of a ray's halves towards horizon ends (ratio 4); the
// adaptive bisection refines from there.
inline constexpr int kEllipsoidRayLevels = 3;

struct EllipsoidFrame : SlopeView {
  EllipsoidNdf<double> ndf;
  double lambda_o = 0;
  bool separable = false;
  double s0x = 0, s0y = 0;         // the slope of the density's peak
  double l11 = 1, l12 = 0, l22 = 1;  // L, upper triangular: s = s0 + L v
  double dx = 0, dy = 0;           // d = s0 - c
  double d2_minus_r2 = -1;         // |d|^2 - 1 / wo.z^2
  double ray_tol = 0;
  // G1's clamp (ellipsoid.h): Lambda(w) = 0 where this is <= 0.
  double Kink(const Vec3<double>& w) const { return ndf.ClampMargin(w); }

  EllipsoidFrame(const EllipsoidNdf<double>& n, double mu, double phi) : SlopeView(mu, phi), ndf(n) {}
  double G2(double lambda_i) const {
    return separable ? 1 / ((1 + lambda_i) * (1 + lambda_o)) : 1 / (1 + lambda_i + lambda_o);
  }
};

struct EllipsoidRayPiece {
  double a, b, value, err;
};

// The part of one ray s = s0 + rho e inside the horizon disk.
class EllipsoidRay {
 public:
  EllipsoidRay(const EllipsoidFrame& f, double psi) : f_(f) {
    const double cs = std::cos(psi), sn = std::sin(psi);
    ex_ = f.l11 * cs + f.l12 * sn;
    ey_ = f.l22 * sn;
    ee_ = ex_ * ex_ + ey_ * ey_;
    const double de = f.dx * ex_ + f.dy * ey_;
    const double disc = de * de - ee_ * f.d2_minus_r2;
    if (!(disc > 0)) return;
    // The roots of ee rho^2 + 2 de rho + (|d|^2 - R^2), without cancellation.
    const double q = -(de + std::copysign(std::sqrt(disc), de));
    const double r1 = q / ee_, r2 = f.d2_minus_r2 / q;
    rho_minus_ = std::min(r1, r2);
    rho_plus_ = std::max(r1, r2);
    if (!(rho_plus_ > 0)) return;
    lo_edge_ = rho_minus_ > 0;
    const double lo = std::max(0.0, rho_minus_);
    omx2_lo_ = 1 / (1 + lo * lo);
    omx2_hi_ = 1 / (1 + rho_plus_ * rho_plus_);
    x_lo_ = lo * std::sqrt(omx2_lo_);
    x_hi_ = rho_plus_ * std::sqrt(omx2_hi_);
    valid_ = x_hi_ > x_lo_;
  }

  // The integral over x = sqrt(u) in [x_lo, x_hi] of G2 (1 + s.c) 2 x, and
  // its error estimate.
  template <class Nodes>
  void Integrate(const Nodes& nodes, double* value, double* error) const {
    *value = *error = 0;
    if (!valid_) return;
    const double len = x_hi_ - x_lo_, mid = 0.5 * len;
    // EllipsoidRayPieces in y = x_hi - x (the upper half, graded towards y = 0) and in
    // t = x - x_lo (the lower half, graded towards t = 0 where that end is
    // a horizon crossing).
    std::vector<EllipsoidRayPiece> pieces;
    auto make = [&](double a, double b) {
      const double c = 0.5 * (a + b), h = 0.5 * (b - a);
      double k, g;
      nodes(*this, c, h, len, &k, &g);
      return EllipsoidRayPiece{a, b, k * h, std::abs(k - g) * h};
    };
    auto graded = [&](double top, bool toward_zero, int levels, bool from_lo) {
      // Offsets [0, top] from one end; stored as signed positions: from the
      // top end as y >= 0, from the bottom end as -(t) - 0 (negative).
      double hi = top;
      if (toward_zero) {
        for (int k = 0; k < levels; ++k) {
          const double lo = 0.25 * hi;
          pieces.push_back(from_lo ? make(-hi, -lo) : make(lo, hi));
          hi = lo;
        }
      }
      pieces.push_back(from_lo ? make(-hi, 0.0) : make(0.0, hi));
    };
    graded(mid, true, kEllipsoidRayLevels, false);
    graded(len - mid, lo_edge_, kEllipsoidRayLevels, true);
    // Where G1(wi)'s clamp turns on or off along the ray, G2 has a kink:
    // bracketed on 12 probes in x, solved, and the piece holding it split
    // there.
    {
      constexpr int kProbes = 12;
      auto kink_at = [&](double x) {
        Vec3<double> wi;
        double lin;
        return WiAt(x_hi_ - x, x - x_lo_, &wi, &lin) ? f_.Kink(wi) : 0.0;
      };
      double x_prev = x_lo_ + 1e-9 * len, k_prev = kink_at(x_prev);
      for (int i = 1; i <= kProbes; ++i) {
        const double x = i == kProbes ? x_hi_ - 1e-9 * len : x_lo_ + len * i / kProbes;
        const double k = kink_at(x);
        if ((k > 0) != (k_prev > 0) && k != 0 && k_prev != 0) {
          const double xc = SolveBracketed(kink_at, x_prev, x, k_prev, k, 1e-13 * len);
          const double o = xc >= x_lo_ + (len - mid) ? x_hi_ - xc : -(xc - x_lo_);
          for (EllipsoidRayPiece& p : pieces) {
            if (p.a < o && o < p.b) {
              const EllipsoidRayPiece q = p;
              p = make(q.a, o);
              pieces.push_back(make(o, q.b));
              break;
            }
          }
        }
        x_prev = x;
        k_prev = k;
      }
    }
    auto sum_err = [&] {
      double e = 0;
      for (const EllipsoidRayPiece& p : pieces) e += p.err;
      return e;
    };
    while (sum_err() > f_.ray_tol && pieces.size() < 96) BisectWorst(&pieces, make);
    for (const EllipsoidRayPiece& p : pieces) *value += p.value;
    *error = sum_err();
  }

 // The node evaluators (ScalarEllipsoidNodes, quadrature_simd.cc) read these.
  // wi (unnormalized, its z without cancellation) and 1 + s.c at x = x_hi -
  // y = x_lo + t; false where wi is not above the horizon.
  bool WiAt(double y, double t, Vec3<double>* wi, double* lin_out) const {
    const double x = x_hi_ - y;
    if (!(x > 0)) return false;
    // 1 - x^2 from the nearer end.
    const double omx2 =
        y <= t ? omx2_hi_ + y * (2 * x_hi_ - y) : omx2_lo_ - t * (2 * x_lo_ + t);
    if (!(omx2 > 0)) return false;
    const double rho = x / std::sqrt(omx2);
    // rho_+ - rho and rho - rho_- from x^2 differences (rho^2 = x^2 / (1 - x^2)).
    const double to_hi = y * (2 * x_hi_ - y) / (omx2_hi_ * omx2 * (rho_plus_ + rho));
    const double from_lo = lo_edge_ ? t * (2 * x_lo_ + t) / (omx2_lo_ * omx2 * (rho + rho_minus_))
                                    : rho - rho_minus_;
    const double p = f_.s0x + rho * ex_, q = f_.s0y + rho * ey_;
    const double n2 = 1 + p * p + q * q;
    const double lin = 1 + p * f_.cx + q * f_.cy;
    const double wiz = f_.wz * ee_ * from_lo * to_hi / n2;
    if (!(wiz > 0) || !(lin > 0)) return false;
    const double k = 2 * f_.wz * lin / n2;
    *wi = Vec3<double>(-k * p - f_.wx, -k * q - f_.wy, wiz);
    *lin_out = lin;
    return true;
  }

  double Eval(double y, double t) const {
    Vec3<double> wi;
    double lin;
    if (!WiAt(y, t, &wi, &lin)) return 0;
    return f_.G2(f_.ndf.Lambda(wi)) * lin * 2 * (x_hi_ - y);
  }

  const EllipsoidFrame& f_;
  double ex_ = 0, ey_ = 0, ee_ = 0;
  double rho_minus_ = 0, rho_plus_ = 0, x_lo_ = 0, x_hi_ = 0, omx2_lo_ = 1, omx2_hi_ = 1;
  bool lo_edge_ = false, valid_ = false;
};

struct ScalarEllipsoidNodes {
  void operator()(const EllipsoidRay& ray, double c, double h, double len, double* k,
                  double* g) const {
    const KronrodRule& r = Kronrod15();
    *k = *g = 0;
    for (int i = 0; i < 15; ++i) {
      const double o = c + h * r.x[i];
      const double y = o >= 0 ? o : len + o;  // x_hi - x
      const double t = o >= 0 ? len - o : -o;  // x - x_lo
      const double v = ray.Eval(y, t);
      *k += r.wk[i] * v;
      *g += r.wg[i] * v;
    }
  }
};

template <class Nodes>
AzimuthalResult EllipsoidAlbedoWith(double alpha_x, double alpha_y, double theta_x,
                                    double theta_y, double theta_z, double mu, double phi,
                                    Masking masking, double tol, int max_pieces,
                                    const Nodes& nodes) {
  constexpr double kTwoPi = 2 * kPi<double>;
  const double ax = std::clamp(alpha_x, 1e-4, 1e4), ay = std::clamp(alpha_y, 1e-4, 1e4);
  EllipsoidFrame f(EllipsoidNdf<double>(ax, ay, theta_x, theta_y, theta_z), mu, phi);
  f.separable = masking == Masking::kSeparable;
  f.lambda_o = f.ndf.Lambda(Vec3<double>(f.wx, f.wy, f.wz));
  f.ray_tol = 0.2 * tol;
  // B = A^-T (= S^-1 R); its columns b1, b2, b3.
  const Mat3<double>& b = f.ndf.inverse_transposed();
  auto col = [&](int j) { return Vec3<double>(b.m[0][j], b.m[1][j], b.m[2][j]); };
  const Vec3<double> b1 = col(0), b2 = col(1), b3 = col(2);
  // Without cancellation for thin, tilted ellipsoids (B's columns up to
  // 1 / alpha_min long and nearly parallel): with n12 = b1 x b2,
  // det G = |n12|^2, s0 by Cramer's rule on the projection onto n12's
  // plane, and Q_min = (det B)^2 / det G (the squared distance from b3 to
  // span(b1, b2)), det B = 1 / (alpha_x alpha_y).
  const Vec3<double> n12 = Cross(b1, b2);
  const double det_g = Dot(n12, n12);
  f.s0x = Dot(Cross(b3, b2), n12) / det_g;
  f.s0y = Dot(Cross(b1, b3), n12) / det_g;
  const double det_b = 1 / (ax * ay);
  const double q_min = det_b * det_b / det_g;
  // G = C^T C, C = [[c11, c12], [0, c22]], c22 = sqrt(det G) / c11; L = sqrt(Q_min) C^-1.
  const double g11 = Dot(b1, b1), g12 = Dot(b1, b2);
  const double c11 = std::sqrt(g11), c12 = g12 / c11, c22 = std::sqrt(det_g) / c11;
  const double sq = std::sqrt(q_min);
  f.l11 = sq / c11;
  f.l12 = -sq * c12 / (c11 * c22);
  f.l22 = sq / c22;
  f.dx = f.s0x - f.cx;
  f.dy = f.s0y - f.cy;
  // |d|^2 - R^2 = |s0|^2 - 2 s0.c + (|c|^2 - 1 / wo.z^2), the last term -1.
  f.d2_minus_r2 = f.s0x * f.s0x + f.s0y * f.s0y - 2 * (f.s0x * f.cx + f.s0y * f.cy) - 1;

  // First cuts where d.e = 0 (cos psi dx l11 + sin psi (dx l12 + dy l22) = 0);
  // at grazing PsiRule grades towards them as in aniso_ggx.h, with delta =
  // |e| sqrt(R^2 - |d|^2) / |d(d.e)/dpsi| when s0 lies inside the disk.
  const double ca = f.dx * f.l11, cb = f.dx * f.l12 + f.dy * f.l22;
  const double psi0 = std::atan2(ca, -cb);
  const double e0x = f.l11 * std::cos(psi0) + f.l12 * std::sin(psi0), e0y = f.l22 * std::sin(psi0);
  const double dde = std::abs(-ca * std::sin(psi0) + cb * std::cos(psi0));
  const double inside = -f.d2_minus_r2;
  const double delta = dde > 0 && inside > 0
                           ? std::sqrt(e0x * e0x + e0y * e0y) * std::sqrt(inside) / dde
                           : 2 * kTwoPi;
  auto ray = [&](double psi, double* err) {
    double v;
    EllipsoidRay(f, psi).Integrate(nodes, &v, err);
    return v;
  };
  return PsiRule(ray, psi0, delta, tol, max_pieces);
}

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_ELLIPSOID_ALBEDO_RULE_H_
