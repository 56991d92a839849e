// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Dynamic dispatch of the baker's one-dimensional rules with their
// azimuthal integrals in double SIMD lanes (quadrature_simd.h): the rules
// themselves are the templates of azimuthal.h and azimuthal_slope.h,
// instantiated per Highway target with node evaluators that take one
// piece's 16 nodes per loop.

#include <cstring>
#include <limits>
#include <type_traits>

#include "quadrature_simd.h"

#include "aniso_ggx_rule.h"
#include "ellipsoid_albedo_rule.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/quadrature_simd.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>
#include <hwy/contrib/math/math-inl.h>

#include "simd/math_f64-inl.h"
#if BRDFBAKE_WITH_STD
#include "simd/std_f64-inl.h"
#endif


HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using DF64 = hn::ScalableTag<double>;

// The remainder of the Schlick-weighted azimuthal integral (azimuthal.h,
// ScalarRemainderNodes) with each piece's 16 nodes (15 and one of weight 0)
// in lanes.
struct SimdRemainderNodes {
  void operator()(const OddRemainder& rem, const AzimuthLadder::Piece* const* pieces, int n,
                  double* k, double* g) const {
    using V = hn::Vec<DF64>;
    const DF64 d;
    const size_t N = hn::Lanes(d);
    const AzimuthLadder& rule = AzimuthLadder::Get(3);
    V t[8];
    for (int m = 0; m < 8; ++m) t[m] = hn::Set(d, rem.t[m]);
    const V a = hn::Set(d, rem.a), vmin = hn::Set(d, rem.vmin), two_b = hn::Set(d, rem.two_b);
    for (int p = 0; p < n; ++p) {
      V ks = hn::Zero(d), gs = hn::Zero(d);
      for (size_t i = 0; i < 16; i += N) {
        const V b = hn::Sqrt(hn::MulAdd(two_b, hn::LoadU(d, pieces[p]->s2 + i), vmin));
        V acc = t[7];
        for (int m = 6; m >= 0; --m) acc = hn::MulAdd(acc, b, t[m]);
        const V ab = hn::Add(a, b);
        const V f = hn::Div(acc, hn::Mul(ab, ab));
        ks = hn::MulAdd(hn::LoadU(d, rule.wk + i), f, ks);
        gs = hn::MulAdd(hn::LoadU(d, rule.wg + i), f, gs);
      }
      k[p] = hn::GetLane(hn::SumOfLanes(d, ks));
      g[p] = hn::GetLane(hn::SumOfLanes(d, gs));
    }
  }
};

// The azimuthal integrals of a slope-space model (azimuthal_slope.h,
// ScalarSlopeNodes) with each piece's 16 nodes in lanes: P22 from the
// model's lane function (BeckmannOverGgx's exponential, StudentTOverGgx's
// power, without their (1 + r2)^2 factor).
template <class P22, class LambdaF>
struct SimdSlopeNodes {
  static constexpr double kNegligibleR2 = P22::kNegligibleR2;
  P22 p22;
  LambdaF lambda;
  void Lambda(const double* a, int n, double* out) const {
    const DF64 d;
    const int N = static_cast<int>(hn::Lanes(d));
    HWY_ALIGN double x[HWY_MAX_BYTES / sizeof(double)];
    HWY_ALIGN double y[HWY_MAX_BYTES / sizeof(double)];
    for (int i = 0; i < n; i += N) {
      for (int j = 0; j < N; ++j) x[j] = i + j < n ? a[i + j] : 1.0;
      hn::Store(lambda(d, hn::Load(d, x)), d, y);
      for (int j = 0; j < N && i + j < n; ++j) out[i + j] = y[j];
    }
  }
  void operator()(const SlopeAzimuth& az, const AzimuthLadder::Piece* const* pieces, int n,
                  double* ke, double* ge, double* kb, double* gb) const {
    using V = hn::Vec<DF64>;
    const DF64 d;
    const size_t N = hn::Lanes(d);
    const AzimuthLadder& rule = AzimuthLadder::Get(2);
    const V r2_0 = hn::Set(d, az.r2_0), r2_t = hn::Set(d, az.r2_t);
    const V v_min = hn::Set(d, az.v_min), two_b = hn::Set(d, az.two_b);
    const V one = hn::Set(d, 1.0), half = hn::Set(d, 0.5), zero = hn::Zero(d);
    for (int p = 0; p < n; ++p) {
      V se = zero, sge = zero, sb = zero, sgb = zero;
      for (size_t i = 0; i < 16; i += N) {
        const V t = hn::Mul(two_b, hn::LoadU(d, pieces[p]->s2 + i));
        const V v = hn::Add(v_min, t);
        const V f = hn::Mul(p22(d, hn::MulAdd(r2_t, t, r2_0)), hn::Mul(v, v));
        const V wk = hn::LoadU(d, rule.wk + i), wg = hn::LoadU(d, rule.wg + i);
        se = hn::MulAdd(wk, f, se);
        sge = hn::MulAdd(wg, f, sge);
        if (az.with_bias) {
          const V m = hn::Max(zero, hn::NegMulAdd(half, hn::Sqrt(v), one));
          const V m2 = hn::Mul(m, m);
          const V fb = hn::Mul(f, hn::Mul(hn::Mul(m2, m2), m));
          sb = hn::MulAdd(wk, fb, sb);
          sgb = hn::MulAdd(wg, fb, sgb);
        }
      }
      ke[p] = hn::GetLane(hn::SumOfLanes(d, se));
      ge[p] = hn::GetLane(hn::SumOfLanes(d, sge));
      kb[p] = hn::GetLane(hn::SumOfLanes(d, sb));
      gb[p] = hn::GetLane(hn::SumOfLanes(d, sgb));
    }
  }
};

