// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Dynamic dispatch of the baker's one-dimensional rules with their
// azimuthal integrals in double SIMD lanes (quadrature_simd.h): the rules
// themselves are the templates of azimuthal.h and azimuthal_slope.h,
// instantiated per Highway target with node evaluators that take one
// piece's 16 nodes per loop.

#include <cstring>
#include <memory>
#include <limits>
#include <type_traits>

#include "quadrature_simd.h"

#include "aniso_ggx_rule.h"
#include "ellipsoid_albedo_rule.h"
#include "sel_norm_rule.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/quadrature_simd.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>
#include <hwy/contrib/math/math-inl.h>

#include "simd/beckmann_azimuth_f64-inl.h"
#include "simd/math_f64-inl.h"
#if BRDFBAKE_WITH_STD
#include "simd/std_f64-inl.h"
#endif


HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using DF64 = hn::ScalableTag<double>;

// A Kronrod piece's 15 nodes in 16 aligned lanes, the 16th repeating the
// first, so that every target runs whole vectors.
HWY_INLINE void NodesTo16(const double* nodes, double* out) {
  for (int i = 0; i < 15; ++i) out[i] = nodes[i];
  out[15] = nodes[0];
}

// The remainder of the Schlick-weighted azimuthal integral (azimuthal.h,
// ScalarRemainderNodes) with each piece's 16 nodes (15 and one of weight 0)
// in lanes. Returns the Kronrod value over all n pieces (the per-piece sums
// times their half widths, accumulated in lanes: one horizontal sum) and
// the error estimate, the sum of |K15 - G7| (one horizontal sum per piece,
// of the nodes times the weight differences).
struct SimdRemainderNodes {
  void operator()(const OddRemainder& rem, const AzimuthLadder::Piece* const* pieces, int n,
                  double* rem_k, double* rem_err) const {
    using V = hn::Vec<DF64>;
    const DF64 d;
    const size_t N = hn::Lanes(d);
    const AzimuthLadder& rule = AzimuthLadder::Get(3);
    V t[8];
    for (int m = 0; m < 8; ++m) t[m] = hn::Set(d, rem.t[m]);
    const V a = hn::Set(d, rem.a), vmin = hn::Set(d, rem.vmin), two_b = hn::Set(d, rem.two_b);
    V total = hn::Zero(d);
    double err = 0;
    for (int p = 0; p < n; ++p) {
      V ks = hn::Zero(d), ds = hn::Zero(d);
      for (size_t i = 0; i < 16; i += N) {
        const V b = hn::Sqrt(hn::MulAdd(two_b, hn::LoadU(d, pieces[p]->s2 + i), vmin));
        V acc = t[7];
        for (int m = 6; m >= 0; --m) acc = hn::MulAdd(acc, b, t[m]);
        const V ab = hn::Add(a, b);
        const V f = hn::Div(acc, hn::Mul(ab, ab));
        const V wk = hn::LoadU(d, rule.wk + i);
        ks = hn::MulAdd(wk, f, ks);
        ds = hn::MulAdd(hn::Sub(wk, hn::LoadU(d, rule.wg + i)), f, ds);
      }
      const double h = pieces[p]->half_width;
      total = hn::MulAdd(hn::Set(d, h), ks, total);
      err += std::abs(hn::GetLane(hn::SumOfLanes(d, ds))) * h;
    }
    *rem_k = hn::GetLane(hn::SumOfLanes(d, total));
    *rem_err = err;
  }
};

// sin and cos of t in [0, pi/2] from the smaller of t and its complement c
// (SinCosWithComplement of azimuthal.h); hn::Sin and hn::Cos are within 3
// ulp on [-39000, 39000] (Highway 1.0.3).
template <class V>
HWY_INLINE void SinCosWithComplement(DF64 d, V t, V c, V* sin_t, V* cos_t) {
  const auto t_le_c = hn::Le(t, c);
  const V x = hn::Min(t, c);
  const V sx = hn::Sin(d, x), cx = hn::Cos(d, x);
  *sin_t = hn::IfThenElse(t_le_c, sx, cx);
  *cos_t = hn::IfThenElse(t_le_c, cx, sx);
}

// AzimuthalFrame::AnglesAt in lanes: sin and cos of A and T, sin and cos
// of theta_i (cos clamped at 0), for the theta_i nodes t.
template <class V>
HWY_INLINE void FrameAngles(DF64 d, const AzimuthalFrame::FrameConsts& fc, V t, V* sa, V* ca, V* st,
                            V* ct, V* s_i, V* mu_i) {
  const V half = hn::Set(d, 0.5);
  const V theta_o = hn::Set(d, fc.theta_o), eps_o = hn::Set(d, fc.eps_o);
  const V eps_i = hn::Add(hn::Sub(hn::Set(d, AzimuthalFrame::kHalfPiHi), t),
                          hn::Set(d, AzimuthalFrame::kHalfPiLo));
  const V ht =
      fc.grazing_o ? hn::Mul(half, hn::Sub(eps_o, eps_i)) : hn::Mul(half, hn::Sub(t, theta_o));
  SinCosWithComplement(d, hn::Mul(half, hn::Add(t, theta_o)), hn::Mul(half, hn::Add(eps_i, eps_o)),
                       sa, ca);
  SinCosWithComplement(d, t, eps_i, s_i, mu_i);
  *st = hn::Sin(d, ht);
  *ct = hn::Cos(d, ht);
  *mu_i = hn::Max(hn::Zero(d), *mu_i);
}

// The azimuthal integrals of a slope-space model (azimuthal_slope.h,
// ScalarSlopeNodes) with each piece's 16 nodes in lanes: P22 from the
// model's lane function (BeckmannOverGgx's exponential, StudentTOverGgx's
// power, without their (1 + r2)^2 factor).
template <class P22, class LambdaF>
struct SimdSlopeNodes {
  static constexpr double kNegligibleR2 = P22::kNegligibleR2;
  P22 p22;
  LambdaF lambda;
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

// SlopeAzimuthalE::EvalPiece in lanes: the angles (AnglesAt), Lambda(wi),
// G2 and the azimuth's parameters of the 15 nodes of a theta_i piece
// together, then each node's azimuthal pieces (SimdSlopeNodes), the same
// operations as the scalar reference. The 16th lane repeats the first node.
template <class P22, class LambdaF>
struct SimdSlopeEval {
  SimdSlopeNodes<P22, LambdaF> nodes;
  AzimuthalFrame::FrameConsts fc;
  SlopeConsts sc;
  bool with_bias;

