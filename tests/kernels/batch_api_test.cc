// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The batch API's contract as a renderer calls it (batch.h): the domain of
// every parameter, checked at the API; per-element parameters (a batch of
// mixed materials in one call) against one call per material; the light
// sampler's directions, densities and weights against the double
// reference, its counts and sentinels on every compiled target, and its
// distribution by a chi-square test.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "brdfbake/batch.h"
#include "brdfbake/model.h"
#include "brdfbake/models/beckmann.h"
#include "brdfbake/models/ggx.h"
#include "brdfbake/targets.h"
#include "reference/reference_albedo.h"
#include "util/simd_test_util.h"
#include "util/test_util.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "tests/kernels/batch_api_test.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>
#include <hwy/tests/hwy_gtest.h>

#ifndef BRDFBAKE_TESTS_BATCH_API_TEST_ONCE_
#define BRDFBAKE_TESTS_BATCH_API_TEST_ONCE_
namespace brdfbake {
namespace batch_api_test {

// A batch of mixed materials: per element alpha_x, alpha_y and F0 from
// mirror-like to rough, isotropic and not.
struct Materials {
  std::vector<float> ax, ay, f0;
};
inline Materials MixedMaterials(size_t n, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<float> uni(0.0f, 1.0f);
  Materials m;
  for (size_t j = 0; j < n; ++j) {
    const float r = 0.02f + 0.98f * uni(rng);
    m.ax.push_back(std::max(1e-4f, r * r));
    m.ay.push_back(j % 3 == 0 ? m.ax.back() : std::max(1e-4f, 0.7f * r * r + 0.05f * uni(rng)));
    m.f0.push_back(j % 2 == 0 ? 0.04f : uni(rng));
  }
  return m;
}

// The message of the std::invalid_argument `f` throws, or "".
template <class F>
std::string ErrorOf(const F& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

inline BatchModel ModelOf(ModelKind kind) {
  BatchModel p;
  p.kind = kind;
  p.alpha_x = 0.3f;
  p.alpha_y = 0.2f;
  p.gamma = 2.5f;
  p.theta_x = 0.2f;
  p.theta_z = 0.4f;
  return p;
}

inline Vec3<double> ToDouble(float x, float y, float z) { return {x, y, z}; }

}  // namespace batch_api_test
}  // namespace brdfbake
#endif  // BRDFBAKE_TESTS_BATCH_API_TEST_ONCE_

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {

// Per-element parameters: every quantity and sampler of ggx and beckmann
// over a mixed batch, at every count to 2N + 3 (sentinels untouched), each
// element within a few float roundings of a call with its own material
// alone (the per-element constants round in float lanes, the per-call ones
// partly in double).
void CheckElementsAgainstOneCallPerMaterial() {
  EXPECT_EQ(BatchTarget(), hwy::TargetName(HWY_TARGET));
  const size_t lanes = hwy::HWY_NAMESPACE::Lanes(hwy::HWY_NAMESPACE::ScalableTag<float>());
  const size_t max_n = 2 * lanes + 3, len = std::max<size_t>(max_n + 8, 200);
  const test::Dirs a = test::RandomDirs(len, 51), b = test::RandomDirs(len, 52);
  const std::vector<float> u1 = test::RandomUniforms(len, 53),
                           u2 = test::RandomUniforms(len, 54);
  const batch_api_test::Materials mat = batch_api_test::MixedMaterials(len, 55);
  const float* in[11] = {a.x.data(), a.y.data(), a.z.data(), b.x.data(),  b.y.data(),  b.z.data(),
                         u1.data(),  u2.data(),  mat.ax.data(), mat.ay.data(), mat.f0.data()};
  const Quantity quantities[] = {Quantity::kD,  Quantity::kLambda, Quantity::kG1,
                                 Quantity::kPdfNdf, Quantity::kG2, Quantity::kBrdf,
                                 Quantity::kPdfVisible};
  for (ModelKind kind : {ModelKind::kGgx, ModelKind::kBeckmann}) {
    if (!ModelBuilt(kind)) continue;
    ASSERT_TRUE(BatchSupportsElements(kind));
    for (Masking masking : {Masking::kHeightCorrelated, Masking::kSeparable}) {
      BatchModel p = batch_api_test::ModelOf(kind);
      p.masking = masking;
      for (Quantity q : quantities) {
        SCOPED_TRACE(std::string(ModelName(kind)) + " " + QuantityName(q));
        // With per-element parameters e, or (e null) one model per call.
        const auto eval = [&](const BatchModel& model, const BatchElements* e,
                              const float* const* v, float* out, size_t n) {
          const DirArrays a{v[0], v[1], v[2]}, b{v[3], v[4], v[5]};
          if (IsPairQuantity(q)) {
            e ? EvalBatch(model, *e, q, a, b, out, n) : EvalBatch(model, q, a, b, out, n);
          } else {
            e ? EvalBatch(model, *e, q, a, out, n) : EvalBatch(model, q, a, out, n);
          }
        };
        test::CheckCountsAndSentinels(
            in, len, max_n, 1,
            [&](const float* const* v, float* const* out, size_t n) {
              const BatchElements e{v[8], v[9], v[10]};
              eval(p, &e, v, out[0], n);
            },
            11);
        // Each element against its material alone.
        std::vector<float> mixed(len);
        const BatchElements e{mat.ax.data(), mat.ay.data(), mat.f0.data()};
        eval(p, &e, in, mixed.data(), len);
        double worst = 0;
        for (size_t j = 0; j < len; ++j) {
          BatchModel one = p;
          one.alpha_x = mat.ax[j];
          one.alpha_y = mat.ay[j];
          one.f0 = mat.f0[j];
          const float* v[6] = {in[0] + j, in[1] + j, in[2] + j, in[3] + j, in[4] + j, in[5] + j};
          float alone = 0;
          eval(one, nullptr, v, &alone, 1);
          // Beckmann's exp(-r2) turns the rounding of its 1 / alpha^2 into a
          // relative error of about r2 ulp (its kernel bound: 1e-6 + 3e-7 r2),
          // r2 the largest squared standard slope of the directions involved.
          double r2 = 0;
          if (kind == ModelKind::kBeckmann) {
            const Vec3<double> da{*v[0], *v[1], *v[2]}, db{*v[3], *v[4], *v[5]};
            std::vector<Vec3<double>> dirs = {da};
            if (IsPairQuantity(q)) dirs = {da, db, Normalize(da + db)};
            for (const Vec3<double>& d : dirs) {
              if (d.z > 0) {
                r2 = std::max(r2, (d.x * d.x / (double(one.alpha_x) * one.alpha_x) +
                                   d.y * d.y / (double(one.alpha_y) * one.alpha_y)) /
                                      (d.z * d.z));
              }
            }
          }
          const double err = test::RelErr(mixed[j], alone);
          const double bound = 3e-6 + 3e-7 * r2;
          worst = std::max(worst, std::isnan(err) ? 1.0 : err / bound);
          ASSERT_LE(err, bound) << j << ": " << mixed[j] << " against " << alone;
        }
        std::printf("%s %s %s: per element within %.2g of the bound against one call per "
                    "material\n",
                    hwy::TargetName(HWY_TARGET), ModelName(kind), QuantityName(q), worst);
      }
    }
    // Isotropic elements: alpha_y left null takes alpha_x.
    const float* v[6] = {in[0], in[1], in[2], in[3], in[4], in[5]};
    std::vector<float> iso(len), explicit_iso(len);
    BatchModel p = batch_api_test::ModelOf(kind);
    EvalBatch(p, BatchElements{mat.ax.data(), nullptr, nullptr}, Quantity::kBrdf,
              {v[0], v[1], v[2]}, {v[3], v[4], v[5]}, iso.data(), len);
    EvalBatch(p, BatchElements{mat.ax.data(), mat.ax.data(), nullptr}, Quantity::kBrdf,
              {v[0], v[1], v[2]}, {v[3], v[4], v[5]}, explicit_iso.data(), len);
    EXPECT_EQ(iso, explicit_iso);
    // The samplers, per element against one call per material.
    for (Sampler s : {Sampler::kNdf, Sampler::kVisible}) {
      test::CheckCountsAndSentinels(
          in, len, max_n, 3,
          [&](const float* const* w, float* const* out, size_t n) {
            SampleBatch(p, BatchElements{w[8], w[9], w[10]}, s, {w[3], w[4], w[5]}, w[6], w[7],
                        {out[0], out[1], out[2]}, n);
          },
          11);
      std::vector<float> mx(len), my(len), mz(len);
      SampleBatch(p, BatchElements{mat.ax.data(), mat.ay.data(), nullptr}, s, {v[3], v[4], v[5]},
                  u1.data(), u2.data(), {mx.data(), my.data(), mz.data()}, len);
      for (size_t j = 0; j < len; ++j) {
        BatchModel one = p;
        one.alpha_x = mat.ax[j];
        one.alpha_y = mat.ay[j];
        float m1[3];
        SampleBatch(one, s, {v[3] + j, v[4] + j, v[5] + j}, &u1[j], &u2[j], {&m1[0], &m1[1], &m1[2]},
                    1);
        const double d = std::max({std::abs(mx[j] - m1[0]), std::abs(my[j] - m1[1]),
                                   std::abs(mz[j] - m1[2])});
        ASSERT_LE(d, 2e-5) << ModelName(kind) << " sampler " << int(s) << " element " << j;
      }
    }
  }
}

// The light sampler on this target: counts and sentinels for one model per
// call and per element; each direction the reflection of wo about the
// sampled normal, its density and weight against the double reference.
void CheckLightSamplerAgainstReference() {
  const size_t lanes = hwy::HWY_NAMESPACE::Lanes(hwy::HWY_NAMESPACE::ScalableTag<float>());
  const size_t max_n = 2 * lanes + 3, len = 600;  // more than one chunk of 256
  // Views in both hemispheres: one in seven below the horizon.
  const test::Dirs wo = test::RandomDirs(len, 61, 7);
  const std::vector<float> u1 = test::RandomUniforms(len, 62),
                           u2 = test::RandomUniforms(len, 63);
  const batch_api_test::Materials mat = batch_api_test::MixedMaterials(len, 64);
  const float* in[11] = {wo.x.data(), wo.y.data(), wo.z.data(), wo.x.data(), wo.y.data(),
                         wo.z.data(), u1.data(),   u2.data(),   mat.ax.data(), mat.ay.data(),
                         mat.f0.data()};
  for (ModelKind kind : {ModelKind::kGgx, ModelKind::kBeckmann, ModelKind::kStudentT,
                         ModelKind::kEllipsoid}) {
    if (!ModelBuilt(kind)) continue;
    SCOPED_TRACE(ModelName(kind));
    BatchModel p = batch_api_test::ModelOf(kind);
    p.fresnel = BatchFresnel::kSchlick;
    p.f0 = 0.5f;
    const bool elements = BatchSupportsElements(kind);
    test::CheckCountsAndSentinels(
        in, len, max_n, 5,
        [&](const float* const* v, float* const* out, size_t n) {
          SampleLightBatch(p, {v[0], v[1], v[2]}, v[6], v[7],
                           {out[0], out[1], out[2], out[3], out[4]}, n);
        },
        8);
    if (elements) {
      test::CheckCountsAndSentinels(
          in, len, max_n, 5,
          [&](const float* const* v, float* const* out, size_t n) {
            SampleLightBatch(p, BatchElements{v[8], v[9], v[10]}, {v[0], v[1], v[2]}, v[6], v[7],
                             {out[0], out[1], out[2], out[3], out[4]}, n);
          },
          11);
    }
    for (int per_element = 0; per_element <= (elements ? 1 : 0); ++per_element) {
      std::vector<float> x(len), y(len), z(len), weight(len), pdf(len);
      if (per_element) {
        SampleLightBatch(p, BatchElements{mat.ax.data(), mat.ay.data(), mat.f0.data()},
                         {in[0], in[1], in[2]}, u1.data(), u2.data(),
                         {x.data(), y.data(), z.data(), weight.data(), pdf.data()}, len);
      } else {
        SampleLightBatch(p, {in[0], in[1], in[2]}, u1.data(), u2.data(),
                         {x.data(), y.data(), z.data(), weight.data(), pdf.data()}, len);
      }
      double worst_pdf = 0, worst_weight = 0;
      int underflows = 0;
      for (size_t j = 0; j < len; ++j) {
        const Vec3<double> o = batch_api_test::ToDouble(wo.x[j], wo.y[j], wo.z[j]);
        const Vec3<double> wi = batch_api_test::ToDouble(x[j], y[j], z[j]);
        if (!(o.z > 0)) {
          EXPECT_EQ(weight[j], 0.0f);
          EXPECT_EQ(pdf[j], 0.0f);
          EXPECT_EQ(wi.x, 0.0);
          EXPECT_EQ(wi.z, 0.0);
          continue;
        }
        ASSERT_TRUE(std::isfinite(weight[j]) && std::isfinite(pdf[j])) << j;
        ASSERT_GE(weight[j], 0.0f);
        ASSERT_GE(pdf[j], 0.0f);
        ASSERT_NEAR(Length(wi), 1.0, 1e-5) << j;
        if (pdf[j] == 0.0f) {
          // A normal from the far tail (u at the ends of [0, 1]) whose
          // density underflows float: no sample, weight 0.
          EXPECT_EQ(weight[j], 0.0f) << j;
          ++underflows;
          continue;
        }
        ModelParams mp = ModelParamsOf(p);
        if (per_element) {
          mp.alpha_x = mat.ax[j];
          mp.alpha_y = mat.ay[j];
        }
        const std::unique_ptr<Model> ref = MakeModel(mp);
        const Vec3<double> h = Normalize(wi + o);
        const double oh = Dot(o, h);
        // The direction is the reflection of wo about its normal (the half
        // vector rebuilt from wi + wo, of length 2 wo.m, carries wi's float
        // rounding divided by that length).
        ASSERT_NEAR(Dot(wi, h), oh, 2e-5 + 2e-7 / oh) << j;
        const double pdf_ref = ref->Pdf(o, h) / (4 * oh);
        const double f0 = per_element ? mat.f0[j] : p.f0;
        const double f = ref->Brdf(wi, o, Fresnel::Schlick({f0, f0, f0}), p.masking, 0);
        const double weight_ref = wi.z > 0 ? f * wi.z / pdf_ref : 0.0;
        // The reference sees wi rounded to float: on a narrow lobe (width
        // alpha) that rounding moves the half vector by about 1e-7 / alpha^2
        // in the density's units, and grazing wo.h amplifies it further.
        const double narrow = std::min(mp.alpha_x, mp.alpha_y);
        // Beckmann's and STD's exponential tails amplify every rounding by
        // the squared standard slope r2 of h (their kernel bound is
        // 1e-6 + 3e-7 r2; here with wi's rounding too).
        const double r2 = kind == ModelKind::kBeckmann || kind == ModelKind::kStudentT
                              ? (h.x * h.x / (mp.alpha_x * mp.alpha_x) +
                                 h.y * h.y / (mp.alpha_y * mp.alpha_y)) / (h.z * h.z)
                              : 0.0;
        const double bound = narrow >= 0.05 && oh >= 1e-2 ? 2e-5 + 3e-6 * r2 : 1e-2;
        const double e_pdf = test::RelErr(pdf[j], pdf_ref);
        const double e_weight = std::abs(weight[j] - weight_ref) / std::max(weight_ref, 1e-3);
        if (bound < 1e-3) {
          worst_pdf = std::max(worst_pdf, e_pdf);
          worst_weight = std::max(worst_weight, e_weight);
        }
        ASSERT_LE(e_pdf, bound) << j << " pdf " << pdf[j] << " against " << pdf_ref;
        ASSERT_LE(e_weight, bound) << j << " weight " << weight[j] << " against " << weight_ref;
      }
      EXPECT_LE(underflows, 4);  // the ends of u only
      std::printf("%s %s%s: light pdf within %.2g, weight within %.2g of the double reference "
                  "(alpha >= 0.05); %d densities underflow\n",
                  hwy::TargetName(HWY_TARGET), ModelName(kind), per_element ? " per element" : "",
                  worst_pdf, worst_weight, underflows);
    }
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace brdfbake {
HWY_BEFORE_TEST(BatchApiTest);
HWY_EXPORT_AND_TEST_P(BatchApiTest, CheckElementsAgainstOneCallPerMaterial);
HWY_EXPORT_AND_TEST_P(BatchApiTest, CheckLightSamplerAgainstReference);

namespace {

using batch_api_test::ErrorOf;

// Every parameter outside its domain is refused at the API, in one line
// naming the call and the field, before any output is written.
TEST(BatchDomainTest, ParametersOutsideTheDomainThrowBeforeWriting) {
  const float x[4] = {0.1f, 0.2f, 0.3f, 0.4f}, z[4] = {0.9f, 0.8f, 0.7f, 0.6f};
  const DirArrays w{x, x, z};
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  struct Case {
    const char* field;
    ModelKind kind;
    void (*set)(BatchModel*, float);
    std::vector<float> bad;
  };
  const std::vector<Case> cases = {
      {"alpha_x", ModelKind::kGgx, [](BatchModel* p, float v) { p->alpha_x = v; },
       {0.0f, -1.0f, nan, inf, 2e4f}},
      {"alpha_y", ModelKind::kBeckmann, [](BatchModel* p, float v) { p->alpha_y = v; },
       {0.0f, -0.5f, nan}},
      {"gamma", ModelKind::kStudentT, [](BatchModel* p, float v) { p->gamma = v; },
       {1.5f, 1.0f, nan, 1.5000001f, 1.50000095f}},
      {"theta_x", ModelKind::kEllipsoid, [](BatchModel* p, float v) { p->theta_x = v; },
       {2.0f, nan, -inf}},
      {"theta_z", ModelKind::kSel, [](BatchModel* p, float v) { p->theta_z = v; }, {-1.6f}},
      {"f0", ModelKind::kGgx, [](BatchModel* p, float v) { p->f0 = v; }, {-0.1f, 1.5f, nan}},
      {"eta", ModelKind::kGgx,
       [](BatchModel* p, float v) {
         p->fresnel = BatchFresnel::kDielectric;
         p->eta = v;
       },
       {0.0f, 1e-3f, 1e3f, nan}},
      {"k", ModelKind::kGgx,
       [](BatchModel* p, float v) {
         p->fresnel = BatchFresnel::kConductor;
         p->eta = 0.2f;
         p->k = v;
       },
       {-1.0f, 1e3f, nan}},
  };
  int refused = 0;
  for (const Case& c : cases) {
    if (!ModelBuilt(c.kind)) continue;
    for (float v : c.bad) {
      BatchModel p;
      p.kind = c.kind;
      c.set(&p, v);
      const Quantity q = c.kind == ModelKind::kSel ? Quantity::kK : Quantity::kD;
      float out[4] = {-7, -7, -7, -7};
      const std::string what = std::string(c.field) + " = " + std::to_string(v);
      for (const std::string& err :
           {ErrorOf([&] { EvalBatch(p, q, w, out, 4); }),
            ErrorOf([&] { EvalBatch(p, Quantity::kBrdf, w, w, out, 4); }),
            ErrorOf([&] { SampleBatch(p, Sampler::kVisible, w, x, z, {out, out, out}, 4); }),
            ErrorOf([&] {
              SampleLightBatch(p, w, x, z, {out, out, out, out, out}, 4);
            })}) {
        if (c.kind == ModelKind::kSel && err.find("has no") != std::string::npos) continue;
        EXPECT_NE(err.find(c.field), std::string::npos) << what << ": " << err;
        EXPECT_EQ(err.find('\n'), std::string::npos) << err;
        ++refused;
      }
      for (float o : out) EXPECT_EQ(o, -7.0f) << what;
    }
  }
  EXPECT_GE(refused, 60);
  // gamma just above 1.5, below the floor 1.5 + 1e-6 where the models would
  // evaluate it: refused with the domain named, not evaluated at the floor.
  BatchModel p;
  float out[4];
  if (ModelBuilt(ModelKind::kStudentT)) {
    p.kind = ModelKind::kStudentT;
    p.gamma = 1.5000001f;
    EXPECT_EQ(ErrorOf([&] { EvalBatch(p, Quantity::kD, w, out, 4); }),
              "EvalBatch: gamma must be >= 1.500001 or inf (the STD's mean slope diverges at 1.5; "
              "got 1.5000001192092896)");
    p.gamma = 1.5000011f;  // the smallest float at or above the floor
    EXPECT_EQ(ErrorOf([&] { EvalBatch(p, Quantity::kBrdf, w, w, out, 4); }), "");
    for (float o : out) EXPECT_TRUE(std::isfinite(o));
    p.gamma = std::numeric_limits<float>::infinity();
    EXPECT_EQ(ErrorOf([&] { EvalBatch(p, Quantity::kBrdf, w, w, out, 4); }), "");
    p = BatchModel{};
  }
  // The ends of the domain are accepted.
  for (float a : {1e-30f, 1e-4f, 1e4f}) {
    p.alpha_x = p.alpha_y = a;
    EXPECT_EQ(ErrorOf([&] { EvalBatch(p, Quantity::kBrdf, w, w, out, 4); }), "") << a;
  }
  p = BatchModel{};
  p.fresnel = BatchFresnel::kConductor;
  p.eta = 0.01f;
  p.k = 100.0f;
  EXPECT_EQ(ErrorOf([&] { EvalBatch(p, Quantity::kBrdf, w, w, out, 4); }), "");
  for (float o : out) EXPECT_TRUE(std::isfinite(o));
  // Zero elements: the model is still checked.
  p = BatchModel{};
  p.alpha_x = 0;
  EXPECT_NE(ErrorOf([&] { EvalBatch(p, Quantity::kD, w, out, 0); }), "");
}

// Widths below 1e-4 are evaluated at 1e-4, as the domain says.
TEST(BatchDomainTest, WidthsBelowTheFloorEvaluateAtTheFloor) {
  const test::Dirs a = test::RandomDirs(64, 71), b = test::RandomDirs(64, 72);
  for (ModelKind kind : {ModelKind::kGgx, ModelKind::kBeckmann}) {
    if (!ModelBuilt(kind)) continue;
    BatchModel tiny, floor;
    tiny.kind = floor.kind = kind;
    tiny.alpha_x = tiny.alpha_y = 1e-7f;
    floor.alpha_x = floor.alpha_y = 1e-4f;
    for (Quantity q : {Quantity::kLambda, Quantity::kG2}) {
      std::vector<float> t(64), f(64);
      const bool pair = IsPairQuantity(q);
      const DirArrays da{a.x.data(), a.y.data(), a.z.data()}, db{b.x.data(), b.y.data(), b.z.data()};
      if (pair) {
        EvalBatch(tiny, q, da, db, t.data(), 64);
        EvalBatch(floor, q, da, db, f.data(), 64);
      } else {
        EvalBatch(tiny, q, da, t.data(), 64);
        EvalBatch(floor, q, da, f.data(), 64);
      }
      EXPECT_EQ(t, f) << ModelName(kind) << " " << QuantityName(q);
    }
  }
}

// Per-element values outside the domain name the element; f0 per element
// needs Schlick; the models without per-element kernels say so.
TEST(BatchDomainTest, PerElementParametersAreCheckedByElement) {
  const float x[4] = {0.1f, 0.2f, 0.3f, 0.4f}, z[4] = {0.9f, 0.8f, 0.7f, 0.6f};
  const DirArrays w{x, x, z};
  const float nan = std::numeric_limits<float>::quiet_NaN();
  float out[4] = {-7, -7, -7, -7};
  const float good[4] = {0.1f, 0.2f, 0.3f, 0.4f};
  for (float v : {0.0f, -0.2f, nan, 3e4f}) {
    const float alpha[4] = {0.1f, 0.2f, v, 0.4f};
    const std::string err =
        ErrorOf([&] { EvalBatch(BatchModel{}, BatchElements{alpha}, Quantity::kD, w, out, 4); });
    EXPECT_NE(err.find("alpha_x[2]"), std::string::npos) << err;
    const std::string err_y = ErrorOf(
        [&] { EvalBatch(BatchModel{}, BatchElements{good, alpha}, Quantity::kD, w, out, 4); });
    EXPECT_NE(err_y.find("alpha_y[2]"), std::string::npos) << err_y;
  }
  const float f0[4] = {0.04f, 1.2f, 0.5f, 0.5f};
  EXPECT_NE(ErrorOf([&] {
              EvalBatch(BatchModel{}, BatchElements{good, nullptr, f0}, Quantity::kBrdf, w, w, out,
                        4);
            }).find("f0[1]"),
            std::string::npos);
  BatchModel dielectric;
  dielectric.fresnel = BatchFresnel::kDielectric;
  const float f0_ok[4] = {0.04f, 0.04f, 0.04f, 0.04f};
  EXPECT_NE(ErrorOf([&] {
              EvalBatch(dielectric, BatchElements{good, nullptr, f0_ok}, Quantity::kBrdf, w, w,
                        out, 4);
            }).find("kSchlick"),
            std::string::npos);
  for (ModelKind kind : {ModelKind::kStudentT, ModelKind::kEllipsoid}) {
    if (!ModelBuilt(kind)) continue;
    EXPECT_FALSE(BatchSupportsElements(kind));
    BatchModel p = batch_api_test::ModelOf(kind);
    EXPECT_NE(ErrorOf([&] { EvalBatch(p, BatchElements{good}, Quantity::kD, w, out, 4); })
                  .find("per call"),
              std::string::npos);
  }
  for (float o : out) EXPECT_EQ(o, -7.0f);
}

// A NaN direction gives NaN or 0 in its own element (the BRDF kernels
// return 0 wherever the pair fails their validity test) and leaves every
// other element as it would be without it.
TEST(BatchDomainTest, NonFiniteDirectionsStayInTheirElement) {
  const size_t n = 37;
  test::Dirs a = test::RandomDirs(n, 81), b = test::RandomDirs(n, 82);
  const DirArrays da{a.x.data(), a.y.data(), a.z.data()}, db{b.x.data(), b.y.data(), b.z.data()};
  for (ModelKind kind : {ModelKind::kGgx, ModelKind::kBeckmann, ModelKind::kStudentT,
                         ModelKind::kEllipsoid}) {
    if (!ModelBuilt(kind)) continue;
    const BatchModel p = batch_api_test::ModelOf(kind);
    std::vector<float> clean(n), dirty(n);
    EvalBatch(p, Quantity::kBrdf, da, db, clean.data(), n);
    const float saved = a.x[17];
    a.x[17] = std::numeric_limits<float>::quiet_NaN();
    EvalBatch(p, Quantity::kBrdf, da, db, dirty.data(), n);
    a.x[17] = saved;
    for (size_t j = 0; j < n; ++j) {
      if (j == 17) {
        EXPECT_TRUE(std::isnan(dirty[j]) || dirty[j] == 0.0f) << ModelName(kind) << dirty[j];
      } else {
        EXPECT_EQ(dirty[j], clean[j]) << ModelName(kind) << " element " << j;
      }
    }
  }
}

// The light sampler draws directions with the density it reports: a
// chi-square test of 1M directions per (model, view), with the density of
// the double reference, pdf_visible(wo, h) / (4 wo.h); and the mean weight
// is the directional albedo the density implies.
TEST(BatchLightSamplerTest, DirectionsChiSquare) {
  struct View {
    ModelKind kind;
    float alpha_x, alpha_y, mu;
  };
  const std::vector<View> views = {{ModelKind::kGgx, 0.3f, 0.3f, 0.5f},
                                   {ModelKind::kGgx, 0.6f, 0.15f, 0.2f},
                                   {ModelKind::kBeckmann, 0.4f, 0.4f, 0.7f},
                                   {ModelKind::kStudentT, 0.3f, 0.3f, 0.4f},
                                   {ModelKind::kEllipsoid, 0.5f, 0.25f, 0.6f}};
  int tests = 0;
  for (const View& v : views) tests += ModelBuilt(v.kind) ? 1 : 0;
  uint64_t seed = 90;
  for (const View& v : views) {
    if (!ModelBuilt(v.kind)) continue;
    BatchModel p = batch_api_test::ModelOf(v.kind);
    p.alpha_x = v.alpha_x;
    p.alpha_y = v.alpha_y;
    const std::unique_ptr<Model> ref = MakeModel(ModelParamsOf(p));
    const float ox = std::sqrt(1 - v.mu * v.mu) * 0.8f, oy = std::sqrt(1 - v.mu * v.mu) * 0.6f,
                oz = v.mu;
    const Vec3<double> o{ox, oy, oz};
    double weight_sum = 0, weight_sq = 0;
    int count = 0;
    const test::ChiSquareResult r = test::ChiSquareDirections(
        [&](double u1, double u2, test::Dir* d) {
          const float fu1 = float(u1), fu2 = float(u2);
          float x, y, z, weight, pdf;
          SampleLightBatch(p, {&ox, &oy, &oz}, &fu1, &fu2, {&x, &y, &z, &weight, &pdf}, 1);
          weight_sum += weight;
          weight_sq += double(weight) * weight;
          ++count;
          if (!(z > 0)) return false;
          *d = Normalize(Vec3<double>{x, y, z});
          return true;
        },
        [&](const test::Dir& wi) {
          const Vec3<double> h = Normalize(wi + o);
          const double oh = Dot(o, h);
          return oh > 0 ? ref->Pdf(o, h) / (4 * oh) : 0.0;
        },
        40, 80, 1000000, seed++);
    std::printf("%s alpha %g x %g mu %g: light directions p = %.3g (mass %.6f)\n",
                ModelName(v.kind), v.alpha_x, v.alpha_y, v.mu, r.p_value, r.pdf_mass);
    EXPECT_GT(r.p_value, test::ChiSquareAlpha(tests)) << ModelName(v.kind);
    // With F = 1 the weights average to the directional albedo E(mu),
    // here of the isotropic views against the independent quadrature of
    // tests/reference (within 5 standard errors).
    const double mean = weight_sum / count;
    const double se = std::sqrt(std::max(0.0, weight_sq / count - mean * mean) / count);
    double e_ref = -1;
    if (v.alpha_x == v.alpha_y && v.kind == ModelKind::kGgx) {
      e_ref = ReferenceEFor(GgxNdf<double>(v.alpha_x), v.mu, p.masking, 1e-9);
    } else if (v.alpha_x == v.alpha_y && v.kind == ModelKind::kBeckmann) {
      e_ref = ReferenceEFor(BeckmannNdf<double>(v.alpha_x), v.mu, p.masking, 1e-9);
    }
    std::printf("  mean weight %.6f +- %.2g (reference E %.6f)\n", mean, se, e_ref);
    if (e_ref >= 0) {
      EXPECT_NEAR(mean, e_ref, 5 * se + 1e-6) << ModelName(v.kind);
    }
    EXPECT_GT(mean, 0.2);
    EXPECT_LE(mean, 1.0 + 5 * se);
  }
}

}  // namespace
}  // namespace brdfbake
#endif  // HWY_ONCE
