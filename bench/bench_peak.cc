// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The machine's own limits, per target, for the hardware-limit analysis
// of docs/performance.md: lane-operations per second of fused multiply-add, division,
// square root and approximate reciprocal square root, each as 12 independent
// dependency chains (enough to cover the latency of every unit), so the
// figure is the unit's throughput (BM_Peak/<op>/<TARGET>); and each BRDF
// kernel against a synthetic loop of its own operation mix
// (BM_Limit/<model>/AVX3).

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "brdfbake/batch.h"
#include "brdfbake/targets.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "bench/bench_peak.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

enum PeakOp { kFma, kDiv, kSqrt, kRsqrt };
// Independent chains: 12 cover a 4-cycle FMA latency at two per cycle with
// room to spare, and still fit the 32 AVX-512 registers (16 on AVX2).
constexpr int kChains = 12;

// (Not MixRun below with one kind: MixRun's runtime-count inner loops put
// scalar branch work on the FMA ports and measured the FMA peak 40% low.)
// Runs `iters` rounds of the op on kChains chains; returns a checksum (so the work
// is kept) and the lanes per vector in *lanes.
float PeakRun(int op, int64_t iters, size_t* lanes) {
  using D = hn::ScalableTag<float>;
  const D d;
  *lanes = hn::Lanes(d);
  // Named variables, not an array: GCC keeps them in registers.
  hn::Vec<D> v0 = hn::Set(d, 1.10f), v1 = hn::Set(d, 1.15f), v2 = hn::Set(d, 1.20f),
             v3 = hn::Set(d, 1.25f), v4 = hn::Set(d, 1.30f), v5 = hn::Set(d, 1.35f),
             v6 = hn::Set(d, 1.40f), v7 = hn::Set(d, 1.45f), v8 = hn::Set(d, 1.50f),
             v9 = hn::Set(d, 1.55f), v10 = hn::Set(d, 1.60f), v11 = hn::Set(d, 1.65f);
  const auto a = hn::Set(d, 0.999f), b = hn::Set(d, 1e-3f), one = hn::Set(d, 1.0f);
  // Each op maps a bounded positive value to a bounded positive value.
  auto step = [&](hn::Vec<D> v) {
    switch (op) {
      case kFma: return hn::MulAdd(v, a, b);
      case kDiv: return hn::Div(one, v);
      case kSqrt: return hn::Sqrt(v);
      default: return hn::ApproximateReciprocalSqrt(v);
    }
  };
  for (int64_t i = 0; i < iters; ++i) {
    v0 = step(v0); v1 = step(v1); v2 = step(v2); v3 = step(v3);
    v4 = step(v4); v5 = step(v5); v6 = step(v6); v7 = step(v7);
    v8 = step(v8); v9 = step(v9); v10 = step(v10); v11 = step(v11);
  }
  const auto sum = hn::Add(hn::Add(hn::Add(hn::Add(v0, v1), hn::Add(v2, v3)),
                                   hn::Add(hn::Add(v4, v5), hn::Add(v6, v7))),
                           hn::Add(hn::Add(v8, v9), hn::Add(v10, v11)));
  return hn::GetLane(sum);
}

