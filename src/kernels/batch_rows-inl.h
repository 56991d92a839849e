// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The loops of the batch interface (batch.h), shared by every
// src/batch_<model>.cc: a model hands in its kernels as generic lambdas
// (d, x, y, z) or (d, separable, wi..., wo..., fresnel) and these run them
// over the structure-of-arrays rows, padded to whole vectors
// (ForEachVector, ForEachVectorOut), with masking and Fresnel resolved
// once per call.

#if defined(BRDFBAKE_SRC_KERNELS_BATCH_ROWS_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef BRDFBAKE_SRC_KERNELS_BATCH_ROWS_INL_H_
#undef BRDFBAKE_SRC_KERNELS_BATCH_ROWS_INL_H_
#else
#define BRDFBAKE_SRC_KERNELS_BATCH_ROWS_INL_H_
#endif

#include <hwy/highway.h>

#include <cstddef>

#include "brdfbake/batch.h"
#include "kernels/common-inl.h"
#include "kernels/foreach-inl.h"
#include "kernels/foreach_out-inl.h"
#include "kernels/fresnel-inl.h"

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// out = k(d, x, y, z) of one direction per lane.
template <class K>
HWY_INLINE void DirRows(const K& k, const float* const* in, float* out, size_t n) {
  ForEachVector<3>(in, 0.5f, out, n, [&](auto d, const auto* v) { return k(d, v[0], v[1], v[2]); });
}

// out = k(d, ax, ay, az, bx, by, bz) of a pair per lane.
template <class K>
HWY_INLINE void PairRows(const K& k, const float* const* in, float* out, size_t n) {
  ForEachVector<6>(in, 0.5f, out, n,
                   [&](auto d, const auto* v) { return k(d, v[0], v[1], v[2], v[3], v[4], v[5]); });
}

// G1 = 1 / (1 + Lambda) from a Lambda kernel lambda(d, x, y, z).
template <class L>
HWY_INLINE void G1Rows(const L& lambda, const float* const* in, float* out, size_t n) {
  ForEachVector<3>(in, 0.5f, out, n, [&](auto d, const auto* v) {
    const auto l = [&](auto x, auto y, auto z) { return lambda(d, x, y, z); };
    return G1FromLambda(d, l, v[0], v[1], v[2]);
  });
}

// G2 of (wi, wo) pairs with `masking`, from a Lambda kernel.
template <class L>
HWY_INLINE void G2Rows(Masking masking, const L& lambda, const float* const* in, float* out,
                       size_t n) {
  WithMasking(masking, [&](auto separable) {
    ForEachVector<6>(in, 0.5f, out, n, [&](auto d, const auto* v) {
      const auto l = [&](auto x, auto y, auto z) { return lambda(d, x, y, z); };
      return G2FromLambda(d, separable, l, v[0], v[1], v[2], v[3], v[4], v[5]);
    });
  });
}

// f(wi, wo) from a BRDF kernel brdf(d, separable, wi..., wo..., fresnel),
// with the Fresnel functor and masking of p.
template <class B>
HWY_INLINE void BrdfRows(const BatchModel& p, const B& brdf, const float* const* in, float* out,
                         size_t n) {
  WithFresnel(hn::ScalableTag<float>(), p, [&](const auto& fresnel) {
    WithMasking(p.masking, [&](auto separable) {
      ForEachVector<6>(in, 0.5f, out, n, [&](auto d, const auto* v) {
        return brdf(d, separable, v[0], v[1], v[2], v[3], v[4], v[5], fresnel);
      });
    });
  });
}

// The quantities every microfacet model's kernels K provide (the
// <Model>Kernels of each model's -inl.h): D, Lambda, G1 (K::G1 if
// K::kOwnG1, else 1 / (1 + Lambda)), G2 and the BRDF, and the NDF density
// D(m) max(0, m.z) if K::kPdfNdfFromD. Returns false for the others, which
// the model's batch file runs itself.
template <class K>
HWY_INLINE bool MicrofacetRows(const K& k, const BatchModel& p, Quantity q, const float* const* in,
                               float* out, size_t n) {
  const auto lambda = [&](auto d, auto x, auto y, auto z) { return k.Lambda(d, x, y, z); };
  switch (q) {
    case Quantity::kD:
      DirRows([&](auto d, auto x, auto y, auto z) { return k.Ndf(d, x, y, z); }, in, out, n);
      return true;
    case Quantity::kLambda:
      DirRows(lambda, in, out, n);
      return true;
    case Quantity::kG1:
      if constexpr (K::kOwnG1) {
        DirRows([&](auto d, auto x, auto y, auto z) { return k.G1(d, x, y, z); }, in, out, n);
      } else {
        G1Rows(lambda, in, out, n);
      }
      return true;
    case Quantity::kPdfNdf:
      if constexpr (K::kPdfNdfFromD) {
        DirRows([&](auto d, auto x, auto y,
                    auto z) { return hn::Mul(k.Ndf(d, x, y, z), hn::Max(z, hn::Zero(d))); },
                in, out, n);
        return true;
      }
      return false;
    case Quantity::kG2:
      G2Rows(p.masking, lambda, in, out, n);
      return true;
    case Quantity::kBrdf:
      BrdfRows(
          p,
          [&](auto d, auto separable, auto ix, auto iy, auto iz, auto ox, auto oy, auto oz,
              const auto& fresnel) {
            return k.Brdf(d, separable, ix, iy, iz, ox, oy, oz, fresnel);
          },
          in, out, n);
      return true;
    default:
      return false;
  }
}

// Normals from a sampler: kVisible calls k(d, wo_x, wo_y, wo_z, u1, u2,
// &m_x, &m_y, &m_z), kNdf calls k(d, u1, u2, &m_x, &m_y, &m_z).
template <class K>
HWY_INLINE void VisibleRows(const K& k, const float* const* in, float* const* out, size_t n) {
  ForEachVectorOut<5, 3>(in, 0.5f, out, n, [&](auto d, const auto* v, auto* r) {
    k(d, v[0], v[1], v[2], v[3], v[4], &r[0], &r[1], &r[2]);
  });
}
template <class K>
HWY_INLINE void NdfSampleRows(const K& k, const float* const* in, float* const* out, size_t n) {
  const float* u[2] = {in[3], in[4]};
  ForEachVectorOut<2, 3>(u, 0.5f, out, n, [&](auto d, const auto* v, auto* r) {
    k(d, v[0], v[1], &r[0], &r[1], &r[2]);
  });
}

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#endif  // BRDFBAKE_SRC_KERNELS_BATCH_ROWS_INL_H_
