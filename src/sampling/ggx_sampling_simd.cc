// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The sampling integrators over GGX's samplers in double SIMD lanes
// (ggx_sampling_simd.h; what they share in sampling_simd-inl.h).

#include "sampling/ggx_sampling_simd.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/sampling/ggx_sampling_simd.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>
#include <hwy/contrib/math/math-inl.h>

#include "kernels/ggx_sampling-inl.h"
#include "kernels/math_f64-inl.h"
#include "sampling/sampling_simd-inl.h"

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

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

}  // namespace brdfbake
#endif  // HWY_ONCE
