// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The GGX batch kernels (src/kernels/ggx-inl.h, ggx_sampling-inl.h) behind
// batch.h, compiled once per Highway target by foreach_target.h.

#include "brdfbake/models/ggx.h"
#include "brdfbake/models/kernel_bounds.h"
#include "kernels/batch_dispatch.h"
#include "kernels/model_row.h"
#include "kernels/ndf_model.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/kernels/batch_ggx.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "kernels/batch_rows-inl.h"
#include "kernels/ggx-inl.h"
#include "kernels/ggx_sampling-inl.h"

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;
using DF = hn::ScalableTag<float>;

// The rows of a call with one model (kP = 0) or per-element parameters
// (kP = kElementParams; batch_rows-inl.h).
template <int kP>
void GgxEvalRows(const BatchModel& p, Quantity q, const float* const* in, float* out, size_t n) {
  if (q == Quantity::kPdfNdf || q == Quantity::kPdfVisible) {
    const GgxSamplingConsts<DF> s(DF(), p.alpha_x, p.alpha_y);
    const auto make = [](const auto* pv) { return GgxSamplingConsts<DF>(DF(), pv[0], pv[1]); };
    if (q == Quantity::kPdfNdf) {
      return Rows<3, kP>(p, in, out, n, [&](auto d, const auto* v, const auto* pv) {
        return WithConsts<kP>(s, make, pv,
                              [&](const auto& c) { return GgxPdfNdf(d, c, v[0], v[1], v[2]); });
      });
    }
    return Rows<6, kP>(p, in, out, n, [&](auto d, const auto* v, const auto* pv) {
      return WithConsts<kP>(s, make, pv, [&](const auto& c) {
        return GgxPdfVisible(d, c, v[0], v[1], v[2], v[3], v[4], v[5]);
      });
    });
  }
  const GgxConsts<DF> call(DF(), p.alpha_x, p.alpha_y, p.f0);
  const auto make = [](const auto* pv) { return GgxConsts<DF>(DF(), pv[0], pv[1], pv[2]); };
  MicrofacetRowsWith<kP, GgxKernels<DF>>(
      [&](auto, const auto* pv, const auto& body) {
        return WithConsts<kP>(call, make, pv, [&](const auto& c) { return body(GgxKernels<DF>{c}); });
      },
      p, q, in, out, n);
}

template <int kP>
void GgxSampleRows(const BatchModel& p, Sampler s, const float* const* in, float* const* out,
                   size_t n) {
  const GgxSamplingConsts<DF> call(DF(), p.alpha_x, p.alpha_y);
  const auto make = [](const auto* pv) { return GgxSamplingConsts<DF>(DF(), pv[0], pv[1]); };
  SampleRowsWith<kP>(
      p, s, call, make, [](auto d, const auto& c, auto... v) { GgxSampleVisible(d, c, v...); },
      [](auto d, const auto& c, auto... v) { GgxSampleNdf(d, c, v...); }, in, out, n);
}

void GgxEval(const BatchModel& p, Quantity q, const float* const* in, float* out, size_t n) {
  GgxEvalRows<0>(p, q, in, out, n);
}
void GgxEvalElements(const BatchModel& p, Quantity q, const float* const* in, float* out,
                     size_t n) {
  GgxEvalRows<kElementParams>(p, q, in, out, n);
}
void GgxSample(const BatchModel& p, Sampler s, const float* const* in, float* const* out,
               size_t n) {
  GgxSampleRows<0>(p, s, in, out, n);
}
void GgxSampleElements(const BatchModel& p, Sampler s, const float* const* in, float* const* out,
                       size_t n) {
  GgxSampleRows<kElementParams>(p, s, in, out, n);
}

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace brdfbake {

BRDFBAKE_BATCH_EVAL_DISPATCH(Ggx)
BRDFBAKE_BATCH_SAMPLE_DISPATCH(Ggx)
BRDFBAKE_BATCH_ELEMENTS_DISPATCH(Ggx)

// The stability study's probe (stability_probe.h): the kernels' bound is
// one relative constant.
void GgxStability(const ModelParams& p, const Vec3<double>& m_in, const Vec3<double>& a_in,
                  const Vec3<double>& b_in, StabilitySample* out) {
  const Vec3<double> m(RoundToFloat(m_in)), a(RoundToFloat(a_in)), b(RoundToFloat(b_in));
  const GgxNdf<double> nd(static_cast<float>(p.alpha_x), static_cast<float>(p.alpha_y));
  out->ref[kStabilityD] = nd.D(m);
  out->ref[kStabilityLambda] = nd.Lambda(a);
  out->ref[kStabilityBrdf] = Brdf(nd, Fresnel::One(), a, b, Masking::kHeightCorrelated);
  out->bound[kStabilityD] = out->bound[kStabilityLambda] = out->bound[kStabilityBrdf] = bounds::kGgxRel;
  ProbeFloatReference(GgxNdf<double>(p.alpha_x, p.alpha_y),
                      GgxNdf<float>(static_cast<float>(p.alpha_x), static_cast<float>(p.alpha_y)), m_in, a_in, b_in,
                      out);
}

// ggx, and ggx-aniso: GGX whose widths a table takes from the roughness
// and the anisotropy strength (tables and eval's E only).
const ModelRow kGgxRows[] = {
    {ModelKind::kGgx, "alpha_x, alpha_y", "Trowbridge-Reitz; VNDF sampling from [Heitz18]", true, 0, false,
     GgxEvalBatch, GgxSampleBatch, false, GgxEvalElementsBatch, GgxSampleElementsBatch, kMicrofacetQuantities,
     Bit(Sampler::kNdf) | Bit(Sampler::kVisible), CheckWidths,
     [](const ModelParams& p) { return MakeNdfModel(p, GgxNdf<double>(p.alpha_x, p.alpha_y)); }, GgxStability},
    {ModelKind::kGgxAniso, nullptr, nullptr, false, 0, false, nullptr, nullptr, false, nullptr, nullptr, 0, 0,
     [](const ModelParams&) {
       Bad("model ggx-aniso has only the table quantities E and E_avg (bake them, or eval {quantity} "
           "E); for its BRDF give {model} ggx with {alpha_x} and {alpha_y}");
     },
     nullptr, nullptr, nullptr, " is a table model; give ggx with its two widths"},
};
extern const ModelFamily kFamily_ggx = {kGgxRows, 2};

}  // namespace brdfbake
#endif  // HWY_ONCE
