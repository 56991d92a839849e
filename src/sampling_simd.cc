// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Dynamic dispatch of the sampling integrators with their points in double
// SIMD lanes (sampling_simd.h). The point sets, the replicas and the error
// estimates are those of sampling_integrators.h (QmcTexelWith,
// EngineRuleWith); only the sum over a point set runs in lanes.

#include <cmath>
#include <memory>
#include <vector>

#include "sampling_simd.h"

#include "sampling_integrators.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/sampling_simd.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>
#include <hwy/contrib/math/math-inl.h>

#include "simd/beckmann_sampling-inl.h"
#include "simd/ggx_sampling-inl.h"
#include "simd/math_f64-inl.h"
#if BRDFBAKE_WITH_STD
#include "simd/std_f64-inl.h"
#endif

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using DF64 = hn::ScalableTag<double>;
using VF64 = hn::Vec<DF64>;

// The sum over n points of `weights(d, u1, u2, &w, &w_fc)`: lane-wise
// partial sums, folded into a double total every kFold vectors (so that no
// lane sums more than kFold terms before it is added up: at most 2^20
// samples per replica leave a relative rounding error below 1e-12, far
// below a sampling integrator's statistical error). The tail's lanes are
// masked off.
template <class Weights>
void SumInLanes(const Weights& weights, const double* u1, const double* u2, int n, double* acc,
                double* acc_fc) {
  constexpr int kFold = 256;
  const DF64 d;
  const int N = static_cast<int>(hn::Lanes(d));
  VF64 s = hn::Zero(d), s_fc = hn::Zero(d);
  double total = 0, total_fc = 0;
  int in_fold = 0;
  for (int i = 0; i < n; i += N) {
    VF64 a, b;
    const bool tail = i + N > n;
    if (!tail) {
      a = hn::LoadU(d, u1 + i);
      b = hn::LoadU(d, u2 + i);
    } else {
      HWY_ALIGN double ta[HWY_MAX_BYTES / sizeof(double)], tb[HWY_MAX_BYTES / sizeof(double)];
      for (int k = 0; k < N; ++k) {
        ta[k] = i + k < n ? u1[i + k] : 0.5;
        tb[k] = i + k < n ? u2[i + k] : 0.5;
      }
      a = hn::Load(d, ta);
      b = hn::Load(d, tb);
    }
    VF64 w, w_fc;
    weights(d, a, b, &w, &w_fc);
    if (tail) {
      const auto live = hn::FirstN(d, static_cast<size_t>(n - i));
      w = hn::IfThenElseZero(live, w);
      w_fc = hn::IfThenElseZero(live, w_fc);
    }
    s = hn::Add(s, w);
    s_fc = hn::Add(s_fc, w_fc);
    if (++in_fold == kFold) {
      total += hn::GetLane(hn::SumOfLanes(d, s));
      total_fc += hn::GetLane(hn::SumOfLanes(d, s_fc));
      s = hn::Zero(d);
      s_fc = hn::Zero(d);
      in_fold = 0;
    }
  }
  *acc = total + hn::GetLane(hn::SumOfLanes(d, s));
  *acc_fc = total_fc + hn::GetLane(hn::SumOfLanes(d, s_fc));
}

// Schlick's weight (1 - c)^5 with 1 - c clamped to [0, 1] (fresnel.h).
HWY_INLINE VF64 SchlickWeightF64(DF64 d, VF64 c) {
  const VF64 m = hn::Min(hn::Max(hn::Sub(hn::Set(d, 1.0), c), hn::Zero(d)), hn::Set(d, 1.0));
  const VF64 m2 = hn::Mul(m, m);
  return hn::Mul(hn::Mul(m2, m2), m);
}

// The view wo = (sx, 0, wz) of SamplingView and its Lambda, as lanes.
struct LanesView {
  VF64 wx, wz, lambda_o, g1_o;
  LanesView(DF64 d, const Vec3<double>& wo, double lambda) {
    wx = hn::Set(d, wo.x);
    wz = hn::Set(d, wo.z);
    lambda_o = hn::Set(d, lambda);
    g1_o = hn::Set(d, 1 / (1 + lambda));
  }
};

