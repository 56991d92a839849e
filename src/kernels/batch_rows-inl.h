// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The loops of the batch interface (batch.h), shared by every
// src/kernels/batch_<family>.cc: a model hands in its kernels and these run
// them over the structure-of-arrays rows in whole vectors (ForEachVector,
// ForEachVectorOut), with masking and Fresnel resolved once per call, and
// the model's constants made once per call or, with per-element
// parameters, once per vector.

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
#include "kernels/fresnel-inl.h"

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Per-element parameters (batch.h, BatchElements) follow the direction
// arrays as kElementParams more inputs: alpha_x, alpha_y and Schlick's F0,
// each null where the call's value holds for every element. kP is 0 for a
// call with one model, kElementParams for one with per-element parameters.
constexpr int kElementParams = 3;

// out = f(d, dirs, params) over kDir direction arrays, with params the
// per-element parameter vectors (alpha_x, alpha_y, F0; the call's value
// where an array is null) when kP = kElementParams.
template <int kDir, int kP, class F>
HWY_INLINE void Rows(const BatchModel& p, const float* const* in, float* out, size_t n,
                     const F& f) {
  float fill[kDir + kElementParams];
  for (int k = 0; k < kDir; ++k) fill[k] = 0.5f;
  fill[kDir] = p.alpha_x;
  fill[kDir + 1] = p.alpha_y;
  fill[kDir + 2] = p.f0;
  float* outs[1] = {out};
  ForEachVectorOut<kDir + kP, 1>(in, fill, outs, n, [&](auto d, const auto* v, auto* r) {
    r[0] = f(d, v, v + kDir);
  });
}

// body(c) with c the call's constants `call` (kP = 0), or the constants
// make(pv) of this vector's elements.
template <int kP, class C, class Make, class V, class B>
HWY_INLINE auto WithConsts(const C& call, const Make& make, const V* pv, const B& body) {
  if constexpr (kP == 0) {
    return body(call);
  } else {
    const auto c = make(pv);
    return body(c);
  }
}

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

// The quantities every microfacet model's kernels K provide (the
// <Model>Kernels of each model's -inl.h): D, Lambda, G1 (K::G1 if
// K::kOwnG1, else 1 / (1 + Lambda)), G2 and the BRDF, and the NDF density
// D(m) max(0, m.z) if K::kPdfNdfFromD. `with(d, pv, body)` returns
// body(kernels) for the parameter vectors pv (see WithConsts). Returns
// false for the other quantities, which the model's batch file runs itself.
template <int kP, class K, class With>
HWY_INLINE bool MicrofacetRowsWith(const With& with, const BatchModel& p, Quantity q,
                                   const float* const* in, float* out, size_t n) {
  const auto one = [&](const auto& f) {
    Rows<3, kP>(p, in, out, n, [&](auto d, const auto* v, const auto* pv) {
      return with(d, pv, [&](const K& k) { return f(d, k, v[0], v[1], v[2]); });
    });
  };
  switch (q) {
    case Quantity::kD:
      one([](auto d, const K& k, auto x, auto y, auto z) { return k.Ndf(d, x, y, z); });
      return true;
    case Quantity::kLambda:
      one([](auto d, const K& k, auto x, auto y, auto z) { return k.Lambda(d, x, y, z); });
      return true;
    case Quantity::kG1:
      one([](auto d, const K& k, auto x, auto y, auto z) {
        if constexpr (K::kOwnG1) {
          return k.G1(d, x, y, z);
        } else {
          const auto l = [&](auto wx, auto wy, auto wz) { return k.Lambda(d, wx, wy, wz); };
          return G1FromLambda(d, l, x, y, z);
        }
      });
      return true;
    case Quantity::kPdfNdf:
      if constexpr (K::kPdfNdfFromD) {
        one([](auto d, const K& k, auto x, auto y, auto z) {
          return hn::Mul(k.Ndf(d, x, y, z), hn::Max(z, hn::Zero(d)));
        });
        return true;
      }
      return false;
    case Quantity::kG2:
      WithMasking(p.masking, [&](auto separable) {
        Rows<6, kP>(p, in, out, n, [&](auto d, const auto* v, const auto* pv) {
          return with(d, pv, [&](const K& k) {
            const auto l = [&](auto x, auto y, auto z) { return k.Lambda(d, x, y, z); };
            return G2FromLambda(d, separable, l, v[0], v[1], v[2], v[3], v[4], v[5]);
          });
        });
      });
      return true;
    case Quantity::kBrdf: {
      const auto brdf = [&](const auto& fresnel_of) {
        WithMasking(p.masking, [&](auto separable) {
          Rows<6, kP>(p, in, out, n, [&](auto d, const auto* v, const auto* pv) {
            return with(d, pv, [&](const K& k) {
              return k.Brdf(d, separable, v[0], v[1], v[2], v[3], v[4], v[5], fresnel_of(pv));
            });
          });
        });
      };
      if constexpr (kP != 0) {
        if (p.fresnel == BatchFresnel::kSchlick) {
          // Schlick's F0 per element.
          brdf([](const auto* pv) { return SchlickFresnel<hn::ScalableTag<float>>{pv[2]}; });
          return true;
        }
      }
      WithFresnel(hn::ScalableTag<float>(), p, [&](const auto& fresnel) {
        brdf([&](const auto*) -> const auto& { return fresnel; });
      });
      return true;
    }
    default:
      return false;
  }
}