  void operator()(const double* theta, AzimuthalValues* out) const {
    using V = hn::Vec<DF64>;
    const DF64 d;
    const size_t N = hn::Lanes(d);
    HWY_ALIGN double th[16], w[16], cav[16], r2_0[16], r2_t[16], v_min[16], two_b[16];
    HWY_ALIGN double start[16], norm[16];
    NodesTo16(theta, th);
    const V zero = hn::Zero(d), one = hn::Set(d, 1.0), four = hn::Set(d, 4.0);
    const V alpha = hn::Set(d, sc.alpha), a2 = hn::Set(d, sc.alpha * sc.alpha);
    const V lambda_o = hn::Set(d, sc.lambda_o), scale = hn::Set(d, fc.scale);
    const V s_o = hn::Set(d, fc.s_o);
    for (size_t i = 0; i < 16; i += N) {
      V sa, ca, st, ct, s_i, mu_i;
      FrameAngles(d, fc, hn::Load(d, th + i), &sa, &ca, &st, &ct, &s_i, &mu_i);
      // a = cot(theta_i) / alpha: 0 (Lambda = inf) on the horizon.
      const V a = hn::IfThenElseZero(hn::Gt(mu_i, zero), hn::Div(mu_i, hn::Mul(alpha, s_i)));
      const V lambda_i = nodes.lambda(d, a);
      const V g2 = sc.separable
                       ? hn::Div(one, hn::Mul(hn::Add(one, lambda_i), hn::Add(one, lambda_o)))
                       : hn::Div(one, hn::Add(hn::Add(one, lambda_i), lambda_o));
      hn::Store(hn::Mul(hn::Mul(scale, g2), s_i), d, w + i);
      hn::Store(ca, d, cav + i);
      const V cc = hn::Mul(ca, ct);
      const V tb = hn::Mul(hn::Mul(four, s_i), s_o);
      hn::Store(hn::Div(hn::Mul(st, st), hn::Mul(hn::Mul(a2, ct), ct)), d, r2_0 + i);
      hn::Store(hn::Div(one, hn::Mul(hn::Mul(hn::Mul(four, a2), cc), cc)), d, r2_t + i);
      hn::Store(hn::Mul(hn::Mul(four, ca), ca), d, v_min + i);
      hn::Store(tb, d, two_b + i);
      // The ladder's start: the lobe's half width (and 2 cos A for Fc).
      const V b = hn::Mul(hn::Set(d, 0.5), tb);
      const V bs = hn::IfThenElse(hn::Gt(b, zero), b, one);
      V st_v = hn::IfThenElse(hn::Gt(b, zero),
                              hn::Mul(hn::Mul(alpha, cc), hn::Sqrt(hn::Div(hn::Set(d, 8.0), bs))),
                              hn::Inf(d));
      if (with_bias) st_v = hn::Min(st_v, hn::Mul(hn::Set(d, 2.0), ca));
      hn::Store(st_v, d, start + i);
      const V cc2 = hn::Mul(cc, cc);
      hn::Store(hn::Div(hn::Set(d, 2.0), hn::Mul(hn::Mul(hn::Mul(a2, hn::Set(d, 16.0)), cc2), cc2)),
                d, norm + i);
    }
    const AzimuthLadder& ladder = AzimuthLadder::Get(sc.ladder_ratio);
    for (int k = 0; k < 15; ++k) {
      AzimuthalValues& v = out[k];
      v = AzimuthalValues();
      if (!(w[k] > 0) || !(cav[k] > 0)) continue;
      SlopeAzimuth az;
      az.r2_0 = r2_0[k];
      az.r2_t = r2_t[k];
      az.v_min = v_min[k];
      az.two_b = two_b[k];
      az.with_bias = with_bias;
      v = SlopeAzimuthOnLadder(ladder, az, start[k], w[k] * norm[k], nodes);
    }
  }
};

// The slope-space rule with SimdSlopeEval's nodes.
template <class Ndf, class P22, class LambdaF>
AzimuthalDfgResult SimdSlopeTexel(const Ndf& ndf, double mu, Masking masking, bool with_bias,
                                  double tol, int max_pieces,
                                  const SimdSlopeNodes<P22, LambdaF>& nodes) {
  const SlopeAzimuthalE<Ndf> f(ndf, mu, masking, tol, with_bias);
  const SimdSlopeEval<P22, LambdaF> eval{nodes, f.frame_consts(), f.slope_consts(), with_bias};
  return AdaptiveAzimuthalRule(
      AzimuthalMesh(f.theta_o(), f.lambda_o(), f.alpha(), f.horizon_widen()), eval, tol,
      max_pieces);
}

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
  return SimdSlopeTexel(ndf, mu, masking, with_bias, tol, max_pieces,
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
    return SimdSlopeTexel(ndf, mu, masking, with_bias, tol, max_pieces,
                          SimdSlopeNodes<BeckmannP22, BeckmannLambda>{});
  }
  return SimdSlopeTexel(ndf, mu, masking, with_bias, tol, max_pieces,
                        SimdSlopeNodes<StudentTP22, StudentTLambda>{
                            {g, 1 / (g - 1)}, StudentTLambda{StudentTLambdaF64Consts(g)}});
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

// The ellipsoid rule's frame (EllipsoidFrame) in lanes, for the node
// evaluator and the rays' set-up below.
struct EllipsoidFrameLanes {
  using V = hn::Vec<DF64>;
  V zero, one, two, two_wz, s0x, s0y, cx, cy, wx, wy;
  V am[3][3];
  V hx, hy, hz, rho, rho2, omr2, lscale, lambda_o1, g1o, tiny;
  explicit EllipsoidFrameLanes(const EllipsoidFrame& f) {
    const DF64 d;
    zero = hn::Zero(d);
    one = hn::Set(d, 1.0);
    two = hn::Set(d, 2.0);
    two_wz = hn::Set(d, 2 * f.wz);
    s0x = hn::Set(d, f.s0x);
    s0y = hn::Set(d, f.s0y);
    cx = hn::Set(d, f.cx);
    cy = hn::Set(d, f.cy);
    wx = hn::Set(d, f.wx);
    wy = hn::Set(d, f.wy);
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) am[i][j] = hn::Set(d, f.ndf.shape_matrix().m[i][j]);
    }
    const Vec3<double>& h_dir = f.ndf.lambda_h_dir();
    hx = hn::Set(d, h_dir.x);
    hy = hn::Set(d, h_dir.y);
    hz = hn::Set(d, h_dir.z);
    const double r = f.ndf.lambda_rho();
    rho = hn::Set(d, r);
    rho2 = hn::Set(d, r * r);
    omr2 = hn::Set(d, (1 - r) * (1 + r));
    lscale = hn::Set(d, f.ndf.lambda_scale());
    lambda_o1 = hn::Set(d, 1 + f.lambda_o);
    g1o = hn::Set(d, 1 / (1 + f.lambda_o));
    tiny = hn::Set(d, std::numeric_limits<double>::min());
  }
};

// A ray's constants in lanes: one ray broadcast (the node evaluator) or a
// ray per lane (SetUpRays).
struct EllipsoidRayLanes {
  hn::Vec<DF64> x_hi, x_lo, omx2_hi, omx2_lo, rho_plus, rho_minus, ex, ey, wz_ee;
};

// a where c, else b: c whether a ray's lower end is a horizon crossing,
// one bool for a piece's nodes or a mask of a ray per lane.
HWY_INLINE hn::Vec<DF64> Pick(bool c, hn::Vec<DF64> a, hn::Vec<DF64> b) { return c ? a : b; }
HWY_INLINE hn::Vec<DF64> Pick(hn::Mask<DF64> c, hn::Vec<DF64> a, hn::Vec<DF64> b) {
  return hn::IfThenElse(c, a, b);
}

// EllipsoidRay::WiAt in lanes at y = x_hi - x, t = x - x_lo: x, sr =
// sqrt(1 - x^2), wi times a positive factor (w below), sr (1 + s.c), and
// whether wi is above the horizon (`ok`; WiAt's true).
// rho = x / sr is never formed: every quantity of WiAt is written over a
// power of sr (p sr, (1 + s.c) sr, ...), and wi is homogeneous: w = sr^3
// den_hi den_lo N^2 wi, times sr once more on a ray whose lower end is a
// horizon crossing. That saves a division per node.
struct EllipsoidWiLanes {
  hn::Vec<DF64> x, sr, wix, wiy, wiz, lin;
  hn::Mask<DF64> ok;
};
template <class LoEdge>
HWY_INLINE EllipsoidWiLanes EllipsoidWi(const EllipsoidFrameLanes& fr, const EllipsoidRayLanes& r,
                                        LoEdge lo_edge, hn::Vec<DF64> y, hn::Vec<DF64> t) {
  using V = hn::Vec<DF64>;
  EllipsoidWiLanes w;
  const V zero = fr.zero, two = fr.two;
  w.x = hn::Sub(r.x_hi, y);
  const V omx2 =
      hn::IfThenElse(hn::Le(y, t), hn::MulAdd(y, hn::Sub(hn::Mul(two, r.x_hi), y), r.omx2_hi),
                     hn::NegMulAdd(t, hn::MulAdd(two, r.x_lo, t), r.omx2_lo));
  const hn::Mask<DF64> ok1 = hn::And(hn::Gt(w.x, zero), hn::Gt(omx2, zero));
  const V omx2s = hn::IfThenElse(ok1, omx2, fr.one);
  w.sr = hn::Sqrt(omx2s);
  // rho_+ - rho = num_hi / den_hi and rho - rho_- = num_lo / den_lo as in
  // WiAt, here with den_hi = dh / sr, den_lo = dl / sr (a crossing at the
  // lower end) or num_lo = nl / sr.
  const V num_hi = hn::Mul(y, hn::Sub(hn::Mul(two, r.x_hi), y));
  const V dh = hn::Mul(hn::Mul(r.omx2_hi, omx2s), hn::MulAdd(w.sr, r.rho_plus, w.x));
  const V nl =
      Pick(lo_edge, hn::Mul(t, hn::MulAdd(two, r.x_lo, t)), hn::NegMulAdd(w.sr, r.rho_minus, w.x));
  const V dens =
      Pick(lo_edge,
           hn::Mul(dh, hn::Mul(hn::Mul(r.omx2_lo, omx2s), hn::MulAdd(w.sr, r.rho_minus, w.x))), dh);
  // sr (p, q) with p = s0x + rho ex, q = s0y + rho ey; sr^2 N^2 and sr (1 +
  // s.c).
  const V sp = hn::MulAdd(w.x, r.ex, hn::Mul(w.sr, fr.s0x));
  const V sq = hn::MulAdd(w.x, r.ey, hn::Mul(w.sr, fr.s0y));
  const V n2 = hn::MulAdd(sq, sq, hn::MulAdd(sp, sp, omx2s));
  w.lin = hn::MulAdd(sq, fr.cy, hn::MulAdd(sp, fr.cx, w.sr));
  // wi.z = wz |e|^2 (rho_+ - rho) (rho - rho_-) / N^2 and k = 2 wz (1 +
  // s.c) / N^2 as in WiAt, times den_hi den_lo N^2 > 0 (no division) and
  // sr^4: wiz's sr^-1 (num_lo) or sr^2 (den_lo) makes up the rest.
  const V dn = hn::Mul(dens, n2);
  w.wiz =
      hn::Mul(hn::Mul(r.wz_ee, hn::Mul(num_hi, nl)), Pick(lo_edge, hn::Mul(omx2s, omx2s), omx2s));
  w.ok = hn::And(ok1, hn::And(hn::Gt(w.wiz, zero), hn::Gt(w.lin, zero)));
  const V kk = hn::Mul(hn::Mul(fr.two_wz, w.lin), dens);
  w.wix = hn::Neg(hn::MulAdd(kk, sp, hn::Mul(fr.wx, dn)));
  w.wiy = hn::Neg(hn::MulAdd(kk, sq, hn::Mul(fr.wy, dn)));
  return w;
}