#if BRDFBAKE_WITH_BECKMANN
// Lambda (simd/math_f64-inl.h) and P22 = exp(-r2) / pi (0 beyond r2 = 706,
// below the smallest normal double).
struct BeckmannLambda {
  template <class V>
  HWY_INLINE V operator()(DF64 d, V a) const {
    return BeckmannLambdaF64(d, a);
  }
};
struct BeckmannP22 {
  static constexpr double kNegligibleR2 = kBeckmannNegligibleR2;
  template <class V>
  HWY_INLINE V operator()(DF64 d, V r2) const {
    const V e = hn::Exp(d, hn::Neg(hn::Min(r2, hn::Set(d, 706.0))));
    return hn::IfThenElseZero(hn::Lt(r2, hn::Set(d, 706.0)),
                              hn::Mul(e, hn::Set(d, 0.3183098861837907)));
  }
};

AzimuthalDfgResult BeckmannAzimuthalTexel(const BeckmannNdf<double>& ndf, double mu,
                                          Masking masking, bool with_bias, double tol,
                                          int max_pieces) {
  return SlopeAzimuthalDfgWith(ndf, mu, masking, with_bias, tol, max_pieces,
                               SimdSlopeNodes<BeckmannP22, BeckmannLambda>{});
}
#endif

#if BRDFBAKE_WITH_STD
// Lambda (simd/std_f64-inl.h) and P22 = exp(-gamma log1p(r2 / (gamma - 1))) / pi
// (seed 004 eq. 13).
struct StudentTLambda {
  StudentTLambdaF64Consts c;
  template <class V>
  HWY_INLINE V operator()(DF64 d, V a) const {
    return StudentTLambdaF64(d, c, a);
  }
};
struct StudentTP22 {
  static constexpr double kNegligibleR2 = std::numeric_limits<double>::infinity();
  double gamma, inv_gamma_minus_1;
  template <class V>
  HWY_INLINE V operator()(DF64 d, V r2) const {
    const V ex = hn::Mul(hn::Set(d, gamma), hn::Log1p(d, hn::Mul(r2, hn::Set(d, inv_gamma_minus_1))));
    const V e = hn::Exp(d, hn::Neg(hn::Min(ex, hn::Set(d, 706.0))));
    return hn::IfThenElseZero(hn::Lt(ex, hn::Set(d, 706.0)),
                              hn::Mul(e, hn::Set(d, 0.3183098861837907)));
  }
};

