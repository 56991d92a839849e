// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Dynamic dispatch of the Fresnel, GGX sampling and ellipsoid batch kernels
// (src/simd/fresnel-inl.h, ggx_sampling-inl.h, ellipsoid-inl.h): compiled
// once per Highway target by foreach_target.h.

#include "brdfbake/batch_extra.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/batch_extra.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "simd/ellipsoid-inl.h"
#include "simd/foreach-inl.h"
#include "simd/foreach_out-inl.h"
#include "simd/fresnel-inl.h"
#include "simd/ggx_sampling-inl.h"
#include "simd/sel-inl.h"

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

void GgxSampleVisibleRow(const GgxBatchParams& p, const float* const* in, float* const* out,
                         size_t n) {
  const GgxSamplingConsts<DF> c(DF(), p.alpha_x, p.alpha_y);
  ForEachVectorOut<5, 3>(in, 0.5f, out, n, [&](auto d, const auto* v, auto* r) {
    GgxSampleVisible(d, c, v[0], v[1], v[2], v[3], v[4], &r[0], &r[1], &r[2]);
  });
}

void GgxPdfVisibleRow(const GgxBatchParams& p, const float* const* in, float* out, size_t n) {
  const GgxSamplingConsts<DF> c(DF(), p.alpha_x, p.alpha_y);
  ForEachVector<6>(in, 0.5f, out, n, [&](auto d, const auto* v) {
    return GgxPdfVisible(d, c, v[0], v[1], v[2], v[3], v[4], v[5]);
  });
}

void GgxSampleNdfRow(const GgxBatchParams& p, const float* const* in, float* const* out,
                     size_t n) {
  const GgxSamplingConsts<DF> c(DF(), p.alpha_x, p.alpha_y);
  ForEachVectorOut<2, 3>(in, 0.5f, out, n, [&](auto d, const auto* v, auto* r) {
    GgxSampleNdf(d, c, v[0], v[1], &r[0], &r[1], &r[2]);
  });
}

void GgxPdfNdfRow(const GgxBatchParams& p, const float* const* in, float* out, size_t n) {
  const GgxSamplingConsts<DF> c(DF(), p.alpha_x, p.alpha_y);
  ForEachVector<3>(in, 0.5f, out, n,
                   [&](auto d, const auto* v) { return GgxPdfNdf(d, c, v[0], v[1], v[2]); });
}

#if BRDFBAKE_WITH_ELLIPSOID
EllipsoidConsts<DF> MakeEllipsoidConsts(const EllipsoidBatchParams& p) {
  return EllipsoidConsts<DF>(DF(), p.alpha_x, p.alpha_y, p.theta_x, p.theta_y, p.theta_z, p.f0);
}

#endif  // BRDFBAKE_WITH_ELLIPSOID
#if BRDFBAKE_WITH_SEL
void SelKRow(const SelBatchParams& p, const float* const* in, float* out, size_t n) {
  const SelConsts<DF> c(DF(), p.alpha_x, p.alpha_y, p.theta_x, p.theta_y, p.theta_z);
  ForEachVector<3>(in, 0.5f, out, n,
                   [&](auto d, const auto* v) { return SelK(d, c, v[0], v[1], v[2]); });
}

#endif  // BRDFBAKE_WITH_SEL
#if BRDFBAKE_WITH_ELLIPSOID
void EllipsoidDRow(const EllipsoidBatchParams& p, const float* const* in, float* out, size_t n) {
  const EllipsoidConsts<DF> c = MakeEllipsoidConsts(p);
  ForEachVector<3>(in, 0.5f, out, n,
                   [&](auto d, const auto* v) { return EllipsoidD(d, c, v[0], v[1], v[2]); });
}

void EllipsoidLambdaRow(const EllipsoidBatchParams& p, const float* const* in, float* out,
                        size_t n) {
  const EllipsoidConsts<DF> c = MakeEllipsoidConsts(p);
  ForEachVector<3>(in, 0.5f, out, n, [&](auto d, const auto* v) {
    return EllipsoidLambda(d, c, v[0], v[1], v[2]);
  });
}

void EllipsoidG1Row(const EllipsoidBatchParams& p, const float* const* in, float* out,
                    size_t n) {
  const EllipsoidConsts<DF> c = MakeEllipsoidConsts(p);
  ForEachVector<3>(in, 0.5f, out, n,
                   [&](auto d, const auto* v) { return EllipsoidG1(d, c, v[0], v[1], v[2]); });
}

