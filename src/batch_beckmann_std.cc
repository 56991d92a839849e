// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Dynamic dispatch of the Beckmann and STD batch kernels
// (src/simd/beckmann-inl.h, src/simd/std-inl.h): compiled once per Highway
// target by foreach_target.h.

#include <cstring>

#include "brdfbake/batch_beckmann_std.h"
#include "brdfbake/config.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/batch_beckmann_std.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "simd/beckmann-inl.h"
#include "simd/foreach-inl.h"
#include "simd/fresnel-inl.h"
#if BRDFBAKE_WITH_STD
#include "simd/std-inl.h"
#endif

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;
using DF = hn::ScalableTag<float>;

// The sampling loop: two input arrays, three outputs, the tail padded into
// one more vector as in ForEachVector (foreach-inl.h).
template <class Kernel>
HWY_INLINE void ForEachSample(const float* u1, const float* u2, float* const* out, size_t n,
                              const Kernel& kernel) {
  const DF d;
  const size_t N = hn::Lanes(d);
  size_t i = 0;
  hn::Vec<DF> m[3];
  for (; i + N <= n; i += N) {
    kernel(d, hn::LoadU(d, u1 + i), hn::LoadU(d, u2 + i), m);
    for (int k = 0; k < 3; ++k) hn::StoreU(m[k], d, out[k] + i);
  }
  if (i < n) {
    HWY_ALIGN float buf[2][HWY_MAX_BYTES / sizeof(float)];
    HWY_ALIGN float res[HWY_MAX_BYTES / sizeof(float)];
    const size_t rem = n - i;
    for (size_t j = 0; j < N; ++j) {
      buf[0][j] = j < rem ? u1[i + j] : 0.5f;
      buf[1][j] = j < rem ? u2[i + j] : 0.5f;
    }
    kernel(d, hn::Load(d, buf[0]), hn::Load(d, buf[1]), m);
    for (int k = 0; k < 3; ++k) {
      hn::Store(m[k], d, res);
      std::memcpy(out[k] + i, res, rem * sizeof(float));
    }
  }
}

void BeckmannBrdfRow(const BeckmannBatchParams& p, const float* const* in, float* out,
                     size_t n) {
  const BeckmannConsts<DF> c(DF(), p.alpha_x, p.alpha_y, p.f0);
  WithFresnel(DF(), p, [&](const auto& fresnel) {
    WithMasking(p.masking, [&](auto separable) {
      ForEachVector<6>(in, 0.5f, out, n, [&](auto d, const auto* v) {
        return BeckmannBrdf(d, c, separable, v[0], v[1], v[2], v[3], v[4], v[5], fresnel);
      });
    });
  });
}

// G1, G2 and the NDF sampling density D(m) m.z of a Beckmann constant set
// (also the STD rows' gamma = inf branch).
void BeckmannG1With(const BeckmannConsts<DF>& c, const float* const* in, float* out, size_t n) {
  ForEachVector<3>(in, 0.5f, out, n, [&](auto d, const auto* v) {
    const auto lambda = [&](auto x, auto y, auto z) { return BeckmannLambda(d, c, x, y, z); };
    return G1FromLambda(d, lambda, v[0], v[1], v[2]);
  });
}
void BeckmannG2With(const BeckmannConsts<DF>& c, bool separable, const float* const* in,
                    float* out, size_t n) {
  ForEachVector<6>(in, 0.5f, out, n, [&](auto d, const auto* v) {
    const auto lambda = [&](auto x, auto y, auto z) { return BeckmannLambda(d, c, x, y, z); };
    return G2FromLambda(d, separable, lambda, v[0], v[1], v[2], v[3], v[4], v[5]);
  });
}
void BeckmannPdfNdfWith(const BeckmannConsts<DF>& c, const float* const* in, float* out,
                        size_t n) {
  ForEachVector<3>(in, 0.5f, out, n, [&](auto d, const auto* v) {
    return hn::Mul(BeckmannD(d, c, v[0], v[1], v[2]), hn::Max(v[2], hn::Zero(d)));
  });
}

