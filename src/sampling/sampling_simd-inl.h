// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// What the sampling integrators' lanes share (sampling_simd.h): the sum
// over a point set in double SIMD lanes, and the QMC / MC and engine
// weights over a model's sampler and Lambda kernel. The point sets, the
// replicas and the error estimates are those of sampling_integrators.h
// (QmcTexelWith, EngineRuleWith); only the sum over a point set runs in
// lanes. Each family's <family>_sampling_simd.cc instantiates them with its
// kernels.

// Normal include guard for the plain includes.
#ifndef BRDFBAKE_SRC_SAMPLING_SAMPLING_SIMD_INL_H_
#define BRDFBAKE_SRC_SAMPLING_SAMPLING_SIMD_INL_H_

#include <cmath>
#include <vector>

#include "sampling/sampling_integrators.h"

#endif  // BRDFBAKE_SRC_SAMPLING_SAMPLING_SIMD_INL_H_

// Per-target include guard.
#if defined(BRDFBAKE_SRC_SAMPLING_SAMPLING_SIMD_INL_H_TARGET) == defined(HWY_TARGET_TOGGLE)
#ifdef BRDFBAKE_SRC_SAMPLING_SAMPLING_SIMD_INL_H_TARGET
#undef BRDFBAKE_SRC_SAMPLING_SAMPLING_SIMD_INL_H_TARGET
#else
#define BRDFBAKE_SRC_SAMPLING_SAMPLING_SIMD_INL_H_TARGET
#endif

#include <hwy/highway.h>

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

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#endif  // BRDFBAKE_SRC_SAMPLING_SAMPLING_SIMD_INL_H_TARGET
