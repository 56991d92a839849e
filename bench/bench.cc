// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Google Benchmark suite. Names carry the model, the quantity and the
// implementation, e.g. BM_Brdf/ggx/scalar: evaluations per second of the
// double-precision scalar reference, one evaluation per call.

#include <cstdio>
#include <cmath>
#include <random>
#include <vector>

#include <benchmark/benchmark.h>

#include "brdfbake/bake.h"
#include "brdfbake/batch.h"
#include "brdfbake/exr.h"
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

struct Inputs {
  std::vector<Vec3<double>> wi, wo;
  std::vector<double> u1, u2;
  Inputs() {
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> uni(0.0, 1.0);
    for (int i = 0; i < kN; ++i) {
      wi.push_back(FromMuPhi(0.02 + 0.98 * uni(rng), 6.283 * uni(rng)));
      wo.push_back(FromMuPhi(0.02 + 0.98 * uni(rng), 6.283 * uni(rng)));
      u1.push_back(uni(rng));
      u2.push_back(uni(rng));
    }
  }
};
const Inputs& In() {
  static const Inputs in;
  return in;
}

template <class Ndf>
void BM_D(benchmark::State& state, Ndf ndf) {
  const Inputs& in = In();
  for (auto _ : state) {
    double acc = 0;
    for (int i = 0; i < kN; ++i) acc += ndf.D(in.wi[i]);
    benchmark::DoNotOptimize(acc);
  }
  state.SetItemsProcessed(state.iterations() * kN);
}

template <class Ndf>
void BM_G2(benchmark::State& state, Ndf ndf) {
  const Inputs& in = In();
  for (auto _ : state) {
    double acc = 0;
    for (int i = 0; i < kN; ++i) {
      Vec3<double> h;
      HalfVector(in.wi[i], in.wo[i], &h);
      acc += G2(ndf, in.wi[i], in.wo[i], h, Masking::kHeightCorrelated);
    }
    benchmark::DoNotOptimize(acc);
  }
  state.SetItemsProcessed(state.iterations() * kN);
}

template <class Ndf>
void BM_Brdf(benchmark::State& state, Ndf ndf) {
  const Inputs& in = In();
  const Fresnel fresnel = Fresnel::Schlick({0.04, 0.04, 0.04});
  for (auto _ : state) {
    double acc = 0;
    for (int i = 0; i < kN; ++i) {
      acc += Brdf(ndf, fresnel, in.wi[i], in.wo[i], Masking::kHeightCorrelated);
    }
    benchmark::DoNotOptimize(acc);
  }
  state.SetItemsProcessed(state.iterations() * kN);
}

template <class Ndf, class SampleFn>
void BM_Sample(benchmark::State& state, Ndf ndf, SampleFn fn) {
  const Inputs& in = In();
  for (auto _ : state) {
    double acc = 0;
    for (int i = 0; i < kN; ++i) acc += fn(ndf, in.wo[i], in.u1[i], in.u2[i]).z;
    benchmark::DoNotOptimize(acc);
  }
  state.SetItemsProcessed(state.iterations() * kN);
}

template <class Ndf>
Vec3<double> Visible(const Ndf& ndf, const Vec3<double>& w, double u1, double u2) {
  return ndf.SampleVisible(w, u1, u2);
}
Vec3<double> PseudoVnis(const StudentTNdf<double>& ndf, const Vec3<double>& w, double u1,
                        double u2) {
  return ndf.SamplePseudoVnis(w, u1, u2);
}

BENCHMARK_CAPTURE(BM_D, ggx/scalar, GgxNdf<double>(0.3, 0.3));
BENCHMARK_CAPTURE(BM_D, beckmann/scalar, BeckmannNdf<double>(0.3, 0.3));
BENCHMARK_CAPTURE(BM_D, std/scalar, StudentTNdf<double>(0.3, 0.3, 3.3));
BENCHMARK_CAPTURE(BM_D, ellipsoid/scalar, EllipsoidNdf<double>(0.3, 0.5, 0.2, 0.1, 0.4));
BENCHMARK_CAPTURE(BM_G2, ggx/scalar, GgxNdf<double>(0.3, 0.3));
BENCHMARK_CAPTURE(BM_G2, beckmann/scalar, BeckmannNdf<double>(0.3, 0.3));
BENCHMARK_CAPTURE(BM_G2, std/scalar, StudentTNdf<double>(0.3, 0.3, 3.3));
BENCHMARK_CAPTURE(BM_G2, ellipsoid/scalar, EllipsoidNdf<double>(0.3, 0.5, 0.2, 0.1, 0.4));
void BM_SelK(benchmark::State& state) {
  const Inputs& in = In();
  const SelLobe<double> lobe = SelLobe<double>::FromAngles(0.3, 0.5, 0.2, 0, 0);
  for (auto _ : state) {
    double acc = 0;
    for (int i = 0; i < kN; ++i) acc += lobe.K(in.wi[i]);
    benchmark::DoNotOptimize(acc);
  }
  state.SetItemsProcessed(state.iterations() * kN);
}
BENCHMARK(BM_SelK)->Name("BM_K/sel/scalar");
BENCHMARK_CAPTURE(BM_Brdf, ggx/scalar, GgxNdf<double>(0.3, 0.3));
BENCHMARK_CAPTURE(BM_Brdf, beckmann/scalar, BeckmannNdf<double>(0.3, 0.3));
BENCHMARK_CAPTURE(BM_Brdf, std/scalar, StudentTNdf<double>(0.3, 0.3, 3.3));
BENCHMARK_CAPTURE(BM_Brdf, ellipsoid/scalar, EllipsoidNdf<double>(0.3, 0.5, 0.2, 0.1, 0.4));
BENCHMARK_CAPTURE(BM_Sample, ggx/scalar, GgxNdf<double>(0.3, 0.3), Visible<GgxNdf<double>>);
BENCHMARK_CAPTURE(BM_Sample, beckmann/scalar, BeckmannNdf<double>(0.3, 0.3),
                  Visible<BeckmannNdf<double>>);
