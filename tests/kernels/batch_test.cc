// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The batch interface (batch.h) as one table: every built model with every
// quantity and sampler it defines, on every compiled target, at every count
// from 0 to 2N + 3 and four misalignments (results equal the full-array
// results, sentinels around each output untouched); every combination it
// does not define throws one line before writing anything.

#include "brdfbake/batch.h"

#include <cstdio>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "brdfbake/model.h"
#include "brdfbake/targets.h"
#include "util/simd_test_util.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "tests/kernels/batch_test.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>
#include <hwy/tests/hwy_gtest.h>

#ifndef BRDFBAKE_TESTS_BATCH_TEST_ONCE_
#define BRDFBAKE_TESTS_BATCH_TEST_ONCE_
namespace brdfbake {
namespace batch_test {

// Every registered kind (BRDFBAKE_MODEL_KINDS), built or not: a family
// registered later is swept with the others.
constexpr ModelKind kKinds[] = {
#define BRDFBAKE_TEST_KIND(family, kind, name) ModelKind::k##kind,
    BRDFBAKE_MODEL_KINDS(BRDFBAKE_TEST_KIND)
#undef BRDFBAKE_TEST_KIND
};
constexpr Quantity kQuantities[] = {Quantity::kD,      Quantity::kLambda,    Quantity::kG1,
                                    Quantity::kPdfNdf, Quantity::kK,         Quantity::kG2,
                                    Quantity::kBrdf,   Quantity::kPdfVisible};
constexpr Sampler kSamplers[] = {Sampler::kNdf, Sampler::kVisible};

// Whether the model takes these widths (an isotropic model refuses two).
inline bool TakesWidths(ModelKind kind, float alpha_x, float alpha_y) {
  ModelParams m;
  m.kind = kind;
  m.alpha_x = alpha_x;
  m.alpha_y = alpha_y;
  try {
    ValidateModelParams(m);
  } catch (const std::invalid_argument&) {
    return false;
  }
  return true;
}

// Descriptors of each kind off their special cases (anisotropic, rotated)
// and through their branches: both maskings, the three Fresnel kinds, and
// for std the pseudo-VNIS's three branches (gamma 3.3: GGX, 7 with these
// widths: the NDF, 12: Beckmann), a heavy tail and the Beckmann limit. An
// isotropic model takes alpha_y = alpha_x, a lobe without a Fresnel factor
// F0 = 1 (BatchTakesFresnel).
inline std::vector<BatchModel> ModelsOf(ModelKind kind) {
  BatchModel p;
  p.kind = kind;
  p.alpha_x = 0.3f;
  p.alpha_y = TakesWidths(kind, 0.3f, 0.12f) ? 0.12f : 0.3f;
  p.gamma = 2.7f;
  p.theta_x = 0.3f;
  p.theta_y = -0.2f;
  p.theta_z = 0.5f;
  p.masking = Masking::kSeparable;
  p.fresnel = BatchFresnel::kDielectric;
  p.eta = 1.6f;
  std::vector<BatchModel> out = {p};
  p.masking = Masking::kHeightCorrelated;
  p.fresnel = BatchFresnel::kConductor;
  p.eta = 0.2f;
  p.k = 3.0f;
  p.gamma = 1.6f;
  out.push_back(p);
  p.fresnel = BatchFresnel::kSchlick;
  p.f0 = 0.04f;
  p.gamma = 1e12f;
  out.push_back(p);
  if (kind == ModelKind::kStudentT) {
    for (float gamma : {3.3f, 7.0f, 12.0f}) {
      p.alpha_x = 0.3f;
      p.alpha_y = gamma == 7.0f ? 0.3f * 0.4444f : 0.3f;
      p.gamma = gamma;
      out.push_back(p);
    }
  }
  if (!BatchTakesFresnel(kind)) {
    for (BatchModel& m : out) {
      m.fresnel = BatchFresnel::kSchlick;
      m.f0 = 1.0f;
    }
  }
  return out;
}

inline std::vector<float> Uniforms(size_t n, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<float> uni(0.0f, 1.0f);
  std::vector<float> u(n);
  for (float& x : u) x = uni(rng);
  return u;
}

}  // namespace batch_test
}  // namespace brdfbake
#endif  // BRDFBAKE_TESTS_BATCH_TEST_ONCE_

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {

void CheckEveryModelQuantityAndCount() {
  EXPECT_EQ(BatchTarget(), hwy::TargetName(HWY_TARGET));
  const size_t lanes = hwy::HWY_NAMESPACE::Lanes(hwy::HWY_NAMESPACE::ScalableTag<float>());
  const size_t max_n = 2 * lanes + 3, len = max_n + 8;
  const test::Dirs a = test::RandomDirs(len, 41), b = test::RandomDirs(len, 42);
  const std::vector<float> u1 = batch_test::Uniforms(len, 43), u2 = batch_test::Uniforms(len, 44);
  const float* in[8] = {a.x.data(), a.y.data(), a.z.data(), b.x.data(),
                        b.y.data(), b.z.data(), u1.data(),  u2.data()};
  int cases = 0;
  for (ModelKind kind : batch_test::kKinds) {
    if (!ModelBuilt(kind)) continue;
    for (const BatchModel& p : batch_test::ModelsOf(kind)) {
      for (Quantity q : batch_test::kQuantities) {
        if (!BatchSupports(kind, q)) continue;
        SCOPED_TRACE(std::string(ModelName(kind)) + " " + QuantityName(q) + " gamma " +
                     std::to_string(p.gamma));
        test::CheckCountsAndSentinels(
            in, len, max_n, 1, [&](const float* const* v, float* const* out, size_t n) {
              if (IsPairQuantity(q)) {
                EvalBatch(p, q, {v[0], v[1], v[2]}, {v[3], v[4], v[5]}, out[0], n);
              } else {
                EvalBatch(p, q, {v[0], v[1], v[2]}, out[0], n);
              }
            });
        ++cases;
      }
      for (Sampler s : batch_test::kSamplers) {
        if (!BatchSupports(kind, s)) continue;
        SCOPED_TRACE(std::string(ModelName(kind)) + (s == Sampler::kNdf ? " ndf" : " visible"));
        test::CheckCountsAndSentinels(
            in, len, max_n, 3, [&](const float* const* v, float* const* out, size_t n) {
              SampleBatch(p, s, {v[3], v[4], v[5]}, v[6], v[7], {out[0], out[1], out[2]}, n);
            });
        ++cases;
      }
    }
  }
  // The Fresnel reflectances alone.
  test::CheckCountsAndSentinels(in, len, max_n, 1,
                                     [](const float* const* v, float* const* out, size_t n) {
                                       FresnelDielectricBatch(1.5f, v[2], out[0], n);
                                     });
  test::CheckCountsAndSentinels(in, len, max_n, 1,
                                     [](const float* const* v, float* const* out, size_t n) {
                                       FresnelConductorBatch(0.2f, 3.0f, v[5], out[0], n);
                                     });
  std::printf("%s: %d (model, quantity or sampler) cases\n", hwy::TargetName(HWY_TARGET), cases);
  EXPECT_GE(cases, 27);  // ggx alone: 3 descriptors x (7 quantities + 2 samplers)
}

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace brdfbake {
HWY_BEFORE_TEST(BatchTest);
HWY_EXPORT_AND_TEST_P(BatchTest, CheckEveryModelQuantityAndCount);

namespace {

// The one-line message of what `f` throws, or "" if it throws nothing.
template <class F>
std::string ErrorOf(const F& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(BatchInterfaceTest, UndefinedCombinationsThrowOneLineBeforeWriting) {
  const float x[4] = {0.1f, 0.2f, 0.3f, 0.4f}, z[4] = {0.9f, 0.8f, 0.7f, 0.6f};
  const DirArrays w{x, x, z};
  const float kSentinel = -7.0f;
  int undefined = 0;
  for (ModelKind kind : batch_test::kKinds) {
    const BatchModel p = batch_test::ModelsOf(kind)[0];
    const bool built = ModelBuilt(kind);
    for (Quantity q : batch_test::kQuantities) {
      float out[4] = {kSentinel, kSentinel, kSentinel, kSentinel};
      const std::string err = ErrorOf([&] {
        if (IsPairQuantity(q)) {
          EvalBatch(p, q, w, w, out, 4);
        } else {
          EvalBatch(p, q, w, out, 4);
        }
      });
      const std::string what = std::string(ModelName(kind)) + " " + QuantityName(q);
      if (built && BatchSupports(kind, q)) {
        EXPECT_EQ(err, "") << what;
        continue;
      }
      ++undefined;
      EXPECT_NE(err.find(ModelName(kind)), std::string::npos) << what << ": " << err;
      EXPECT_EQ(err.find('\n'), std::string::npos) << err;
      for (float v : out) EXPECT_EQ(v, kSentinel) << what;
      // The other shape is refused too.
      const std::string shape = ErrorOf([&] {
        if (IsPairQuantity(q)) {
          EvalBatch(p, q, w, out, 4);
        } else {
          EvalBatch(p, q, w, w, out, 4);
        }
      });
      EXPECT_NE(shape, "") << what;
    }
    for (Sampler s : batch_test::kSamplers) {
      float mx[4] = {kSentinel, kSentinel, kSentinel, kSentinel};
      float my[4], mz[4];
      const std::string err = ErrorOf([&] { SampleBatch(p, s, w, x, z, {mx, my, mz}, 4); });
      if (built && BatchSupports(kind, s)) {
        EXPECT_EQ(err, "") << ModelName(kind);
        continue;
      }
      ++undefined;
      EXPECT_NE(err.find(ModelName(kind)), std::string::npos) << err;
      EXPECT_EQ(mx[0], kSentinel);
    }
  }
  // A one-direction quantity given a pair: refused by shape.
  float out[4];
  EXPECT_NE(ErrorOf([&] {
              EvalBatch(BatchModel{}, Quantity::kD, w, w, out, 4);
            }).find("D takes one direction"),
            std::string::npos);
  EXPECT_NE(ErrorOf([&] {
              EvalBatch(BatchModel{}, Quantity::kG2, w, out, 4);
            }).find("G2 takes a pair of directions"),
            std::string::npos);
  // sel (7 + 2), ggx-aniso and ggx-glass (8 + 2 each), ellipsoid pdf_ndf and
  // NDF sampling, and the other lobes' gaps.
  EXPECT_GE(undefined, 20);
}

TEST(BatchInterfaceTest, BatchModelOfTakesParametersAndOneFresnelChannel) {
  ModelParams m;
  m.kind = ModelKind::kStudentT;
  m.alpha_x = 0.3;
  m.alpha_y = 0.2;
  m.gamma = 4.5;
  m.theta_z = 0.25;
  BatchModel p = BatchModelOf(m, Masking::kSeparable, Fresnel::Schlick({0.04, 0.5, 0.9}));
  EXPECT_EQ(p.kind, ModelKind::kStudentT);
  EXPECT_EQ(p.alpha_x, 0.3f);
  EXPECT_EQ(p.alpha_y, 0.2f);
  EXPECT_EQ(p.gamma, 4.5f);
  EXPECT_EQ(p.theta_z, 0.25f);
  EXPECT_EQ(p.masking, Masking::kSeparable);
  EXPECT_EQ(p.fresnel, BatchFresnel::kSchlick);
  EXPECT_EQ(p.f0, 0.04f);
  p = BatchModelOf(m, Masking::kHeightCorrelated,
                   Fresnel::Conductor({0.2, 0.9, 1.1}, {3.9, 2.4, 2.1}));
  EXPECT_EQ(p.fresnel, BatchFresnel::kConductor);
  EXPECT_EQ(p.eta, 0.2f);
  EXPECT_EQ(p.k, 3.9f);
  p = BatchModelOf(m);
  EXPECT_EQ(p.fresnel, BatchFresnel::kSchlick);
  EXPECT_EQ(p.f0, 1.0f);
}

}  // namespace
}  // namespace brdfbake
#endif  // HWY_ONCE