AzimuthalDfgResult StudentTAzimuthalTexel(const StudentTNdf<double>& ndf, double mu,
                                          Masking masking, bool with_bias, double tol,
                                          int max_pieces) {
  const double g = ndf.gamma();
  if (std::isinf(g)) {
    return SlopeAzimuthalDfgWith(ndf, mu, masking, with_bias, tol, max_pieces,
                                 SimdSlopeNodes<BeckmannP22, BeckmannLambda>{});
  }
  return SlopeAzimuthalDfgWith(
      ndf, mu, masking, with_bias, tol, max_pieces,
      SimdSlopeNodes<StudentTP22, StudentTLambda>{{g, 1 / (g - 1)},
                                                 StudentTLambda{StudentTLambdaF64Consts(g)}});
}
#endif

// One piece of a ggx-aniso ray (aniso_ggx_rule.h, ScalarAnisoNodes) with
// its 16 nodes (15 and one of weight 0) in lanes: AnisoRay::Eval, the same
// operations in the same order.
struct SimdAnisoNodes {
  struct Rule {
    HWY_ALIGN double x[16], wk[16], wg[16];
    Rule() {
      const KronrodRule& r = Kronrod15();
      for (int i = 0; i < 16; ++i) {
        x[i] = i < 15 ? r.x[i] : 0.0;
        wk[i] = i < 15 ? r.wk[i] : 0.0;
        wg[i] = i < 15 ? r.wg[i] : 0.0;
      }
    }
  };
  void operator()(const AnisoFrame& f, const AnisoRay& ray, double v_b, double c, double h,
                  double* k, double* g) const {
    using V = hn::Vec<DF64>;
    static const Rule rule;
    const DF64 d;
    const size_t N = hn::Lanes(d);
    const V zero = hn::Zero(d), one = hn::Set(d, 1.0), two = hn::Set(d, 2.0);
    const V vb = hn::Set(d, v_b), two_vb = hn::Set(d, 2 * v_b);
    const V cv = hn::Set(d, c), hv = hn::Set(d, h);
    const V u_b = hn::Set(d, ray.u_b), omub = hn::Set(d, ray.one_minus_ub);
    const V ex = hn::Set(d, ray.ex), ey = hn::Set(d, ray.ey), ce = hn::Set(d, ray.ce);
    const V rho_b = hn::Set(d, ray.rho_b), isc = hn::Set(d, ray.inv_s_plus_ce);
    const V wz_ee = hn::Set(d, f.wz * ray.ee), two_wz = hn::Set(d, 2 * f.wz);
    const V wx = hn::Set(d, f.wx), wy = hn::Set(d, f.wy);
    const V fax = hn::Set(d, f.ax), fay = hn::Set(d, f.ay);
    const V zw = hn::Set(d, f.z_weight), gs = hn::Set(d, f.g_scale);
    V ks = zero, gsum = zero;
    for (size_t i = 0; i < 16; i += N) {
      const V x = hn::MulAdd(hv, hn::Load(d, rule.x + i), cv);
      const V w = hn::Mul(x, hn::Sub(two_vb, x));
      const V jac = hn::Mul(two, hn::Sub(vb, x));
      const V u = hn::Max(zero, hn::Sub(u_b, w));
      const V omu = hn::Add(omub, w);
      const V rho = hn::Sqrt(hn::Div(u, omu));
      const V p = hn::Mul(rho, ex), q = hn::Mul(rho, ey);
      const V n2 = hn::MulAdd(q, q, hn::MulAdd(p, p, one));
      const V lin = hn::MulAdd(rho, ce, one);
      const V m = hn::Mul(hn::Mul(omub, omu), hn::Add(rho_b, rho));
      const V z = hn::Mul(hn::Mul(wz_ee, w), hn::Add(rho, isc));
      const V kk = hn::Mul(two_wz, lin);
      const V X = hn::Neg(hn::Mul(hn::MulAdd(kk, p, hn::Mul(wx, n2)), m));
      const V Y = hn::Neg(hn::Mul(hn::MulAdd(kk, q, hn::Mul(wy, n2)), m));
      const V ax = hn::Mul(fax, X), ay = hn::Mul(fay, Y);
      const V root = hn::Sqrt(hn::MulAdd(z, z, hn::MulAdd(ax, ax, hn::Mul(ay, ay))));
      const V val = hn::Mul(hn::Div(hn::Mul(hn::Mul(two, z), lin), hn::MulAdd(zw, z, root)), gs);
      const auto valid = hn::And(hn::Gt(z, zero), hn::Gt(lin, zero));
      const V v = hn::Mul(hn::IfThenElseZero(valid, val), jac);
      ks = hn::MulAdd(hn::Load(d, rule.wk + i), v, ks);
      gsum = hn::MulAdd(hn::Load(d, rule.wg + i), v, gsum);
    }
    *k = hn::GetLane(hn::SumOfLanes(d, ks));
    *g = hn::GetLane(hn::SumOfLanes(d, gsum));
  }
};

