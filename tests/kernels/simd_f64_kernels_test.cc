// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The GGX kernels of src/kernels/ggx-inl.h instantiated for double lanes (the
// same source as the float batch kernels) against the double scalar
// reference (GgxNdf<double>, Brdf) on every compiled target: D, Lambda, G1,
// G2 and the BRDF (F = 1 and Schlick, both maskings) over alpha 1e-4 to 1,
// anisotropy 1000:1 and directions down to mu = 1e-6. Each check asserts a
// bound and prints the observed maximum.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "brdfbake/models/beckmann.h"
#include "brdfbake/models/brdf.h"
#include "brdfbake/models/fresnel.h"
#include "brdfbake/models/ggx.h"
#include "brdfbake/models/std_ndf.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "tests/kernels/simd_f64_kernels_test.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>
#include <hwy/tests/hwy_gtest.h>

#include "kernels/beckmann-inl.h"
#include "kernels/ggx-inl.h"
#if BRDFBAKE_WITH_STD
#include "kernels/std-inl.h"
#endif

#ifndef BRDFBAKE_TESTS_SIMD_F64_KERNELS_TEST_ONCE_
#define BRDFBAKE_TESTS_SIMD_F64_KERNELS_TEST_ONCE_
namespace brdfbake {
namespace ggx_f64_test {

// Unit vectors as double arrays: mu uniform, log-uniform down to 1e-6, and
// the pole now and then; `below` puts every 11th under the horizon.
struct Dirs64 {
  std::vector<double> x, y, z;
  Vec3<double> At(size_t i) const { return {x[i], y[i], z[i]}; }
};
inline Dirs64 MakeDirs(size_t n, uint64_t seed, bool below) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  Dirs64 d;
  for (size_t i = 0; i < n; ++i) {
    double mu = i % 5 == 0 ? std::pow(10.0, -6 * uni(rng)) : uni(rng);
    if (i % 97 == 0) mu = 1.0;
    if (below && i % 11 == 0) mu = -uni(rng);
    const Vec3<double> w = FromMuPhi(mu, 2 * 3.141592653589793 * uni(rng));
    d.x.push_back(w.x);
    d.y.push_back(w.y);
    d.z.push_back(w.z);
  }
  return d;
}

// |got - ref| relative to max(|ref|, floor); 0 when both are infinite.
inline double RelTo(double got, double ref, double floor) {
  if (std::isinf(ref)) return std::isinf(got) ? 0.0 : 1.0;
  return std::abs(got - ref) / std::max(std::abs(ref), floor);
}

constexpr float kAlphas[][2] = {{1e-4f, 1e-4f}, {1e-3f, 1e-3f}, {0.05f, 0.05f}, {0.3f, 0.3f},
                                {1.0f, 1.0f},   {1.0f, 1e-3f},  {2e-3f, 0.8f}};

// Bounds against the double reference at the same inputs: D and the BRDF
// relative, Lambda relative to max(1, Lambda) (its form differs from the
// reference's; both are a few ulps), G relative.
constexpr double kDRel = 1e-14, kLambdaRel = 1e-14, kGRel = 1e-14, kBrdfRel = 1e-14;
// Beckmann and STD: relative error of D and the BRDF per unit of the
// exponent E of their exp(-E) (r2 for Beckmann).
constexpr double kExpSlope = 2e-15;

}  // namespace ggx_f64_test
}  // namespace brdfbake
#endif  // BRDFBAKE_TESTS_SIMD_F64_KERNELS_TEST_ONCE_

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace {

namespace hn = hwy::HWY_NAMESPACE;
using namespace ggx_f64_test;
using DD = hn::ScalableTag<double>;

// out[i] = k(d, a..., b...) over whole vectors of n (padded with the pole).
template <class K>
std::vector<double> Run(const Dirs64& a, const Dirs64& b, const K& k) {
  const DD d;
  const size_t N = hn::Lanes(d), n = a.x.size();
  const size_t padded = (n + N - 1) / N * N;
  auto pad = [&](const std::vector<double>& v, double fill) {
    std::vector<double> p(v);
    p.resize(padded, fill);
    return p;
  };
  const std::vector<double> ax = pad(a.x, 0), ay = pad(a.y, 0), az = pad(a.z, 1);
  const std::vector<double> bx = pad(b.x, 0), by = pad(b.y, 0), bz = pad(b.z, 1);
  std::vector<double> out(padded);
  for (size_t i = 0; i < padded; i += N) {
    hn::StoreU(k(d, hn::LoadU(d, &ax[i]), hn::LoadU(d, &ay[i]), hn::LoadU(d, &az[i]),
                 hn::LoadU(d, &bx[i]), hn::LoadU(d, &by[i]), hn::LoadU(d, &bz[i])),
               d, &out[i]);
  }
  out.resize(n);
  return out;
}

}  // namespace

