// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Dynamic dispatch of the sampling integrators with their points in double
// SIMD lanes (sampling_simd.h). The point sets, the replicas and the error
// estimates are those of sampling_integrators.h (QmcTexelWith,
// EngineRuleWith); only the sum over a point set runs in lanes.

#include "sampling/sampling_simd.h"

#include <cmath>
#include <vector>

#include "sampling/sampling_integrators.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/sampling/sampling_simd.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>
#include <hwy/contrib/math/math-inl.h>

#include "kernels/beckmann_sampling-inl.h"
#include "kernels/ggx_sampling-inl.h"
#include "kernels/math_f64-inl.h"
#if BRDFBAKE_WITH_STD
#include "kernels/std-inl.h"
#endif

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using DF64 = hn::ScalableTag<double>;
using VF64 = hn::Vec<DF64>;

// The sum over n points of `weights(d, u1, u2, &w, &w_fc)`: lane-wise
// partial sums, then one horizontal sum. The callers pass at most
// kSamplingBlock points (sampling_integrators.h), so no lane sums more than
// 2048 terms of at most 1 (relative rounding below 5e-13 of the block's
// sum, far below a sampling integrator's statistical error). The tail's
// lanes are masked off.
template <class Weights>
void SumInLanes(const Weights& weights, const double* u1, const double* u2, int n, double* acc,
                double* acc_fc) {
  const DF64 d;
  const int N = static_cast<int>(hn::Lanes(d));
  VF64 s = hn::Zero(d), s_fc = hn::Zero(d);
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
  }
  *acc = hn::GetLane(hn::SumOfLanes(d, s));
  *acc_fc = hn::GetLane(hn::SumOfLanes(d, s_fc));
}

// Schlick's weight (1 - c)^5 with 1 - c clamped to [0, 1] (fresnel.h).
HWY_INLINE VF64 SchlickWeightF64(DF64 d, VF64 c) {
  const VF64 m = hn::Min(hn::Max(hn::Sub(hn::Set(d, 1.0), c), hn::Zero(d)), hn::Set(d, 1.0));
  const VF64 m2 = hn::Mul(m, m);
  return hn::Mul(hn::Mul(m2, m2), m);
}

