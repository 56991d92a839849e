// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The Disney diffuse batch kernel (src/kernels/sheen-inl.h) behind
// batch.h, compiled once per Highway target by foreach_target.h.

#include <cmath>

#include "base/text.h"
#include "brdfbake/models/disney_diffuse.h"
#include "kernels/batch_dispatch.h"
#include "kernels/model_row.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/kernels/batch_disney.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "kernels/batch_rows-inl.h"
#include "kernels/sheen-inl.h"

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;
using DF = hn::ScalableTag<float>;

void DisneyEval(const BatchModel& p, Quantity, const float* const* in, float* out, size_t n) {
  const DisneyConsts<DF> c(DF(), std::sqrt(double(p.alpha_x)));
  PairRows(
      [&](auto d, auto ix, auto iy, auto iz, auto ox, auto oy, auto oz) {
        return DisneyBrdf(d, c, ix, iy, iz, ox, oy, oz);
      },
      in, out, n);
}

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace brdfbake {

BRDFBAKE_BATCH_EVAL_DISPATCH(Disney)

namespace {

// The Disney diffuse BRDF (models/disney_diffuse.h) at r = sqrt(alpha_x).
class DisneyDiffuseModel : public Model {
 public:
  explicit DisneyDiffuseModel(const ModelParams& p) : p_(p), diffuse_(std::sqrt(p.alpha_x)) {}
  const ModelParams& params() const override { return p_; }
  bool IsMicrofacet() const override { return false; }
  double D(const Vec3<double>&) const override { NotDefined("D"); }
  double Lambda(const Vec3<double>&) const override { NotDefined("Lambda"); }
  double G1(const Vec3<double>&) const override { NotDefined("G1"); }
  double G2(const Vec3<double>&, const Vec3<double>&, Masking) const override { NotDefined("G2"); }
  double Brdf(const Vec3<double>& wi, const Vec3<double>& wo, const Fresnel& fresnel, Masking,
              int) const override {
    CheckNoFresnel("disney-diffuse", fresnel);
    return diffuse_.Brdf(wi, wo);
  }
  Vec3<double> Sample(const Vec3<double>&, double, double) const override { NotDefined("normal sampling"); }
  double Pdf(const Vec3<double>&, const Vec3<double>&) const override { NotDefined("pdf"); }

 private:
  [[noreturn]] static void NotDefined(const char* what) {
    Bad(std::string("model disney-diffuse (a diffuse BRDF, no microfacets) has no ") + what +
        "; use the quantity brdf");
  }
  ModelParams p_;
  DisneyDiffuse<double> diffuse_;
};

const ModelRow kDisneyRow = {
    ModelKind::kDisneyDiffuse, "r = sqrt(alpha) in [0, 1] (isotropic)", "Disney diffuse, [Burley12]; no microfacets",
    true, 0, true, DisneyEvalBatch, nullptr, false, nullptr, nullptr, Bit(Quantity::kBrdf), 0,
    [](const ModelParams& p) {
      // r = sqrt(alpha) in [0, 1]: r = 0 is an ordinary diffuse lobe.
      if (!(p.alpha_x >= 0 && p.alpha_x <= 1) || p.alpha_x != p.alpha_y) {
        Bad("model disney-diffuse takes one roughness r in [0, 1] (alpha = r^2; got alpha_x " +
            ExactText(p.alpha_x) + ", alpha_y " + ExactText(p.alpha_y) + ")");
      }
    },
    [](const ModelParams& p) -> std::unique_ptr<Model> { return std::make_unique<DisneyDiffuseModel>(p); },
    nullptr};

}  // namespace

extern const ModelFamily kFamily_disney = {&kDisneyRow, 1};

}  // namespace brdfbake
#endif  // HWY_ONCE