void BeckmannG1Row(const BeckmannBatchParams& p, const float* const* in, float* out, size_t n) {
  BeckmannG1With(BeckmannConsts<DF>(DF(), p.alpha_x, p.alpha_y, p.f0), in, out, n);
}
void BeckmannG2Row(const BeckmannBatchParams& p, const float* const* in, float* out, size_t n) {
  BeckmannG2With(BeckmannConsts<DF>(DF(), p.alpha_x, p.alpha_y, p.f0),
                 p.masking == Masking::kSeparable, in, out, n);
}
void BeckmannPdfNdfRow(const BeckmannBatchParams& p, const float* const* in, float* out,
                       size_t n) {
  BeckmannPdfNdfWith(BeckmannConsts<DF>(DF(), p.alpha_x, p.alpha_y, p.f0), in, out, n);
}

void BeckmannDRow(const BeckmannBatchParams& p, const float* const* in, float* out, size_t n) {
  const BeckmannConsts<DF> c(DF(), p.alpha_x, p.alpha_y, p.f0);
  ForEachVector<3>(in, 0.5f, out, n,
                   [&](auto d, const auto* v) { return BeckmannD(d, c, v[0], v[1], v[2]); });
}

void BeckmannLambdaRow(const BeckmannBatchParams& p, const float* const* in, float* out,
                       size_t n) {
  const BeckmannConsts<DF> c(DF(), p.alpha_x, p.alpha_y, p.f0);
  ForEachVector<3>(in, 0.5f, out, n, [&](auto d, const auto* v) {
    return BeckmannLambda(d, c, v[0], v[1], v[2]);
  });
}

void BeckmannSampleRow(const BeckmannBatchParams& p, const float* u1, const float* u2,
                       float* const* out, size_t n) {
  const BeckmannConsts<DF> c(DF(), p.alpha_x, p.alpha_y, p.f0);
  ForEachSample(u1, u2, out, n, [&](auto d, auto v1, auto v2, auto* m) {
    BeckmannSampleNdf(d, c, v1, v2, &m[0], &m[1], &m[2]);
  });
}

#if BRDFBAKE_WITH_STD
// The STD rows run the Beckmann kernels when gamma >= kStudentTBeckmannGamma.
void StudentTBrdfRow(const StudentTBatchParams& p, const float* const* in, float* out, size_t n) {
  const StudentTConsts<DF> c(DF(), p.alpha_x, p.alpha_y, p.f0, p.gamma);
  WithFresnel(DF(), p, [&](const auto& fresnel) {
    WithMasking(p.masking, [&](auto separable) {
      if (c.beckmann) {
        ForEachVector<6>(in, 0.5f, out, n, [&](auto d, const auto* v) {
          return BeckmannBrdf(d, c.b, separable, v[0], v[1], v[2], v[3], v[4], v[5], fresnel);
        });
        return;
      }
      ForEachVector<6>(in, 0.5f, out, n, [&](auto d, const auto* v) {
        return StudentTBrdf(d, c, separable, v[0], v[1], v[2], v[3], v[4], v[5], fresnel);
      });
    });
  });
}