// One model's kernels in double lanes against its double scalar reference.
// D and the BRDF are allowed rel + slope r2, r2 the exponent of a Beckmann
// D (0 for GGX): exp(-r2) turns the rounding of r2 into a relative error.
template <template <class> class Kernels, class MakeNdf, class MakeConsts, class Exponent>
void CheckF64(const char* name, double slope, const MakeNdf& make_ndf,
              const MakeConsts& make_consts, const Exponent& exponent_of) {
  const size_t n = 20000;
  const Dirs64 wi = MakeDirs(n, 51, true), wo = MakeDirs(n, 52, false);
  double worst_d = 0, worst_l = 0, worst_g = 0, worst_f = 0;
  for (const auto& a : kAlphas) {
    const auto ndf = make_ndf(a[0], a[1]);
    const auto c = make_consts(a[0], a[1], 1.0);
    const Kernels<DD> k{c};
    const auto lambda = [&](auto x, auto y, auto z) { return k.Lambda(DD(), x, y, z); };
    const std::vector<double> dv =
        Run(wi, wo,
            [&](auto d, auto x, auto y, auto z, auto, auto, auto) { return k.Ndf(d, x, y, z); });
    const std::vector<double> lv =
        Run(wi, wo,
            [&](auto d, auto x, auto y, auto z, auto, auto, auto) { return k.Lambda(d, x, y, z); });
    const std::vector<double> g1 =
        Run(wi, wo, [&](auto d, auto x, auto y, auto z, auto, auto, auto) {
          return G1FromLambda(d, lambda, x, y, z);
        });
    auto r2_of = [&](const Vec3<double>& m) {
      const double sx = m.x / std::max<double>(a[0], 1e-4), sy = m.y / std::max<double>(a[1], 1e-4);
      return exponent_of((sx * sx + sy * sy) / (m.z * m.z));
    };
    for (size_t i = 0; i < n; ++i) {
      const Vec3<double> w = wi.At(i);
      const double rd = w.z > 0 ? ndf.D(w) : 0.0;
      const double r2 = w.z > 0 ? r2_of(w) : 0.0;
      // Where exp(-E) leaves the normal doubles (E > 700: past Beckmann's cut
      // BeckmannMaxR2 D is 0, and a subnormal exp(-E) keeps only an absolute
      // accuracy) the relative bound does not apply.
      const double ed =
          slope > 0 && r2 > 700 ? 0.0 : RelTo(dv[i], rd, 1e-300) / (kDRel + slope * r2);
      worst_d = std::max(worst_d, ed);
      ASSERT_LE(ed, 1.0) << name << " D alpha " << a[0] << "," << a[1] << " i " << i << " got "
                         << dv[i] << " ref " << rd;
      const double rl = ndf.Lambda(w);
      const double el = RelTo(lv[i], rl, 1.0);
      worst_l = std::max(worst_l, el);
      ASSERT_LE(el, kLambdaRel) << name << " Lambda alpha " << a[0] << "," << a[1] << " i " << i;
      const double eg = RelTo(g1[i], ndf.G1(w), 1e-300);
      worst_g = std::max(worst_g, eg);
      ASSERT_LE(eg, kGRel) << name << " G1 i " << i;
    }
    for (Masking masking : {Masking::kHeightCorrelated, Masking::kSeparable}) {
      const bool sep = masking == Masking::kSeparable;
      const std::vector<double> g2 =
          Run(wi, wo, [&](auto d, auto ix, auto iy, auto iz, auto ox, auto oy, auto oz) {
            return G2FromLambda(d, sep, lambda, ix, iy, iz, ox, oy, oz);
          });
      for (double f0 : {1.0, 0.04}) {
        const auto cf = make_consts(a[0], a[1], f0);
        const Kernels<DD> kf{cf};
        const SchlickFresnel<DD> fresnel{hn::Set(DD(), f0)};
        const std::vector<double> fv =
            Run(wi, wo, [&](auto d, auto ix, auto iy, auto iz, auto ox, auto oy, auto oz) {
              return kf.Brdf(d, sep, ix, iy, iz, ox, oy, oz, fresnel);
            });
        const Fresnel fr = Fresnel::Schlick({f0, f0, f0});
        for (size_t i = 0; i < n; ++i) {
          const Vec3<double> a_i = wi.At(i), b_i = wo.At(i);
          const double rf = Brdf(ndf, fr, a_i, b_i, masking);
          Vec3<double> h;
          const bool has_h = HalfVector(a_i, b_i, &h);
          const double r2h = has_h && h.z > 0 ? r2_of(h) : 0.0;
          const double ef =
              slope > 0 && r2h > 700 ? 0.0 : RelTo(fv[i], rf, 1e-300) / (kBrdfRel + slope * r2h);
          worst_f = std::max(worst_f, ef);
          ASSERT_LE(ef, 1.0) << name << " BRDF alpha " << a[0] << "," << a[1] << " f0 " << f0
                             << " i " << i << " got " << fv[i] << " ref " << rf;
          if (f0 != 1.0 || !(a_i.z > 0)) continue;
          const double rg = has_h ? G2(ndf, a_i, b_i, h, masking) : 0.0;
          const double eg = RelTo(g2[i], rg, 1e-300);
          worst_g = std::max(worst_g, eg);
          ASSERT_LE(eg, kGRel) << name << " G2 i " << i << " got " << g2[i] << " ref " << rg;
        }
      }
    }
  }
  std::printf(
      "%s: %s in double lanes, max error / bound: D %.3g, BRDF %.3g; max rel error "
      "Lambda %.3g, G1/G2 %.3g (bounds %.0e + %.0e r2, %.0e + %.0e r2, %.0e, %.0e)\n",
      hwy::TargetName(HWY_TARGET), name, worst_d, worst_f, worst_l, worst_g, kDRel, slope, kBrdfRel,
      slope, kLambdaRel, kGRel);
}