BENCHMARK_CAPTURE(BM_Sample, std/scalar, StudentTNdf<double>(0.3, 0.3, 3.3), PseudoVnis);
BENCHMARK_CAPTURE(BM_Sample, ellipsoid/scalar, EllipsoidNdf<double>(0.3, 0.5, 0.2, 0.1, 0.4),
                  Visible<EllipsoidNdf<double>>);

// SIMD batch kernels per target (forced), float lanes, SoA arrays of 4096
// pairs, and the float scalar reference compiled without auto-vectorization.
struct FloatInputs {
  std::vector<float> ix, iy, iz, ox, oy, oz, out;
  FloatInputs() {
    const Inputs& in = In();
    for (int i = 0; i < kN; ++i) {
      ix.push_back(float(in.wi[i].x)); iy.push_back(float(in.wi[i].y)); iz.push_back(float(in.wi[i].z));
      ox.push_back(float(in.wo[i].x)); oy.push_back(float(in.wo[i].y)); oz.push_back(float(in.wo[i].z));
    }
    out.resize(kN);
  }
};
FloatInputs& FIn() {
  static FloatInputs in;
  return in;
}

// The batch interface per target: every model's BRDF, D, G2 (and the sel
// lobe's K) over the same inputs, and the visible-normal samplers. D takes
// the wi array as normals, G2 and the BRDF the (wi, wo) pairs, the samplers
// the wo array.
BatchModel BenchModel(ModelKind kind) {
  BatchModel p;
  p.kind = kind;
  p.alpha_x = p.alpha_y = 0.3f;
  p.f0 = 0.04f;
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

void BM_EvalBatch(benchmark::State& state, ModelKind kind, Quantity q, std::string target) {
  ForceTarget(target);
  FloatInputs& in = FIn();
  const BatchModel p = BenchModel(kind);
  const DirArrays wi{in.ix.data(), in.iy.data(), in.iz.data()};
  const DirArrays wo{in.ox.data(), in.oy.data(), in.oz.data()};
  for (auto _ : state) {
    if (IsPairQuantity(q)) {
      EvalBatch(p, q, wi, wo, in.out.data(), kN);
    } else {
      EvalBatch(p, q, wi, in.out.data(), kN);
    }
    benchmark::DoNotOptimize(in.out.data());
  }
  ForceTarget("best");
  state.SetItemsProcessed(state.iterations() * kN);
}

void BM_VisibleSamples(benchmark::State& state, ModelKind kind, std::string target) {
  ForceTarget(target);
  FloatInputs& in = FIn();
  static std::vector<float> u1, u2, mx(kN), my(kN), mz(kN);
  if (u1.empty()) {
    for (int i = 0; i < kN; ++i) {
      u1.push_back(float(In().u1[i]));
      u2.push_back(float(In().u2[i]));
    }
  }
  const BatchModel p = BenchModel(kind);
  for (auto _ : state) {
    SampleBatch(p, Sampler::kVisible, {in.ox.data(), in.oy.data(), in.oz.data()}, u1.data(),
                u2.data(), {mx.data(), my.data(), mz.data()}, kN);
    benchmark::DoNotOptimize(mz.data());
  }
  ForceTarget("best");
  state.SetItemsProcessed(state.iterations() * kN);
}

__attribute__((optimize("no-tree-vectorize"))) void ScalarFloatBrdf(FloatInputs& in) {
  const GgxNdf<float> ndf(0.3f);
  const Fresnel fresnel = Fresnel::Schlick({0.04, 0.04, 0.04});
  for (int i = 0; i < kN; ++i) {
    in.out[i] = Brdf(ndf, fresnel, Vec3<float>(in.ix[i], in.iy[i], in.iz[i]),
                     Vec3<float>(in.ox[i], in.oy[i], in.oz[i]), Masking::kHeightCorrelated);
  }
}
void BM_BrdfScalarFloat(benchmark::State& state) {
  FloatInputs& in = FIn();
  for (auto _ : state) {
    ScalarFloatBrdf(in);
    benchmark::DoNotOptimize(in.out.data());
  }
  state.SetItemsProcessed(state.iterations() * kN);
}
BENCHMARK(BM_BrdfScalarFloat)->Name("BM_Brdf/ggx/scalar_float");

// Grid evaluation (GGX BRDF over the hemisphere of wi, 1024 x 1024, SIMD
// kernels dispatched per row) at 1 and 2 threads.
void BM_Grid(benchmark::State& state) {
  GridRequest req;
  req.kind = GridKind::kHemisphere;
  req.width = req.height = 1024;
  req.fresnel = Fresnel::Schlick({0.04, 0.04, 0.04});
  req.threads = static_cast<int>(state.range(0));
  for (auto _ : state) {
    const Grid g = EvalGrid(req);
    benchmark::DoNotOptimize(g.values.data());
  }
  state.SetItemsProcessed(state.iterations() * req.width * req.height);
}
BENCHMARK(BM_Grid)->Name("BM_Grid/hemisphere/ggx")->Arg(1)->Arg(2)->UseRealTime()
    ->Unit(benchmark::kMillisecond);

// The E table of the default GGX (edges placement, size NxN): the bake
// alone, or the bake and the EXR file written (`write`). Counters: the
// claimed maximum error and the true one against a reference baked at
// tolerance 1e-12 (computed once, outside the timed loop).
void BM_BakeE(benchmark::State& state, IntegratorKind kind, int samples, double tolerance,
              bool write) {
  BakeSpec spec;
  spec.mu.size = spec.roughness.size = static_cast<int>(state.range(0));
  spec.integrator = kind;
  spec.samples = samples;
  spec.tolerance = tolerance;
  spec.estimate_error = false;
  const std::string path = "/tmp/brdfbake_bench_E.exr";
  Table t;
  for (auto _ : state) {
    t = Bake(spec);
    if (write) WriteExr(t, path);
    benchmark::DoNotOptimize(t.channels[0].values.data());
  }
  if (write) std::remove(path.c_str());
  BakeSpec ref_spec = spec;
  ref_spec.integrator = IntegratorKind::kQuadrature;
  ref_spec.samples = 0;
  ref_spec.tolerance = 1e-12;
  const Table ref = Bake(ref_spec);
  double true_err = 0;
  for (size_t i = 0; i < ref.channels[0].values.size(); ++i) {
    // The value as stored (float pixels) against the reference.
    const double stored = static_cast<float>(t.channels[0].values[i]);
    true_err = std::max(true_err, std::abs(stored - ref.channels[0].values[i]));
  }
  if (kind != IntegratorKind::kEngine) state.counters["claimed_max_error"] = t.max_abs_error;
  state.counters["true_max_error"] = true_err;
  state.SetItemsProcessed(state.iterations() * spec.mu.size * spec.roughness.size);
}
BENCHMARK_CAPTURE(BM_BakeE, ggx/quadrature_tol1e-6, IntegratorKind::kQuadrature, 0, 1e-6, false)
    ->Arg(32)->Arg(128)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime()
    ->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK_CAPTURE(BM_BakeE, ggx/quadrature_tol1e-7, IntegratorKind::kQuadrature, 0, 1e-7, false)
    ->Arg(128)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime()
    ->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK_CAPTURE(BM_BakeE, ggx/quadrature_tol1e-6_exr, IntegratorKind::kQuadrature, 0, 1e-6, true)
    ->Arg(128)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime()
    ->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK_CAPTURE(BM_BakeE, ggx/engine1024, IntegratorKind::kEngine, 1024, 0.0, false)
    ->Arg(32)->Arg(128)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime()
    ->Repetitions(5)->ReportAggregatesOnly(true);

}  // namespace
}  // namespace brdfbake