// G2 (brdf.h) of the reflection pair (wi, wo) about m, from Lambda(wi)
// (+inf on the horizon) and the view's Lambda; 0 unless wi.z > 0 and
// wo.m > 0 (wi.m = wo.m for a reflection).
template <bool kSeparable>
HWY_INLINE VF64 G2FromLambdaI(DF64 d, const LanesView& v, VF64 lambda_i, VF64 wiz, VF64 wo_m) {
  const VF64 one = hn::Set(d, 1.0);
  const VF64 g2 = kSeparable ? hn::Mul(hn::Div(one, hn::Add(one, lambda_i)), v.g1_o)
                             : hn::Div(one, hn::Add(hn::Add(one, lambda_i), v.lambda_o));
  return hn::IfThenElseZero(hn::And(hn::Gt(wiz, hn::Zero(d)), hn::Gt(wo_m, hn::Zero(d))), g2);
}

// Lambda of an isotropic slope model from a = cot(theta) / alpha: the
// model's `lambda_of_a(d, a)` (+inf for a = 0, the horizon; a = +inf at
// the pole gives 0), +inf below the horizon.
template <class LambdaOfA>
HWY_INLINE VF64 IsotropicLambda(DF64 d, const LambdaOfA& lambda_of_a, double alpha, VF64 wx,
                                VF64 wy, VF64 wz) {
  const VF64 s = hn::Sqrt(hn::MulAdd(wx, wx, hn::Mul(wy, wy)));
  const auto above = hn::Gt(wz, hn::Zero(d));
  const VF64 a = hn::IfThenElseZero(above, hn::Div(wz, hn::Mul(hn::Set(d, alpha), s)));
  return hn::IfThenElse(above, lambda_of_a(d, a), hn::Inf(d));
}

// The reflection wi = 2 (wo.m) m - wo of the view about m.
HWY_INLINE void ReflectView(const LanesView& v, VF64 mx, VF64 my, VF64 mz, VF64 wo_m, VF64* ix,
                            VF64* iy, VF64* iz) {
  const VF64 k = hn::Add(wo_m, wo_m);
  *ix = hn::MulSub(k, mx, v.wx);
  *iy = hn::Mul(k, my);
  *iz = hn::MulSub(k, mz, v.wz);
}

// The engine's weight G2 (wo.h) / (wo.z h.z) at the half vector h from the
// model's NDF sampler, and w Fc (EngineRule).
template <bool kSeparable, class Lambda>
HWY_INLINE void EngineWeight(DF64 d, const LanesView& v, const Lambda& lambda, VF64 hx, VF64 hy,
                             VF64 hz, VF64* w, VF64* w_fc) {
  const VF64 wo_h = hn::MulAdd(v.wx, hx, hn::Mul(v.wz, hz));
  VF64 ix, iy, iz;
  ReflectView(v, hx, hy, hz, wo_h, &ix, &iy, &iz);
  const VF64 g2 = G2FromLambdaI<kSeparable>(d, v, lambda(d, ix, iy, iz), iz, wo_h);
  const auto ok = hn::Gt(hz, hn::Zero(d));
  *w = hn::IfThenElseZero(ok, hn::Div(hn::Mul(g2, wo_h), hn::Mul(v.wz, hz)));
  *w_fc = hn::Mul(*w, SchlickWeightF64(d, wo_h));
}

// NDF sampling of an isotropic slope model (slope_ndf.h SampleNdf): radial
// slope r = sqrt(r2(u2)) along 2 pi u1 (SinCos2Pi), times alpha, and m =
// normalize(-slope, 1).
HWY_INLINE void SlopeNormal(DF64 d, double alpha, VF64 r2, VF64 u1, VF64* mx, VF64* my,
                            VF64* mz) {
  VF64 sn, cs;
  SinCos2Pi(d, u1, &sn, &cs);
  const VF64 r = hn::Mul(hn::Sqrt(r2), hn::Set(d, alpha));
  const VF64 px = hn::Mul(r, cs), py = hn::Mul(r, sn);
  const VF64 inv = hn::Div(hn::Set(d, 1.0), hn::Sqrt(hn::MulAdd(px, px, hn::MulAdd(py, py,
                                                                               hn::Set(d, 1.0)))));
  *mx = hn::Neg(hn::Mul(px, inv));
  *my = hn::Neg(hn::Mul(py, inv));
  *mz = inv;
}

