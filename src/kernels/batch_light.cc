// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The two elementwise steps of SampleLightBatch (batch.cc) around the
// model's kernels, compiled once per Highway target: the reflection of wo
// about the sampled normal, and the light direction's density and weight.

#include "kernels/batch_dispatch.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/kernels/batch_light.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "kernels/foreach-inl.h"

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// wi = 2 (wo.m) m - wo, and 0 for wo.z <= 0.
// in: wo_x, wo_y, wo_z, m_x, m_y, m_z; out: wi_x, wi_y, wi_z.
void Reflect(const float* const* in, float* const* out, size_t n) {
  ForEachVectorOut<6, 3>(in, 0.5f, out, n, [](auto d, const auto* v, auto* r) {
    const auto om = hn::MulAdd(v[0], v[3], hn::MulAdd(v[1], v[4], hn::Mul(v[2], v[5])));
    const auto two_om = hn::Add(om, om);
    const auto above = hn::Gt(v[2], hn::Zero(d));
    for (int k = 0; k < 3; ++k) r[k] = hn::IfThenElseZero(above, hn::MulSub(two_om, v[3 + k], v[k]));
  });
}

// pdf = pdf_m / (4 wo.m), weight = f wi.z / pdf, both 0 unless wo.z > 0,
// wo.m > 0 and pdf_m > 0 (weight also 0 unless wi.z > 0).
// in: wo_x, wo_y, wo_z, m_x, m_y, m_z, wi_z, pdf_m, f; out: weight, pdf.
void LightWeight(const float* const* in, float* const* out, size_t n) {
  ForEachVectorOut<9, 2>(in, 0.5f, out, n, [](auto d, const auto* v, auto* r) {
    const auto zero = hn::Zero(d);
    const auto om = hn::MulAdd(v[0], v[3], hn::MulAdd(v[1], v[4], hn::Mul(v[2], v[5])));
    const auto four_om = hn::Mul(hn::Set(d, 4.0f), om);
    const auto valid =
        hn::And(hn::And(hn::Gt(v[2], zero), hn::Gt(om, zero)), hn::Gt(v[7], zero));
    // Divisors kept away from 0 in the lanes that are masked out.
    const auto one = hn::Set(d, 1.0f);
    const auto pdf_m = hn::IfThenElse(valid, v[7], one);
    r[1] = hn::IfThenElseZero(valid, hn::Div(pdf_m, hn::IfThenElse(valid, four_om, one)));
    const auto weight = hn::Div(hn::Mul(hn::Mul(v[8], v[6]), four_om), pdf_m);
    r[0] = hn::IfThenElseZero(hn::And(valid, hn::Gt(v[6], zero)), weight);
  });
}

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace brdfbake {

HWY_EXPORT(Reflect);
HWY_EXPORT(LightWeight);

void ReflectBatch(const float* const* in, float* const* out, size_t n) {
  HWY_DYNAMIC_DISPATCH(Reflect)(in, out, n);
}
void LightWeightBatch(const float* const* in, float* const* out, size_t n) {
  HWY_DYNAMIC_DISPATCH(LightWeight)(in, out, n);
}

}  // namespace brdfbake
#endif  // HWY_ONCE