// The view wo = (sx, 0, wz) of SamplingView and its Lambda, as lanes.
struct LanesView {
  VF64 wx, wz, lambda_o, g1_o, inv_g1_o;
  LanesView(DF64 d, const Vec3<double>& wo, double lambda) {
    wx = hn::Set(d, wo.x);
    wz = hn::Set(d, wo.z);
    lambda_o = hn::Set(d, lambda);
    g1_o = hn::Set(d, 1 / (1 + lambda));
    inv_g1_o = hn::Set(d, 1 + lambda);
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

// QMC and MC with the weight f cos_i / pdf = G2 factor(m, wo.m) at the
// normal m = sample(d, u1, u2) (VisibleSampler): for an exact visible-normal
// sampler factor = 1 / G1(wo) = 1 + Lambda(wo) (ExactVisible).
template <class Sample, class Factor, class Lambda>
TexelEstimate QmcInLanes(const LanesView& v, Masking masking, int samples, uint64_t seed,
                         bool plain_mc, const Sample& sample, const Factor& factor,
                         const Lambda& lambda) {
  TexelEstimate out;
  WithMasking(masking, [&](auto separable) {
    auto weights = [&](DF64 d, VF64 u1, VF64 u2, VF64* w, VF64* w_fc) {
      VF64 mx, my, mz;
      sample(d, u1, u2, &mx, &my, &mz);
      const VF64 wo_m = hn::MulAdd(v.wx, mx, hn::Mul(v.wz, mz));
      VF64 ix, iy, iz;
      ReflectView(v, mx, my, mz, wo_m, &ix, &iy, &iz);
      const VF64 g2 =
          G2FromLambdaI<decltype(separable)::value>(d, v, lambda(d, ix, iy, iz), iz, wo_m);
      *w = hn::Mul(g2, factor(d, mx, my, mz, wo_m));
      *w_fc = hn::Mul(*w, SchlickWeightF64(d, wo_m));
    };
    out = QmcTexelWith(samples, seed, plain_mc,
                       [&](const double* u1, const double* u2, int n, double* acc, double* acc_fc) {
                         SumInLanes(weights, u1, u2, n, acc, acc_fc);
                       });
  });
  return out;
}

// QmcInLanes' factor for an exact visible-normal sampler.
struct ExactVisible {
  VF64 inv_g1_o;
  HWY_INLINE VF64 operator()(DF64, VF64, VF64, VF64, VF64) const { return inv_g1_o; }
};

// The view's lanes.
inline LanesView ViewOf(double mu, double lambda_o) {
  return LanesView(DF64(), SamplingView(mu), lambda_o);
}

// The engine rule for a model with NDF sampler `normal(d, u1, u2, &m)` and
// Lambda kernel `lambda`.
template <class Normal, class Lambda>
QuadratureResult EngineInLanes(double mu, double lambda_o, Masking masking, int samples,
                               const Normal& normal, const Lambda& lambda) {
  const LanesView v = ViewOf(mu, lambda_o);
  QuadratureResult out;
  WithMasking(masking, [&](auto separable) {
    auto weights = [&](DF64 d, VF64 u1, VF64 u2, VF64* w, VF64* w_fc) {
      VF64 hx, hy, hz;
      normal(d, u1, u2, &hx, &hy, &hz);
      EngineWeight<decltype(separable)::value>(d, v, lambda, hx, hy, hz, w, w_fc);
    };
    out = EngineRuleWith(
        samples, [&](const double* u1, const double* u2, int n, double* acc, double* acc_fc) {
          SumInLanes(weights, u1, u2, n, acc, acc_fc);
        });
  });
  return out;
}

// ---- GGX ----

struct GgxLanesLambda {
  const GgxConsts<DF64>* c;
  HWY_INLINE VF64 operator()(DF64 d, VF64 x, VF64 y, VF64 z) const {
    return GgxLambda(d, *c, x, y, z);
  }
};

TexelEstimate GgxQmcTexel(const GgxNdf<double>& ndf, double mu, Masking masking, int samples,
                          uint64_t seed, bool plain_mc) {
  const GgxSamplingConsts<DF64> c(DF64(), ndf.alpha_x(), ndf.alpha_y());
  const LanesView v = ViewOf(mu, ndf.Lambda(SamplingView(mu)));
  return QmcInLanes(
      v, masking, samples, seed, plain_mc,
      [&](DF64 d, VF64 u1, VF64 u2, VF64* x, VF64* y, VF64* z) {
        GgxSampleVisible(d, c, v.wx, hn::Zero(d), v.wz, u1, u2, x, y, z);
      },
      ExactVisible{v.inv_g1_o}, GgxLanesLambda{&c.ggx});
}

QuadratureResult GgxEngineTexel(const GgxNdf<double>& ndf, double mu, Masking masking,
                                int samples) {
  const GgxSamplingConsts<DF64> c(DF64(), ndf.alpha_x(), ndf.alpha_y());
  return EngineInLanes(
      mu, ndf.Lambda(SamplingView(mu)), masking, samples,
      [&](DF64 d, VF64 u1, VF64 u2, VF64* x, VF64* y, VF64* z) {
        GgxSampleNdf(d, c, u1, u2, x, y, z);
      },
      GgxLanesLambda{&c.ggx});
}

// ---- Beckmann ----

#if BRDFBAKE_WITH_BECKMANN || BRDFBAKE_WITH_STD
struct BeckmannLanesLambda {
  const BeckmannConsts<DF64>* c;
  HWY_INLINE VF64 operator()(DF64 d, VF64 x, VF64 y, VF64 z) const {
    return BeckmannLambda(d, *c, x, y, z);
  }
};
QuadratureResult BeckmannEngineInLanes(const BeckmannConsts<DF64>& c, double mu, double lambda_o,
                                       Masking masking, int samples) {
  return EngineInLanes(
      mu, lambda_o, masking, samples,
      [&](DF64 d, VF64 u1, VF64 u2, VF64* x, VF64* y, VF64* z) {
        BeckmannSampleNdf(d, c, u1, u2, x, y, z);
      },
      BeckmannLanesLambda{&c});
}
#endif

#if BRDFBAKE_WITH_BECKMANN
QuadratureResult BeckmannEngineTexel(const BeckmannNdf<double>& ndf, double mu, Masking masking,
                                     int samples) {
  const BeckmannConsts<DF64> c(DF64(), ndf.alpha_x(), ndf.alpha_y(), 1.0);
  return BeckmannEngineInLanes(c, mu, ndf.Lambda(SamplingView(mu)), masking, samples);
}
TexelEstimate BeckmannQmcTexel(const BeckmannNdf<double>& ndf, double mu, Masking masking,
                               int samples, uint64_t seed, bool plain_mc) {
  const BeckmannConsts<DF64> c(DF64(), ndf.alpha_x(), ndf.alpha_y(), 1.0);
  const LanesView v = ViewOf(mu, ndf.Lambda(SamplingView(mu)));
  return QmcInLanes(
      v, masking, samples, seed, plain_mc,
      [&](DF64 d, VF64 u1, VF64 u2, VF64* x, VF64* y, VF64* z) {
        BeckmannSampleVisible(d, c, v.wx, hn::Zero(d), v.wz, u1, u2, x, y, z);
      },
      ExactVisible{v.inv_g1_o}, BeckmannLanesLambda{&c});
}
#endif

// ---- STD ----

#if BRDFBAKE_WITH_STD
struct StudentTLanesLambda {
  const StudentTConsts<DF64>* c;
  HWY_INLINE VF64 operator()(DF64 d, VF64 x, VF64 y, VF64 z) const {
    return StudentTLambda(d, *c, x, y, z);
  }
};

// The STD's kernels in double lanes (std-inl.h), over its Beckmann
// constants from gamma = 1e10 on (StudentTConsts::beckmann), as the batch
// calls do: the Beckmann limit is within about r2^2 / (2 gamma) <= 7e-8 of
// the STD's radial slope there, which moves a texel by far less than the
// sampling error.
QuadratureResult StdEngineTexel(const StudentTNdf<double>& ndf, double mu, Masking masking,
                                int samples) {
  const StudentTConsts<DF64> c(DF64(), ndf.alpha_x(), ndf.alpha_y(), 1.0, ndf.gamma());
  const double lambda_o = ndf.Lambda(SamplingView(mu));
  if (c.beckmann) return BeckmannEngineInLanes(c.b, mu, lambda_o, masking, samples);
  return EngineInLanes(
      mu, lambda_o, masking, samples,
      [&](DF64 d, VF64 u1, VF64 u2, VF64* x, VF64* y, VF64* z) {
        StudentTSampleNdf(d, c, u1, u2, x, y, z);
      },
      StudentTLanesLambda{&c});
}

// QmcTexel for the STD with the pseudo visible-normal sampler of Algorithm
// 1 (VisibleSampler<StudentTNdf>): the branch is the material's
// (PseudoVnisBranch); the weight D G2 (wo.m) / (wo.z pdf) with the branch's
// density (GGX's or Beckmann's visible normals), and for NDF sampling
// (pdf = D m.z) G2 (wo.m) / (wo.z m.z), D cancelled.
template <class Lambda>
TexelEstimate StdQmcInLanes(const StudentTNdf<double>& ndf, const StudentTConsts<DF64>& c,
                            double mu, Masking masking, int samples, uint64_t seed, bool plain_mc,
                            const Lambda& lambda) {
  const GgxSamplingConsts<DF64> gc(DF64(), ndf.alpha_x(), ndf.alpha_y());
  const LanesView v = ViewOf(mu, ndf.Lambda(SamplingView(mu)));
  const int branch = ndf.PseudoVnisBranch();
  auto sample = [&](DF64 d, VF64 u1, VF64 u2, VF64* x, VF64* y, VF64* z) {
    if (branch == 1) {
      GgxSampleVisible(d, gc, v.wx, hn::Zero(d), v.wz, u1, u2, x, y, z);
    } else if (branch == 2) {
      BeckmannSampleVisible(d, c.b, v.wx, hn::Zero(d), v.wz, u1, u2, x, y, z);
    } else if (c.beckmann) {
      BeckmannSampleNdf(d, c.b, u1, u2, x, y, z);
    } else {
      StudentTSampleNdf(d, c, u1, u2, x, y, z);
    }
  };
  auto factor = [&](DF64 d, VF64 mx, VF64 my, VF64 mz, VF64 wo_m) {
    const VF64 zero = hn::Zero(d), one = hn::Set(d, 1.0);
    VF64 ratio;  // D / pdf, or 1 / m.z for NDF sampling
    if (branch == 0) {
      ratio = hn::Div(one, mz);
    } else {
      const VF64 pdf = branch == 1 ? GgxPdfVisible(d, gc, v.wx, zero, v.wz, mx, my, mz)
                                   : BeckmannPdfVisible(d, c.b, v.wx, zero, v.wz, mx, my, mz);
      const VF64 dm = c.beckmann ? BeckmannD(d, c.b, mx, my, mz) : StudentTD(d, c, mx, my, mz);
      const auto ok = hn::Gt(pdf, zero);
      ratio = hn::IfThenElseZero(ok, hn::Div(dm, hn::IfThenElse(ok, pdf, one)));
    }
    return hn::Div(hn::Mul(ratio, wo_m), v.wz);
  };
  return QmcInLanes(v, masking, samples, seed, plain_mc, sample, factor, lambda);
}

TexelEstimate StdQmcTexel(const StudentTNdf<double>& ndf, double mu, Masking masking, int samples,
                          uint64_t seed, bool plain_mc) {
  const StudentTConsts<DF64> c(DF64(), ndf.alpha_x(), ndf.alpha_y(), 1.0, ndf.gamma());
  if (c.beckmann) {
    return StdQmcInLanes(ndf, c, mu, masking, samples, seed, plain_mc, BeckmannLanesLambda{&c.b});
  }
  return StdQmcInLanes(ndf, c, mu, masking, samples, seed, plain_mc, StudentTLanesLambda{&c});
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
TexelEstimate SimdQmcTexel(const BeckmannNdf<double>& ndf, double mu, Masking masking, int samples,
                           uint64_t seed, bool plain_mc) {
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
TexelEstimate SimdQmcTexel(const StudentTNdf<double>& ndf, double mu, Masking masking, int samples,
                           uint64_t seed, bool plain_mc) {
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
