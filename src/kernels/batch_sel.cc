// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The squared ellipsoidal lobe's batch kernel (src/kernels/sel-inl.h, seed
// 002) behind batch.h, compiled once per Highway target by
// foreach_target.h.

#include "brdfbake/models/sel.h"
#include "kernels/batch_dispatch.h"
#include "kernels/model_row.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/kernels/batch_sel.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "kernels/batch_rows-inl.h"
#include "kernels/sel-inl.h"

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;
using DF = hn::ScalableTag<float>;

void SelEval(const BatchModel& p, Quantity q, const float* const* in, float* out, size_t n) {
  const SelConsts<DF> c(DF(), p.alpha_x, p.alpha_y, p.theta_x, p.theta_y, p.theta_z);
  DirRows([&](auto d, auto x, auto y, auto z) { return SelK(d, c, x, y, z); }, in, out, n);
}

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace brdfbake {

BRDFBAKE_BATCH_EVAL_DISPATCH(Sel)

namespace {

// The lobe K(w) alone: sel is no microfacet BRDF.
class SelModel : public Model {
 public:
  explicit SelModel(const ModelParams& p)
      : p_(p), lobe_(SelLobe<double>::FromAngles(p.alpha_x, p.alpha_y, p.theta_x, p.theta_y, p.theta_z)) {}
  const ModelParams& params() const override { return p_; }
  bool IsMicrofacet() const override { return false; }
  double D(const Vec3<double>&) const override { NotDefined("D"); }
  double Lambda(const Vec3<double>&) const override { NotDefined("Lambda"); }
  double G1(const Vec3<double>&) const override { NotDefined("G1"); }
  double G2(const Vec3<double>&, const Vec3<double>&, Masking) const override { NotDefined("G2"); }
  double Brdf(const Vec3<double>&, const Vec3<double>&, const Fresnel&, Masking, int) const override {
    NotDefined("brdf");
  }
  Vec3<double> Sample(const Vec3<double>&, double, double) const override { NotDefined("sampling"); }
  double Pdf(const Vec3<double>&, const Vec3<double>&) const override { NotDefined("pdf"); }
  double K(const Vec3<double>& w) const override { return lobe_.K(w); }

 private:
  [[noreturn]] static void NotDefined(const char* what) {
    Bad(std::string("model sel (a lobe, not a microfacet BRDF) has no ") + what + "; use the quantity K");
  }
  ModelParams p_;
  SelLobe<double> lobe_;
};

const ModelRow kSelRow = {
    ModelKind::kSel, "alpha_x, alpha_y, theta_x, theta_y, theta_z (lobe frame Q = Rx Ry Rz)",
    "squared ellipsoidal lobe K(w), [TokuyoshiHarada]", true, Bit(ModelOption::kRotation), false, SelEvalBatch,
    nullptr, false, nullptr, nullptr, Bit(Quantity::kK), 0,
    [](const ModelParams& p) {
      CheckWidths(p);
      CheckAngles(p);
    },
    [](const ModelParams& p) -> std::unique_ptr<Model> { return std::make_unique<SelModel>(p); },
    nullptr};

}  // namespace

extern const ModelFamily kFamily_sel = {&kSelRow, 1};

}  // namespace brdfbake
#endif  // HWY_ONCE