void StudentTG1Row(const StudentTBatchParams& p, const float* const* in, float* out, size_t n) {
  const StudentTConsts<DF> c(DF(), p.alpha_x, p.alpha_y, p.f0, p.gamma);
  if (c.beckmann) return BeckmannG1With(c.b, in, out, n);
  ForEachVector<3>(in, 0.5f, out, n, [&](auto d, const auto* v) {
    const auto lambda = [&](auto x, auto y, auto z) { return StudentTLambda(d, c, x, y, z); };
    return G1FromLambda(d, lambda, v[0], v[1], v[2]);
  });
}
void StudentTG2Row(const StudentTBatchParams& p, const float* const* in, float* out, size_t n) {
  const StudentTConsts<DF> c(DF(), p.alpha_x, p.alpha_y, p.f0, p.gamma);
  const bool separable = p.masking == Masking::kSeparable;
  if (c.beckmann) return BeckmannG2With(c.b, separable, in, out, n);
  ForEachVector<6>(in, 0.5f, out, n, [&](auto d, const auto* v) {
    const auto lambda = [&](auto x, auto y, auto z) { return StudentTLambda(d, c, x, y, z); };
    return G2FromLambda(d, separable, lambda, v[0], v[1], v[2], v[3], v[4], v[5]);
  });
}
void StudentTPdfNdfRow(const StudentTBatchParams& p, const float* const* in, float* out, size_t n) {
  const StudentTConsts<DF> c(DF(), p.alpha_x, p.alpha_y, p.f0, p.gamma);
  if (c.beckmann) return BeckmannPdfNdfWith(c.b, in, out, n);
  ForEachVector<3>(in, 0.5f, out, n, [&](auto d, const auto* v) {
    return hn::Mul(StudentTD(d, c, v[0], v[1], v[2]), hn::Max(v[2], hn::Zero(d)));
  });
}

void StudentTDRow(const StudentTBatchParams& p, const float* const* in, float* out, size_t n) {
  const StudentTConsts<DF> c(DF(), p.alpha_x, p.alpha_y, p.f0, p.gamma);
  if (c.beckmann) {
    ForEachVector<3>(in, 0.5f, out, n,
                     [&](auto d, const auto* v) { return BeckmannD(d, c.b, v[0], v[1], v[2]); });
    return;
  }
  ForEachVector<3>(in, 0.5f, out, n,
                   [&](auto d, const auto* v) { return StudentTD(d, c, v[0], v[1], v[2]); });
}

void StudentTLambdaRow(const StudentTBatchParams& p, const float* const* in, float* out, size_t n) {
  const StudentTConsts<DF> c(DF(), p.alpha_x, p.alpha_y, p.f0, p.gamma);
  if (c.beckmann) {
    ForEachVector<3>(in, 0.5f, out, n, [&](auto d, const auto* v) {
      return BeckmannLambda(d, c.b, v[0], v[1], v[2]);
    });
    return;
  }
  ForEachVector<3>(in, 0.5f, out, n,
                   [&](auto d, const auto* v) { return StudentTLambda(d, c, v[0], v[1], v[2]); });
}

void StudentTSampleRow(const StudentTBatchParams& p, const float* u1, const float* u2,
                       float* const* out, size_t n) {
  const StudentTConsts<DF> c(DF(), p.alpha_x, p.alpha_y, p.f0, p.gamma);
  if (c.beckmann) {
    ForEachSample(u1, u2, out, n, [&](auto d, auto v1, auto v2, auto* m) {
      BeckmannSampleNdf(d, c.b, v1, v2, &m[0], &m[1], &m[2]);
    });
    return;
  }
  ForEachSample(u1, u2, out, n, [&](auto d, auto v1, auto v2, auto* m) {
    StudentTSampleNdf(d, c, v1, v2, &m[0], &m[1], &m[2]);
  });
}

#endif  // BRDFBAKE_WITH_STD
}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
#include "flush_subnormals.h"