// Lambda(wi) = (nn / dd) scale / wi.z as in EllipsoidNdf::Lambda (0 where
// nn <= 0, the clamp), as the pair wiz_dd = wi.z dd (wi.z taken as 1 where
// wi is not above the horizon) and nn_scale = max(nn, 0) scale:
// homogeneous in wi, so the scale of EllipsoidWi's w drops out.
HWY_INLINE void EllipsoidLambdaParts(const EllipsoidFrameLanes& fr, const EllipsoidWiLanes& w,
                                     hn::Vec<DF64>* wiz_dd, hn::Vec<DF64>* nn_scale) {
  using V = hn::Vec<DF64>;
  const V ax =
      hn::MulAdd(fr.am[0][2], w.wiz, hn::MulAdd(fr.am[0][1], w.wiy, hn::Mul(fr.am[0][0], w.wix)));
  const V ay =
      hn::MulAdd(fr.am[1][2], w.wiz, hn::MulAdd(fr.am[1][1], w.wiy, hn::Mul(fr.am[1][0], w.wix)));
  const V az =
      hn::MulAdd(fr.am[2][2], w.wiz, hn::MulAdd(fr.am[2][1], w.wiy, hn::Mul(fr.am[2][0], w.wix)));
  const V a_len = hn::Sqrt(hn::MulAdd(az, az, hn::MulAdd(ay, ay, hn::Mul(ax, ax))));
  const V ah = hn::MulAdd(az, fr.hz, hn::MulAdd(ay, fr.hy, hn::Mul(ax, fr.hx)));
  const V px = hn::NegMulAdd(fr.hx, ah, ax), py = hn::NegMulAdd(fr.hy, ah, ay),
          pz = hn::NegMulAdd(fr.hz, ah, az);
  const V perp2 = hn::MulAdd(pz, pz, hn::MulAdd(py, py, hn::Mul(px, px)));
  const hn::Mask<DF64> pos = hn::Gt(ah, fr.zero);
  const V nn = hn::IfThenElse(pos, hn::NegMulAdd(hn::Mul(fr.omr2, ah), ah, hn::Mul(fr.rho2, perp2)),
                              hn::NegMulAdd(fr.one, ah, hn::Mul(fr.rho, a_len)));
  const V dd = hn::IfThenElse(pos, hn::MulAdd(fr.rho, a_len, ah), fr.one);
  *wiz_dd = hn::Mul(hn::IfThenElse(w.ok, w.wiz, fr.one), dd);
  *nn_scale = hn::Mul(hn::ZeroIfNegative(nn), fr.lscale);
}