// One piece of an ellipsoid ray (ellipsoid_albedo_rule.h,
// ScalarEllipsoidNodes) with its 16 nodes in lanes: EllipsoidRay::WiAt and
// the ellipsoid's Lambda (ellipsoid.h), with both sides of each branch
// computed and selected per lane.
struct SimdEllipsoidNodes {
  void operator()(const EllipsoidRay &ray, const double *a, const double *b, int n, double len,
                  double *k, double *g) const {
    using V = hn::Vec<DF64>;
    static const SimdAnisoNodes::Rule rule;
    const EllipsoidFrame &f = ray.f_;
    const DF64 d;
    const size_t N = hn::Lanes(d);
    const V zero = hn::Zero(d), one = hn::Set(d, 1.0), two = hn::Set(d, 2.0);
    const V lenv = hn::Set(d, len);
    const V x_hi = hn::Set(d, ray.x_hi_), x_lo = hn::Set(d, ray.x_lo_);
    const V omx2_hi = hn::Set(d, ray.omx2_hi_), omx2_lo = hn::Set(d, ray.omx2_lo_);
    const V rho_plus = hn::Set(d, ray.rho_plus_), rho_minus = hn::Set(d, ray.rho_minus_);
    const V ex = hn::Set(d, ray.ex_), ey = hn::Set(d, ray.ey_);
    const V wz_ee = hn::Set(d, f.wz * ray.ee_), two_wz = hn::Set(d, 2 * f.wz);
    const V s0x = hn::Set(d, f.s0x), s0y = hn::Set(d, f.s0y);
    const V cx = hn::Set(d, f.cx), cy = hn::Set(d, f.cy), wx = hn::Set(d, f.wx),
            wy = hn::Set(d, f.wy);
    V am[3][3];
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) am[i][j] = hn::Set(d, f.ndf.shape_matrix().m[i][j]);
    }
    const Vec3<double> &h_dir = f.ndf.lambda_h_dir();
    const V hx = hn::Set(d, h_dir.x), hy = hn::Set(d, h_dir.y), hz = hn::Set(d, h_dir.z);
    const double rho = f.ndf.lambda_rho();
    const V rho_v = hn::Set(d, rho), rho2 = hn::Set(d, rho * rho);
    const V omr2 = hn::Set(d, (1 - rho) * (1 + rho)), lscale = hn::Set(d, f.ndf.lambda_scale());
    const V lambda_o1 = hn::Set(d, 1 + f.lambda_o), g1o = hn::Set(d, 1 / (1 + f.lambda_o));
    const V tiny = hn::Set(d, std::numeric_limits<double>::min());
    // Piece by piece; the pieces are independent, so their dependency
    // chains (two square roots and two divisions deep) overlap.
    for (int j = 0; j < n; ++j) {
      const V cv = hn::Set(d, 0.5 * (a[j] + b[j])), hv = hn::Set(d, 0.5 * (b[j] - a[j]));
      V ks = zero, gsum = zero;
      for (size_t i = 0; i < 16; i += N) {
        const V o = hn::MulAdd(hv, hn::Load(d, rule.x + i), cv);
        const auto upper = hn::Ge(o, zero);
        const V y = hn::IfThenElse(upper, o, hn::Add(lenv, o));           // x_hi - x
        const V t = hn::IfThenElse(upper, hn::Sub(lenv, o), hn::Neg(o));  // x - x_lo
        const V x = hn::Sub(x_hi, y);
        const V omx2 =
            hn::IfThenElse(hn::Le(y, t), hn::MulAdd(y, hn::Sub(hn::Mul(two, x_hi), y), omx2_hi),
                           hn::NegMulAdd(t, hn::MulAdd(two, x_lo, t), omx2_lo));
        const auto ok1 = hn::And(hn::Gt(x, zero), hn::Gt(omx2, zero));
        const V omx2s = hn::IfThenElse(ok1, omx2, one);
        const V rho_n = hn::Div(x, hn::Sqrt(omx2s));
        // wi.z = wz |e|^2 (rho_+ - rho) (rho - rho_-) / N^2 and k = 2 wz lin /
        // N^2 as in EllipsoidRay::WiAt, the differences as quotients
        // num / den: r = 1 / (den_hi den_lo N^2) is their common factor.
        const V num_hi = hn::Mul(y, hn::Sub(hn::Mul(two, x_hi), y));
        const V den_hi = hn::Mul(hn::Mul(omx2_hi, omx2s), hn::Add(rho_plus, rho_n));
        const V num_lo =
            ray.lo_edge_ ? hn::Mul(t, hn::MulAdd(two, x_lo, t)) : hn::Sub(rho_n, rho_minus);
        const V den_lo =
            ray.lo_edge_ ? hn::Mul(hn::Mul(omx2_lo, omx2s), hn::Add(rho_n, rho_minus)) : one;
        const V p = hn::MulAdd(rho_n, ex, s0x), q = hn::MulAdd(rho_n, ey, s0y);
        const V n2 = hn::MulAdd(q, q, hn::MulAdd(p, p, one));
        const V lin = hn::MulAdd(q, cy, hn::MulAdd(p, cx, one));
        // wi times 1 / r = den_hi den_lo N^2 > 0, without a division:
        // Lambda is homogeneous of degree 0 in wi, and so is G2 below in
        // (wi.z dd, nn), so the scale drops out.
        const V dens = hn::Mul(den_hi, den_lo);
        const V dn = hn::Mul(dens, n2);
        const V wiz = hn::Mul(wz_ee, hn::Mul(num_hi, num_lo));
        const auto ok = hn::And(ok1, hn::And(hn::Gt(wiz, zero), hn::Gt(lin, zero)));
        const V kk = hn::Mul(hn::Mul(two_wz, lin), dens);
        const V wix = hn::Neg(hn::MulAdd(kk, p, hn::Mul(wx, dn)));
        const V wiy = hn::Neg(hn::MulAdd(kk, q, hn::Mul(wy, dn)));
        // Lambda(wi) = (nn / dd) scale / wi.z as in EllipsoidNdf::Lambda
        // (0 where nn <= 0, the clamp), and G2 from it with one division:
        // 1 / (1 + Lambda_o + Lambda_i) = wi.z dd / ((1 + Lambda_o) wi.z dd +
        // nn scale).
        const V ax = hn::MulAdd(am[0][2], wiz, hn::MulAdd(am[0][1], wiy, hn::Mul(am[0][0], wix)));
        const V ay = hn::MulAdd(am[1][2], wiz, hn::MulAdd(am[1][1], wiy, hn::Mul(am[1][0], wix)));
        const V az = hn::MulAdd(am[2][2], wiz, hn::MulAdd(am[2][1], wiy, hn::Mul(am[2][0], wix)));
        const V a_len = hn::Sqrt(hn::MulAdd(az, az, hn::MulAdd(ay, ay, hn::Mul(ax, ax))));
        const V ah = hn::MulAdd(az, hz, hn::MulAdd(ay, hy, hn::Mul(ax, hx)));
        const V px = hn::NegMulAdd(hx, ah, ax), py = hn::NegMulAdd(hy, ah, ay),
                pz = hn::NegMulAdd(hz, ah, az);
        const V perp2 = hn::MulAdd(pz, pz, hn::MulAdd(py, py, hn::Mul(px, px)));
        const auto pos = hn::Gt(ah, zero);
        const V nn = hn::IfThenElse(pos, hn::NegMulAdd(hn::Mul(omr2, ah), ah, hn::Mul(rho2, perp2)),
                                    hn::NegMulAdd(one, ah, hn::Mul(rho_v, a_len)));
        const V dd = hn::IfThenElse(pos, hn::MulAdd(rho_v, a_len, ah), one);
        const V wiz_dd = hn::Mul(hn::IfThenElse(ok, wiz, one), dd);
        const V nn_scale = hn::Mul(hn::ZeroIfNegative(nn), lscale);
        // (Kept off 0 / 0 where wi.z dd underflows.)
        const V g2 = f.separable
                         ? hn::Div(hn::Mul(g1o, wiz_dd), hn::Max(hn::Add(wiz_dd, nn_scale), tiny))
                         : hn::Div(wiz_dd, hn::Max(hn::MulAdd(lambda_o1, wiz_dd, nn_scale), tiny));
        const V v = hn::IfThenElseZero(ok, hn::Mul(hn::Mul(g2, lin), hn::Mul(two, x)));
        ks = hn::MulAdd(hn::Load(d, rule.wk + i), v, ks);
        gsum = hn::MulAdd(hn::Load(d, rule.wg + i), v, gsum);
      }
      k[j] = hn::GetLane(hn::SumOfLanes(d, ks));
      g[j] = hn::GetLane(hn::SumOfLanes(d, gsum));
    }
  }
};

