// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The Student's-t (std) batch kernels (src/kernels/std-inl.h,
// std_sampling-inl.h) behind batch.h, compiled once per Highway target by
// foreach_target.h. From gamma = 1e10 on (kStudentTBeckmannGamma) D,
// Lambda, G1, G2, the BRDF and NDF sampling are Beckmann's kernels; the
// pseudo-VNIS handles that limit itself.

#include "brdfbake/models/std_ndf.h"
#include "kernels/batch_dispatch.h"
#include "kernels/model_row.h"
#include "kernels/ndf_model.h"
#include "kernels/slope_stability.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/kernels/batch_std.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "kernels/batch_rows-inl.h"
#include "kernels/beckmann-inl.h"
#include "kernels/std-inl.h"
#include "kernels/std_sampling-inl.h"

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;
using DF = hn::ScalableTag<float>;

// batch_beckmann.cc, the same target.
void BeckmannEval(const BatchModel& p, Quantity q, const float* const* in, float* out, size_t n);

void StudentTEval(const BatchModel& p, Quantity q, const float* const* in, float* out, size_t n) {
  if (q == Quantity::kPdfVisible) {
    const StudentTSamplingConsts<DF> s(DF(), p.alpha_x, p.alpha_y, p.gamma);
    return PairRows([&](auto d, auto ox, auto oy, auto oz, auto mx, auto my,
                        auto mz) { return StudentTPdfPseudoVnis(d, s, ox, oy, oz, mx, my, mz); },
                    in, out, n);
  }
  const StudentTConsts<DF> c(DF(), p.alpha_x, p.alpha_y, p.f0, p.gamma);
  if (c.beckmann) {
    MicrofacetRows(BeckmannKernels<DF>{c.b}, p, q, in, out, n);
  } else {
    MicrofacetRows(StudentTKernels<DF>{c}, p, q, in, out, n);
  }
}

void StudentTSample(const BatchModel& p, Sampler s, const float* const* in, float* const* out,
                    size_t n) {
  if (s == Sampler::kVisible) {
    const StudentTSamplingConsts<DF> c(DF(), p.alpha_x, p.alpha_y, p.gamma);
    return VisibleRows<0>(p,
                          [&](auto d, const auto*, auto ox, auto oy, auto oz, auto u1, auto u2,
                              auto* mx, auto* my, auto* mz) {
                            StudentTSamplePseudoVnis(d, c, ox, oy, oz, u1, u2, mx, my, mz);
                          },
                          in, out, n);
  }
  const StudentTConsts<DF> c(DF(), p.alpha_x, p.alpha_y, p.f0, p.gamma);
  if (c.beckmann) {
    return NdfSampleRows<0>(p,
                            [&](auto d, const auto*, auto u1, auto u2, auto* mx, auto* my,
                                auto* mz) { BeckmannSampleNdf(d, c.b, u1, u2, mx, my, mz); },
                            in, out, n);
  }
  NdfSampleRows<0>(p,
                   [&](auto d, const auto*, auto u1, auto u2, auto* mx, auto* my,
                       auto* mz) { StudentTSampleNdf(d, c, u1, u2, mx, my, mz); },
                   in, out, n);
}

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace brdfbake {

BRDFBAKE_BATCH_EVAL_DISPATCH(StudentT)
BRDFBAKE_BATCH_SAMPLE_DISPATCH(StudentT)

namespace {

// The STD samples by its pseudo visible-normal importance sampler
// ([Ribardiere17] Algorithm 1) and reports that density.
struct PseudoVnis {
  static Vec3<double> Sample(const StudentTNdf<double>& ndf, const Vec3<double>& wo, double u1, double u2) {
    return ndf.SamplePseudoVnis(wo, u1, u2);
  }
  static double Pdf(const StudentTNdf<double>& ndf, const Vec3<double>& wo, const Vec3<double>& m) {
    return ndf.PdfPseudoVnis(wo, m);
  }
};

// The stability study's probe (stability_probe.h, slope_stability.h).
void StudentTStability(const ModelParams& p, const Vec3<double>& m, const Vec3<double>& a, const Vec3<double>& b,
                       StabilitySample* out) {
  ProbeSlopeKernels(false, p, m, a, b, out);
  ProbeFloatReference(StudentTNdf<double>(p.alpha_x, p.alpha_y, p.gamma),
                      StudentTNdf<float>(static_cast<float>(p.alpha_x), static_cast<float>(p.alpha_y),
                                         static_cast<float>(p.gamma)),
                      m, a, b, out);
}

const ModelRow kStudentTRow = {
    ModelKind::kStudentT, "alpha_x, alpha_y, gamma in [1.500001, inf]",
    "Student's t slopes, [Ribardiere17]; gamma=2 is ggx, inf is beckmann", true, Bit(ModelOption::kGamma), false,
    StudentTEvalBatch, StudentTSampleBatch, true, nullptr, nullptr, kMicrofacetQuantities,
    Bit(Sampler::kNdf) | Bit(Sampler::kVisible),
    [](const ModelParams& p) {
      CheckWidths(p);
      if (!StudentTGammaAllowed(p.gamma)) Bad("gamma " + StudentTGammaDomain(p.gamma));
    },
    [](const ModelParams& p) {
      return MakeNdfModel<PseudoVnis>(p, StudentTNdf<double>(p.alpha_x, p.alpha_y, p.gamma));
    },
    StudentTStability};

}  // namespace

extern const ModelFamily kFamily_std = {&kStudentTRow, 1};

}  // namespace brdfbake
#endif  // HWY_ONCE
