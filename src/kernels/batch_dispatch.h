// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The per-model dispatchers behind batch.h, defined in each
// src/kernels/batch_<family>.cc and reached through its row (model_row.h):
// each runs its model's kernels on the target dynamic dispatch picks, for a
// (model, quantity) pair that batch.cc has checked. `in` holds 3 arrays (one
// direction) or 6 (a pair); a sampler's `in` is {wo_x, wo_y, wo_z, u1, u2}
// and its `out` {m_x, m_y, m_z}.

#ifndef BRDFBAKE_SRC_KERNELS_BATCH_DISPATCH_H_
#define BRDFBAKE_SRC_KERNELS_BATCH_DISPATCH_H_

#include <cstddef>

#include "brdfbake/batch.h"

namespace brdfbake {

using BatchEvalFn = void (*)(const BatchModel& p, Quantity q, const float* const* in, float* out,
                             size_t n);
using BatchSampleFn = void (*)(const BatchModel& p, Sampler s, const float* const* in,
                               float* const* out, size_t n);

// True if every a[j], j < n, lies in (lo, hi] (open_low) or [lo, hi];
// false for NaN (batch_check.cc).
bool AllWithinBatch(const float* a, size_t n, float lo, float hi, bool open_low);

// The steps of SampleLightBatch around the model's kernels
// (batch_light.cc): wi from (wo, m), then (weight, pdf) from
// (wo, m, wi.z, pdf_visible(wo, m), f(wi, wo)).
void ReflectBatch(const float* const* in, float* const* out, size_t n);
void LightWeightBatch(const float* const* in, float* const* out, size_t n);

// The rough dielectric (batch_glass.cc): `in` holds the 6 arrays of (wi, wo).
void GlassEvalBatch(const BatchDielectric& p, DielectricQuantity q, const float* const* in,
                    float* out, size_t n);

// In the HWY_ONCE part of src/kernels/batch_<family>.cc: exports the
// per-target Model##Eval (and Model##Sample) and defines its dispatchers
// Model##EvalBatch (and Model##SampleBatch), which the family's row holds.
#define BRDFBAKE_BATCH_EVAL_DISPATCH(Model)                                                   \
  HWY_EXPORT(Model##Eval);                                                                    \
  void Model##EvalBatch(const BatchModel& p, Quantity q, const float* const* in, float* out, \
                        size_t n) {                                                           \
    HWY_DYNAMIC_DISPATCH(Model##Eval)(p, q, in, out, n);                                      \
  }
#define BRDFBAKE_BATCH_SAMPLE_DISPATCH(Model)                                                 \
  HWY_EXPORT(Model##Sample);                                                                  \
  void Model##SampleBatch(const BatchModel& p, Sampler s, const float* const* in,             \
                          float* const* out, size_t n) {                                      \
    HWY_DYNAMIC_DISPATCH(Model##Sample)(p, s, in, out, n);                                    \
  }

#define BRDFBAKE_BATCH_ELEMENTS_DISPATCH(Model)                                              \
  HWY_EXPORT(Model##EvalElements);                                                           \
  HWY_EXPORT(Model##SampleElements);                                                         \
  void Model##EvalElementsBatch(const BatchModel& p, Quantity q, const float* const* in,     \
                                float* out, size_t n) {                                      \
    HWY_DYNAMIC_DISPATCH(Model##EvalElements)(p, q, in, out, n);                             \
  }                                                                                          \
  void Model##SampleElementsBatch(const BatchModel& p, Sampler s, const float* const* in,    \
                                  float* const* out, size_t n) {                             \
    HWY_DYNAMIC_DISPATCH(Model##SampleElements)(p, s, in, out, n);                           \
  }

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_KERNELS_BATCH_DISPATCH_H_
