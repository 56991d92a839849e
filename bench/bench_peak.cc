// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The machine's own limits, per target, for the README's hardware-limit
// analysis: lane-operations per second of fused multiply-add, division,
// square root and approximate reciprocal square root, each as 12 independent
// dependency chains (enough to cover the latency of every unit), so the
// figure is the unit's throughput. Names: BM_Peak/<op>/<TARGET>.

#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "brdfbake/batch.h"

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

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace brdfbake {
namespace {

HWY_EXPORT(PeakRun);

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