void EllipsoidBrdfRow(const EllipsoidBatchParams& p, const float* const* in, float* out,
                      size_t n) {
  const EllipsoidConsts<DF> c = MakeEllipsoidConsts(p);
  WithFresnel(DF(), p, [&](const auto& fresnel) {
    WithMasking(p.masking, [&](auto separable) {
      ForEachVector<6>(in, 0.5f, out, n, [&](auto d, const auto* v) {
        return EllipsoidBrdf(d, c, separable, v[0], v[1], v[2], v[3], v[4], v[5], fresnel);
      });
    });
  });
}

void EllipsoidG2Row(const EllipsoidBatchParams& p, const float* const* in, float* out,
                    size_t n) {
  const EllipsoidConsts<DF> c = MakeEllipsoidConsts(p);
  const bool separable = p.masking == Masking::kSeparable;
  ForEachVector<6>(in, 0.5f, out, n, [&](auto d, const auto* v) {
    const auto lambda = [&](auto x, auto y, auto z) { return EllipsoidLambda(d, c, x, y, z); };
    return G2FromLambda(d, separable, lambda, v[0], v[1], v[2], v[3], v[4], v[5]);
  });
}

void EllipsoidPdfVisibleRow(const EllipsoidBatchParams& p, const float* const* in, float* out,
                            size_t n) {
  const EllipsoidConsts<DF> c = MakeEllipsoidConsts(p);
  ForEachVector<6>(in, 0.5f, out, n, [&](auto d, const auto* v) {
    return EllipsoidPdfVisible(d, c, v[0], v[1], v[2], v[3], v[4], v[5]);
  });
}

void EllipsoidSampleVisibleRow(const EllipsoidBatchParams& p, const float* const* in,
                               float* const* out, size_t n) {
  const EllipsoidConsts<DF> c = MakeEllipsoidConsts(p);
  ForEachVectorOut<5, 3>(in, 0.5f, out, n, [&](auto d, const auto* v, auto* r) {
    EllipsoidSampleVisible(d, c, v[0], v[1], v[2], v[3], v[4], &r[0], &r[1], &r[2]);
  });
}

