// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Dynamic dispatch of the Beckmann and STD visible-normal samplers and their
// densities (src/simd/beckmann_sampling-inl.h, std_sampling-inl.h): compiled
// once per Highway target by foreach_target.h.

#include "brdfbake/batch_sampling.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/batch_sampling.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "simd/beckmann_sampling-inl.h"
#include "simd/foreach-inl.h"
#include "simd/foreach_out-inl.h"
#include "simd/std_sampling-inl.h"

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;
using DF = hn::ScalableTag<float>;

void BeckmannSampleVisibleRow(const BeckmannBatchParams& p, const float* const* in,
                              float* const* out, size_t n) {
  const BeckmannConsts<DF> c(DF(), p.alpha_x, p.alpha_y, p.f0);
  ForEachVectorOut<5, 3>(in, 0.5f, out, n, [&](auto d, const auto* v, auto* r) {
    BeckmannSampleVisible(d, c, v[0], v[1], v[2], v[3], v[4], &r[0], &r[1], &r[2]);
  });
}

void BeckmannPdfVisibleRow(const BeckmannBatchParams& p, const float* const* in, float* out,
                           size_t n) {
  const BeckmannConsts<DF> c(DF(), p.alpha_x, p.alpha_y, p.f0);
  ForEachVector<6>(in, 0.5f, out, n, [&](auto d, const auto* v) {
    return BeckmannPdfVisible(d, c, v[0], v[1], v[2], v[3], v[4], v[5]);
  });
}

#if BRDFBAKE_WITH_STD
void StudentTSamplePseudoVnisRow(const StudentTBatchParams& p, const float* const* in,
                                 float* const* out, size_t n) {
  const StudentTSamplingConsts<DF> c(DF(), p.alpha_x, p.alpha_y, p.gamma);
  ForEachVectorOut<5, 3>(in, 0.5f, out, n, [&](auto d, const auto* v, auto* r) {
    StudentTSamplePseudoVnis(d, c, v[0], v[1], v[2], v[3], v[4], &r[0], &r[1], &r[2]);
  });
}

void StudentTPdfPseudoVnisRow(const StudentTBatchParams& p, const float* const* in, float* out,
                         size_t n) {
  const StudentTSamplingConsts<DF> c(DF(), p.alpha_x, p.alpha_y, p.gamma);
  ForEachVector<6>(in, 0.5f, out, n, [&](auto d, const auto* v) {
    return StudentTPdfPseudoVnis(d, c, v[0], v[1], v[2], v[3], v[4], v[5]);
  });
}

#endif  // BRDFBAKE_WITH_STD
}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
#include "flush_subnormals.h"

namespace brdfbake {
HWY_EXPORT(BeckmannSampleVisibleRow);
HWY_EXPORT(BeckmannPdfVisibleRow);
#if BRDFBAKE_WITH_STD
HWY_EXPORT(StudentTSamplePseudoVnisRow);
HWY_EXPORT(StudentTPdfPseudoVnisRow);
#endif

void BeckmannSampleVisibleBatch(const BeckmannBatchParams& p, const float* wo_x,
                                const float* wo_y, const float* wo_z, const float* u1,
                                const float* u2, float* m_x, float* m_y, float* m_z, size_t n) {
  const float* in[5] = {wo_x, wo_y, wo_z, u1, u2};
  float* out[3] = {m_x, m_y, m_z};
  const FlushSubnormals ftz;
  HWY_DYNAMIC_DISPATCH(BeckmannSampleVisibleRow)(p, in, out, n);
}

void BeckmannPdfVisibleBatch(const BeckmannBatchParams& p, const float* wo_x, const float* wo_y,
                             const float* wo_z, const float* m_x, const float* m_y,
                             const float* m_z, float* out, size_t n) {
  const float* in[6] = {wo_x, wo_y, wo_z, m_x, m_y, m_z};
  const FlushSubnormals ftz;
  HWY_DYNAMIC_DISPATCH(BeckmannPdfVisibleRow)(p, in, out, n);
}

#if BRDFBAKE_WITH_STD
void StudentTSamplePseudoVnisBatch(const StudentTBatchParams& p, const float* wo_x,
                                   const float* wo_y, const float* wo_z, const float* u1,
                                   const float* u2, float* m_x, float* m_y, float* m_z, size_t n) {
  const float* in[5] = {wo_x, wo_y, wo_z, u1, u2};
  float* out[3] = {m_x, m_y, m_z};
  const FlushSubnormals ftz;
  HWY_DYNAMIC_DISPATCH(StudentTSamplePseudoVnisRow)(p, in, out, n);
}

void StudentTPdfPseudoVnisBatch(const StudentTBatchParams& p, const float* wo_x, const float* wo_y,
                           const float* wo_z, const float* m_x, const float* m_y,
                           const float* m_z, float* out, size_t n) {
  const float* in[6] = {wo_x, wo_y, wo_z, m_x, m_y, m_z};
  const FlushSubnormals ftz;
  HWY_DYNAMIC_DISPATCH(StudentTPdfPseudoVnisRow)(p, in, out, n);
}

#endif  // BRDFBAKE_WITH_STD
}  // namespace brdfbake
#endif  // HWY_ONCE