int main(int argc, char** argv) {
  using brdfbake::ModelKind;
  using brdfbake::Quantity;
  const ModelKind kinds[] = {ModelKind::kGgx, ModelKind::kBeckmann, ModelKind::kStudentT,
                             ModelKind::kEllipsoid, ModelKind::kSel};
  const std::pair<const char*, Quantity> quantities[] = {
      {"BM_Brdf/", Quantity::kBrdf}, {"BM_D/", Quantity::kD}, {"BM_G2/", Quantity::kG2},
      {"BM_K/", Quantity::kK}};
  for (const std::string& t : brdfbake::AvailableTargets()) {
    for (const auto& [prefix, q] : quantities) {
      for (ModelKind kind : kinds) {
        if (!brdfbake::BatchSupports(kind, q)) continue;
        const std::string name = prefix + std::string(brdfbake::ModelName(kind)) + "/" + t;
        benchmark::RegisterBenchmark(name.c_str(), brdfbake::BM_EvalBatch, kind, q, t);
      }
    }
    for (ModelKind kind : {ModelKind::kGgx, ModelKind::kEllipsoid}) {
      const std::string name = "BM_SampleVisible/" + std::string(brdfbake::ModelName(kind)) + "/" + t;
      benchmark::RegisterBenchmark(name.c_str(), brdfbake::BM_VisibleSamples, kind, t);
    }
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
