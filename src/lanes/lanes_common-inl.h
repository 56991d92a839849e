// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// What the double-lane node evaluators of every family share: a Kronrod
// piece's nodes in whole vectors, the azimuthal frame's angles and the
// Schlick-weighted remainder of the GGX-frame azimuthal integral.

#include <cstddef>

#include "rules/ggx/azimuthal.h"

// Per-target part: included once per Highway target.
#if defined(BRDFBAKE_SRC_LANES_LANES_COMMON_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef BRDFBAKE_SRC_LANES_LANES_COMMON_INL_H_
#undef BRDFBAKE_SRC_LANES_LANES_COMMON_INL_H_
#else
#define BRDFBAKE_SRC_LANES_LANES_COMMON_INL_H_
#endif

#include <hwy/highway.h>
#include <hwy/contrib/math/math-inl.h>

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using DF64 = hn::ScalableTag<double>;

// The 15-point Kronrod rule in 16 aligned lanes, the 16th node at 0 with
// weight 0, so that every target runs whole vectors.
struct Kronrod16 {
  HWY_ALIGN double x[16], wk[16], wg[16];
  Kronrod16() {
    const KronrodRule& r = Kronrod15();
    for (int i = 0; i < 16; ++i) {
      x[i] = i < 15 ? r.x[i] : 0.0;
      wk[i] = i < 15 ? r.wk[i] : 0.0;
      wg[i] = i < 15 ? r.wg[i] : 0.0;
    }
  }
};

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


}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#endif  // BRDFBAKE_SRC_LANES_LANES_COMMON_INL_H_
