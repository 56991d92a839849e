// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The visible-normal samplers (Sampler::kVisible of batch.h):
// BM_SampleVisible/<model>/<implementation>/n:4096, the implementation as in
// bench.cc: double_reference and float_reference (one sample per call, the
// float one compiled without auto-vectorization) or the batch call forced
// to a Highway target. ggx [Heitz18], beckmann (exact CDF inversion),
// ellipsoid [Walter15], and for std the pseudo-VNIS of [Ribardiere17]
// Algorithm 1 (SamplePseudoVnis: the GGX branch at sigma = 0.3, the
// Beckmann branch being the beckmann row). Items are samples: 4096 views
// (mu uniform in [0.02, 1], any azimuth) with uniform (u1, u2); the models
// of bench.cc (alpha 0.3, std gamma 3.3, the ellipsoid 0.3 x 0.5 rotated
// by (0.2, 0.1, 0.4) radians).

#include <random>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "brdfbake/batch.h"
#include "brdfbake/models/beckmann.h"
#include "brdfbake/models/ellipsoid.h"
#include "brdfbake/models/ggx.h"
#include "brdfbake/models/std_ndf.h"
#include "brdfbake/targets.h"

namespace brdfbake {
namespace {

constexpr int kSamples = 4096;

struct SampleData {
  std::vector<Vec3<double>> w;
  std::vector<double> u1, u2;
  std::vector<float> wx, wy, wz, u1f, u2f, mx, my, mz;
  SampleData() : mx(kSamples), my(kSamples), mz(kSamples) {
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> uni(0.0, 1.0);
    for (int i = 0; i < kSamples; ++i) {
      w.push_back(FromMuPhi(0.02 + 0.98 * uni(rng), 6.283185307179586 * uni(rng)));
      u1.push_back(uni(rng));
      u2.push_back(uni(rng));
      wx.push_back(static_cast<float>(w[i].x));
      wy.push_back(static_cast<float>(w[i].y));
      wz.push_back(static_cast<float>(w[i].z));
      u1f.push_back(static_cast<float>(u1[i]));
      u2f.push_back(static_cast<float>(u2[i]));
    }
  }
};
SampleData& Data() {
  static SampleData data;
  return data;
}

int Count(const benchmark::State& state) { return static_cast<int>(state.range(0)); }

BatchModel SamplerModel(ModelKind kind) {
  BatchModel p{kind};
  p.alpha_x = p.alpha_y = 0.3f;
  if (kind == ModelKind::kStudentT) p.gamma = 3.3f;
  if (kind == ModelKind::kEllipsoid) {
    p.alpha_y = 0.5f;
    p.theta_x = 0.2f;
    p.theta_y = 0.1f;
    p.theta_z = 0.4f;
  }
  return p;
}

void BM_SampleBatch(benchmark::State& state, ModelKind kind, std::string target) {
  ForceTarget(target);
  SampleData& s = Data();
  const size_t n = static_cast<size_t>(Count(state));
  const BatchModel p = SamplerModel(kind);
  for (auto _ : state) {
    SampleBatch(p, Sampler::kVisible, {s.wx.data(), s.wy.data(), s.wz.data()}, s.u1f.data(),
                s.u2f.data(), {s.mx.data(), s.my.data(), s.mz.data()}, n);
    benchmark::DoNotOptimize(s.mz.data());
  }
  ForceTarget("best");
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(n));
}

// The scalar sampler of a model in precision T: SampleVisible, or
// SamplePseudoVnis for std.
template <class T>
Vec3<T> Sample(const GgxNdf<T>& ndf, const Vec3<T>& w, T u1, T u2) {
  return ndf.SampleVisible(w, u1, u2);
}
template <class T>
Vec3<T> Sample(const BeckmannNdf<T>& ndf, const Vec3<T>& w, T u1, T u2) {
  return ndf.SampleVisible(w, u1, u2);
}
template <class T>
Vec3<T> Sample(const EllipsoidNdf<T>& ndf, const Vec3<T>& w, T u1, T u2) {
  return ndf.SampleVisible(w, u1, u2);
}
template <class T>
Vec3<T> Sample(const StudentTNdf<T>& ndf, const Vec3<T>& w, T u1, T u2) {
  return ndf.SamplePseudoVnis(w, u1, u2);
}

template <class Ndf>
void BM_SampleDouble(benchmark::State& state, Ndf ndf) {
  const SampleData& s = Data();
  const int n = Count(state);
  for (auto _ : state) {
    double acc = 0;
    for (int i = 0; i < n; ++i) acc += Sample(ndf, s.w[i], s.u1[i], s.u2[i]).z;
    benchmark::DoNotOptimize(acc);
  }
  state.SetItemsProcessed(state.iterations() * n);
}

template <class Ndf>
__attribute__((optimize("no-tree-vectorize"))) void FloatSamples(const Ndf& ndf, SampleData& s,
                                                                 int n) {
  for (int i = 0; i < n; ++i) {
    const Vec3<float> m = Sample(ndf, Vec3<float>(s.wx[i], s.wy[i], s.wz[i]), s.u1f[i], s.u2f[i]);
    s.mx[i] = m.x;
    s.my[i] = m.y;
    s.mz[i] = m.z;
  }
}

template <class Ndf>
void BM_SampleFloat(benchmark::State& state, Ndf ndf) {
  SampleData& s = Data();
  const int n = Count(state);
  for (auto _ : state) {
    FloatSamples(ndf, s, n);
    benchmark::DoNotOptimize(s.mz.data());
  }
  state.SetItemsProcessed(state.iterations() * n);
}

template <template <class> class Ndf, class... Params>
void RegisterReferences(const char* model, Params... params) {
  const std::string prefix = std::string("BM_SampleVisible/") + model;
  benchmark::RegisterBenchmark((prefix + "/double_reference").c_str(), BM_SampleDouble<Ndf<double>>,
                               Ndf<double>(static_cast<double>(params)...))
      ->ArgNames({"n"})
      ->Arg(kSamples);
  benchmark::RegisterBenchmark((prefix + "/float_reference").c_str(), BM_SampleFloat<Ndf<float>>,
                               Ndf<float>(static_cast<float>(params)...))
      ->ArgNames({"n"})
      ->Arg(kSamples);
}

[[maybe_unused]] const int kRegistered = [] {
  RegisterReferences<GgxNdf>("ggx", 0.3, 0.3);
  RegisterReferences<BeckmannNdf>("beckmann", 0.3, 0.3);
  RegisterReferences<StudentTNdf>("std", 0.3, 0.3, 3.3);
  RegisterReferences<EllipsoidNdf>("ellipsoid", 0.3, 0.5, 0.2, 0.1, 0.4);
  for (ModelKind kind : ModelKindsBuilt()) {
    if (!BatchSupports(kind, Sampler::kVisible)) continue;
    for (const std::string& t : AvailableTargets()) {
      const std::string name = "BM_SampleVisible/" + std::string(ModelName(kind)) + "/" + t;
      benchmark::RegisterBenchmark(name.c_str(), BM_SampleBatch, kind, t)
          ->ArgNames({"n"})
          ->Arg(kSamples);
    }
  }
  return 0;
}();

}  // namespace
}  // namespace brdfbake
