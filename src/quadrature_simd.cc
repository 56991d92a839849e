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

AzimuthalDfgResult StudentTAzimuthalTexel(const StdNdf<double>& ndf, double mu, Masking masking,
                                          bool with_bias, double tol, int max_pieces) {
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

AzimuthalDfgResult GgxDfgTexel(double alpha, double mu, Masking masking, double tol,
                               int max_pieces) {
  return GgxAzimuthalDfgWith(alpha, mu, masking, tol, max_pieces, SimdRemainderNodes());
}

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace brdfbake {

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
AzimuthalDfgResult SimdSlopeAzimuthalDfg(const StdNdf<double>& ndf, double mu, Masking masking,
                                         bool with_bias, double tol, int max_pieces) {
  return HWY_DYNAMIC_DISPATCH(StudentTAzimuthalTexel)(ndf, mu, masking, with_bias, tol,
                                                      max_pieces);
}
#endif

}  // namespace brdfbake
#endif  // HWY_ONCE