#endif  // BRDFBAKE_WITH_ELLIPSOID
}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace brdfbake {

HWY_EXPORT(FresnelDielectricRow);
HWY_EXPORT(FresnelConductorRow);
HWY_EXPORT(GgxSampleVisibleRow);
HWY_EXPORT(GgxPdfVisibleRow);
HWY_EXPORT(GgxSampleNdfRow);
HWY_EXPORT(GgxPdfNdfRow);
#if BRDFBAKE_WITH_SEL
HWY_EXPORT(SelKRow);
#endif
#if BRDFBAKE_WITH_ELLIPSOID
HWY_EXPORT(EllipsoidDRow);
HWY_EXPORT(EllipsoidLambdaRow);
HWY_EXPORT(EllipsoidG1Row);
HWY_EXPORT(EllipsoidBrdfRow);
HWY_EXPORT(EllipsoidG2Row);
HWY_EXPORT(EllipsoidPdfVisibleRow);
HWY_EXPORT(EllipsoidSampleVisibleRow);
#endif

void FresnelDielectricBatch(float eta, const float* cos_i, float* out, size_t n) {
  HWY_DYNAMIC_DISPATCH(FresnelDielectricRow)(eta, cos_i, out, n);
}

void FresnelConductorBatch(float eta_re, float eta_im, const float* cos_i, float* out,
                           size_t n) {
  HWY_DYNAMIC_DISPATCH(FresnelConductorRow)(eta_re, eta_im, cos_i, out, n);
}

void GgxSampleVisibleBatch(const GgxBatchParams& p, const float* wo_x, const float* wo_y,
                           const float* wo_z, const float* u1, const float* u2, float* m_x,
                           float* m_y, float* m_z, size_t n) {
  const float* in[5] = {wo_x, wo_y, wo_z, u1, u2};
  float* out[3] = {m_x, m_y, m_z};
  HWY_DYNAMIC_DISPATCH(GgxSampleVisibleRow)(p, in, out, n);
}

void GgxPdfVisibleBatch(const GgxBatchParams& p, const float* wo_x, const float* wo_y,
                        const float* wo_z, const float* m_x, const float* m_y, const float* m_z,
                        float* out, size_t n) {
  const float* in[6] = {wo_x, wo_y, wo_z, m_x, m_y, m_z};
  HWY_DYNAMIC_DISPATCH(GgxPdfVisibleRow)(p, in, out, n);
}

void GgxSampleNdfBatch(const GgxBatchParams& p, const float* u1, const float* u2, float* m_x,
                       float* m_y, float* m_z, size_t n) {
  const float* in[2] = {u1, u2};
  float* out[3] = {m_x, m_y, m_z};
  HWY_DYNAMIC_DISPATCH(GgxSampleNdfRow)(p, in, out, n);
}

void GgxPdfNdfBatch(const GgxBatchParams& p, const float* m_x, const float* m_y,
                    const float* m_z, float* out, size_t n) {
  const float* in[3] = {m_x, m_y, m_z};
  HWY_DYNAMIC_DISPATCH(GgxPdfNdfRow)(p, in, out, n);
}

#if BRDFBAKE_WITH_ELLIPSOID
void EllipsoidDBatch(const EllipsoidBatchParams& p, const float* m_x, const float* m_y,
                     const float* m_z, float* out, size_t n) {
  const float* in[3] = {m_x, m_y, m_z};
  HWY_DYNAMIC_DISPATCH(EllipsoidDRow)(p, in, out, n);
}

void EllipsoidLambdaBatch(const EllipsoidBatchParams& p, const float* w_x, const float* w_y,
                          const float* w_z, float* out, size_t n) {
  const float* in[3] = {w_x, w_y, w_z};
  HWY_DYNAMIC_DISPATCH(EllipsoidLambdaRow)(p, in, out, n);
}

void EllipsoidG1Batch(const EllipsoidBatchParams& p, const float* w_x, const float* w_y,
                      const float* w_z, float* out, size_t n) {
  const float* in[3] = {w_x, w_y, w_z};
  HWY_DYNAMIC_DISPATCH(EllipsoidG1Row)(p, in, out, n);
}

void EllipsoidBrdfBatch(const EllipsoidBatchParams& p, const float* wi_x, const float* wi_y,
                        const float* wi_z, const float* wo_x, const float* wo_y,
                        const float* wo_z, float* out, size_t n) {
  const float* in[6] = {wi_x, wi_y, wi_z, wo_x, wo_y, wo_z};
  HWY_DYNAMIC_DISPATCH(EllipsoidBrdfRow)(p, in, out, n);
}

void EllipsoidSampleVisibleBatch(const EllipsoidBatchParams& p, const float* wo_x,
                                 const float* wo_y, const float* wo_z, const float* u1,
                                 const float* u2, float* m_x, float* m_y, float* m_z,
                                 size_t n) {
  const float* in[5] = {wo_x, wo_y, wo_z, u1, u2};
  float* out[3] = {m_x, m_y, m_z};
  HWY_DYNAMIC_DISPATCH(EllipsoidSampleVisibleRow)(p, in, out, n);
}

void EllipsoidPdfVisibleBatch(const EllipsoidBatchParams& p, const float* wo_x,
                              const float* wo_y, const float* wo_z, const float* m_x,
                              const float* m_y, const float* m_z, float* out, size_t n) {
  const float* in[6] = {wo_x, wo_y, wo_z, m_x, m_y, m_z};
  HWY_DYNAMIC_DISPATCH(EllipsoidPdfVisibleRow)(p, in, out, n);
}

void EllipsoidG2Batch(const EllipsoidBatchParams& p, const float* wi_x, const float* wi_y,
                      const float* wi_z, const float* wo_x, const float* wo_y,
                      const float* wo_z, float* out, size_t n) {
  const float* in[6] = {wi_x, wi_y, wi_z, wo_x, wo_y, wo_z};
  HWY_DYNAMIC_DISPATCH(EllipsoidG2Row)(p, in, out, n);
}

#endif  // BRDFBAKE_WITH_ELLIPSOID
#if BRDFBAKE_WITH_SEL
void SelKBatch(const SelBatchParams& p, const float* w_x, const float* w_y, const float* w_z,
               float* out, size_t n) {
  const float* in[3] = {w_x, w_y, w_z};
  HWY_DYNAMIC_DISPATCH(SelKRow)(p, in, out, n);
}

#endif  // BRDFBAKE_WITH_SEL
}  // namespace brdfbake
#endif  // HWY_ONCE