// The scalar models' clamp of u before the inverse radial CDF: 1 - 2^-53.
HWY_INLINE VF64 ClampBelowOne(DF64 d, VF64 u) { return hn::Min(u, hn::Set(d, 1 - 0x1p-53)); }

// ---- GGX ----

struct GgxLanesLambda {
  const GgxConsts<DF64>* c;
  HWY_INLINE VF64 operator()(DF64 d, VF64 x, VF64 y, VF64 z) const {
    return GgxLambda(d, *c, x, y, z);
  }
};

// QMC and MC with a model's exact visible-normal sampler `sample(d, wx,
// wy, wz, u1, u2, &m)`: f cos_i / pdf = G2 / G1(wo) (VisibleSampler).
template <class Sample, class Lambda>
TexelEstimate VisibleQmcInLanes(double mu, double lambda_o, Masking masking, int samples,
                                uint64_t seed, bool plain_mc, const Sample& sample,
                                const Lambda& lambda) {
  const LanesView v(DF64(), SamplingView(mu), lambda_o);
  TexelEstimate out;
  WithMasking(masking, [&](auto separable) {
    auto weights = [&](DF64 d, VF64 u1, VF64 u2, VF64* w, VF64* w_fc) {
      VF64 mx, my, mz;
      sample(d, v.wx, hn::Zero(d), v.wz, u1, u2, &mx, &my, &mz);
      const VF64 wo_m = hn::MulAdd(v.wx, mx, hn::Mul(v.wz, mz));
      VF64 ix, iy, iz;
      ReflectView(v, mx, my, mz, wo_m, &ix, &iy, &iz);
      const VF64 g2 = G2FromLambdaI<decltype(separable)::value>(d, v, lambda(d, ix, iy, iz), iz,
                                                                 wo_m);
      *w = hn::Div(g2, v.g1_o);
      *w_fc = hn::Mul(*w, SchlickWeightF64(d, wo_m));
    };
    out = QmcTexelWith(samples, seed, plain_mc,
                       [&](const double* u1, const double* u2, int n, double* acc,
                           double* acc_fc) { SumInLanes(weights, u1, u2, n, acc, acc_fc); });
  });
  return out;
}

TexelEstimate GgxQmcTexel(const GgxNdf<double>& ndf, double mu, Masking masking, int samples,
                          uint64_t seed, bool plain_mc) {
  const GgxSamplingConsts<DF64> c(DF64(), ndf.alpha_x(), ndf.alpha_y());
  return VisibleQmcInLanes(
      mu, ndf.Lambda(SamplingView(mu)), masking, samples, seed, plain_mc,
      [&](DF64 d, VF64 wx, VF64 wy, VF64 wz, VF64 u1, VF64 u2, VF64* x, VF64* y, VF64* z) {
        GgxSampleVisible(d, c, wx, wy, wz, u1, u2, x, y, z);
      },
      GgxLanesLambda{&c.ggx});
}

// The engine rule for a model with NDF sampler `normal(d, u1, u2, &m)` and
// Lambda kernel `lambda`.
template <class Normal, class Lambda>
QuadratureResult EngineInLanes(double mu, double lambda_o, Masking masking, int samples,
                               const Normal& normal, const Lambda& lambda) {
  const DF64 d;
  const LanesView v(d, SamplingView(mu), lambda_o);
  QuadratureResult out;
  WithMasking(masking, [&](auto separable) {
    auto weights = [&](DF64 d, VF64 u1, VF64 u2, VF64* w, VF64* w_fc) {
      VF64 hx, hy, hz;
      normal(d, u1, u2, &hx, &hy, &hz);
      EngineWeight<decltype(separable)::value>(d, v, lambda, hx, hy, hz, w, w_fc);
    };
    out = EngineRuleWith(samples, [&](const double* u1, const double* u2, int n, double* acc,
                                      double* acc_fc) {
      SumInLanes(weights, u1, u2, n, acc, acc_fc);
    });
  });
  return out;
}

