// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Benchmarks of the Beckmann visible-normal sampler and the STD pseudo-VNIS
// (batch_sampling.h): BM_SampleVisible/<model>/<TARGET> runs the batch
// kernel forced to each available target, BM_SampleVisible/<model>/scalar
// the float scalar reference one sample at a time (compiled without
// auto-vectorization, as bench.cc's scalar_float baseline). Items are
// samples: 4096 views (mu uniform in [0.02, 1], any azimuth) with uniform
// (u1, u2). alpha = 0.3; STD at gamma = 3.3 as in bench.cc, the GGX branch
// of Algorithm 1 at sigma = 0.3 (the Beckmann branch is the beckmann row).

#include <random>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "brdfbake/batch.h"
#include "brdfbake/models/beckmann.h"
#include "brdfbake/models/std_ndf.h"
#include "brdfbake/targets.h"

namespace brdfbake {
namespace {

constexpr int kSamples = 4096;
constexpr float kAlpha = 0.3f, kGamma = 3.3f;

enum class Model { kBeckmann, kStd };

struct SampleData {
  std::vector<float> wx, wy, wz, u1, u2, mx, my, mz;
  SampleData() : mx(kSamples), my(kSamples), mz(kSamples) {
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> uni(0.0, 1.0);
    for (int i = 0; i < kSamples; ++i) {
      const Vec3<double> w = FromMuPhi(0.02 + 0.98 * uni(rng), 6.283185307179586 * uni(rng));
      wx.push_back(static_cast<float>(w.x));
      wy.push_back(static_cast<float>(w.y));
      wz.push_back(static_cast<float>(w.z));
      u1.push_back(static_cast<float>(uni(rng)));
      u2.push_back(static_cast<float>(uni(rng)));
    }
  }
};
SampleData& Data() {
  static SampleData data;
  return data;
}

void BM_SampleVisibleBatch(benchmark::State& state, Model model, std::string target) {
  ForceTarget(target);
  SampleData& s = Data();
  BatchModel bp{ModelKind::kBeckmann};
  bp.alpha_x = bp.alpha_y = kAlpha;
  BatchModel sp{ModelKind::kStudentT};
  sp.alpha_x = sp.alpha_y = kAlpha;
  sp.gamma = kGamma;
  for (auto _ : state) {
    if (model == Model::kBeckmann) {
      SampleBatch(bp, Sampler::kVisible, {s.wx.data(), s.wy.data(), s.wz.data()}, s.u1.data(),
                  s.u2.data(), {s.mx.data(), s.my.data(), s.mz.data()}, kSamples);
    } else {
      SampleBatch(sp, Sampler::kVisible, {s.wx.data(), s.wy.data(), s.wz.data()}, s.u1.data(),
                  s.u2.data(), {s.mx.data(), s.my.data(), s.mz.data()}, kSamples);
    }
    benchmark::DoNotOptimize(s.mz.data());
  }
  ForceTarget("best");
  state.SetItemsProcessed(state.iterations() * kSamples);
}

template <class Sampler>
__attribute__((optimize("no-tree-vectorize"))) void ScalarSamples(const Sampler& sample,
                                                                   SampleData& s) {
  for (int i = 0; i < kSamples; ++i) {
    const Vec3<float> m = sample(Vec3<float>(s.wx[i], s.wy[i], s.wz[i]), s.u1[i], s.u2[i]);
    s.mx[i] = m.x;
    s.my[i] = m.y;
    s.mz[i] = m.z;
  }
}

void BM_SampleVisibleScalar(benchmark::State& state, Model model) {
  SampleData& s = Data();
  const BeckmannNdf<float> beckmann(kAlpha);
  const StudentTNdf<float> std_ndf(kAlpha, kAlpha, kGamma);
  for (auto _ : state) {
    if (model == Model::kBeckmann) {
      ScalarSamples([&](const Vec3<float>& w, float u1, float u2) {
        return beckmann.SampleVisible(w, u1, u2);
      }, s);
    } else {
      ScalarSamples([&](const Vec3<float>& w, float u1, float u2) {
        return std_ndf.SamplePseudoVnis(w, u1, u2);
      }, s);
    }
    benchmark::DoNotOptimize(s.mz.data());
  }
  state.SetItemsProcessed(state.iterations() * kSamples);
}

[[maybe_unused]] const int registered = [] {
  for (const std::string& t : AvailableTargets()) {
    benchmark::RegisterBenchmark(("BM_SampleVisible/beckmann/" + t).c_str(),
                                 BM_SampleVisibleBatch, Model::kBeckmann, t);
    benchmark::RegisterBenchmark(("BM_SampleVisible/std/" + t).c_str(), BM_SampleVisibleBatch,
                                 Model::kStd, t);
  }
  benchmark::RegisterBenchmark("BM_SampleVisible/beckmann/scalar", BM_SampleVisibleScalar,
                               Model::kBeckmann);
  benchmark::RegisterBenchmark("BM_SampleVisible/std/scalar", BM_SampleVisibleScalar,
                               Model::kStd);
  return 0;
}();

}  // namespace
}  // namespace brdfbake
