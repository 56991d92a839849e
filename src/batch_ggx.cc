// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Dynamic dispatch of the GGX batch kernels (src/simd/ggx-inl.h): compiled
// once per Highway target by foreach_target.h.

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "brdfbake/batch.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/batch_ggx.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "simd/foreach-inl.h"
#include "simd/fresnel-inl.h"
#include "simd/ggx-inl.h"

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

void GgxBrdfRow(const GgxBatchParams& p, const float* const* in, float* out, size_t n) {
  using D = hn::ScalableTag<float>;
  const D d;
  const GgxConsts<D> c(d, p.alpha_x, p.alpha_y, p.f0);
  WithFresnel(d, p, [&](const auto& fresnel) {
    WithMasking(p.masking, [&](auto separable) {
      ForEachVector<6>(in, 0.5f, out, n, [&](auto dd, const auto* v) {
        return GgxBrdf(dd, c, separable, v[0], v[1], v[2], v[3], v[4], v[5], fresnel);
      });
    });
  });
}

void GgxG1Row(const GgxBatchParams& p, const float* const* in, float* out, size_t n) {
  using D = hn::ScalableTag<float>;
  const D d;
  const GgxConsts<D> c(d, p.alpha_x, p.alpha_y, p.f0);
  ForEachVector<3>(in, 0.5f, out, n, [&](auto dd, const auto* v) {
    const auto lambda = [&](auto x, auto y, auto z) { return GgxLambda(dd, c, x, y, z); };
    return G1FromLambda(dd, lambda, v[0], v[1], v[2]);
  });
}

void GgxG2Row(const GgxBatchParams& p, const float* const* in, float* out, size_t n) {
  using D = hn::ScalableTag<float>;
  const D d;
  const GgxConsts<D> c(d, p.alpha_x, p.alpha_y, p.f0);
  WithMasking(p.masking, [&](auto separable) {
    ForEachVector<6>(in, 0.5f, out, n, [&](auto dd, const auto* v) {
      const auto lambda = [&](auto x, auto y, auto z) { return GgxLambda(dd, c, x, y, z); };
      return G2FromLambda(dd, separable, lambda, v[0], v[1], v[2], v[3], v[4], v[5]);
    });
  });
}

void GgxDRow(const GgxBatchParams& p, const float* const* in, float* out, size_t n) {
  using D = hn::ScalableTag<float>;
  const D d;
  const GgxConsts<D> c(d, p.alpha_x, p.alpha_y, p.f0);
  ForEachVector<3>(in, 0.5f, out, n,
                   [&](auto dd, const auto* v) { return GgxD(dd, c, v[0], v[1], v[2]); });
}

void GgxLambdaRow(const GgxBatchParams& p, const float* const* in, float* out, size_t n) {
  using D = hn::ScalableTag<float>;
  const D d;
  const GgxConsts<D> c(d, p.alpha_x, p.alpha_y, p.f0);
  ForEachVector<3>(in, 0.5f, out, n,
                   [&](auto dd, const auto* v) { return GgxLambda(dd, c, v[0], v[1], v[2]); });
}

int64_t ThisTarget() { return HWY_TARGET; }

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace brdfbake {

HWY_EXPORT(GgxBrdfRow);
HWY_EXPORT(GgxDRow);
HWY_EXPORT(GgxLambdaRow);
HWY_EXPORT(GgxG1Row);
HWY_EXPORT(GgxG2Row);
HWY_EXPORT(ThisTarget);

void GgxBrdfBatch(const GgxBatchParams& p, const float* wi_x, const float* wi_y,
                  const float* wi_z, const float* wo_x, const float* wo_y, const float* wo_z,
                  float* out, size_t n) {
  const float* in[6] = {wi_x, wi_y, wi_z, wo_x, wo_y, wo_z};
  HWY_DYNAMIC_DISPATCH(GgxBrdfRow)(p, in, out, n);
}

void GgxDBatch(const GgxBatchParams& p, const float* m_x, const float* m_y, const float* m_z,
               float* out, size_t n) {
  const float* in[3] = {m_x, m_y, m_z};
  HWY_DYNAMIC_DISPATCH(GgxDRow)(p, in, out, n);
}

void GgxLambdaBatch(const GgxBatchParams& p, const float* w_x, const float* w_y,
                    const float* w_z, float* out, size_t n) {
  const float* in[3] = {w_x, w_y, w_z};
  HWY_DYNAMIC_DISPATCH(GgxLambdaRow)(p, in, out, n);
}

void GgxG1Batch(const GgxBatchParams& p, const float* w_x, const float* w_y, const float* w_z,
                float* out, size_t n) {
  const float* in[3] = {w_x, w_y, w_z};
  HWY_DYNAMIC_DISPATCH(GgxG1Row)(p, in, out, n);
}

void GgxG2Batch(const GgxBatchParams& p, const float* wi_x, const float* wi_y,
                const float* wi_z, const float* wo_x, const float* wo_y, const float* wo_z,
                float* out, size_t n) {
  const float* in[6] = {wi_x, wi_y, wi_z, wo_x, wo_y, wo_z};
  HWY_DYNAMIC_DISPATCH(GgxG2Row)(p, in, out, n);
}

std::string BatchTarget() { return hwy::TargetName(HWY_DYNAMIC_DISPATCH(ThisTarget)()); }

std::vector<std::string> AvailableTargets() {
  std::vector<std::string> names;
  hwy::SetSupportedTargetsForTest(0);
  const int64_t usable = hwy::SupportedTargets() & HWY_TARGETS;
  for (int64_t t = usable; t != 0; t &= t - 1) names.push_back(hwy::TargetName(t & (~t + 1)));
  return names;
}

void ForceTarget(const std::string& name) {
  hwy::SetSupportedTargetsForTest(0);
  if (name == "best") return;
  const int64_t usable = hwy::SupportedTargets() & HWY_TARGETS;
  for (int64_t t = HWY_TARGETS; t != 0; t &= t - 1) {
    const int64_t bit = t & (~t + 1);
    if (name == hwy::TargetName(bit)) {
      if (!(usable & bit)) {
        throw std::invalid_argument("--target: " + name + " is compiled in but this CPU lacks it");
      }
      hwy::SetSupportedTargetsForTest(bit);
      return;
    }
  }
  std::string list;
  for (int64_t t = HWY_TARGETS; t != 0; t &= t - 1) list += std::string(list.empty() ? "" : ", ") + hwy::TargetName(t & (~t + 1));
  throw std::invalid_argument("--target: unknown target '" + name + "' (compiled: " + list + ", or best)");
}

}  // namespace brdfbake
#endif  // HWY_ONCE