// The ellipsoid rule's work in lanes (ellipsoid_albedo_rule.h, against
// ScalarEllipsoidNodes): one piece of a ray with its 16 nodes in lanes
// (operator(): EllipsoidRay::At, its half and map chosen per piece,
// hn::Expm1, 4 ulp, for std::expm1; EllipsoidRay::WiAt and the
// ellipsoid's Lambda, ellipsoid.h, with both sides of each other branch
// computed and selected per lane); a psi piece's rays set up a ray per
// lane (SetUpRays); the brackets of their kinks' quartics searched a
// bracket per lane (SearchRoots).
struct SimdEllipsoidNodes {
  // InterleavedRootSearch (poly_roots.h) in lanes, a task per lane: the same
  // steps (Horner's rule with fused multiply-adds, so each root agrees
  // with the scalar search's to the tasks' tolerance, not bit for bit),
  // lanes masked off as their tasks end. Quartics and cubics alike, a
  // cubic's c[4] being 0.
  void SearchRoots(RootTask* tasks, int m) const {
    const DF64 d;
    using V = hn::Vec<DF64>;
    using M = hn::Mask<DF64>;
    constexpr size_t kN = hn::MaxLanes(DF64());
    HWY_ALIGN double buf[kMaxPolyDegree + 5][kN];
    const V zero = hn::Zero(d), half = hn::Set(d, 0.5), one = hn::Set(d, 1.0);
    for (int t0 = 0; t0 < m; t0 += static_cast<int>(kN)) {
      const int lanes = std::min(static_cast<int>(kN), m - t0);
      // Rows: c[0..4], a, b, pa, tol; lanes past the tasks start done.
      for (size_t i = 0; i < kN; ++i) {
        const bool real = static_cast<int>(i) < lanes;
        const RootTask& t = tasks[t0 + (real ? i : 0)];
        for (int k = 0; k <= kMaxPolyDegree; ++k) buf[k][i] = k <= t.n ? t.c[k] : 0.0;
        buf[5][i] = t.r.a;
        buf[6][i] = t.r.b;
        buf[7][i] = t.r.pa;
        buf[8][i] = real ? t.r.tol : HUGE_VAL;
      }
      V c[kMaxPolyDegree + 1];
      for (int k = 0; k <= kMaxPolyDegree; ++k) c[k] = hn::Load(d, buf[k]);
      V a = hn::Load(d, buf[5]), b = hn::Load(d, buf[6]);
      const M pa_pos = hn::Gt(hn::Load(d, buf[7]), zero);
      const V tol = hn::Load(d, buf[8]), half_tol = hn::Mul(half, tol);
      V x = hn::Mul(half, hn::Add(a, b));
      V it = zero;
      const V most = hn::Set(d, 100.0);
      M done = hn::Not(hn::And(hn::Lt(it, most), hn::Gt(hn::Sub(b, a), tol)));
      while (!hn::AllTrue(d, done)) {
        V v = c[kMaxPolyDegree], dv = zero;
        for (int k = kMaxPolyDegree - 1; k >= 0; --k) {
          dv = hn::MulAdd(dv, x, v);
          v = hn::MulAdd(v, x, c[k]);
        }
        it = hn::Add(it, one);
        const M hit = hn::AndNot(done, hn::Eq(v, zero));
        const M live = hn::Not(hn::Or(done, hit));
        const M same = hn::Not(hn::Xor(hn::Gt(v, zero), pa_pos));
        a = hn::IfThenElse(hn::And(live, same), x, a);
        b = hn::IfThenElse(hn::AndNot(same, live), x, b);
        const V step = hn::Div(v, dv);
        const M converged = hn::And(live, hn::Le(hn::Abs(step), half_tol));
        const V newton = hn::Sub(x, step);
        const M inside = hn::And(hn::Gt(newton, a), hn::Lt(newton, b));
        const V next = hn::IfThenElse(converged, hn::Min(hn::Max(newton, a), b),
                                      hn::IfThenElse(inside, newton, hn::Mul(half, hn::Add(a, b))));
        x = hn::IfThenElse(live, next, x);
        done = hn::Or(hn::Or(done, hit), converged);
        done = hn::Or(done, hn::Not(hn::And(hn::Lt(it, most), hn::Gt(hn::Sub(b, a), tol))));
      }
      HWY_ALIGN double out[kN];
      hn::Store(x, d, out);
      for (int i = 0; i < lanes; ++i) *tasks[t0 + i].out = out[i];
    }
  }
  // ScalarEllipsoidNodes::SetUpRays (EllipsoidRay::SetUp) with a ray per
  // lane: hn::Cos and hn::Sin (3 ulp in double, against the C library's;
  // |psi| < 4 pi here, in their range), the same steps with both sides of
  // each branch selected per lane, and the rise widths' probes by
  // EllipsoidWi and EllipsoidLambdaParts.
  void SetUpRays(EllipsoidRay* rays, int n) const {
    if (n == 0) return;
    using V = hn::Vec<DF64>;
    using M = hn::Mask<DF64>;
    const DF64 d;
    constexpr size_t kN = hn::MaxLanes(DF64());
    const EllipsoidFrame& f = rays[0].f_;
    const EllipsoidFrameLanes fr(f);
    const V zero = fr.zero, one = fr.one, half = hn::Set(d, 0.5);
    const V l11 = hn::Set(d, f.l11), l12 = hn::Set(d, f.l12), l22 = hn::Set(d, f.l22);
    const V dx = hn::Set(d, f.dx), dy = hn::Set(d, f.dy), d2r2 = hn::Set(d, f.d2_minus_r2);
    const V wz = hn::Set(d, f.wz), probe = hn::Set(d, kLayerProbe);
    // 0.5 o / scale, scale = 1 + Lambda(wo) (height-correlated) or 1.
    const V rise_scale = hn::Set(d, 0.5 / (f.separable ? 1.0 : 1 + f.lambda_o));
    enum Field {
      kEx,
      kEy,
      kEe,
      kRhoMinus,
      kRhoPlus,
      kOmx2Lo,
      kOmx2Hi,
      kXLo,
      kXHi,
      kLen,
      kMid,
      kCHi,
      kCLo,
      kLoEdge,
      kValid,
      kSpanHi,
      kSpanLo,
      kKinks,
      kKinkC,
      kKinkAh = kKinkC + 5,
      kKinkLo = kKinkAh + 3,
      kKinkSc,
      kFields
    };
    // EllipsoidRay::SetUpKinkQuartic's constants: w[0], l0, m0.
    constexpr double kTwoPi = 2 * kPi<double>;
    const double l0 = f.wz - f.wx * f.s0x - f.wy * f.s0y;
    const double m0 = 1 + f.s0x * f.s0x + f.s0y * f.s0y;
    const Vec3<double> n0(-f.s0x, -f.s0y, 1), wo_d(f.wx, f.wy, f.wz);
    const Vec3<double> w0 = n0 * (2 * l0) - wo_d * m0;
    const Vec3<double> a0 = f.ndf.shape_matrix() * w0;
    const Vec3<double>& h_dir = f.ndf.lambda_h_dir();
    const double ah0 = Dot(a0, h_dir);
    const Vec3<double> ap0 = a0 - h_dir * ah0;
    const double rc = f.ndf.lambda_rho();
    const V rc2 = hn::Set(d, rc * rc), omr2 = hn::Set(d, (1 - rc) * (1 + rc));
    const V psi0 = hn::Set(d, f.kink_psi0), psi_range = hn::Set(d, f.kink_psi_range);
    const V rho_cap = hn::Set(d, f.kink_rho_max);
    const V two_pi = hn::Set(d, kTwoPi), inv_two_pi = hn::Set(d, 1 / kTwoPi);
    HWY_ALIGN double in[kN], out[kFields][kN];
    for (int i0 = 0; i0 < n; i0 += static_cast<int>(kN)) {
      const int lanes = std::min(static_cast<int>(kN), n - i0);
      for (size_t i = 0; i < kN; ++i)
        in[i] = rays[i0 + std::min(static_cast<int>(i), lanes - 1)].psi_;
      const V psi = hn::Load(d, in);
      const V cs = hn::Cos(d, psi), sn = hn::Sin(d, psi);
      EllipsoidRayLanes r;
      r.ex = hn::MulAdd(l11, cs, hn::Mul(l12, sn));
      r.ey = hn::Mul(l22, sn);
      const V ee = hn::MulAdd(r.ex, r.ex, hn::Mul(r.ey, r.ey));
      r.wz_ee = hn::Mul(wz, ee);
      const V de = hn::MulAdd(dx, r.ex, hn::Mul(dy, r.ey));
      const V disc = hn::NegMulAdd(ee, d2r2, hn::Mul(de, de));
      const M has_roots = hn::Gt(disc, zero);
      // The roots of ee rho^2 + 2 de rho + (|d|^2 - R^2), without
      // cancellation: q = -(de + sign(de) sqrt(disc)).
      const V root = hn::Sqrt(hn::IfThenElse(has_roots, disc, one));
      const V q = hn::Neg(hn::Add(de, hn::CopySign(root, de)));
      const V r1 = hn::Div(q, ee), r2 = hn::Div(d2r2, hn::IfThenElse(has_roots, q, one));
      r.rho_minus = hn::Min(r1, r2);
      r.rho_plus = hn::Max(r1, r2);
      const M ahead = hn::And(has_roots, hn::Gt(r.rho_plus, zero));
      const M lo_edge = hn::And(ahead, hn::Gt(r.rho_minus, zero));
      const V lo = hn::ZeroIfNegative(r.rho_minus);
      r.omx2_lo = hn::Div(one, hn::MulAdd(lo, lo, one));
      r.omx2_hi = hn::Div(one, hn::MulAdd(r.rho_plus, r.rho_plus, one));
      r.x_lo = hn::Mul(lo, hn::Sqrt(r.omx2_lo));
      r.x_hi = hn::Mul(r.rho_plus, hn::Sqrt(r.omx2_hi));
      const M valid = hn::And(ahead, hn::Gt(r.x_hi, r.x_lo));
      const V len = hn::Sub(r.x_hi, r.x_lo), mid = hn::Mul(half, len);
      // EllipsoidRay::RiseWidth: Lambda(wi) probed at kLayerProbe of each
      // half from its end (0 where the probe fails); the upper one at most
      // 0.5 omx2_hi / x_hi.
      const V o_hi = hn::Mul(probe, mid), o_lo = hn::Mul(probe, hn::Sub(len, mid));
      V c[2];
      for (int lower = 0; lower < 2; ++lower) {
        const V o = lower ? o_lo : o_hi;
        const V y = lower ? hn::Sub(len, o) : o, t = lower ? o : hn::Sub(len, o);
        const EllipsoidWiLanes w = EllipsoidWi(fr, r, lo_edge, y, t);
        V wiz_dd, nn_scale;
        EllipsoidLambdaParts(fr, w, &wiz_dd, &nn_scale);
        const V lambda = hn::Div(nn_scale, wiz_dd);
        c[lower] = hn::IfThenElseZero(w.ok, hn::Mul(hn::Mul(rise_scale, o), lambda));
      }
      const V c_hi = hn::Min(c[0], hn::Div(hn::Mul(half, r.omx2_hi), r.x_hi));
      const V c_lo = hn::IfThenElseZero(lo_edge, c[1]);
      hn::Store(r.ex, d, out[kEx]);
      hn::Store(r.ey, d, out[kEy]);
      hn::Store(ee, d, out[kEe]);
      hn::Store(r.rho_minus, d, out[kRhoMinus]);
      hn::Store(r.rho_plus, d, out[kRhoPlus]);
      hn::Store(r.omx2_lo, d, out[kOmx2Lo]);
      hn::Store(r.omx2_hi, d, out[kOmx2Hi]);
      hn::Store(r.x_lo, d, out[kXLo]);
      hn::Store(r.x_hi, d, out[kXHi]);
      hn::Store(len, d, out[kLen]);
      hn::Store(mid, d, out[kMid]);
      hn::Store(c_hi, d, out[kCHi]);
      hn::Store(c_lo, d, out[kCLo]);
      hn::Store(hn::IfThenElseZero(lo_edge, one), d, out[kLoEdge]);
      hn::Store(hn::IfThenElseZero(valid, one), d, out[kValid]);
      // The halves' spans (EllipsoidRay::SetUp): hn::Log1p, 2 ulp.
      const V span_hi = hn::IfThenElse(
          hn::Gt(c_hi, zero),
          hn::Log1p(d, hn::Div(mid, hn::IfThenElse(hn::Gt(c_hi, zero), c_hi, one))), mid);
      const V lower_half = hn::Sub(len, mid);
      const V span_lo = hn::IfThenElse(
          hn::Gt(c_lo, zero),
          hn::Log1p(d, hn::Div(lower_half, hn::IfThenElse(hn::Gt(c_lo, zero), c_lo, one))),
          lower_half);
      hn::Store(span_hi, d, out[kSpanHi]);
      hn::Store(span_lo, d, out[kSpanLo]);
      // EllipsoidRay::SetUpKinkQuartic in lanes.
      const V from0 = hn::NegMulAdd(two_pi, hn::Floor(hn::Mul(hn::Sub(psi, psi0), inv_two_pi)),
                                    hn::Sub(psi, psi0));
      // t = rho / sc, sc = min(rho_+, the edge's reach).
      const V sc = hn::Min(r.rho_plus, rho_cap);
      const V kink_lo = hn::Div(hn::ZeroIfNegative(r.rho_minus), sc);
      const M kinks = hn::And(hn::And(valid, hn::Le(from0, psi_range)), hn::Lt(kink_lo, one));
      hn::Store(hn::IfThenElseZero(kinks, one), d, out[kKinks]);
      hn::Store(sc, d, out[kKinkSc]);
      hn::Store(kink_lo, d, out[kKinkLo]);
      {
        const V l1 = hn::Neg(hn::MulAdd(fr.wx, r.ex, hn::Mul(fr.wy, r.ey)));
        const V m1 = hn::Mul(fr.two, hn::MulAdd(fr.s0x, r.ex, hn::Mul(fr.s0y, r.ey)));
        const V sc2 = hn::Mul(sc, sc);
        const V l0v = hn::Set(d, l0);
        // w1 = (n1 l0 + n0 l1) 2 sc - wo m1 sc, w2 = (n1 2 l1 - wo ee) sc^2,
        // n1 = (-ex, -ey, 0).
        const V two_sc = hn::Mul(fr.two, sc), m1sc = hn::Mul(m1, sc);
        V w[3][3];
        w[1][0] = hn::NegMulAdd(
            fr.wx, m1sc, hn::Mul(two_sc, hn::NegMulAdd(r.ex, l0v, hn::Mul(hn::Neg(fr.s0x), l1))));
        w[1][1] = hn::NegMulAdd(
            fr.wy, m1sc, hn::Mul(two_sc, hn::NegMulAdd(r.ey, l0v, hn::Mul(hn::Neg(fr.s0y), l1))));
        w[1][2] = hn::NegMulAdd(wz, m1sc, hn::Mul(two_sc, l1));
        const V two_l1 = hn::Mul(fr.two, l1);
        w[2][0] = hn::Mul(sc2, hn::NegMulAdd(fr.wx, ee, hn::Mul(hn::Neg(r.ex), two_l1)));
        w[2][1] = hn::Mul(sc2, hn::NegMulAdd(fr.wy, ee, hn::Mul(hn::Neg(r.ey), two_l1)));
        w[2][2] = hn::Mul(sc2, hn::Neg(hn::Mul(wz, ee)));
        V ah[3], ap[3][3];
        ah[0] = hn::Set(d, ah0);
        for (int i = 0; i < 3; ++i) ap[0][i] = hn::Set(d, ap0[i]);
        for (int k = 1; k < 3; ++k) {
          V a[3];
          for (int i = 0; i < 3; ++i) {
            a[i] = hn::MulAdd(fr.am[i][2], w[k][2],
                              hn::MulAdd(fr.am[i][1], w[k][1], hn::Mul(fr.am[i][0], w[k][0])));
          }
          ah[k] = hn::MulAdd(a[2], fr.hz, hn::MulAdd(a[1], fr.hy, hn::Mul(a[0], fr.hx)));
          ap[k][0] = hn::NegMulAdd(fr.hx, ah[k], a[0]);
          ap[k][1] = hn::NegMulAdd(fr.hy, ah[k], a[1]);
          ap[k][2] = hn::NegMulAdd(fr.hz, ah[k], a[2]);
        }
        V c[5] = {zero, zero, zero, zero, zero};
        for (int i = 0; i < 3; ++i) {
          for (int j = 0; j < 3; ++j) {
            const V dot = hn::MulAdd(ap[i][2], ap[j][2],
                                     hn::MulAdd(ap[i][1], ap[j][1], hn::Mul(ap[i][0], ap[j][0])));
            c[i + j] =
                hn::Add(c[i + j], hn::MulSub(rc2, dot, hn::Mul(omr2, hn::Mul(ah[i], ah[j]))));
          }
        }
        for (int i = 0; i < 5; ++i) hn::Store(c[i], d, out[kKinkC + i]);
        for (int i = 0; i < 3; ++i) hn::Store(ah[i], d, out[kKinkAh + i]);
      }
      for (int i = 0; i < lanes; ++i) {
        EllipsoidRay& ray = rays[i0 + i];
        ray.ex_ = out[kEx][i];
        ray.ey_ = out[kEy][i];
        ray.ee_ = out[kEe][i];
        ray.valid_ = out[kValid][i] > 0;
        if (!ray.valid_) continue;
        ray.rho_minus_ = out[kRhoMinus][i];
        ray.rho_plus_ = out[kRhoPlus][i];
        ray.lo_edge_ = out[kLoEdge][i] > 0;
        ray.omx2_lo_ = out[kOmx2Lo][i];
        ray.omx2_hi_ = out[kOmx2Hi][i];
        ray.x_lo_ = out[kXLo][i];
        ray.x_hi_ = out[kXHi][i];
        ray.len_ = out[kLen][i];
        ray.mid_ = out[kMid][i];
        ray.c_hi_ = out[kCHi][i];
        ray.c_lo_ = out[kCLo][i];
        ray.span_hi_ = out[kSpanHi][i];
        ray.span_lo_ = out[kSpanLo][i];
        ray.kinks_ = out[kKinks][i] > 0;
        for (int c = 0; c < 5; ++c) ray.kink_c_[c] = out[kKinkC + c][i];
        for (int c = 0; c < 3; ++c) ray.kink_ah_[c] = out[kKinkAh + c][i];
        ray.kink_lo_ = out[kKinkLo][i];
        ray.kink_sc_ = out[kKinkSc][i];
      }
    }
  }