namespace brdfbake {
HWY_EXPORT(BeckmannBrdfRow);
HWY_EXPORT(BeckmannDRow);
HWY_EXPORT(BeckmannLambdaRow);
HWY_EXPORT(BeckmannSampleRow);
HWY_EXPORT(BeckmannG1Row);
HWY_EXPORT(BeckmannG2Row);
HWY_EXPORT(BeckmannPdfNdfRow);
#if BRDFBAKE_WITH_STD
HWY_EXPORT(StudentTBrdfRow);
HWY_EXPORT(StudentTDRow);
HWY_EXPORT(StudentTLambdaRow);
HWY_EXPORT(StudentTSampleRow);
HWY_EXPORT(StudentTG1Row);
HWY_EXPORT(StudentTG2Row);
HWY_EXPORT(StudentTPdfNdfRow);
#endif

void BeckmannSampleNdfBatch(const BeckmannBatchParams& p, const float* u1, const float* u2,
                            float* m_x, float* m_y, float* m_z, size_t n) {
  float* out[3] = {m_x, m_y, m_z};
  const FlushSubnormals ftz;
  HWY_DYNAMIC_DISPATCH(BeckmannSampleRow)(p, u1, u2, out, n);
}

#if BRDFBAKE_WITH_STD
void StudentTSampleNdfBatch(const StudentTBatchParams& p, const float* u1, const float* u2,
                            float* m_x, float* m_y, float* m_z, size_t n) {
  float* out[3] = {m_x, m_y, m_z};
  const FlushSubnormals ftz;
  HWY_DYNAMIC_DISPATCH(StudentTSampleRow)(p, u1, u2, out, n);
}

#endif  // BRDFBAKE_WITH_STD
#define BRDFBAKE_BATCH_3(Name, Params, Row)                                              \
  void Name(const Params& p, const float* x, const float* y, const float* z, float* out,   \
            size_t n) {                                                                     \
    const float* in[3] = {x, y, z};                                                         \
    const FlushSubnormals ftz;                                                              \
    HWY_DYNAMIC_DISPATCH(Row)(p, in, out, n);                                               \
  }
#define BRDFBAKE_BATCH_6(Name, Params, Row)                                                 \
  void Name(const Params& p, const float* ix, const float* iy, const float* iz,            \
            const float* ox, const float* oy, const float* oz, float* out, size_t n) {     \
    const float* in[6] = {ix, iy, iz, ox, oy, oz};                                          \
    const FlushSubnormals ftz;                                                              \
    HWY_DYNAMIC_DISPATCH(Row)(p, in, out, n);                                               \
  }
// The batch functions of the 3-component (one direction) and 6-component
// (a pair) rows, each under the subnormal flush.
BRDFBAKE_BATCH_6(BeckmannBrdfBatch, BeckmannBatchParams, BeckmannBrdfRow)
BRDFBAKE_BATCH_3(BeckmannDBatch, BeckmannBatchParams, BeckmannDRow)
BRDFBAKE_BATCH_3(BeckmannLambdaBatch, BeckmannBatchParams, BeckmannLambdaRow)
BRDFBAKE_BATCH_3(BeckmannG1Batch, BeckmannBatchParams, BeckmannG1Row)
BRDFBAKE_BATCH_6(BeckmannG2Batch, BeckmannBatchParams, BeckmannG2Row)
BRDFBAKE_BATCH_3(BeckmannPdfNdfBatch, BeckmannBatchParams, BeckmannPdfNdfRow)
#if BRDFBAKE_WITH_STD
BRDFBAKE_BATCH_6(StudentTBrdfBatch, StudentTBatchParams, StudentTBrdfRow)
BRDFBAKE_BATCH_3(StudentTDBatch, StudentTBatchParams, StudentTDRow)
BRDFBAKE_BATCH_3(StudentTLambdaBatch, StudentTBatchParams, StudentTLambdaRow)
BRDFBAKE_BATCH_3(StudentTG1Batch, StudentTBatchParams, StudentTG1Row)
BRDFBAKE_BATCH_6(StudentTG2Batch, StudentTBatchParams, StudentTG2Row)
BRDFBAKE_BATCH_3(StudentTPdfNdfBatch, StudentTBatchParams, StudentTPdfNdfRow)
#endif  // BRDFBAKE_WITH_STD
#undef BRDFBAKE_BATCH_3
#undef BRDFBAKE_BATCH_6

}  // namespace brdfbake
#endif  // HWY_ONCE
