// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Google Benchmark suite. Names carry the model, the quantity and the
// implementation, e.g. BM_Brdf/ggx/scalar: evaluations per second of the
// double-precision scalar reference, one evaluation per call.

#include <cmath>
#include <random>
#include <vector>

#include <benchmark/benchmark.h>

#include "brdfbake/beckmann.h"
#include "brdfbake/brdf.h"
#include "brdfbake/ellipsoid.h"
#include "brdfbake/ggx.h"
#include "brdfbake/std_ndf.h"

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
Vec3<double> PseudoVnis(const StdNdf<double>& ndf, const Vec3<double>& w, double u1, double u2) {
  return ndf.SamplePseudoVnis(w, u1, u2);
}

BENCHMARK_CAPTURE(BM_D, ggx/scalar, GgxNdf<double>(0.3, 0.3));
BENCHMARK_CAPTURE(BM_D, beckmann/scalar, BeckmannNdf<double>(0.3, 0.3));
BENCHMARK_CAPTURE(BM_D, std/scalar, StdNdf<double>(0.3, 0.3, 3.3));
BENCHMARK_CAPTURE(BM_D, ellipsoid/scalar, EllipsoidNdf<double>(0.3, 0.5, 0.2, 0.1, 0.4));
BENCHMARK_CAPTURE(BM_G2, ggx/scalar, GgxNdf<double>(0.3, 0.3));
BENCHMARK_CAPTURE(BM_G2, beckmann/scalar, BeckmannNdf<double>(0.3, 0.3));
BENCHMARK_CAPTURE(BM_G2, std/scalar, StdNdf<double>(0.3, 0.3, 3.3));
BENCHMARK_CAPTURE(BM_G2, ellipsoid/scalar, EllipsoidNdf<double>(0.3, 0.5, 0.2, 0.1, 0.4));
BENCHMARK_CAPTURE(BM_Brdf, ggx/scalar, GgxNdf<double>(0.3, 0.3));
BENCHMARK_CAPTURE(BM_Brdf, beckmann/scalar, BeckmannNdf<double>(0.3, 0.3));
BENCHMARK_CAPTURE(BM_Brdf, std/scalar, StdNdf<double>(0.3, 0.3, 3.3));
BENCHMARK_CAPTURE(BM_Brdf, ellipsoid/scalar, EllipsoidNdf<double>(0.3, 0.5, 0.2, 0.1, 0.4));
BENCHMARK_CAPTURE(BM_Sample, ggx/scalar, GgxNdf<double>(0.3, 0.3), Visible<GgxNdf<double>>);
BENCHMARK_CAPTURE(BM_Sample, beckmann/scalar, BeckmannNdf<double>(0.3, 0.3),
                  Visible<BeckmannNdf<double>>);
BENCHMARK_CAPTURE(BM_Sample, std/scalar, StdNdf<double>(0.3, 0.3, 3.3), PseudoVnis);
BENCHMARK_CAPTURE(BM_Sample, ellipsoid/scalar, EllipsoidNdf<double>(0.3, 0.5, 0.2, 0.1, 0.4),
                  Visible<EllipsoidNdf<double>>);

}  // namespace
}  // namespace brdfbake

BENCHMARK_MAIN();