  void operator()(const EllipsoidRay* const* rays, const double* a, const double* b, int n,
                  double* k, double* g) const {
    if (n == 0) return;
    using V = hn::Vec<DF64>;
    static const SimdAnisoNodes::Rule rule;
    const EllipsoidFrame& f = rays[0]->f_;  // the same for every ray
    const EllipsoidFrameLanes fr(f);
    const DF64 d;
    // The kK vectors of a piece's nodes advance together, stage by stage:
    // each one's dependency chain (an expm1, two square roots and a
    // division deep) is longer than the core can look ahead within one
    // vector's instructions, and interleaving the chains lets it overlap
    // them.
    constexpr size_t kN = hn::MaxLanes(DF64());
    constexpr size_t kK = 16 / kN;
    for (int j = 0; j < n; ++j) {
      const EllipsoidRay& ray = *rays[j];
      EllipsoidRayLanes r;
      r.x_hi = hn::Set(d, ray.x_hi_);
      r.x_lo = hn::Set(d, ray.x_lo_);
      r.omx2_hi = hn::Set(d, ray.omx2_hi_);
      r.omx2_lo = hn::Set(d, ray.omx2_lo_);
      r.rho_plus = hn::Set(d, ray.rho_plus_);
      r.rho_minus = hn::Set(d, ray.rho_minus_);
      r.ex = hn::Set(d, ray.ex_);
      r.ey = hn::Set(d, ray.ey_);
      r.wz_ee = hn::Set(d, f.wz * ray.ee_);
      const V lenv = hn::Set(d, ray.len_);
      const V cv = hn::Set(d, 0.5 * (a[j] + b[j])), hv = hn::Set(d, 0.5 * (b[j] - a[j]));
      // A piece lies in one half of its ray (Layout): its side, and
      // whether that half is mapped, hold for all its nodes.
      const bool upper = a[j] + b[j] >= 0;
      const double c_piece = upper ? ray.c_hi_ : ray.c_lo_;
      const bool mapped = c_piece > 0;
      const V c = hn::Set(d, c_piece);
      V off[kK];
      for (size_t u = 0; u < kK; ++u) {
        const V tau = hn::Abs(hn::MulAdd(hv, hn::Load(d, rule.x + u * kN), cv));
        off[u] = mapped ? hn::Mul(c, hn::Expm1(d, tau)) : tau;
      }
      EllipsoidWiLanes w[kK];
      for (size_t u = 0; u < kK; ++u) {
        const V y = upper ? off[u] : hn::Sub(lenv, off[u]);  // x_hi - x
        const V t = upper ? hn::Sub(lenv, off[u]) : off[u];  // x - x_lo
        w[u] = EllipsoidWi(fr, r, ray.lo_edge_, y, t);
      }
      V wiz_dd[kK], nn_scale[kK];
      for (size_t u = 0; u < kK; ++u) EllipsoidLambdaParts(fr, w[u], &wiz_dd[u], &nn_scale[u]);
      V ks = fr.zero, gsum = fr.zero;
      for (size_t u = 0; u < kK; ++u) {
        // G2 (1 + s.c) 2 x with one division: 1 / (1 + Lambda_o +
        // Lambda_i) = wi.z dd / ((1 + Lambda_o) wi.z dd + nn scale), which
        // also takes lin's sr; (kept off 0 / 0 where wi.z dd underflows).
        const V num = hn::Mul(hn::Mul(wiz_dd[u], w[u].lin), hn::Mul(fr.two, w[u].x));
        const V den = f.separable
                          ? hn::Mul(w[u].sr, hn::Add(wiz_dd[u], nn_scale[u]))
                          : hn::Mul(w[u].sr, hn::MulAdd(fr.lambda_o1, wiz_dd[u], nn_scale[u]));
        const V f2 = hn::Div(f.separable ? hn::Mul(fr.g1o, num) : num, hn::Max(den, fr.tiny));
        // Times the map's Jacobian, y + c or t + c.
        const V v = hn::IfThenElseZero(w[u].ok, mapped ? hn::Mul(f2, hn::Add(off[u], c)) : f2);
        ks = hn::MulAdd(hn::Load(d, rule.wk + u * kN), v, ks);
        gsum = hn::MulAdd(hn::Load(d, rule.wg + u * kN), v, gsum);
      }
      k[j] = hn::GetLane(hn::SumOfLanes(d, ks));
      g[j] = hn::GetLane(hn::SumOfLanes(d, gsum));
    }
  }
};

