// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The models' quantities, evaluated over n = 4096 random pairs (wi, wo):
// BM_<quantity>/<model>/<implementation>/n:<count>, where the
// implementation is
//   double_reference  the double scalar reference (ggx.h, beckmann.h, ...),
//                     one evaluation per call
//   float_reference   the same in float, compiled without auto-vectorization
//                     (BM_Brdf/ggx only)
//   AVX3, AVX2, ...   the batch call (batch.h) forced to that Highway target
// Items are evaluations. BM_Brdf/ggx/<target> also runs at n = 16 and 17:
// one or two whole vectors, and the same plus one lane, so the cost of a
// partial vector shows. Mixed materials and light directions
// (BM_BrdfMixed, BM_SampleLight, BM_SampleLightMixed) and the grid are
// below; the visible-normal samplers are in bench_sampling.cc.

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include <benchmark/benchmark.h>

#include "brdfbake/batch.h"
#include "brdfbake/grid.h"
#include "brdfbake/models/beckmann.h"
#include "brdfbake/models/brdf.h"
#include "brdfbake/models/ellipsoid.h"
#include "brdfbake/models/ggx.h"
#include "brdfbake/models/sel.h"
#include "brdfbake/models/std_ndf.h"
#include "brdfbake/targets.h"

namespace brdfbake {
namespace {

constexpr int kN = 4096;

// mu in [0.02, 1], any azimuth, for wi and wo.
struct Inputs {
  std::vector<Vec3<double>> wi, wo;
  std::vector<float> ix, iy, iz, ox, oy, oz, out;
  Inputs() : out(kN) {
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> uni(0.0, 1.0);
    for (int i = 0; i < kN; ++i) {
      wi.push_back(FromMuPhi(0.02 + 0.98 * uni(rng), 6.283185307179586 * uni(rng)));
      wo.push_back(FromMuPhi(0.02 + 0.98 * uni(rng), 6.283185307179586 * uni(rng)));
      ix.push_back(float(wi[i].x));
      iy.push_back(float(wi[i].y));
      iz.push_back(float(wi[i].z));
      ox.push_back(float(wo[i].x));
      oy.push_back(float(wo[i].y));
      oz.push_back(float(wo[i].z));
    }
  }
};
Inputs& In() {
  static Inputs in;
  return in;
}

// The models of every row: alpha 0.3; std at gamma 3.3; the ellipsoid
// 0.3 x 0.5 rotated by (0.2, 0.1, 0.4) radians; the sel lobe 0.3 x 0.5
// rotated by 0.2 about x; any other model of the build at its defaults;
// Schlick F0 = 0.04 (1 for a lobe without a Fresnel factor),
// height-correlated masking.
const GgxNdf<double> kGgx(0.3, 0.3);
const BeckmannNdf<double> kBeckmann(0.3, 0.3);
const StudentTNdf<double> kStd(0.3, 0.3, 3.3);
const EllipsoidNdf<double> kEllipsoid(0.3, 0.5, 0.2, 0.1, 0.4);

BatchModel BenchModel(ModelKind kind) {
  BatchModel p;
  p.kind = kind;
  p.alpha_x = p.alpha_y = 0.3f;
  p.f0 = BatchTakesFresnel(kind) ? 0.04f : 1.0f;
  if (kind == ModelKind::kStudentT) p.gamma = 3.3f;
  if (kind == ModelKind::kEllipsoid || kind == ModelKind::kSel) {
    p.alpha_y = 0.5f;
    p.theta_x = 0.2f;
  }
  if (kind == ModelKind::kEllipsoid) {
    p.theta_y = 0.1f;
    p.theta_z = 0.4f;
  }
  return p;
}

int Count(const benchmark::State& state) { return static_cast<int>(state.range(0)); }

template <class Ndf>
void BM_D(benchmark::State& state, Ndf ndf) {
  const Inputs& in = In();
  const int n = Count(state);
  for (auto _ : state) {
    double acc = 0;
    for (int i = 0; i < n; ++i) acc += ndf.D(in.wi[i]);
    benchmark::DoNotOptimize(acc);
  }
  state.SetItemsProcessed(state.iterations() * n);
}

template <class Ndf>
void BM_G2(benchmark::State& state, Ndf ndf) {
  const Inputs& in = In();
  const int n = Count(state);
  for (auto _ : state) {
    double acc = 0;
    for (int i = 0; i < n; ++i) {
      Vec3<double> h;
      HalfVector(in.wi[i], in.wo[i], &h);
      acc += G2(ndf, in.wi[i], in.wo[i], h, Masking::kHeightCorrelated);
    }
    benchmark::DoNotOptimize(acc);
  }
  state.SetItemsProcessed(state.iterations() * n);
}

template <class Ndf>
void BM_Brdf(benchmark::State& state, Ndf ndf) {
  const Inputs& in = In();
  const int n = Count(state);
  const Fresnel fresnel = Fresnel::Schlick({0.04, 0.04, 0.04});
  for (auto _ : state) {
    double acc = 0;
    for (int i = 0; i < n; ++i) {
      acc += Brdf(ndf, fresnel, in.wi[i], in.wo[i], Masking::kHeightCorrelated);
    }
    benchmark::DoNotOptimize(acc);
  }
  state.SetItemsProcessed(state.iterations() * n);
}

void BM_K(benchmark::State& state) {
  const Inputs& in = In();
  const int n = Count(state);
  const SelLobe<double> lobe = SelLobe<double>::FromAngles(0.3, 0.5, 0.2, 0, 0);
  for (auto _ : state) {
    double acc = 0;
    for (int i = 0; i < n; ++i) acc += lobe.K(in.wi[i]);
    benchmark::DoNotOptimize(acc);
  }
  state.SetItemsProcessed(state.iterations() * n);
}

__attribute__((optimize("no-tree-vectorize"))) void FloatBrdf(Inputs& in, int n) {
  const GgxNdf<float> ndf(0.3f);
  const Fresnel fresnel = Fresnel::Schlick({0.04, 0.04, 0.04});
  for (int i = 0; i < n; ++i) {
    in.out[i] = Brdf(ndf, fresnel, Vec3<float>(in.ix[i], in.iy[i], in.iz[i]),
                     Vec3<float>(in.ox[i], in.oy[i], in.oz[i]), Masking::kHeightCorrelated);
  }
}
void BM_BrdfFloat(benchmark::State& state) {
  Inputs& in = In();
  const int n = Count(state);
  for (auto _ : state) {
    FloatBrdf(in, n);
    benchmark::DoNotOptimize(in.out.data());
  }
  state.SetItemsProcessed(state.iterations() * n);
}

// The batch call forced to one target. D and K take the wi array (as the
// normals, for D), G2 and the BRDF the (wi, wo) pairs.
void BM_EvalBatch(benchmark::State& state, ModelKind kind, Quantity q, std::string target) {
  ForceTarget(target);
  Inputs& in = In();
  const size_t n = static_cast<size_t>(Count(state));
  const BatchModel p = BenchModel(kind);
  const DirArrays wi{in.ix.data(), in.iy.data(), in.iz.data()};
  const DirArrays wo{in.ox.data(), in.oy.data(), in.oz.data()};
  for (auto _ : state) {
    if (IsPairQuantity(q)) {
      EvalBatch(p, q, wi, wo, in.out.data(), n);
    } else {
      EvalBatch(p, q, wi, in.out.data(), n);
    }
    benchmark::DoNotOptimize(in.out.data());
  }
  ForceTarget("best");
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(n));
}

// A shading batch of mixed materials on one target, n = 4096: the GGX or
// Beckmann BRDF with alpha and F0 per element (BM_BrdfMixed), and light
// directions with weight and pdf (BM_SampleLight, one material per call;
// BM_SampleLightMixed, per element). Items are elements.
struct Mixed {
  std::vector<float> alpha, f0, u1, u2, x, y, z, weight, pdf;
  Mixed() {
    std::mt19937_64 rng(2);
    std::uniform_real_distribution<float> uni(0.0f, 1.0f);
    for (int i = 0; i < kN; ++i) {
      const float r = 0.05f + 0.95f * uni(rng);
      alpha.push_back(r * r);
      f0.push_back(i % 2 ? 0.04f : uni(rng));
      u1.push_back(uni(rng));
      u2.push_back(uni(rng));
    }
    x = y = z = weight = pdf = std::vector<float>(kN);
  }
};
Mixed& MixedIn() {
  static Mixed m;
  return m;
}
enum class MixedCall { kBrdf, kLight, kLightMixed };
void BM_Mixed(benchmark::State& state, ModelKind kind, MixedCall call, std::string target) {
  ForceTarget(target);
  Inputs& in = In();
  Mixed& m = MixedIn();
  const BatchModel p = BenchModel(kind);
  const BatchElements elements{m.alpha.data(), nullptr, m.f0.data()};
  const DirArrays wi{in.ix.data(), in.iy.data(), in.iz.data()};
  const DirArrays wo{in.ox.data(), in.oy.data(), in.oz.data()};
  const LightSampleArrays light{m.x.data(), m.y.data(), m.z.data(), m.weight.data(), m.pdf.data()};
  for (auto _ : state) {
    switch (call) {
      case MixedCall::kBrdf:
        EvalBatch(p, elements, Quantity::kBrdf, wi, wo, in.out.data(), kN);
        break;
      case MixedCall::kLight:
        SampleLightBatch(p, wo, m.u1.data(), m.u2.data(), light, kN);
        break;
      case MixedCall::kLightMixed:
        SampleLightBatch(p, elements, wo, m.u1.data(), m.u2.data(), light, kN);
        break;
    }
    benchmark::DoNotOptimize(in.out.data());
    benchmark::DoNotOptimize(m.weight.data());
  }
  ForceTarget("best");
  state.SetItemsProcessed(state.iterations() * kN);
}
[[maybe_unused]] const int kMixedRegistered = [] {
  const std::pair<const char*, MixedCall> calls[] = {{"BM_BrdfMixed/", MixedCall::kBrdf},
                                                     {"BM_SampleLight/", MixedCall::kLight},
                                                     {"BM_SampleLightMixed/", MixedCall::kLightMixed}};
  for (const auto& [prefix, call] : calls) {
    for (ModelKind kind : ModelKindsBuilt()) {
      if (!BatchSupportsElements(kind)) continue;
      for (const std::string& t : AvailableTargets()) {
        const std::string name = prefix + std::string(ModelName(kind)) + "/" + t;
        benchmark::RegisterBenchmark(name.c_str(), BM_Mixed, kind, call, t)
            ->ArgNames({"n"})
            ->Arg(kN);
      }
    }
  }
  return 0;
}();

#define BRDFBAKE_REFERENCE(family, model, ndf)                                   \
  BENCHMARK_CAPTURE(BM_##family, model/double_reference, ndf)->ArgNames({"n"}) \
      ->Arg(kN)
BRDFBAKE_REFERENCE(D, ggx, kGgx);
BRDFBAKE_REFERENCE(D, beckmann, kBeckmann);
BRDFBAKE_REFERENCE(D, std, kStd);
BRDFBAKE_REFERENCE(D, ellipsoid, kEllipsoid);
BRDFBAKE_REFERENCE(G2, ggx, kGgx);
BRDFBAKE_REFERENCE(G2, beckmann, kBeckmann);
BRDFBAKE_REFERENCE(G2, std, kStd);
BRDFBAKE_REFERENCE(G2, ellipsoid, kEllipsoid);
BRDFBAKE_REFERENCE(Brdf, ggx, kGgx);
BRDFBAKE_REFERENCE(Brdf, beckmann, kBeckmann);
BRDFBAKE_REFERENCE(Brdf, std, kStd);
BRDFBAKE_REFERENCE(Brdf, ellipsoid, kEllipsoid);
#undef BRDFBAKE_REFERENCE
BENCHMARK(BM_K)->Name("BM_K/sel/double_reference")->ArgNames({"n"})->Arg(kN);
BENCHMARK(BM_BrdfFloat)->Name("BM_Brdf/ggx/float_reference")->ArgNames({"n"})->Arg(kN);

[[maybe_unused]] const int kRegistered = [] {
  const std::pair<const char*, Quantity> quantities[] = {{"BM_D/", Quantity::kD},
                                                         {"BM_G2/", Quantity::kG2},
                                                         {"BM_Brdf/", Quantity::kBrdf},
                                                         {"BM_K/", Quantity::kK}};
  for (const auto& [prefix, q] : quantities) {
    for (ModelKind kind : ModelKindsBuilt()) {
      if (!BatchSupports(kind, q)) continue;
      for (const std::string& t : AvailableTargets()) {
        const std::string name = prefix + std::string(ModelName(kind)) + "/" + t;
        benchmark::internal::Benchmark* b =
            benchmark::RegisterBenchmark(name.c_str(), BM_EvalBatch, kind, q, t)
                ->ArgNames({"n"})
                ->Arg(kN);
        if (kind == ModelKind::kGgx && q == Quantity::kBrdf) b->Arg(16)->Arg(17);
      }
    }
  }
  return 0;
}();

// The GGX BRDF (alpha 0.25, Schlick F0 = 0.04) over the hemisphere of wi,
// size x size pixels, the SIMD kernels dispatched per row, on 1 thread and
// on every core. Items are pixels.
void BM_Grid(benchmark::State& state) {
  GridRequest req;
  req.kind = GridKind::kHemisphere;
  req.width = req.height = static_cast<int>(state.range(0));
  req.fresnel = Fresnel::Schlick({0.04, 0.04, 0.04});
  req.threads = static_cast<int>(state.range(1));
  for (auto _ : state) {
    const Grid g = EvalGrid(req);
    benchmark::DoNotOptimize(g.values.data());
  }
  state.SetItemsProcessed(state.iterations() * req.width * req.height);
}
[[maybe_unused]] const int kGridRegistered = [] {
  const int64_t cores = std::max(1u, std::thread::hardware_concurrency());
  benchmark::internal::Benchmark* b =
      benchmark::RegisterBenchmark("BM_Grid/hemisphere/ggx/simd", BM_Grid)
          ->ArgNames({"size", "threads"})
          ->Args({1024, 1})
          ->UseRealTime()
          ->Unit(benchmark::kMillisecond);
  if (cores > 1) b->Args({1024, cores});
  return 0;
}();

}  // namespace
}  // namespace brdfbake
