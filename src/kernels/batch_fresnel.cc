// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The Fresnel reflectance batch kernels (src/kernels/fresnel-inl.h) behind
// batch.h, compiled once per Highway target by foreach_target.h.

#include "brdfbake/batch.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/kernels/batch_fresnel.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "kernels/foreach-inl.h"
#include "kernels/fresnel-inl.h"

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;
using DF = hn::ScalableTag<float>;

void FresnelDielectricRow(float eta, const float* cos_i, float* out, size_t n) {
  const FresnelDielectricConsts<DF> c(DF(), eta);
  const float* in[1] = {cos_i};
  ForEachVector<1>(in, 0.5f, out, n,
                   [&](auto d, const auto* v) { return FresnelDielectric(d, c, v[0]); });
}

void FresnelConductorRow(float eta_re, float eta_im, const float* cos_i, float* out, size_t n) {
  const FresnelConductorConsts<DF> c(DF(), eta_re, eta_im);
  const float* in[1] = {cos_i};
  ForEachVector<1>(in, 0.5f, out, n,
                   [&](auto d, const auto* v) { return FresnelConductor(d, c, v[0]); });
}

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace brdfbake {

HWY_EXPORT(FresnelDielectricRow);
HWY_EXPORT(FresnelConductorRow);

void FresnelDielectricBatch(float eta, const float* cos_i, float* out, size_t n) {
  HWY_DYNAMIC_DISPATCH(FresnelDielectricRow)(eta, cos_i, out, n);
}

void FresnelConductorBatch(float eta_re, float eta_im, const float* cos_i, float* out, size_t n) {
  HWY_DYNAMIC_DISPATCH(FresnelConductorRow)(eta_re, eta_im, cos_i, out, n);
}

}  // namespace brdfbake
#endif  // HWY_ONCE