// The binding limit of a kernel, measured: `iters` rounds of a synthetic
// evaluation with the kernel's count of FMA-pipe operations, divisions,
// square roots and approximate reciprocal square roots, on kChains
// independent vectors with the operations of the chains interleaved (the
// best schedule there is: every unit busy, no dependency stalls). Returns a
// checksum; *lanes as PeakRun.
float MixRun(int n_fma, int n_div, int n_sqrt, int n_rsqrt, int64_t iters, size_t* lanes) {
  using D = hn::ScalableTag<float>;
  const D d;
  *lanes = hn::Lanes(d);
  hn::Vec<D> v0 = hn::Set(d, 1.10f), v1 = hn::Set(d, 1.15f), v2 = hn::Set(d, 1.20f),
             v3 = hn::Set(d, 1.25f), v4 = hn::Set(d, 1.30f), v5 = hn::Set(d, 1.35f),
             v6 = hn::Set(d, 1.40f), v7 = hn::Set(d, 1.45f), v8 = hn::Set(d, 1.50f),
             v9 = hn::Set(d, 1.55f), v10 = hn::Set(d, 1.60f), v11 = hn::Set(d, 1.65f);
  const auto a = hn::Set(d, 0.999f), b = hn::Set(d, 1e-3f), one = hn::Set(d, 1.0f);
#define BRDFBAKE_ALL(expr)                                                          \
  v0 = expr(v0); v1 = expr(v1); v2 = expr(v2); v3 = expr(v3); v4 = expr(v4);       \
  v5 = expr(v5); v6 = expr(v6); v7 = expr(v7); v8 = expr(v8); v9 = expr(v9);       \
  v10 = expr(v10); v11 = expr(v11)
  const auto fma = [&](hn::Vec<D> v) { return hn::MulAdd(v, a, b); };
  const auto div = [&](hn::Vec<D> v) { return hn::Div(one, v); };
  const auto sqrt = [&](hn::Vec<D> v) { return hn::Sqrt(v); };
  const auto rsqrt = [&](hn::Vec<D> v) { return hn::ApproximateReciprocalSqrt(v); };
  // The FMAs are spread in equal blocks between the other operations, so
  // that the out-of-order window always holds work for both the divider and
  // the FMA ports (in program-order phases the two would not overlap).
  const int specials = n_div + n_sqrt + n_rsqrt;
  for (int64_t i = 0; i < iters; ++i) {
    for (int b = 0; b <= specials; ++b) {
      const int block = n_fma / (specials + 1) + (b < n_fma % (specials + 1) ? 1 : 0);
      for (int j = 0; j < block; ++j) { BRDFBAKE_ALL(fma); }
      if (b == specials) break;
      if (b < n_div) {
        BRDFBAKE_ALL(div);
      } else if (b < n_div + n_sqrt) {
        BRDFBAKE_ALL(sqrt);
      } else {
        BRDFBAKE_ALL(rsqrt);
      }
    }
  }
#undef BRDFBAKE_ALL
  const auto sum = hn::Add(hn::Add(hn::Add(hn::Add(v0, v1), hn::Add(v2, v3)),
                                   hn::Add(hn::Add(v4, v5), hn::Add(v6, v7))),
                           hn::Add(hn::Add(v8, v9), hn::Add(v10, v11)));
  return hn::GetLane(sum);
}

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace brdfbake {
namespace {

constexpr int kLimitN = 16384;

HWY_EXPORT(PeakRun);
HWY_EXPORT(MixRun);

// A kernel against its own binding limit, alternating the two in every
// iteration so that both see the same clock (this machine's speed drifts by
// tens of percent between runs). The operation counts per vector are those
// of the AVX3 loop bodies (objdump of the Schlick, height-correlated rows:
// vector arithmetic, compares and blends counted as FMA-pipe operations;
// loads and stores run on other ports).
struct KernelMix {
  const char* name;
  int fma, div, sqrt, rsqrt;
  void (*run)(const std::vector<float>* in, std::vector<float>* out);
};

std::vector<std::vector<float>>& LimitInputs() {
  static std::vector<std::vector<float>> in = [] {
    std::vector<std::vector<float>> v(6, std::vector<float>(kLimitN));
    uint64_t x = 88172645463325252ull;
    auto uni = [&] {
      x ^= x << 13; x ^= x >> 7; x ^= x << 17;
      return (x >> 11) * 0x1.0p-53;
    };
    for (int i = 0; i < kLimitN; ++i) {
      for (int w = 0; w < 2; ++w) {
        const double mu = 0.02 + 0.98 * uni(), phi = 6.283185307179586 * uni();
        const double s = std::sqrt(1 - mu * mu);
        v[3 * w][i] = float(s * std::cos(phi));
        v[3 * w + 1][i] = float(s * std::sin(phi));
        v[3 * w + 2][i] = float(mu);
      }
    }
    return v;
  }();
  return in;
}

// The benchmark's time is the kernel's alone (manual timing): each
// iteration also runs the synthetic op-mix loop, and timing both would
// report an items_per_second that is neither rate. items_per_second is the
// kernel's BRDF evaluations per second; op_mix_items_per_second the
// evaluations per second the op-mix loop would allow (its lanes through
// one kernel's worth of operations); kernel_over_op_mix their ratio; the
// *_ops counters the operation counts of the mix.
void BM_Limit(benchmark::State& state, KernelMix k, std::string target) {
  ForceTarget(target);
  const std::vector<std::vector<float>>& in = LimitInputs();
  std::vector<float> out(kLimitN);
  size_t lanes = 1;
  double t_kernel = 0, t_limit = 0;
  // One mix round is 12 vectors of 16 lanes: about as many evaluations as
  // the kernel's 16384, so that the two halves take similar times.
  const int64_t mix_iters = (kLimitN + 12 * 16 - 1) / (12 * 16);
  int64_t kernel_evals = 0, limit_evals = 0;
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    k.run(in.data(), &out);
    const auto t1 = std::chrono::steady_clock::now();
    benchmark::DoNotOptimize(HWY_DYNAMIC_DISPATCH(MixRun)(k.fma, k.div, k.sqrt, k.rsqrt,
                                                           mix_iters, &lanes));
    const auto t2 = std::chrono::steady_clock::now();
    const double kernel_seconds = std::chrono::duration<double>(t1 - t0).count();
    state.SetIterationTime(kernel_seconds);
    t_kernel += kernel_seconds;
    t_limit += std::chrono::duration<double>(t2 - t1).count();
    kernel_evals += kLimitN;
    limit_evals += mix_iters * 12 * static_cast<int64_t>(lanes);
  }
  ForceTarget("best");
  const double kernel_rate = kernel_evals / t_kernel, limit_rate = limit_evals / t_limit;
  state.counters["op_mix_items_per_second"] = limit_rate;
  state.counters["kernel_over_op_mix"] = kernel_rate / limit_rate;
  state.counters["fma_ops"] = k.fma;
  state.counters["div_ops"] = k.div;
  state.counters["sqrt_ops"] = k.sqrt;
  state.counters["rsqrt_ops"] = k.rsqrt;
  state.SetItemsProcessed(kernel_evals);
}

void BM_Peak(benchmark::State& state, int op, std::string target) {
  ForceTarget(target);
  const int64_t iters = 1 << 16;
  size_t lanes = 1;
  for (auto _ : state) {
    benchmark::DoNotOptimize(HWY_DYNAMIC_DISPATCH(PeakRun)(op, iters, &lanes));
  }
  ForceTarget("best");
  // Items: lane-operations.
  state.SetItemsProcessed(state.iterations() * iters * 12 * static_cast<int64_t>(lanes));
}

const int kRegistered = [] {
  static const KernelMix kMixes[] = {
      {"ggx", 47, 1, 2, 1,
       [](const std::vector<float>* v, std::vector<float>* o) {
         BatchModel p{ModelKind::kGgx};
         p.alpha_x = p.alpha_y = 0.3f;
         p.f0 = 0.04f;
         EvalBatch(p, Quantity::kBrdf, {v[0].data(), v[1].data(), v[2].data()},
                   {v[3].data(), v[4].data(), v[5].data()}, o->data(), o->size());
       }},
      {"beckmann", 201, 4, 0, 3,
       [](const std::vector<float>* v, std::vector<float>* o) {
         BatchModel p{ModelKind::kBeckmann};
         p.alpha_x = p.alpha_y = 0.3f;
         p.f0 = 0.04f;
         EvalBatch(p, Quantity::kBrdf, {v[0].data(), v[1].data(), v[2].data()},
                   {v[3].data(), v[4].data(), v[5].data()}, o->data(), o->size());
       }},
      {"std", 537, 12, 2, 33,
       [](const std::vector<float>* v, std::vector<float>* o) {
         BatchModel p{ModelKind::kStudentT};
         p.alpha_x = p.alpha_y = 0.3f;
         p.gamma = 3.3f;
         p.f0 = 0.04f;
         EvalBatch(p, Quantity::kBrdf, {v[0].data(), v[1].data(), v[2].data()},
                   {v[3].data(), v[4].data(), v[5].data()}, o->data(), o->size());
       }},
      {"ellipsoid", 164, 1, 2, 1,
       [](const std::vector<float>* v, std::vector<float>* o) {
         BatchModel p{ModelKind::kEllipsoid};
         p.alpha_x = 0.3f;
         p.alpha_y = 0.5f;
         p.theta_x = 0.2f;
         p.theta_y = 0.1f;
         p.theta_z = 0.4f;
         p.f0 = 0.04f;
         EvalBatch(p, Quantity::kBrdf, {v[0].data(), v[1].data(), v[2].data()},
                   {v[3].data(), v[4].data(), v[5].data()}, o->data(), o->size());
       }}};
  const std::vector<std::string> targets = AvailableTargets();
  const bool avx3 = std::find(targets.begin(), targets.end(), "AVX3") != targets.end();
  for (const KernelMix& k : kMixes) {
    if (!avx3) break;  // the counts are those of the AVX3 code
    benchmark::RegisterBenchmark(("BM_Limit/" + std::string(k.name) + "/AVX3").c_str(),
                                 BM_Limit, k, std::string("AVX3"))
        ->UseManualTime();
  }
  const char* names[] = {"fma", "div", "sqrt", "rsqrt"};
  for (const std::string& t : AvailableTargets()) {
    for (int op = 0; op < 4; ++op) {
      benchmark::RegisterBenchmark(("BM_Peak/" + std::string(names[op]) + "/" + t).c_str(),
                                   BM_Peak, op, t);
    }
  }
  return 0;
}();

}  // namespace
}  // namespace brdfbake
#endif  // HWY_ONCE