QuadratureResult GgxEngineTexel(const GgxNdf<double>& ndf, double mu, Masking masking,
                                int samples) {
  const DF64 d;
  const GgxSamplingConsts<DF64> c(d, ndf.alpha_x(), ndf.alpha_y());
  return EngineInLanes(
      mu, ndf.Lambda(SamplingView(mu)), masking, samples,
      [&](DF64 d, VF64 u1, VF64 u2, VF64* x, VF64* y, VF64* z) {
        GgxSampleNdf(d, c, u1, u2, x, y, z);
      },
      GgxLanesLambda{&c.ggx});
}

// ---- Beckmann ----

#if BRDFBAKE_WITH_BECKMANN || BRDFBAKE_WITH_STD
// Beckmann's radial inverse CDF r2 = -log(1 - u) (BeckmannNdf::UnitSampleR2).
HWY_INLINE VF64 BeckmannR2(DF64 d, VF64 u) {
  return hn::Neg(hn::Log1p(d, hn::Neg(ClampBelowOne(d, u))));
}
struct BeckmannLanesLambda {
  const BeckmannConsts<DF64>* c;
  HWY_INLINE VF64 operator()(DF64 d, VF64 x, VF64 y, VF64 z) const {
    return BeckmannLambda(d, *c, x, y, z);
  }
};
QuadratureResult BeckmannEngineInLanes(double alpha, double mu, double lambda_o, Masking masking,
                                       int samples) {
  const BeckmannConsts<DF64> c(DF64(), alpha, alpha, 1.0);
  return EngineInLanes(
      mu, lambda_o, masking, samples,
      [&](DF64 d, VF64 u1, VF64 u2, VF64* x, VF64* y, VF64* z) {
        SlopeNormal(d, alpha, BeckmannR2(d, u2), u1, x, y, z);
      },
      BeckmannLanesLambda{&c});
}
TexelEstimate BeckmannQmcInLanes(double alpha, double mu, double lambda_o, Masking masking,
                                 int samples, uint64_t seed, bool plain_mc) {
  const BeckmannConsts<DF64> c(DF64(), alpha, alpha, 1.0);
  return VisibleQmcInLanes(
      mu, lambda_o, masking, samples, seed, plain_mc,
      [&](DF64 d, VF64 wx, VF64 wy, VF64 wz, VF64 u1, VF64 u2, VF64* x, VF64* y, VF64* z) {
        BeckmannSampleVisible(d, c, wx, wy, wz, u1, u2, x, y, z);
      },
      BeckmannLanesLambda{&c});
}
#endif

#if BRDFBAKE_WITH_BECKMANN
QuadratureResult BeckmannEngineTexel(const BeckmannNdf<double>& ndf, double mu, Masking masking,
                                     int samples) {
  return BeckmannEngineInLanes(ndf.alpha_x(), mu, ndf.Lambda(SamplingView(mu)), masking, samples);
}
TexelEstimate BeckmannQmcTexel(const BeckmannNdf<double>& ndf, double mu, Masking masking,
                               int samples, uint64_t seed, bool plain_mc) {
  return BeckmannQmcInLanes(ndf.alpha_x(), mu, ndf.Lambda(SamplingView(mu)), masking, samples,
                            seed, plain_mc);
}
#endif

// ---- STD ----

#if BRDFBAKE_WITH_STD
QuadratureResult StdEngineTexel(const StudentTNdf<double>& ndf, double mu, Masking masking,
                                int samples) {
  const double alpha = ndf.alpha_x(), g = ndf.gamma();
  const double lambda_o = ndf.Lambda(SamplingView(mu));
  if (std::isinf(g)) return BeckmannEngineInLanes(alpha, mu, lambda_o, masking, samples);
  // StudentTNdf::UnitSampleR2: r2 = (gamma - 1) expm1(-log1p(-u) / (gamma - 1)).
  const StudentTLambdaF64Consts lc(g);
  return EngineInLanes(
      mu, lambda_o, masking, samples,
      [&](DF64 d, VF64 u1, VF64 u2, VF64* x, VF64* y, VF64* z) {
        const VF64 e = hn::Neg(hn::Log1p(d, hn::Neg(ClampBelowOne(d, u2))));
        const VF64 r2 = hn::Mul(hn::Set(d, g - 1), hn::Expm1(d, hn::Div(e, hn::Set(d, g - 1))));
        SlopeNormal(d, alpha, r2, u1, x, y, z);
      },
      [&](DF64 d, VF64 x, VF64 y, VF64 z) {
        return IsotropicLambda(
            d, [&](DF64 d, VF64 a) { return StudentTLambdaF64(d, lc, a); }, alpha, x, y, z);
      });
}