void SetUpEllipsoidRaysLanes(EllipsoidRay* rays, int n) { SimdEllipsoidNodes().SetUpRays(rays, n); }

void PolyRootsLanes(PolyRootsProblem* problems, int m) {
  PolyRootsInBatch(problems, m,
                   [](RootTask* tasks, int n) { SimdEllipsoidNodes().SearchRoots(tasks, n); });
}

AzimuthalResult EllipsoidAlbedoTexel(double alpha_x, double alpha_y, double theta_x, double theta_y,
                                     double theta_z, double mu, double phi, Masking masking,
                                     double tol, int max_pieces) {
  return EllipsoidAlbedoWith(alpha_x, alpha_y, theta_x, theta_y, theta_z, mu, phi, masking, tol,
                             max_pieces, SimdEllipsoidNodes{});
}

// ScalarSelNodes (sel_norm_rule.h) with the 15 angles in lanes (the 16th
// repeats the first): cos and sin by Highway's Cos and Sin (3 ulp in
// double, against the C library's), the rest the same operations.
struct SimdSelNodes {
  void operator()(const SelPhiTerms& t, const double* phi, double* g) const {
    using V = hn::Vec<DF64>;
    const DF64 d;
    const size_t N = hn::Lanes(d);
    HWY_ALIGN double p[16], out[16];
    NodesTo16(phi, p);
    const V s2 = hn::Set(d, t.s2), c2 = hn::Set(d, t.c * t.c);
    const V ikx2 = hn::Set(d, t.ikx2), iky2 = hn::Set(d, t.iky2), one = hn::Set(d, 1.0);
    for (size_t i = 0; i < 16; i += N) {
      const V x = hn::Load(d, p + i);
      const V cp = hn::Cos(d, x), sp = hn::Sin(d, x);
      const V q = hn::Add(
          hn::Mul(s2, hn::Add(hn::Mul(hn::Mul(cp, cp), ikx2), hn::Mul(hn::Mul(sp, sp), iky2))), c2);
      hn::Store(hn::Div(one, hn::Sqrt(q)), d, out + i);
    }
    for (int i = 0; i < 15; ++i) g[i] = out[i];
  }
};

SelIntegral SelLobeTexel(double alpha_x, double alpha_y, double tol) {
  return SelLobeIntegralWith(alpha_x, alpha_y, tol, SimdSelNodes{});
}

AzimuthalResult AnisoAlbedoTexel(double alpha_x, double alpha_y, double mu, double phi,
                                 Masking masking, double tol, int max_pieces) {
  return AnisoGgxAlbedoWith(alpha_x, alpha_y, mu, phi, masking, tol, max_pieces,
                            SimdAnisoNodes{});
}

// GgxAzimuthalE at the 15 nodes of one theta_i piece in lanes: its
// operator() (E's integrand, Albedo) and EvalDfg (operator()), with
// everything but the remainder's azimuthal nodes in lanes: the angles
// (AnglesAt), Phi, G2 and the closed-form moments, the same operations as
// the scalar reference, then the remainder node by node
// (SimdRemainderNodes). The 16th lane repeats the first node.
struct SimdGgxNodes {
  AzimuthalFrame::FrameConsts fc;
  GgxAzimuthalE::DfgConsts gc;

  // Per node: E's integrand, and for dfg the weight w norm of the bias, the
  // closed part, and the remainder's a = sqrt(kappa), vmin, 2 B and start
  // 2 cos A.
  struct Terms {
    HWY_ALIGN double e[16], wn[16], closed[16], sk[16], vmin[16], two_bb[16], start[16];
  };

  void Albedo(const double* theta, double* out) const {
    Terms terms;
    Front<false>(theta, &terms);
    for (int i = 0; i < 15; ++i) out[i] = terms.e[i];
  }

  void operator()(const double* theta, AzimuthalValues* out) const {
    Terms terms;
    Front<true>(theta, &terms);
    const double *e = terms.e, *wn = terms.wn, *closed = terms.closed, *sk = terms.sk,
                 *vmin = terms.vmin, *two_bb = terms.two_bb, *start = terms.start;
    const AzimuthLadder& ladder = AzimuthLadder::Get(3);
    const SimdRemainderNodes nodes;
    for (int i = 0; i < 15; ++i) {
      AzimuthalValues& v = out[i];
      v = AzimuthalValues();
      v.e = e[i];
      if (!(wn[i] > 0)) continue;
      const OddRemainder rem(sk[i], vmin[i], two_bb[i]);
      const AzimuthLadder::Piece* used[AzimuthLadder::kMaxPieces];
      const int pieces = ladder.Select(start[i], used);
      double rem_k, rem_err;
      nodes(rem, used, pieces, &rem_k, &rem_err);
      v.bias = wn[i] * (closed[i] - 2 * rem_k);
      v.bias_error = wn[i] * 2 * rem_err;
    }
  }

