// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The Beckmann batch kernels (src/kernels/beckmann-inl.h,
// beckmann_sampling-inl.h) behind batch.h, compiled once per Highway target
// by foreach_target.h.

#include "brdfbake/models/beckmann.h"
#include "kernels/batch_dispatch.h"
#include "kernels/model_row.h"
#include "kernels/ndf_model.h"
#include "kernels/slope_stability.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/kernels/batch_beckmann.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "kernels/batch_rows-inl.h"
#include "kernels/beckmann-inl.h"
#include "kernels/beckmann_sampling-inl.h"

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;
using DF = hn::ScalableTag<float>;

// The rows of a call with one model (kP = 0) or per-element parameters
// (kP = kElementParams; batch_rows-inl.h).
template <int kP>
void BeckmannEvalRows(const BatchModel& p, Quantity q, const float* const* in, float* out,
                      size_t n) {
  const BeckmannConsts<DF> call(DF(), p.alpha_x, p.alpha_y, p.f0);
  const auto make = [](const auto* pv) { return BeckmannConsts<DF>(DF(), pv[0], pv[1], pv[2]); };
  const auto with = [&](auto, const auto* pv, const auto& body) {
    return WithConsts<kP>(call, make, pv,
                          [&](const auto& c) { return body(BeckmannKernels<DF>{c}); });
  };
  if (MicrofacetRowsWith<kP, BeckmannKernels<DF>>(with, p, q, in, out, n)) return;
  if (q != Quantity::kPdfVisible) return;
  Rows<6, kP>(p, in, out, n, [&](auto d, const auto* v, const auto* pv) {
    return WithConsts<kP>(call, make, pv, [&](const auto& c) {
      return BeckmannPdfVisible(d, c, v[0], v[1], v[2], v[3], v[4], v[5]);
    });
  });
}

template <int kP>
void BeckmannSampleRows(const BatchModel& p, Sampler s, const float* const* in, float* const* out,
                        size_t n) {
  const BeckmannConsts<DF> call(DF(), p.alpha_x, p.alpha_y, p.f0);
  const auto make = [](const auto* pv) { return BeckmannConsts<DF>(DF(), pv[0], pv[1], pv[2]); };
  SampleRowsWith<kP>(
      p, s, call, make, [](auto d, const auto& c, auto... v) { BeckmannSampleVisible(d, c, v...); },
      [](auto d, const auto& c, auto... v) { BeckmannSampleNdf(d, c, v...); }, in, out, n);
}

void BeckmannEval(const BatchModel& p, Quantity q, const float* const* in, float* out, size_t n) {
  BeckmannEvalRows<0>(p, q, in, out, n);
}
void BeckmannEvalElements(const BatchModel& p, Quantity q, const float* const* in, float* out,
                          size_t n) {
  BeckmannEvalRows<kElementParams>(p, q, in, out, n);
}
void BeckmannSample(const BatchModel& p, Sampler s, const float* const* in, float* const* out,
                    size_t n) {
  BeckmannSampleRows<0>(p, s, in, out, n);
}
void BeckmannSampleElements(const BatchModel& p, Sampler s, const float* const* in,
                            float* const* out, size_t n) {
  BeckmannSampleRows<kElementParams>(p, s, in, out, n);
}

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace brdfbake {

BRDFBAKE_BATCH_EVAL_DISPATCH(Beckmann)
BRDFBAKE_BATCH_SAMPLE_DISPATCH(Beckmann)
BRDFBAKE_BATCH_ELEMENTS_DISPATCH(Beckmann)

// The stability study's probe (stability_probe.h, slope_stability.h).
void BeckmannStability(const ModelParams& p, const Vec3<double>& m, const Vec3<double>& a, const Vec3<double>& b,
                       StabilitySample* out) {
  ProbeSlopeKernels(true, p, m, a, b, out);
  ProbeFloatReference(BeckmannNdf<double>(p.alpha_x, p.alpha_y),
                      BeckmannNdf<float>(static_cast<float>(p.alpha_x), static_cast<float>(p.alpha_y)), m, a, b, out);
}

const ModelRow kBeckmannRow = {
    ModelKind::kBeckmann, "alpha_x, alpha_y", "Gaussian slopes; exact VNDF sampling by CDF inversion", true, 0,
    false, BeckmannEvalBatch, BeckmannSampleBatch, true, BeckmannEvalElementsBatch, BeckmannSampleElementsBatch,
    kMicrofacetQuantities, Bit(Sampler::kNdf) | Bit(Sampler::kVisible), CheckWidths,
    [](const ModelParams& p) { return MakeNdfModel(p, BeckmannNdf<double>(p.alpha_x, p.alpha_y)); },
    BeckmannStability};
extern const ModelFamily kFamily_beckmann = {&kBeckmannRow, 1};

}  // namespace brdfbake
#endif  // HWY_ONCE
