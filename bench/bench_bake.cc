// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Whole bakes: BM_Bake/<table>/<model>/<integrator>/<implementation>/<axes>/threads:<n>,
// on every core (n = the machine's hardware threads) and some on 1, the
// wall time of Bake() with the table in memory (no file), each bake
// building its own tables (ReleaseBakeCaches before every one, as one CLI
// run does). The implementation is `simd` (the integrand in double SIMD
// lanes of the target dispatch picks, the default) or `double_reference`
// (the double scalar reference of the same rule, `bake --target scalar`).
// The axes are the table's sizes: size:N is an N x N table (E, dfg) or N
// entries (E_avg); tables with other axes name each one (mu, phi,
// roughness, anisotropy, alpha_x, alpha_y), gammas:D adds D gamma slices
// (std) and iors:D D ior slices (ggx-glass). Items are texels.
//
// Counters: integration_error, the claimed maximum error before storage,
// and true_error, the largest difference of the values before storage from
// the same table baked by the quadrature at tolerance 1e-10 (once per
// table, outside the timed loop). The quadrature bakes run at the default
// tolerance 1e-7, qmc and engine at their default samples (qmc 4096 per
// texel, engine 1024, whose bake includes its own error against the
// quadrature at 1e-10).

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include <benchmark/benchmark.h>

#include "brdfbake/bake.h"

