// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The sampling integrators over the samplers of Beckmann and the STD (the
// STD's pseudo visible-normal sampler draws from GGX's or Beckmann's) in double SIMD lanes
// (slope_sampling_simd.h; what they share in sampling_simd-inl.h).

#include "sampling/slope_sampling_simd.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/sampling/slope_sampling_simd.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>
#include <hwy/contrib/math/math-inl.h>

#include "kernels/beckmann_sampling-inl.h"
#include "kernels/ggx_sampling-inl.h"
#include "kernels/math_f64-inl.h"
#if BRDFBAKE_WITH_STD
#include "kernels/std-inl.h"
#endif
#include "sampling/sampling_simd-inl.h"

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

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
