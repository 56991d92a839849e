// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The ellipsoid NDF's batch kernels (src/kernels/ellipsoid-inl.h, [Walter15])
// behind batch.h, compiled once per Highway target by foreach_target.h.

#include "brdfbake/models/ellipsoid.h"
#include "brdfbake/models/kernel_bounds.h"
#include "kernels/batch_dispatch.h"
#include "kernels/model_row.h"
#include "kernels/ndf_model.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/kernels/batch_ellipsoid.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "kernels/batch_rows-inl.h"
#include "kernels/ellipsoid-inl.h"

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;
using DF = hn::ScalableTag<float>;

EllipsoidConsts<DF> MakeEllipsoidConsts(const BatchModel& p) {
  return EllipsoidConsts<DF>(DF(), p.alpha_x, p.alpha_y, p.theta_x, p.theta_y, p.theta_z, p.f0);
}

void EllipsoidEval(const BatchModel& p, Quantity q, const float* const* in, float* out, size_t n) {
  const EllipsoidConsts<DF> c = MakeEllipsoidConsts(p);
  if (MicrofacetRows(EllipsoidKernels<DF>{c}, p, q, in, out, n)) return;
  if (q != Quantity::kPdfVisible) return;
  PairRows([&](auto d, auto ox, auto oy, auto oz, auto mx, auto my,
               auto mz) { return EllipsoidPdfVisible(d, c, ox, oy, oz, mx, my, mz); },
           in, out, n);
}

void EllipsoidSample(const BatchModel& p, Sampler s, const float* const* in, float* const* out,
                     size_t n) {
  const EllipsoidConsts<DF> c = MakeEllipsoidConsts(p);
  VisibleRows<0>(p,
                 [&](auto d, const auto*, auto ox, auto oy, auto oz, auto u1, auto u2, auto* mx,
                     auto* my, auto* mz) {
                   EllipsoidSampleVisible(d, c, ox, oy, oz, u1, u2, mx, my, mz);
                 },
                 in, out, n);
}

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace brdfbake {

BRDFBAKE_BATCH_EVAL_DISPATCH(Ellipsoid)
BRDFBAKE_BATCH_SAMPLE_DISPATCH(Ellipsoid)

// The stability study's probe (stability_probe.h): the kernels' bounds
// grow with the condition of the matrix products at the sample
// (kernel_bounds.h).
void EllipsoidStability(const ModelParams& p, const Vec3<double>& m_in, const Vec3<double>& a_in,
                        const Vec3<double>& b_in, StabilitySample* out) {
  const Vec3<double> m(RoundToFloat(m_in)), a(RoundToFloat(a_in)), b(RoundToFloat(b_in));
  const float ax = static_cast<float>(p.alpha_x), ay = static_cast<float>(p.alpha_y);
  const float tx = static_cast<float>(p.theta_x), ty = static_cast<float>(p.theta_y),
              tz = static_cast<float>(p.theta_z);
  const EllipsoidNdf<double> nd(ax, ay, tx, ty, tz);
  const Mat3<double>& m_a = nd.shape_matrix();
  const Mat3<double> m_ait = bounds::EllipsoidKernelInvT(ax, ay, tx, ty, tz);
  const double li = nd.Lambda(a), lo = nd.Lambda(b);
  out->ref[kStabilityD] = nd.D(m);
  out->ref[kStabilityLambda] = li;
  out->ref[kStabilityBrdf] = Brdf(nd, Fresnel::One(), a, b, Masking::kHeightCorrelated);
  out->bound[kStabilityD] = bounds::kEllipsoidDRel * bounds::Kappa(m_ait, m);
  out->bound[kStabilityLambda] = std::isinf(li) ? 1.0
                                                : bounds::kEllipsoidLambdaRel * bounds::Kappa(m_a, a) *
                                                      bounds::EllipsoidLambdaScale(m_a, a, li) / (1 + li);
  out->bound[kStabilityBrdf] = bounds::kEllipsoidBrdfRel * bounds::EllipsoidBrdfCondition(m_a, m_ait, a, b, li, lo);
  ProbeFloatReference(EllipsoidNdf<double>(p.alpha_x, p.alpha_y, p.theta_x, p.theta_y, p.theta_z),
                      EllipsoidNdf<float>(ax, ay, tx, ty, tz), m_in, a_in, b_in, out);
}

const ModelRow kEllipsoidRow = {
    ModelKind::kEllipsoid, "alpha_x, alpha_y, theta_x, theta_y, theta_z",
    "Walter et al. ellipsoid NDF, [Walter15]; A = S Rx Ry Rz", true, Bit(ModelOption::kRotation), false,
    EllipsoidEvalBatch, EllipsoidSampleBatch, false, nullptr, nullptr,
    kMicrofacetQuantities & ~Bit(Quantity::kPdfNdf), Bit(Sampler::kVisible),
    [](const ModelParams& p) {
      CheckWidths(p);
      CheckAngles(p);
    },
    [](const ModelParams& p) {
      return MakeNdfModel(p, EllipsoidNdf<double>(p.alpha_x, p.alpha_y, p.theta_x, p.theta_y, p.theta_z));
    },
    EllipsoidStability};
extern const ModelFamily kFamily_ellipsoid = {&kEllipsoidRow, 1};

}  // namespace brdfbake
#endif  // HWY_ONCE