namespace brdfbake {
namespace {

struct BakeRow {
  BakeSpec spec;                   // everything but the sizes and threads
  std::vector<std::string> axes;   // the arguments' names, threads last
  double reference_tolerance;      // 0: no true error
};

void ApplyArg(const std::string& name, int value, BakeSpec* spec) {
  if (name == "size") {
    spec->mu.size = spec->roughness.size = value;
  } else if (name == "mu") {
    spec->mu.size = value;
  } else if (name == "phi") {
    spec->phi.size = value;
  } else if (name == "roughness") {
    spec->roughness.size = value;
  } else if (name == "anisotropy") {
    spec->anisotropy.size = value;
  } else if (name == "alpha_x") {
    spec->alpha_x.size = value;
  } else if (name == "alpha_y") {
    spec->alpha_y.size = value;
  } else if (name == "gammas") {
    spec->gamma.size = value;
  } else if (name == "iors") {
    spec->ior.size = value;
  } else if (name == "threads") {
    spec->threads = value;
  }
}

double MaxDifference(const Table& a, const Table& b) {
  double d = 0;
  for (size_t k = 0; k < b.channels.size(); ++k) {
    for (size_t i = 0; i < b.channels[k].values.size(); ++i) {
      d = std::max(d, std::abs(a.channels[k].values[i] - b.channels[k].values[i]));
    }
  }
  return d;
}

// The reference of a table: the quadrature at `tolerance`, baked once per
// run and kept (every repetition, and the rows that bake the same table in
// another way, compare with it).
const Table& Reference(const BakeSpec& spec, double tolerance) {
  BakeSpec ref = spec;
  ref.integrator = IntegratorKind::kQuadrature;
  ref.samples = 0;
  ref.simd = true;
  ref.threads = 0;
  ref.tolerance = tolerance;
  std::string key = std::string(TableName(ref.table)) + " " + ref.model.ToJson();
  for (const Axis* a : {&ref.mu, &ref.roughness, &ref.gamma, &ref.phi, &ref.anisotropy,
                        &ref.alpha_x, &ref.alpha_y}) {
    key += " " + a->ToJson();
  }
  key += " " + std::to_string(tolerance);
  static std::map<std::string, Table> references;
  auto it = references.find(key);
  if (it == references.end()) it = references.emplace(key, Bake(ref)).first;
  return it->second;
}

void BM_Bake(benchmark::State& state, BakeRow row) {
  BakeSpec spec = row.spec;
  for (size_t i = 0; i < row.axes.size(); ++i) {
    ApplyArg(row.axes[i], static_cast<int>(state.range(static_cast<int>(i))), &spec);
  }
  Table t;
  for (auto _ : state) {
    ReleaseBakeCaches();
    t = Bake(spec);
    benchmark::DoNotOptimize(t.channels[0].values.data());
  }
  state.counters["integration_error"] = t.integration_error;
  if (row.reference_tolerance > 0) {
    state.counters["true_error"] = MaxDifference(t, Reference(spec, row.reference_tolerance));
  }
  state.SetItemsProcessed(state.iterations() * int64_t(t.channels[0].values.size()));
}

BakeSpec Spec(TableKind table, ModelKind kind,
              IntegratorKind integrator = IntegratorKind::kQuadrature, bool simd = true) {
  BakeSpec spec;
  spec.table = table;
  spec.model.kind = kind;
  spec.integrator = integrator;
  spec.simd = simd;
  return spec;
}

BakeSpec Std(TableKind table, double gamma, IntegratorKind integrator = IntegratorKind::kQuadrature,
             bool simd = true) {
  BakeSpec spec = Spec(table, ModelKind::kStudentT, integrator, simd);
  spec.model.gamma = gamma;
  return spec;
}

// One ellipsoid material: alpha 0.3 x 0.6, theta_x 20, theta_z 30 degrees;
// E over mu x phi_o in [0, 2 pi].
BakeSpec Ellipsoid(TableKind table) {
  BakeSpec spec = Spec(table, ModelKind::kEllipsoid);
  spec.model.alpha_x = 0.3;
  spec.model.alpha_y = 0.6;
  spec.model.theta_x = 20 * 3.14159265358979323846 / 180;
  spec.model.theta_z = 30 * 3.14159265358979323846 / 180;
  spec.phi.max = 2 * 3.14159265358979323846;
  return spec;
}

void Add(const std::string& model, const BakeSpec& spec, std::vector<std::string> axes,
         const std::vector<std::vector<int64_t>>& args, double reference_tolerance = 1e-10) {
  axes.push_back("threads");
  const std::string name = std::string("BM_Bake/") + TableName(spec.table) + "/" + model + "/" +
                           IntegratorName(spec.integrator) + "/" +
                           (spec.simd ? "simd" : "double_reference");
  benchmark::internal::Benchmark* b =
      benchmark::RegisterBenchmark(name.c_str(), BM_Bake, BakeRow{spec, axes, reference_tolerance});
  b->ArgNames(axes)->Unit(benchmark::kMillisecond)->UseRealTime();
  for (const std::vector<int64_t>& a : args) b->Args(a);
}

[[maybe_unused]] const int kRegistered = [] {
  using I = IntegratorKind;
  using T = TableKind;
  const ModelKind ggx = ModelKind::kGgx, beckmann = ModelKind::kBeckmann;
  const std::vector<std::string> size{"size"};
  const int64_t c = std::max(1u, std::thread::hardware_concurrency());
  // The quadrature in SIMD lanes on every core, and on 1 for the scaling.
  std::vector<std::vector<int64_t>> dfg_ggx{{32, c}, {128, c}}, e_beckmann{{32, c}};
  if (c > 1) {
    dfg_ggx.push_back({128, 1});
    e_beckmann.push_back({32, 1});
  }
  Add("ggx", Spec(T::kE, ggx), size, {{32, c}, {128, c}});
  Add("ggx", Spec(T::kEavg, ggx), size, {{128, c}});
  Add("ggx", Spec(T::kDfg, ggx), size, dfg_ggx);
  Add("beckmann", Spec(T::kE, beckmann), size, e_beckmann);
  Add("beckmann", Spec(T::kEavg, beckmann), size, {{128, c}});
  Add("beckmann", Spec(T::kDfg, beckmann), size, {{32, c}});
  for (const auto& [label, gamma] : std::vector<std::pair<const char*, double>>{
           {"std_gamma1.501", 1.501}, {"std_gamma1.6", 1.6}, {"std_gamma3", 3},
           {"std_gamma30", 30}, {"std_gamma_inf", kInfinity}}) {
    Add(label, Std(T::kE, gamma), size, {{32, c}});
  }
  for (const auto& [label, gamma] : std::vector<std::pair<const char*, double>>{
           {"std_gamma1.501", 1.501}, {"std_gamma3", 3}, {"std_gamma30", 30}}) {
    Add(label, Std(T::kEavg, gamma), size, {{128, c}});
  }
  // std over its gamma axis (1.501 to inf, the tail warp).
  Add("std_gamma_axis", Std(T::kE, 2), {"size", "gammas"}, {{32, 16, c}});
  Add("std_gamma_axis", Std(T::kEavg, 2), {"size", "gammas"}, {{32, 16, c}});
  // ggx-aniso: its default E table, a smaller one that the double reference
  // bakes too, and E_avg; no true error (no reference bake of these tables).
  const std::vector<std::string> aniso_e{"mu", "phi", "roughness", "anisotropy"};
  Add("ggx-aniso", Spec(T::kE, ModelKind::kGgxAniso), aniso_e,
      {{32, 16, 32, 16, c}, {32, 16, 32, 4, c}}, 0);
  Add("ggx-aniso", Spec(T::kEavg, ModelKind::kGgxAniso), {"roughness", "anisotropy"}, {{8, 4, c}},
      0);
  Add("ellipsoid", Ellipsoid(T::kE), {"mu", "phi"}, {{64, 64, c}});
  Add("ellipsoid", Ellipsoid(T::kEavg), {}, {{c}});
  Add("sel", Spec(T::kSelNorm, ModelKind::kSel), {"alpha_x", "alpha_y"}, {{32, 32, c}});
#if BRDFBAKE_WITH_CHARLIE
  // The sheen: E with either visibility, and E_avg.
  BakeSpec neubelt = Spec(T::kE, ModelKind::kCharlie);
  neubelt.model.visibility = SheenVisibility::kNeubelt;
  Add("charlie_neubelt", neubelt, size, {{64, c}});
  Add("charlie_conty-kulla", Spec(T::kE, ModelKind::kCharlie), size, {{64, c}});
  Add("charlie_conty-kulla", Spec(T::kEavg, ModelKind::kCharlie), size, {{32, c}});
#endif
#if BRDFBAKE_WITH_DISNEY
  Add("disney-diffuse", Spec(T::kE, ModelKind::kDisneyDiffuse), size, {{64, c}});
#endif
#if BRDFBAKE_WITH_GLASS
  // ggx-glass: the four tables of Cycles' set on its axes (16 entries each,
  // mu and roughness clamped at 1e-4, ior from 1 to 99.5 = z 0 to 0.99 with
  // the fresnel-z warp; inverse: eta = 1 / ior), and a 32^3 E over the
  // default ior range 1 to 3; no true error (no reference bake of these).
  // Each ray piece's nodes in lanes (src/lanes/glass_lanes.cc): simd.
  for (bool inverse : {false, true}) {
    for (T table : {T::kE, T::kEavg}) {
      BakeSpec cycles = Spec(table, ModelKind::kGgxGlass, I::kQuadrature);
      cycles.inverse = inverse;
      cycles.mu.clamp_min = cycles.roughness.clamp_min = 1e-4;
      cycles.ior.max = (1 + 0.99 * 0.99) / (1 - 0.99 * 0.99);
      const std::string label = inverse ? "ggx-glass_cycles_inverse" : "ggx-glass_cycles";
      if (table == T::kE) {
        Add(label, cycles, {"size", "iors"}, {{16, 16, c}}, 0);
      } else {
        Add(label, cycles, {"roughness", "iors"}, {{16, 16, c}}, 0);
      }
    }
  }
  Add("ggx-glass", Spec(T::kE, ModelKind::kGgxGlass, I::kQuadrature), {"size", "iors"},
      {{32, 32, c}}, 0);
#endif

  // The double scalar reference of the same rules.
  Add("ggx", Spec(T::kDfg, ggx, I::kQuadrature, false), size, {{128, c}});
  Add("beckmann", Spec(T::kE, beckmann, I::kQuadrature, false), size, {{32, c}});
  Add("std_gamma3", Std(T::kE, 3, I::kQuadrature, false), size, {{32, c}});
  Add("ggx-aniso", Spec(T::kE, ModelKind::kGgxAniso, I::kQuadrature, false), aniso_e,
      {{32, 16, 32, 4, c}}, 0);
  Add("sel", Spec(T::kSelNorm, ModelKind::kSel, I::kQuadrature, false), {"alpha_x", "alpha_y"},
      {{32, 32, c}});
#if BRDFBAKE_WITH_GLASS
  BakeSpec glass_ref = Spec(T::kE, ModelKind::kGgxGlass, I::kQuadrature, false);
  glass_ref.mu.clamp_min = glass_ref.roughness.clamp_min = 1e-4;
  glass_ref.ior.max = (1 + 0.99 * 0.99) / (1 - 0.99 * 0.99);
  Add("ggx-glass_cycles", glass_ref, {"size", "iors"}, {{16, 16, c}}, 0);
#endif

  // The sampling integrators, their points in lanes or in the reference.
  for (I integrator : {I::kQmc, I::kEngine}) {
    for (bool simd : {true, false}) {
      Add("ggx", Spec(T::kE, ggx, integrator, simd), size, {{32, c}});
      Add("beckmann", Spec(T::kE, beckmann, integrator, simd), size, {{32, c}});
      Add("std_gamma3", Std(T::kE, 3, integrator, simd), size, {{32, c}});
    }
  }
  return 0;
}();

}  // namespace
}  // namespace brdfbake
