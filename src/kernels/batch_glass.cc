// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The rough dielectric BSDF's batch kernel (src/kernels/dielectric-inl.h)
// behind batch.h (DielectricBsdfBatch), compiled once per Highway target by
// foreach_target.h.

#include "base/text.h"
#include "brdfbake/config.h"
#include "kernels/batch_dispatch.h"
#include "kernels/model_row.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/kernels/batch_glass.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "kernels/batch_rows-inl.h"
#include "kernels/dielectric-inl.h"

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;
using DF = hn::ScalableTag<float>;

// One pass over the pairs with the NDF's part `ndf`; masking and the
// cosine weight resolved once per call.
template <class Ndf>
void GlassRows(const DielectricConsts<DF>& k, const Ndf& ndf, bool separable, bool cos_weighted,
               const float* const* in, float* out, size_t n) {
  PairRows(
      [&](auto d, auto ix, auto iy, auto iz, auto ox, auto oy, auto oz) {
        return DielectricBsdf(d, k, ndf, separable, cos_weighted, ix, iy, iz, ox, oy, oz);
      },
      in, out, n);
}

void GlassEval(const BatchDielectric& p, DielectricQuantity q, const float* const* in, float* out,
               size_t n) {
  const DF d;
  const DielectricConsts<DF> k(d, p.eta, p.transport);
  const bool separable = p.masking == Masking::kSeparable;
  const bool cos_weighted = q == DielectricQuantity::kBsdfCos;
#if BRDFBAKE_WITH_BECKMANN
  if (p.ndf == ModelKind::kBeckmann) {
    const BeckmannConsts<DF> c(d, p.alpha_x, p.alpha_y, 1.0f);
    return GlassRows(k, BeckmannDielectricNdf<DF>{c}, separable, cos_weighted, in, out, n);
  }
#endif
  const GgxConsts<DF> c(d, p.alpha_x, p.alpha_y, 1.0f);
  GlassRows(k, GgxDielectricNdf<DF>{c}, separable, cos_weighted, in, out, n);
}

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace brdfbake {

HWY_EXPORT(GlassEval);
void GlassEvalBatch(const BatchDielectric& p, DielectricQuantity q, const float* const* in,
                    float* out, size_t n) {
  HWY_DYNAMIC_DISPATCH(GlassEval)(p, q, in, out, n);
}

// ggx-glass: the rough dielectric over GGX as a table model (E and E_avg);
// its BSDF is DielectricBsdfBatch, not a Model.
const ModelRow kGgxGlassRow = {
    ModelKind::kGgxGlass, "roughness, ior in [0.01, 100] (E and E_avg only)",
    "rough dielectric over GGX, [Walter07]: reflection + refraction, exact Fresnel", false, Bit(ModelOption::kIor),
    false, nullptr, nullptr, false, nullptr, nullptr, 0, 0,
    [](const ModelParams& p) {
      if (!(p.ior >= kMinFresnelIndex && p.ior <= kMaxFresnelIndex)) {
        Bad("ior must lie in [0.01, 100] (the relative index of refraction; below 1 light leaves the "
            "denser medium; got " +
            ExactText(p.ior) + ")");
      }
      CheckWidths(p);
    },
    [](const ModelParams&) -> std::unique_ptr<Model> {
      Bad("model ggx-glass has only the table quantities E and E_avg (bake them, or eval {quantity} "
          "E or E_avg); its BSDF is evaluated by DielectricBsdfBatch");
    },
    nullptr,
    nullptr,
    " is a table model; the rough dielectric's batch is DielectricBsdfBatch"};
extern const ModelFamily kFamily_glass = {&kGgxGlassRow, 1};

}  // namespace brdfbake
#endif  // HWY_ONCE