 private:
  template <bool kDfg>
  void Front(const double* theta, Terms* terms) const {
    using V = hn::Vec<DF64>;
    const DF64 d;
    const size_t N = hn::Lanes(d);
    constexpr double kTwoPi = 6.283185307179586;
    HWY_ALIGN double th[16];
    NodesTo16(theta, th);
    double *e = terms->e, *wn = terms->wn, *closed = terms->closed, *sk = terms->sk,
           *vmin = terms->vmin, *two_bb = terms->two_bb, *start = terms->start;
    const V half = hn::Set(d, 0.5), one = hn::Set(d, 1.0), two = hn::Set(d, 2.0),
            four = hn::Set(d, 4.0), zero = hn::Zero(d), two_pi = hn::Set(d, kTwoPi);
    const V a2 = hn::Set(d, gc.a2), b = hn::Set(d, gc.b);
    const V lambda_o1 = hn::Set(d, 1 + gc.lambda_o), scale = hn::Set(d, fc.scale);
    const V s_o = hn::Set(d, fc.s_o), norm = hn::Set(d, gc.a2 / 3.141592653589793);
    for (size_t i = 0; i < 16; i += N) {
      V sa, ca, st, ct, s_i, mu_i;
      FrameAngles(d, fc, hn::Load(d, th + i), &sa, &ca, &st, &ct, &s_i, &mu_i);
      // PhiAt.
      const V x = hn::MulAdd(hn::Mul(a2, ct), ct, hn::Mul(st, st));
      const V y = hn::MulAdd(hn::Mul(a2, ca), ca, hn::Mul(sa, sa));
      const V xy = hn::Mul(x, y);
      const V ca2 = hn::Mul(ca, ca), ct2 = hn::Mul(ct, ct);
      const V q = hn::Div(hn::Mul(hn::Mul(b, ca), ct), hn::Sqrt(xy));
      const V inner = hn::Div(hn::Mul(b, hn::MulAdd(ca2, x, hn::Mul(ct2, y))), hn::Mul(two, xy));
      const V phi = hn::Mul(hn::Mul(two, a2), hn::MulAdd(q, hn::Add(two, inner), one));
      // G2.
      const V a2s2 = hn::Mul(hn::Mul(a2, s_i), s_i);
      const V n =
          hn::Mul(hn::Mul(two, mu_i), hn::Add(mu_i, hn::Sqrt(hn::MulAdd(mu_i, mu_i, a2s2))));
      const V g2 = gc.separable ? hn::Div(n, hn::Mul(hn::Add(n, a2s2), lambda_o1))
                                : hn::Div(n, hn::MulAdd(n, lambda_o1, a2s2));
      if constexpr (!kDfg) {
        // operator(): scale G2 Phi sin(theta_i), in that order.
        hn::Store(hn::Mul(hn::Mul(hn::Mul(scale, g2), phi), s_i), d, e + i);
        continue;
      }
      const V w = hn::Mul(hn::Mul(scale, g2), s_i);
      hn::Store(hn::Mul(w, phi), d, e + i);
      // The closed-form moments.
      const V r = hn::Mul(hn::Mul(hn::Mul(four, ca), ct), hn::Sqrt(xy));
      const auto valid = hn::And(hn::Gt(r, zero), hn::Gt(w, zero));
      const V rs = hn::IfThenElse(valid, r, one);
      const V cmb = hn::Mul(hn::Mul(four, ca2), x), cpb = hn::Mul(hn::Mul(four, ct2), y);
      const V c = hn::Mul(half, hn::Add(cmb, cpb));
      const V bb = hn::Mul(hn::Mul(two, s_i), s_o);
      const V i_m2 = hn::Div(hn::Mul(two_pi, c), hn::Mul(hn::Mul(rs, rs), rs));
      const V i_m1 = hn::Div(two_pi, rs);
      const V i_1 = hn::Mul(two_pi, c);
      const V i_2 = hn::Mul(two_pi, hn::MulAdd(hn::Mul(half, bb), bb, hn::Mul(c, c)));
      const V kappa = hn::Mul(hn::Mul(hn::Mul(b, four), ca2), ct2);
      const V skv = hn::Sqrt(kappa);
      const V f = hn::NegMulAdd(half, skv, one), f2 = hn::Mul(f, f), f4 = hn::Mul(f2, f2);
      const V g_k = hn::Mul(hn::Mul(hn::Mul(kappa, kappa), f4), f);
      const V gp_k =
          hn::Mul(hn::Mul(kappa, f4), hn::NegMulAdd(hn::Set(d, 1.25), skv, hn::Mul(two, f)));
      const V c2 = hn::MulAdd(kappa, hn::MulAdd(kappa, hn::Set(d, 1.875), hn::Set(d, 7.5)), one);
      const V c3 = hn::MulAdd(hn::Set(d, 1.25), kappa, hn::Set(d, 2.5));
      V cl = hn::Mul(g_k, i_m2);
      cl = hn::MulAdd(gp_k, i_m1, cl);
      cl = hn::MulAdd(c2, two_pi, cl);
      cl = hn::MulAdd(c3, i_1, cl);
      cl = hn::MulAdd(hn::Set(d, 0.3125), i_2, cl);
      hn::Store(hn::IfThenElseZero(valid, hn::Mul(w, norm)), d, wn + i);
      hn::Store(cl, d, closed + i);
      hn::Store(skv, d, sk + i);
      hn::Store(hn::Mul(four, ca2), d, vmin + i);
      hn::Store(hn::Mul(two, bb), d, two_bb + i);
      hn::Store(hn::Mul(two, ca), d, start + i);
    }
  }
};

AzimuthalResult GgxAlbedoTexel(double alpha, double mu, Masking masking, double tol,
                               int max_pieces) {
  return GgxAzimuthalAlbedoWith(
      alpha, mu, masking, tol, max_pieces,
      [](const GgxAzimuthalE& f, const double* theta, double* out) {
        SimdGgxNodes{f.frame_consts(), f.dfg_consts()}.Albedo(theta, out);
      });
}

AzimuthalDfgResult GgxDfgTexel(double alpha, double mu, Masking masking, double tol,
                               int max_pieces) {
  const GgxAzimuthalE f(alpha, mu, masking);
  const SimdGgxNodes nodes{f.frame_consts(), f.dfg_consts()};
  return AdaptiveAzimuthalRule(AzimuthalMesh(f.theta_o(), f.lambda_o(), alpha), nodes, tol,
                               max_pieces);
}

// MomentAzimuthalE's integrand at the 15 nodes of one theta_i piece in
// lanes (the 16th repeats the first): the angles, Lambda(wi), G2 and the
// terms, then the model's moments and c(r2_0) from `model.Lambda(d, a)`
// (a = cot(theta_i) / alpha, 0 on the horizon) and `model.Moments(d, t,
// m, &c)`; the same operations as the scalar reference.
struct MomentTermsF64 {
  hn::Vec<DF64> a2, cc, two_b, v_min, r2_0;
};
template <class Model>
void SimdMomentNodes(const AzimuthalFrame::FrameConsts& fc, const MomentAzimuthalE::Consts& mc,
                     const Model& model, const double* theta, double* out) {
  using V = hn::Vec<DF64>;
  const DF64 d;
  const size_t N = hn::Lanes(d);
  HWY_ALIGN double th[16], e[16];
  NodesTo16(theta, th);
  const V zero = hn::Zero(d), one = hn::Set(d, 1.0), two = hn::Set(d, 2.0),
          four = hn::Set(d, 4.0);
  const V alpha = hn::Set(d, mc.alpha), a2 = hn::Set(d, mc.alpha * mc.alpha);
  const V lambda_o = hn::Set(d, mc.lambda_o), scale = hn::Set(d, fc.scale);
  const V s_o = hn::Set(d, fc.s_o);
  const V norm_c = hn::Set(d, 3.141592653589793 * (mc.alpha * mc.alpha) * 16);
  for (size_t i = 0; i < 16; i += N) {
    V sa, ca, st, ct, s_i, mu_i;
    FrameAngles(d, fc, hn::Load(d, th + i), &sa, &ca, &st, &ct, &s_i, &mu_i);
    const V a = hn::IfThenElseZero(hn::Gt(mu_i, zero), hn::Div(mu_i, hn::Mul(alpha, s_i)));
    const V lambda_i = model.Lambda(d, a);
    const V g2 = mc.separable ? hn::Div(one, hn::Mul(hn::Add(one, lambda_i), hn::Add(one, lambda_o)))
                           : hn::Div(one, hn::Add(hn::Add(one, lambda_i), lambda_o));
    const V w = hn::Mul(hn::Mul(scale, g2), s_i);
    const auto valid = hn::And(hn::Gt(w, zero), hn::Gt(ca, zero));
    MomentTermsF64 t;
    t.a2 = a2;
    t.cc = hn::IfThenElse(valid, hn::Mul(ca, ct), one);
    t.two_b = hn::Mul(hn::Mul(four, s_i), s_o);
    t.v_min = hn::Mul(hn::Mul(four, ca), ca);
    t.r2_0 = hn::Div(hn::Mul(st, st), hn::Mul(hn::Mul(a2, ct), ct));
    V m[3], c;
    model.Moments(d, t, m, &c);
    const V sum = hn::MulAdd(
        hn::Mul(t.two_b, t.two_b), m[2],
        hn::Mul(hn::MulAdd(t.v_min, m[0], hn::Mul(hn::Mul(two, t.two_b), m[1])), t.v_min));
    const V cc2 = hn::Mul(t.cc, t.cc);
    const V norm = hn::Div(two, hn::Mul(hn::Mul(norm_c, cc2), cc2));
    const V v = hn::Mul(w, hn::Mul(hn::Mul(norm, c), sum));
    hn::Store(hn::IfThenElseZero(valid, v), d, e + i);
  }
  for (int i = 0; i < 15; ++i) out[i] = e[i];
}