// The STD's D (StudentTNdf::D, isotropic alpha): exp(-gamma log1p(r2 /
// (gamma - 1)) - log(alpha^2 z^4)) / pi with r2 = |m_xy|^2 / (alpha^2 z^2),
// one exponential of the whole exponent as the scalar twin; 0 for m.z <= 0.
HWY_INLINE VF64 StudentTDF64(DF64 d, double alpha, double gamma, VF64 mx, VF64 my, VF64 mz) {
  const VF64 z2 = hn::Mul(mz, mz);
  const VF64 s2 = hn::Div(hn::MulAdd(mx, mx, hn::Mul(my, my)), hn::Set(d, alpha * alpha));
  const VF64 r2 = hn::Div(s2, z2);
  const VF64 ex = hn::MulAdd(hn::Set(d, -gamma), hn::Log1p(d, hn::Div(r2, hn::Set(d, gamma - 1))),
                             hn::NegMulAdd(hn::Set(d, 2.0), hn::Log(d, z2),
                                           hn::Set(d, -2 * std::log(alpha))));
  const VF64 v = hn::Mul(hn::Exp(d, ex), hn::Set(d, 0.3183098861837907));
  return hn::IfThenElseZero(hn::Gt(mz, hn::Zero(d)), v);
}

// QmcTexel for the STD with the pseudo visible-normal sampler of Algorithm
// 1 (VisibleSampler<StudentTNdf>): the branch is the material's
// (PseudoVnisBranch); the weight D G2 (wo.m) / (wo.z pdf) with the branch's
// density (GGX's or Beckmann's visible normals), and for NDF sampling
// (pdf = D m.z) G2 (wo.m) / (wo.z m.z), D cancelled.
TexelEstimate StdQmcTexel(const StudentTNdf<double>& ndf, double mu, Masking masking, int samples,
                          uint64_t seed, bool plain_mc) {
  const double alpha = ndf.alpha_x(), g = ndf.gamma();
  const bool inf = std::isinf(g);
  const DF64 d;
  const LanesView v(d, SamplingView(mu), ndf.Lambda(SamplingView(mu)));
  const GgxSamplingConsts<DF64> gc(d, alpha, alpha);
  const BeckmannConsts<DF64> bc(d, alpha, alpha, 1.0);
  std::unique_ptr<StudentTLambdaF64Consts> lc;
  if (!inf) lc = std::make_unique<StudentTLambdaF64Consts>(g);
  auto lambda = [&](DF64 d, VF64 x, VF64 y, VF64 z) {
    if (inf) return BeckmannLambda(d, bc, x, y, z);
    return IsotropicLambda(
        d, [&](DF64 d, VF64 a) { return StudentTLambdaF64(d, *lc, a); }, alpha, x, y, z);
  };
  const int branch = ndf.PseudoVnisBranch();
  TexelEstimate out;
  WithMasking(masking, [&](auto separable) {
    auto weights = [&](DF64 d, VF64 u1, VF64 u2, VF64* w, VF64* w_fc) {
      const VF64 zero = hn::Zero(d);
      VF64 mx, my, mz, ratio;  // ratio = D / pdf times m.z's share
      if (branch == 0) {
        VF64 r2;
        if (inf) {
          r2 = BeckmannR2(d, u2);
        } else {
          const VF64 e = hn::Neg(hn::Log1p(d, hn::Neg(ClampBelowOne(d, u2))));
          r2 = hn::Mul(hn::Set(d, g - 1), hn::Expm1(d, hn::Div(e, hn::Set(d, g - 1))));
        }
        SlopeNormal(d, alpha, r2, u1, &mx, &my, &mz);
        ratio = hn::Div(hn::Set(d, 1.0), mz);
      } else {
        VF64 pdf;
        if (branch == 1) {
          GgxSampleVisible(d, gc, v.wx, zero, v.wz, u1, u2, &mx, &my, &mz);
          pdf = GgxPdfVisible(d, gc, v.wx, zero, v.wz, mx, my, mz);
        } else {
          BeckmannSampleVisible(d, bc, v.wx, zero, v.wz, u1, u2, &mx, &my, &mz);
          pdf = BeckmannPdfVisible(d, bc, v.wx, zero, v.wz, mx, my, mz);
        }
        const VF64 dm = inf ? BeckmannD(d, bc, mx, my, mz) : StudentTDF64(d, alpha, g, mx, my, mz);
        ratio = hn::IfThenElseZero(hn::Gt(pdf, zero),
                                   hn::Div(dm, hn::IfThenElse(hn::Gt(pdf, zero), pdf,
                                                              hn::Set(d, 1.0))));
      }
      const VF64 wo_m = hn::MulAdd(v.wx, mx, hn::Mul(v.wz, mz));
      VF64 ix, iy, iz;
      ReflectView(v, mx, my, mz, wo_m, &ix, &iy, &iz);
      const VF64 g2 = G2FromLambdaI<decltype(separable)::value>(d, v, lambda(d, ix, iy, iz), iz,
                                                                 wo_m);
      *w = hn::Div(hn::Mul(hn::Mul(ratio, g2), wo_m), v.wz);
      *w_fc = hn::Mul(*w, SchlickWeightF64(d, wo_m));
    };
    out = QmcTexelWith(samples, seed, plain_mc,
                       [&](const double* u1, const double* u2, int n, double* acc,
                           double* acc_fc) { SumInLanes(weights, u1, u2, n, acc, acc_fc); });
  });
  return out;
}
#endif

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace brdfbake {

HWY_EXPORT(GgxQmcTexel);
TexelEstimate SimdQmcTexel(const GgxNdf<double>& ndf, double mu, Masking masking, int samples,
                           uint64_t seed, bool plain_mc) {
  return HWY_DYNAMIC_DISPATCH(GgxQmcTexel)(ndf, mu, masking, samples, seed, plain_mc);
}

HWY_EXPORT(GgxEngineTexel);
QuadratureResult SimdEngineRule(const GgxNdf<double>& ndf, double mu, Masking masking,
                                int samples) {
  return HWY_DYNAMIC_DISPATCH(GgxEngineTexel)(ndf, mu, masking, samples);
}

#if BRDFBAKE_WITH_BECKMANN
HWY_EXPORT(BeckmannQmcTexel);
TexelEstimate SimdQmcTexel(const BeckmannNdf<double>& ndf, double mu, Masking masking,
                           int samples, uint64_t seed, bool plain_mc) {
  return HWY_DYNAMIC_DISPATCH(BeckmannQmcTexel)(ndf, mu, masking, samples, seed, plain_mc);
}

HWY_EXPORT(BeckmannEngineTexel);
QuadratureResult SimdEngineRule(const BeckmannNdf<double>& ndf, double mu, Masking masking,
                                int samples) {
  return HWY_DYNAMIC_DISPATCH(BeckmannEngineTexel)(ndf, mu, masking, samples);
}
#endif

#if BRDFBAKE_WITH_STD
HWY_EXPORT(StdQmcTexel);
TexelEstimate SimdQmcTexel(const StudentTNdf<double>& ndf, double mu, Masking masking,
                           int samples, uint64_t seed, bool plain_mc) {
  return HWY_DYNAMIC_DISPATCH(StdQmcTexel)(ndf, mu, masking, samples, seed, plain_mc);
}

HWY_EXPORT(StdEngineTexel);
QuadratureResult SimdEngineRule(const StudentTNdf<double>& ndf, double mu, Masking masking,
                                int samples) {
  return HWY_DYNAMIC_DISPATCH(StdEngineTexel)(ndf, mu, masking, samples);
}
#endif

}  // namespace brdfbake
#endif  // HWY_ONCE
