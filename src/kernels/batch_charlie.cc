// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The Charlie sheen's batch kernels (src/kernels/sheen-inl.h) behind
// batch.h, compiled once per Highway target by foreach_target.h.

#include <cmath>

#include "base/text.h"
#include "brdfbake/models/sheen.h"
#include "kernels/batch_dispatch.h"
#include "kernels/model_row.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/kernels/batch_charlie.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>
#include <hwy/contrib/math/math-inl.h>

#include "kernels/batch_rows-inl.h"
#include "kernels/ggx_sampling-inl.h"
#include "kernels/sheen-inl.h"

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;
using DF = hn::ScalableTag<float>;

void CharlieEval(const BatchModel& p, Quantity q, const float* const* in, float* out, size_t n) {
  const CharlieConsts<DF> c(DF(), p.alpha_x, p.visibility);
  switch (q) {
    case Quantity::kD:
      return DirRows([&](auto d, auto, auto, auto z) { return CharlieD(d, c, z); }, in, out, n);
    case Quantity::kPdfNdf:
      return DirRows(
          [&](auto d, auto, auto, auto z) {
            return hn::Mul(CharlieD(d, c, z), hn::Min(hn::Max(z, hn::Zero(d)), hn::Set(d, 1.0f)));
          },
          in, out, n);
    case Quantity::kLambda:
      return DirRows([&](auto d, auto, auto, auto z) { return CharlieLambda(d, c, z); }, in, out,
                     n);
    case Quantity::kG1:
      return DirRows([&](auto d, auto, auto, auto z) { return CharlieG1(d, c, z); }, in, out, n);
    case Quantity::kG2:
      return PairRows(
          [&](auto d, auto, auto, auto iz, auto, auto, auto oz) { return CharlieG2(d, c, iz, oz); },
          in, out, n);
    case Quantity::kBrdf:
      return PairRows(
          [&](auto d, auto ix, auto iy, auto iz, auto ox, auto oy, auto oz) {
            return CharlieBrdf(d, c, ix, iy, iz, ox, oy, oz);
          },
          in, out, n);
    default:
      return;  // batch.cc admits no other quantity
  }
}

// Normals with density D(m) m.z (CharlieSheen<T>::SampleNdf): phi = 2 pi u1,
// sin(theta_m) = u2^(alpha / (2 alpha + 1)).
void CharlieSample(const BatchModel& p, Sampler, const float* const* in, float* const* out,
                   size_t n) {
  const double alpha = ClampSheenAlpha(double(p.alpha_x));
  const float expo = static_cast<float>(alpha / (2 * alpha + 1));
  NdfSampleRows<0>(
      p,
      [&](auto d, const auto*, auto u1, auto u2, auto* mx, auto* my, auto* mz) {
        const auto one = hn::Set(d, 1.0f);
        const auto uc = hn::Min(hn::Max(u2, hn::Zero(d)), one);
        const auto pos = hn::Gt(uc, hn::Zero(d));
        const auto s = hn::IfThenElseZero(
            pos, hn::Exp(d, hn::Mul(hn::Set(d, expo), hn::Log(d, hn::IfThenElse(pos, uc, one)))));
        const auto z = hn::Sqrt(hn::Max(hn::Mul(hn::Sub(one, s), hn::Add(one, s)), hn::Zero(d)));
        using V = hn::Vec<decltype(d)>;
        V sn = hn::Zero(d), cs = hn::Zero(d);
        SinCos2Pi(d, u1, &sn, &cs);
        *mx = hn::Mul(s, cs);
        *my = hn::Mul(s, sn);
        *mz = z;
      },
      in, out, n);
}

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace brdfbake {

BRDFBAKE_BATCH_EVAL_DISPATCH(Charlie)
BRDFBAKE_BATCH_SAMPLE_DISPATCH(Charlie)

namespace {

// What a visibility without masking (no Lambda) cannot give.
std::string LacksMasking(SheenVisibility v, const char* what) {
  return std::string("charlie with the ") + SheenVisibilityName(v) + " visibility has no " + what +
         " (it has no masking term)";
}

// The Charlie sheen (models/sheen.h): an NDF with its own visibility; the
// masking argument does not apply (the conty-kulla G2 is height-correlated).
class CharlieModel : public Model {
 public:
  explicit CharlieModel(const ModelParams& p) : p_(p), sheen_(p.alpha_x, p.visibility) {}
  const ModelParams& params() const override { return p_; }
  double D(const Vec3<double>& m) const override { return sheen_.D(m); }
  double Lambda(const Vec3<double>& w) const override {
    NeedsMasking("Lambda");
    return sheen_.Lambda(w);
  }
  double G1(const Vec3<double>& w) const override {
    NeedsMasking("G1");
    return sheen_.G1(w);
  }
  double G2(const Vec3<double>& wi, const Vec3<double>& wo, Masking) const override {
    NeedsMasking("G2");
    return sheen_.G2Cos(wi.z, wo.z);
  }
  double Brdf(const Vec3<double>& wi, const Vec3<double>& wo, const Fresnel& fresnel, Masking,
              int) const override {
    CheckNoFresnel("charlie", fresnel);
    return sheen_.Brdf(wi, wo);
  }
  // The NDF's own sampler (density D(m) m.z): the sheen has no visible-normal one.
  Vec3<double> Sample(const Vec3<double>&, double u1, double u2) const override { return sheen_.SampleNdf(u1, u2); }
  double Pdf(const Vec3<double>&, const Vec3<double>& m) const override { return sheen_.PdfNdf(m); }

 private:
  void NeedsMasking(const char* what) const {
    if (!SheenHasLambda(p_.visibility)) Bad(LacksMasking(p_.visibility, what) + "; use the conty-kulla visibility");
  }
  ModelParams p_;
  CharlieSheen<double> sheen_;
};

const ModelRow kCharlieRow = {
    ModelKind::kCharlie, "alpha in (0, 1] (isotropic), visibility neubelt or conty-kulla",
    "Charlie sheen, [EstevezKulla17]; visibility [Neubelt13] or the paper's fitted Lambda", true,
    Bit(ModelOption::kVisibility), true, CharlieEvalBatch, CharlieSampleBatch, true, nullptr, nullptr,
    kMicrofacetQuantities & ~Bit(Quantity::kPdfVisible), Bit(Sampler::kNdf),
    [](const ModelParams& p) {
      CheckWidths(p);
      if (p.alpha_x != p.alpha_y) {
        Bad("model " + std::string(p.name()) + " is isotropic: alpha_x and alpha_y must be equal (got " +
            ExactText(p.alpha_x) + " and " + ExactText(p.alpha_y) + ")");
      }
      if (p.alpha_x > 1) {
        Bad("alpha of model " + std::string(p.name()) + " must lie in (0, 1] (roughness at most 1; got " +
            ExactText(p.alpha_x) + ")");
      }
    },
    [](const ModelParams& p) -> std::unique_ptr<Model> { return std::make_unique<CharlieModel>(p); },
    nullptr,
    [](const BatchModel& model, Quantity q) {
      if (SheenHasLambda(model.visibility) ||
          (q != Quantity::kLambda && q != Quantity::kG1 && q != Quantity::kG2)) {
        return std::string();
      }
      return LacksMasking(model.visibility, QuantityName(q));
    }};

}  // namespace

extern const ModelFamily kFamily_charlie = {&kCharlieRow, 1};

}  // namespace brdfbake
#endif  // HWY_ONCE