AzimuthalResult EllipsoidAlbedoTexel(double alpha_x, double alpha_y, double theta_x,
                                     double theta_y, double theta_z, double mu, double phi,
                                     Masking masking, double tol, int max_pieces) {
  return EllipsoidAlbedoWith(alpha_x, alpha_y, theta_x, theta_y, theta_z, mu, phi, masking, tol,
                             max_pieces, SimdEllipsoidNodes{});
}

AzimuthalResult AnisoAlbedoTexel(double alpha_x, double alpha_y, double mu, double phi,
                                 Masking masking, double tol, int max_pieces) {
  return AnisoGgxAlbedoWith(alpha_x, alpha_y, mu, phi, masking, tol, max_pieces,
                            SimdAnisoNodes{});
}

AzimuthalDfgResult GgxDfgTexel(double alpha, double mu, Masking masking, double tol,
                               int max_pieces) {
  return GgxAzimuthalDfgWith(alpha, mu, masking, tol, max_pieces, SimdRemainderNodes());
}

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace brdfbake {

HWY_EXPORT(EllipsoidAlbedoTexel);
AzimuthalResult SimdEllipsoidAlbedo(double alpha_x, double alpha_y, double theta_x,
                                    double theta_y, double theta_z, double mu, double phi,
                                    Masking masking, double tol, int max_pieces) {
  return HWY_DYNAMIC_DISPATCH(EllipsoidAlbedoTexel)(alpha_x, alpha_y, theta_x, theta_y, theta_z,
                                                    mu, phi, masking, tol, max_pieces);
}

HWY_EXPORT(AnisoAlbedoTexel);
AzimuthalResult SimdAnisoGgxAlbedo(double alpha_x, double alpha_y, double mu, double phi,
                                   Masking masking, double tol, int max_pieces) {
  return HWY_DYNAMIC_DISPATCH(AnisoAlbedoTexel)(alpha_x, alpha_y, mu, phi, masking, tol,
                                                max_pieces);
}

HWY_EXPORT(GgxDfgTexel);
AzimuthalDfgResult SimdGgxAzimuthalDfg(double alpha, double mu, Masking masking, double tol,
                                       int max_pieces) {
  return HWY_DYNAMIC_DISPATCH(GgxDfgTexel)(alpha, mu, masking, tol, max_pieces);
}

#if BRDFBAKE_WITH_BECKMANN
HWY_EXPORT(BeckmannAzimuthalTexel);
AzimuthalDfgResult SimdSlopeAzimuthalDfg(const BeckmannNdf<double>& ndf, double mu,
                                         Masking masking, bool with_bias, double tol,
                                         int max_pieces) {
  return HWY_DYNAMIC_DISPATCH(BeckmannAzimuthalTexel)(ndf, mu, masking, with_bias, tol,
                                                      max_pieces);
}
#endif
#if BRDFBAKE_WITH_STD
HWY_EXPORT(StudentTAzimuthalTexel);
AzimuthalDfgResult SimdSlopeAzimuthalDfg(const StudentTNdf<double>& ndf, double mu, Masking masking,
                                         bool with_bias, double tol, int max_pieces) {
  return HWY_DYNAMIC_DISPATCH(StudentTAzimuthalTexel)(ndf, mu, masking, with_bias, tol,
                                                      max_pieces);
}
#endif

}  // namespace brdfbake
#endif  // HWY_ONCE