// The same for one model per call.
template <class K>
HWY_INLINE bool MicrofacetRows(const K& k, const BatchModel& p, Quantity q, const float* const* in,
                               float* out, size_t n) {
  return MicrofacetRowsWith<0, K>([&](auto, const auto*, const auto& body) { return body(k); }, p,
                                  q, in, out, n);
}

// Normals from a sampler: kVisible calls k(d, pv, wo_x, wo_y, wo_z, u1, u2,
// &m_x, &m_y, &m_z), kNdf calls k(d, pv, u1, u2, &m_x, &m_y, &m_z), pv the
// per-element parameter vectors (see Rows).
template <int kP, class K>
HWY_INLINE void VisibleRows(const BatchModel& p, const K& k, const float* const* in,
                            float* const* out, size_t n) {
  float fill[5 + kElementParams] = {0.5f, 0.5f, 0.5f, 0.5f, 0.5f, p.alpha_x, p.alpha_y, p.f0};
  ForEachVectorOut<5 + kP, 3>(in, fill, out, n, [&](auto d, const auto* v, auto* r) {
    k(d, v + 5, v[0], v[1], v[2], v[3], v[4], &r[0], &r[1], &r[2]);
  });
}
template <int kP, class K>
HWY_INLINE void NdfSampleRows(const BatchModel& p, const K& k, const float* const* in,
                              float* const* out, size_t n) {
  // The NDF samplers do not read wo: its arrays are left out.
  const float* u[2 + kElementParams] = {in[3], in[4]};
  for (int j = 0; j < kP; ++j) u[2 + j] = in[5 + j];
  float fill[2 + kElementParams] = {0.5f, 0.5f, p.alpha_x, p.alpha_y, p.f0};
  ForEachVectorOut<2 + kP, 3>(u, fill, out, n, [&](auto d, const auto* v, auto* r) {
    k(d, v + 2, v[0], v[1], &r[0], &r[1], &r[2]);
  });
}

// A model's two samplers over its constants (made once per call, or per
// vector from the per-element parameters; see WithConsts):
// visible(d, c, wo_x, wo_y, wo_z, u1, u2, &m_x, &m_y, &m_z) and
// ndf(d, c, u1, u2, &m_x, &m_y, &m_z).
template <int kP, class C, class Make, class Visible, class Ndf>
HWY_INLINE void SampleRowsWith(const BatchModel& p, Sampler s, const C& call, const Make& make,
                               const Visible& visible, const Ndf& ndf, const float* const* in,
                               float* const* out, size_t n) {
  if (s == Sampler::kVisible) {
    return VisibleRows<kP>(p,
                           [&](auto d, const auto* pv, auto ox, auto oy, auto oz, auto u1, auto u2,
                               auto* mx, auto* my, auto* mz) {
                             WithConsts<kP>(call, make, pv, [&](const auto& c) {
                               visible(d, c, ox, oy, oz, u1, u2, mx, my, mz);
                             });
                           },
                           in, out, n);
  }
  NdfSampleRows<kP>(p,
                    [&](auto d, const auto* pv, auto u1, auto u2, auto* mx, auto* my, auto* mz) {
                      WithConsts<kP>(call, make, pv,
                                     [&](const auto& c) { ndf(d, c, u1, u2, mx, my, mz); });
                    },
                    in, out, n);
}

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#endif  // BRDFBAKE_SRC_KERNELS_BATCH_ROWS_INL_H_
