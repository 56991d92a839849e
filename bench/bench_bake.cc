// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Whole bakes: BM_Bake/<table>/<model>/<integrand>/<size>/threads:<n>, the
// quadrature at the default tolerance (1e-7) with the integrand in double
// SIMD lanes (`simd`, the default) or the double scalar reference
// (`scalar`, `bake --target scalar`). Wall time of Bake() (the table in
// memory, no file; with the tables it builds, ReleaseBakeCaches), median of
// the repetitions. Counters: the claimed
// maximum error before storage (integration_error) and the true one, against
// the same table baked at tolerance 1e-10 (outside the timed loop; where the
// rules' claims stop near 1e-9, the reference is still far more accurate
// than the tables measured).

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <benchmark/benchmark.h>

#include "brdfbake/bake.h"

namespace brdfbake {
namespace {

struct BakeCase {
  TableKind table;
  const char* model;
  double gamma;
  bool simd;
  bool gamma_axis = false;  // std over a gamma axis of state.range(2) slices
};

void BM_Bake(benchmark::State& state, BakeCase c) {
  BakeSpec spec;
  spec.table = c.table;
  spec.model.kind = ParseModelKind(c.model);
  spec.model.gamma = c.gamma;
  spec.simd = c.simd;
  spec.mu.size = spec.roughness.size = static_cast<int>(state.range(0));
  spec.threads = static_cast<int>(state.range(1));
  if (c.gamma_axis) spec.gamma.size = static_cast<int>(state.range(2));
  Table t;
  for (auto _ : state) {
    ReleaseBakeCaches();  // each bake builds its tables, as one CLI run does
    t = Bake(spec);
    benchmark::DoNotOptimize(t.channels[0].values.data());
  }
  BakeSpec ref_spec = spec;
  ref_spec.simd = true;
  ref_spec.threads = 0;
  ref_spec.tolerance = 1e-10;
  const Table ref = Bake(ref_spec);
  double true_err = 0;
  for (size_t k = 0; k < ref.channels.size(); ++k) {
    for (size_t i = 0; i < ref.channels[k].values.size(); ++i) {
      true_err = std::max(true_err, std::abs(t.channels[k].values[i] - ref.channels[k].values[i]));
    }
  }
  state.counters["integration_error"] = t.integration_error;
  state.counters["true_error"] = true_err;
  const int64_t texels =
      (c.table == TableKind::kEavg ? spec.roughness.size : int64_t(spec.mu.size) * spec.roughness.size) *
      (c.gamma_axis ? spec.gamma.size : 1);
  state.SetItemsProcessed(state.iterations() * texels);
}

constexpr double kInf = std::numeric_limits<double>::infinity();

#define BRDFBAKE_BAKE_BENCH(name, table, model, gamma, simd) \
  BENCHMARK_CAPTURE(BM_Bake, name, BakeCase{table, model, gamma, simd})

// docs/performance.md, "Bakes": the SIMD rules at 2 threads (and 1 for the scaling),
// then the double scalar reference of the same rules for the ratio.
#define BRDFBAKE_BAKE_ARGS(reps) \
  Unit(benchmark::kMillisecond)->UseRealTime()->Repetitions(reps)->ReportAggregatesOnly(true)

BRDFBAKE_BAKE_BENCH(dfg/ggx/simd, TableKind::kDfg, "ggx", 2, true)
    ->Args({32, 2})->Args({128, 2})->Args({128, 1})->BRDFBAKE_BAKE_ARGS(5);
BRDFBAKE_BAKE_BENCH(E/ggx/simd, TableKind::kE, "ggx", 2, true)
    ->Args({128, 2})->BRDFBAKE_BAKE_ARGS(5);
BRDFBAKE_BAKE_BENCH(E_avg/ggx/simd, TableKind::kEavg, "ggx", 2, true)
    ->Args({128, 2})->BRDFBAKE_BAKE_ARGS(5);
BRDFBAKE_BAKE_BENCH(E/beckmann/simd, TableKind::kE, "beckmann", 2, true)
    ->Args({32, 2})->Args({32, 1})->BRDFBAKE_BAKE_ARGS(5);
BRDFBAKE_BAKE_BENCH(dfg/beckmann/simd, TableKind::kDfg, "beckmann", 2, true)
    ->Args({32, 2})->BRDFBAKE_BAKE_ARGS(5);
BRDFBAKE_BAKE_BENCH(E_avg/beckmann/simd, TableKind::kEavg, "beckmann", 2, true)
    ->Args({128, 2})->BRDFBAKE_BAKE_ARGS(5);
BRDFBAKE_BAKE_BENCH(E/std_gamma1.501/simd, TableKind::kE, "std", 1.501, true)
    ->Args({32, 2})->BRDFBAKE_BAKE_ARGS(5);
BRDFBAKE_BAKE_BENCH(E/std_gamma1.6/simd, TableKind::kE, "std", 1.6, true)
    ->Args({32, 2})->BRDFBAKE_BAKE_ARGS(5);
BRDFBAKE_BAKE_BENCH(E/std_gamma3/simd, TableKind::kE, "std", 3, true)
    ->Args({32, 2})->BRDFBAKE_BAKE_ARGS(5);
BRDFBAKE_BAKE_BENCH(E/std_gamma30/simd, TableKind::kE, "std", 30, true)
    ->Args({32, 2})->BRDFBAKE_BAKE_ARGS(5);
BRDFBAKE_BAKE_BENCH(E/std_gamma_inf/simd, TableKind::kE, "std", kInf, true)
    ->Args({32, 2})->BRDFBAKE_BAKE_ARGS(5);
BRDFBAKE_BAKE_BENCH(E_avg/std_gamma1.501/simd, TableKind::kEavg, "std", 1.501, true)
    ->Args({128, 2})->BRDFBAKE_BAKE_ARGS(5);
BRDFBAKE_BAKE_BENCH(E_avg/std_gamma3/simd, TableKind::kEavg, "std", 3, true)
    ->Args({128, 2})->BRDFBAKE_BAKE_ARGS(5);
BRDFBAKE_BAKE_BENCH(E_avg/std_gamma30/simd, TableKind::kEavg, "std", 30, true)
    ->Args({128, 2})->BRDFBAKE_BAKE_ARGS(5);
// std over the gamma axis (1.501 to inf, tail warp): mu x roughness x gamma,
// and E_avg over roughness x gamma.
BENCHMARK_CAPTURE(BM_Bake, E/std_gamma_axis/simd, BakeCase{TableKind::kE, "std", 2, true, true})
    ->Args({32, 2, 16})->BRDFBAKE_BAKE_ARGS(3);
BENCHMARK_CAPTURE(BM_Bake, E_avg/std_gamma_axis/simd, BakeCase{TableKind::kEavg, "std", 2, true, true})
    ->Args({32, 2, 16})->BRDFBAKE_BAKE_ARGS(3);

// The sampling integrators (their default samples: qmc and mc 4096 per
// texel, engine 1024 plus its error against the quadrature at 1e-10), E
// 32x32 at 2 threads, their points in lanes (`simd`) or the scalar
// reference (`scalar`). range(2) is the integrator.
void BM_BakeSampling(benchmark::State& state, const char* model, bool simd) {
  BakeSpec spec;
  spec.table = TableKind::kE;
  spec.model.kind = ParseModelKind(model);
  spec.model.gamma = 3;
  spec.integrator = static_cast<IntegratorKind>(state.range(2));
  spec.simd = simd;
  spec.mu.size = spec.roughness.size = static_cast<int>(state.range(0));
  spec.threads = static_cast<int>(state.range(1));
  Table t;
  for (auto _ : state) {
    ReleaseBakeCaches();
    t = Bake(spec);
    benchmark::DoNotOptimize(t.channels[0].values.data());
  }
  state.counters["integration_error"] = t.integration_error;
  state.SetItemsProcessed(state.iterations() * int64_t(t.channels[0].values.size()));
}
#define BRDFBAKE_SAMPLING_ARGS(integrator) \
  Args({32, 2, static_cast<int64_t>(IntegratorKind::integrator)})
BENCHMARK_CAPTURE(BM_BakeSampling, E/ggx/qmc/simd, "ggx", true)
    ->BRDFBAKE_SAMPLING_ARGS(kQmc)->BRDFBAKE_BAKE_ARGS(3);
BENCHMARK_CAPTURE(BM_BakeSampling, E/ggx/qmc/scalar, "ggx", false)
    ->BRDFBAKE_SAMPLING_ARGS(kQmc)->BRDFBAKE_BAKE_ARGS(3);
BENCHMARK_CAPTURE(BM_BakeSampling, E/beckmann/qmc/simd, "beckmann", true)
    ->BRDFBAKE_SAMPLING_ARGS(kQmc)->BRDFBAKE_BAKE_ARGS(3);
BENCHMARK_CAPTURE(BM_BakeSampling, E/beckmann/qmc/scalar, "beckmann", false)
    ->BRDFBAKE_SAMPLING_ARGS(kQmc)->BRDFBAKE_BAKE_ARGS(3);
BENCHMARK_CAPTURE(BM_BakeSampling, E/std_gamma3/qmc/simd, "std", true)
    ->BRDFBAKE_SAMPLING_ARGS(kQmc)->BRDFBAKE_BAKE_ARGS(3);
BENCHMARK_CAPTURE(BM_BakeSampling, E/std_gamma3/qmc/scalar, "std", false)
    ->BRDFBAKE_SAMPLING_ARGS(kQmc)->BRDFBAKE_BAKE_ARGS(3);
BENCHMARK_CAPTURE(BM_BakeSampling, E/ggx/engine/simd, "ggx", true)
    ->BRDFBAKE_SAMPLING_ARGS(kEngine)->BRDFBAKE_BAKE_ARGS(3);
BENCHMARK_CAPTURE(BM_BakeSampling, E/ggx/engine/scalar, "ggx", false)
    ->BRDFBAKE_SAMPLING_ARGS(kEngine)->BRDFBAKE_BAKE_ARGS(3);
BENCHMARK_CAPTURE(BM_BakeSampling, E/beckmann/engine/simd, "beckmann", true)
    ->BRDFBAKE_SAMPLING_ARGS(kEngine)->BRDFBAKE_BAKE_ARGS(3);
BENCHMARK_CAPTURE(BM_BakeSampling, E/beckmann/engine/scalar, "beckmann", false)
    ->BRDFBAKE_SAMPLING_ARGS(kEngine)->BRDFBAKE_BAKE_ARGS(3);
BENCHMARK_CAPTURE(BM_BakeSampling, E/std_gamma3/engine/simd, "std", true)
    ->BRDFBAKE_SAMPLING_ARGS(kEngine)->BRDFBAKE_BAKE_ARGS(3);
BENCHMARK_CAPTURE(BM_BakeSampling, E/std_gamma3/engine/scalar, "std", false)
    ->BRDFBAKE_SAMPLING_ARGS(kEngine)->BRDFBAKE_BAKE_ARGS(3);

// The timed loop of the model-specific entries below.
void TimeBake(benchmark::State& state, const BakeSpec& spec) {
  Table t;
  for (auto _ : state) {
    t = Bake(spec);
    benchmark::DoNotOptimize(t.channels[0].values.data());
  }
  state.counters["integration_error"] = t.integration_error;
  state.SetItemsProcessed(state.iterations() * int64_t(t.channels[0].values.size()));
}

// ggx-aniso: E over mu x phi_o x roughness x anisotropy (the sizes in the
// name; range(0) and range(1) are the size of the mu and roughness axes and
// the threads), E_avg over roughness x anisotropy.
void BM_BakeAniso(benchmark::State& state, TableKind table) {
  BakeSpec spec;
  spec.table = table;
  spec.model.kind = ModelKind::kGgxAniso;
  spec.mu.size = spec.roughness.size = static_cast<int>(state.range(0));
  spec.phi.size = spec.anisotropy.size = static_cast<int>(state.range(0)) / 2;
  spec.threads = static_cast<int>(state.range(1));
  TimeBake(state, spec);
}
BENCHMARK_CAPTURE(BM_BakeAniso, E/ggx-aniso/simd/32x16x32x16, TableKind::kE)
    ->Args({32, 2})->BRDFBAKE_BAKE_ARGS(3);
BENCHMARK_CAPTURE(BM_BakeAniso, E_avg/ggx-aniso/simd/8x4, TableKind::kEavg)
    ->Args({8, 2})->BRDFBAKE_BAKE_ARGS(3);

// One ellipsoid material (alpha 0.3 x 0.6, theta_x 20, theta_z 30 degrees):
// E over mu x phi_o, and its E_avg.
void BM_BakeEllipsoid(benchmark::State& state, TableKind table) {
  BakeSpec spec;
  spec.table = table;
  spec.model.kind = ModelKind::kEllipsoid;
  spec.model.alpha_x = 0.3;
  spec.model.alpha_y = 0.6;
  spec.model.theta_x = 20 * 3.14159265358979323846 / 180;
  spec.model.theta_z = 30 * 3.14159265358979323846 / 180;
  spec.mu.size = spec.phi.size = static_cast<int>(state.range(0));
  spec.phi.max = 2 * 3.14159265358979323846;
  spec.threads = static_cast<int>(state.range(1));
  TimeBake(state, spec);
}
BENCHMARK_CAPTURE(BM_BakeEllipsoid, E/ellipsoid/64x64, TableKind::kE)
    ->Args({64, 2})->BRDFBAKE_BAKE_ARGS(3);
BENCHMARK_CAPTURE(BM_BakeEllipsoid, E_avg/ellipsoid, TableKind::kEavg)
    ->Args({1, 2})->BRDFBAKE_BAKE_ARGS(3);

// The sel lobe's integral over (alpha_x, alpha_y), 32x32 (lanes or
// --target scalar).
void BM_BakeSel(benchmark::State& state, bool simd) {
  BakeSpec spec;
  spec.table = TableKind::kSelNorm;
  spec.model.kind = ModelKind::kSel;
  spec.alpha_x.size = spec.alpha_y.size = static_cast<int>(state.range(0));
  spec.threads = static_cast<int>(state.range(1));
  spec.simd = simd;
  TimeBake(state, spec);
}
BENCHMARK_CAPTURE(BM_BakeSel, sel_norm/sel/simd/32x32, true)
    ->Args({32, 2})->BRDFBAKE_BAKE_ARGS(5);
BENCHMARK_CAPTURE(BM_BakeSel, sel_norm/sel/scalar/32x32, false)
    ->Args({32, 2})->BRDFBAKE_BAKE_ARGS(5);

BRDFBAKE_BAKE_BENCH(dfg/ggx/scalar, TableKind::kDfg, "ggx", 2, false)
    ->Args({128, 2})->BRDFBAKE_BAKE_ARGS(3);
BRDFBAKE_BAKE_BENCH(E/beckmann/scalar, TableKind::kE, "beckmann", 2, false)
    ->Args({32, 2})->BRDFBAKE_BAKE_ARGS(3);
BRDFBAKE_BAKE_BENCH(E/std_gamma3/scalar, TableKind::kE, "std", 3, false)
    ->Args({32, 2})->BRDFBAKE_BAKE_ARGS(3);

}  // namespace
}  // namespace brdfbake
