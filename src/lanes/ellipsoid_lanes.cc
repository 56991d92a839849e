// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The ellipsoid's slope-plane rule (rules/ellipsoid/ellipsoid_albedo_rule.h)
// in double SIMD lanes: the rays' set-up, the kinks' roots and the node
// evaluator.

#include <cstddef>
#include <cstring>

#include "lanes/ellipsoid_lanes.h"
#include "rules/ellipsoid/ellipsoid_albedo_rule.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/lanes/ellipsoid_lanes.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>
#include <hwy/contrib/math/math-inl.h>

#include "lanes/lanes_common-inl.h"

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

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
    const V two_pi = hn::Set(d, kTwoPi<double>), inv_two_pi = hn::Set(d, 1 / kTwoPi<double>);
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
    static const Kronrod16 rule;
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

RuleResult EllipsoidAlbedoTexel(double alpha_x, double alpha_y, double theta_x, double theta_y,
                                     double theta_z, double mu, double phi, Masking masking,
                                     double tol, int max_pieces) {
  return EllipsoidAlbedoWith(alpha_x, alpha_y, theta_x, theta_y, theta_z, mu, phi, masking, tol,
                             max_pieces, SimdEllipsoidNodes{});
}

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace brdfbake {

HWY_EXPORT(SetUpEllipsoidRaysLanes);
void SimdSetUpEllipsoidRays(EllipsoidRay* rays, int n) {
  HWY_DYNAMIC_DISPATCH(SetUpEllipsoidRaysLanes)(rays, n);
}

HWY_EXPORT(PolyRootsLanes);
void SimdPolyRootsInBatch(PolyRootsProblem* problems, int m) {
  HWY_DYNAMIC_DISPATCH(PolyRootsLanes)(problems, m);
}

HWY_EXPORT(EllipsoidAlbedoTexel);
RuleResult SimdEllipsoidAlbedo(double alpha_x, double alpha_y, double theta_x,
                                    double theta_y, double theta_z, double mu, double phi,
                                    Masking masking, double tol, int max_pieces) {
  return HWY_DYNAMIC_DISPATCH(EllipsoidAlbedoTexel)(alpha_x, alpha_y, theta_x, theta_y, theta_z,
                                                    mu, phi, masking, tol, max_pieces);
}

}  // namespace brdfbake
#endif  // HWY_ONCE