void CheckGgxF64AgainstScalar() {
  CheckF64<GgxKernels>(
      "GGX", 0.0, [](double ax, double ay) { return GgxNdf<double>(ax, ay); },
      [](double ax, double ay, double f0) { return GgxConsts<DD>(DD(), ax, ay, f0); },
      [](double r2) { return r2; });
}

void CheckBeckmannF64AgainstScalar() {
  CheckF64<BeckmannKernels>(
      "Beckmann", kExpSlope, [](double ax, double ay) { return BeckmannNdf<double>(ax, ay); },
      [](double ax, double ay, double f0) { return BeckmannConsts<DD>(DD(), ax, ay, f0); },
      [](double r2) { return r2; });
}

#if BRDFBAKE_WITH_STD
void CheckStudentTF64AgainstScalar() {
  for (double gamma : {1.501, 1.6, 2.0, 3.0, 7.5, 30.0, 1e4, 1e6}) {
    char name[32];
    std::snprintf(name, sizeof(name), "STD gamma %g", gamma);
    CheckF64<StudentTKernels>(
        name, kExpSlope,
        [gamma](double ax, double ay) { return StudentTNdf<double>(ax, ay, gamma); },
        [gamma](double ax, double ay, double f0) {
          return StudentTConsts<DD>(DD(), ax, ay, f0, gamma);
        },
        // The exponent E = gamma log1p(r2 / (gamma - 1)) of exp(-E).
        [gamma](double r2) { return gamma * std::log1p(r2 / (gamma - 1)); });
  }
}
#endif  // BRDFBAKE_WITH_STD

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace brdfbake {
HWY_BEFORE_TEST(SimdF64KernelsTest);
HWY_EXPORT_AND_TEST_P(SimdF64KernelsTest, CheckGgxF64AgainstScalar);
HWY_EXPORT_AND_TEST_P(SimdF64KernelsTest, CheckBeckmannF64AgainstScalar);
#if BRDFBAKE_WITH_STD
HWY_EXPORT_AND_TEST_P(SimdF64KernelsTest, CheckStudentTF64AgainstScalar);
#endif
}  // namespace brdfbake
#endif