// BeckmannAzimuthalE::operator() in lanes: Lambda by BeckmannLambdaF64,
// the closed-form moments by BeckmannAzimuthMomentsF64.
struct SimdBeckmannModel {
  hn::Vec<DF64> Lambda(DF64 d, hn::Vec<DF64> a) const { return BeckmannLambdaF64(d, a); }
  void Moments(DF64 d, const MomentTermsF64& t, hn::Vec<DF64>* m, hn::Vec<DF64>* c) const {
    using V = hn::Vec<DF64>;
    const V four = hn::Set(d, 4.0), max_r2 = hn::Set(d, 706.0);
    const V x = hn::Div(t.two_b, hn::Mul(hn::Mul(hn::Mul(four, t.a2), t.cc), t.cc));
    BeckmannAzimuthMomentsF64(d, x, &m[0], &m[1], &m[2]);
    // exp(-r2_0): 0 from 706 on (below the smallest normal double).
    *c = hn::IfThenElseZero(hn::Lt(t.r2_0, max_r2), hn::Exp(d, hn::Neg(hn::Min(t.r2_0, max_r2))));
  }
};

AzimuthalResult BeckmannAlbedoTexel(double alpha, double mu, Masking masking, double tol,
                                    int max_pieces) {
  return BeckmannAzimuthalAlbedoWith(
      alpha, mu, masking, tol, max_pieces,
      [](const BeckmannAzimuthalE& f, const double* theta, double* out) {
        SimdMomentNodes(f.frame_consts(), f.consts(), SimdBeckmannModel{}, theta, out);
      });
}

#if BRDFBAKE_WITH_STD
// StdAzimuthalE::operator() in lanes: Lambda by StudentTLambdaF64, y and
// the tabulated moments (Clenshaw's recurrence on each lane's own piece of
// the table), the same operations as the scalar reference.
struct SimdStdModel {
  double gamma;
  const StdAzimuthMoments* moments;
  const StudentTLambdaF64Consts* lc;

  hn::Vec<DF64> Lambda(DF64 d, hn::Vec<DF64> a) const { return StudentTLambdaF64(d, *lc, a); }
  void Moments(DF64 d, const MomentTermsF64& t, hn::Vec<DF64>* n, hn::Vec<DF64>* c) const {
    using T = StdAzimuthMoments;
    using V = hn::Vec<DF64>;
    const V zero = hn::Zero(d), one = hn::Set(d, 1.0), four = hn::Set(d, 4.0);
    const V gamma_v = hn::Set(d, gamma), gm1 = hn::Set(d, gamma - 1);
    const V min_exp = hn::Set(d, -706.0);
    const double* coef = moments->coef();
    const double* p = moments->p();
    const V l0 = hn::Log1p(d, hn::Div(t.r2_0, gm1));
    const V y =
        hn::Mul(hn::Div(t.two_b, hn::Mul(hn::Mul(hn::Mul(hn::Mul(four, t.a2), t.cc), t.cc), gm1)),
                hn::Exp(d, hn::Neg(l0)));
    // StdAzimuthMoments::At.
    const V z = hn::Mul(gamma_v, y);
    const V tt = hn::Min(hn::Log1p(d, z), hn::Set(d, T::kMaxT));
    const V piece_f =
        hn::Min(hn::Floor(hn::Mul(tt, hn::Set(d, 1 / T::kWidth))), hn::Set(d, T::kPieces - 1.0));
    const V x = hn::Sub(hn::NegMulAdd(piece_f, hn::Set(d, T::kWidth), tt), one);
    const int degree = moments->degree();
    const V inv = hn::Div(one, hn::Add(one, z)), r = hn::Sqrt(inv);
    const V half_powers[3] = {r, hn::Mul(r, inv), hn::Mul(hn::Mul(r, inv), inv)};
    const V x2 = hn::Add(x, x);
    // Clenshaw's recurrence, the three chains interleaved, once per
    // distinct table piece among the lanes (the nodes of a theta_i piece
    // mostly share one or two) with its coefficients broadcast, each lane
    // taking the sums of its own piece: the same operations per lane as
    // the scalar reference.
    HWY_ALIGN double piece_of[HWY_MAX_BYTES / sizeof(double)];
    hn::Store(piece_f, d, piece_of);
    for (int k = 0; k < 3; ++k) n[k] = zero;
    auto todo = hn::Eq(piece_f, piece_f);
    while (!hn::AllFalse(d, todo)) {
      const double pc = piece_of[hn::FindFirstTrue(d, todo)];
      const auto mine = hn::And(todo, hn::Eq(piece_f, hn::Set(d, pc)));
      todo = hn::AndNot(mine, todo);
      const double* cf = coef + static_cast<size_t>(pc) * (degree + 1) * 3;
      V b1[3] = {zero, zero, zero}, b2[3] = {zero, zero, zero};
      for (int j = degree; j >= 1; --j) {
        for (int k = 0; k < 3; ++k) {
          const V b0 = hn::MulAdd(x2, b1[k], hn::Sub(hn::Set(d, cf[j * 3 + k]), b2[k]));
          b2[k] = b1[k];
          b1[k] = b0;
        }
      }
      for (int k = 0; k < 3; ++k) {
        n[k] = hn::IfThenElse(mine, hn::MulAdd(x, b1[k], hn::Sub(hn::Set(d, cf[k]), b2[k])), n[k]);
      }
    }
    for (int k = 0; k < 3; ++k) {
      const V decay = p[k] < k + 0.5 ? hn::Exp(d, hn::Mul(hn::Set(d, -p[k]), tt)) : half_powers[k];
      n[k] = hn::Mul(n[k], decay);
    }
    const V arg = hn::Neg(hn::Mul(gamma_v, l0));
    *c = hn::IfThenElseZero(hn::Gt(arg, min_exp), hn::Exp(d, hn::Max(arg, min_exp)));
  }
};

AzimuthalResult StdAlbedoTexel(const StudentTNdf<double>& ndf, double mu, Masking masking,
                               double tol, int max_pieces) {
  // Lambda's constants (series coefficients, Gamma ratios: a few us), kept
  // per thread for the last gamma.
  thread_local double lc_gamma = std::numeric_limits<double>::quiet_NaN();
  thread_local std::unique_ptr<StudentTLambdaF64Consts> lc_cached;
  if (!(lc_gamma == ndf.gamma())) {
    lc_cached = std::make_unique<StudentTLambdaF64Consts>(ndf.gamma());
    lc_gamma = ndf.gamma();
  }
  const StudentTLambdaF64Consts& lc = *lc_cached;
  return StdAzimuthalAlbedoWith(
      ndf, mu, masking, tol, max_pieces,
      [&](const StdAzimuthalE& f, const double* theta, double* out) {
        SimdMomentNodes(f.frame_consts(), f.consts(), SimdStdModel{f.gamma(), &f.moments(), &lc},
                        theta, out);
      });
}
#endif

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace brdfbake {

HWY_EXPORT(SelLobeTexel);
SelIntegral SimdSelLobeIntegral(double alpha_x, double alpha_y, double tol) {
  return HWY_DYNAMIC_DISPATCH(SelLobeTexel)(alpha_x, alpha_y, tol);
}

HWY_EXPORT(SetUpEllipsoidRaysLanes);
void SimdSetUpEllipsoidRays(EllipsoidRay* rays, int n) {
  HWY_DYNAMIC_DISPATCH(SetUpEllipsoidRaysLanes)(rays, n);
}

HWY_EXPORT(PolyRootsLanes);
void SimdPolyRootsInBatch(PolyRootsProblem* problems, int m) {
  HWY_DYNAMIC_DISPATCH(PolyRootsLanes)(problems, m);
}

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

HWY_EXPORT(GgxAlbedoTexel);
AzimuthalResult SimdGgxAzimuthalAlbedo(double alpha, double mu, Masking masking, double tol,
                                       int max_pieces) {
  return HWY_DYNAMIC_DISPATCH(GgxAlbedoTexel)(alpha, mu, masking, tol, max_pieces);
}

HWY_EXPORT(BeckmannAlbedoTexel);
AzimuthalResult SimdBeckmannAzimuthalAlbedo(double alpha, double mu, Masking masking, double tol,
                                            int max_pieces) {
  return HWY_DYNAMIC_DISPATCH(BeckmannAlbedoTexel)(alpha, mu, masking, tol, max_pieces);
}

#if BRDFBAKE_WITH_STD
HWY_EXPORT(StdAlbedoTexel);
AzimuthalResult SimdStdAzimuthalAlbedo(const StudentTNdf<double>& ndf, double mu, Masking masking,
                                       double tol, int max_pieces) {
  return HWY_DYNAMIC_DISPATCH(StdAlbedoTexel)(ndf, mu, masking, tol, max_pieces);
}
#endif

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
