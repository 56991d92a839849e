// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The rough dielectric kernel (kernels/dielectric-inl.h) against
// RoughDielectric<double> at the same float inputs, on every compiled
// target: the batch function in float lanes and the same kernel in double
// lanes, over random pairs on the whole sphere and the stiff corners (alpha
// 1e-4 at the peaks, grazing directions, eta within 1e-4 of 1, eta < 1 at
// the critical angle), with the bounds of dielectric-inl.h; and the batch
// function's checks, counts and tails.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>
#include <vector>

#include "brdfbake/batch.h"
#include "brdfbake/config.h"
#include "brdfbake/models/beckmann.h"
#include "brdfbake/models/dielectric.h"
#include "brdfbake/models/ggx.h"
#include "util/simd_test_util.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "tests/kernels/simd_dielectric_test.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>
#include <hwy/tests/hwy_gtest.h>

#include "kernels/dielectric-inl.h"

#ifndef BRDFBAKE_SIMD_DIELECTRIC_TEST_ONCE_
#define BRDFBAKE_SIMD_DIELECTRIC_TEST_ONCE_
namespace brdfbake {
namespace test {

// Pairs (wi, wo) for the interface of index eta below: random on the
// sphere, grazing, and (one in three) wi near the reflection or refraction
// of wo, off by a few alpha; for eta < 1 some views sit at the critical
// angle.
struct Pairs {
  Dirs wi, wo;
};

inline Vec3<double> Refracted(const Vec3<double>& wo, double eta) {
  // Through the macro normal, from wo's side into the other.
  const double e = wo.z > 0 ? eta : 1 / eta;
  const double c = std::abs(wo.z);
  const double ct2 = 1 - (1 - c * c) / (e * e);
  if (ct2 <= 0) return {wo.x, wo.y, -wo.z};  // total internal reflection: below anyway
  const Vec3<double> n(0, 0, wo.z > 0 ? 1 : -1);
  return Normalize(wo * (-1 / e) + n * (c / e - std::sqrt(ct2)));
}

inline Pairs MakePairs(size_t n, double eta, double alpha, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  auto sphere = [&] {
    double mu = 2 * uni(rng) - 1;
    if (uni(rng) < 0.15) mu = std::copysign(std::pow(10.0, -6.5 * uni(rng)), mu);
    return FromMuPhi(mu, kTwoPi<double> * uni(rng));
  };
  const double crit = eta < 1 ? std::sqrt((1 - eta) * (1 + eta)) : -1;
  Pairs p;
  for (size_t i = 0; i < n; ++i) {
    Vec3<double> wo = sphere();
    if (crit > 0 && i % 5 == 0) {
      // wo above, in the dense medium, near the critical cosine.
      wo = FromMuPhi(crit * (1 + 1e-3 * (2 * uni(rng) - 1)), kTwoPi<double> * uni(rng));
    }
    Vec3<double> wi = sphere();
    const int kind = static_cast<int>(i % 3);
    if (kind != 0) {
      const Vec3<double> base = kind == 1 ? Vec3<double>(-wo.x, -wo.y, wo.z) : Refracted(wo, eta);
      const double spread = std::min(1.0, alpha * 4 * uni(rng) + 1e-7);
      wi = Normalize(base +
                     Vec3<double>(2 * uni(rng) - 1, 2 * uni(rng) - 1, 2 * uni(rng) - 1) * spread);
    }
    p.wi.Push(wi);
    p.wo.Push(wo);
  }
  return p;
}

// The bound of dielectric-inl.h for one pair: 4e-6, the reflectance's
// condition number kappa times the relative error of its cosine, the
// conditioning of |wi.s| |wo.s| and of the chi+ edges (|s| / |w.s|), and
// (Beckmann) the exponent r2. Returns the relative bound for float lanes;
// `eps_part` receives the part that scales with the lanes' epsilon,
// `ref_part` the reference's own error, `r2_out` (if not null) r2.
template <class Model>
double PairBound(const Model& m, const Vec3<double>& wi, const Vec3<double>& wo, bool beckmann,
                 double* eps_part, double* ref_part, double* r2_out) {
  const bool same = (wi.z > 0) == (wo.z > 0);
  const double eta = m.eta();
  Vec3<double> s = same ? wi + wo : wi * m.IndexOf(wi) + wo * m.IndexOf(wo);
  if (s.z < 0) s = -s;
  const double len = Length(s);
  const double ai = std::abs(Dot(wi, s)) / len, ao = std::abs(Dot(wo, s)) / len;
  // The Fresnel cosine and index as the model takes them.
  double c, e;
  if (same) {
    c = 0.5 * (ai + ao);
    e = wo.z > 0 ? eta : 1 / eta;
  } else {
    c = wi.z > 0 ? ai : ao;
    e = eta;
  }
  c = std::min(c, 1.0);
  const double h = 1e-7 * std::max(c, 1e-3);
  const double dF =
      (FresnelDielectric(e, std::min(c + h, 1.0)) - FresnelDielectric(e, std::max(c - h, 0.0))) /
      (std::min(c + h, 1.0) - std::max(c - h, 0.0));
  const double f = FresnelDielectric(e, c);
  const double denom = same ? f : 1 - f;
  const double kappa = denom > 0 ? c * std::abs(dF) / denom : 0;
  const double cond = 1 / std::max(ai, 1e-30) + 1 / std::max(ao, 1e-30);
  double r2 = 0;
  if (beckmann) {
    const double a = m.ndf().alpha_x();
    r2 = (s.x * s.x + s.y * s.y) / (a * a * s.z * s.z);
  }
  *eps_part = 2e-7 * kappa * (1 + cond) + 4e-7 * cond + 4e-7 * r2;
  // The reference's own error next to the critical angle: fresnel.h forms
  // cos_t^2 = g^2 / eta_rel^2 with an absolute error of a few 1e-16.
  const double g2 = c * c + (e - 1) * (e + 1);
  *ref_part = 4e-16 * e * e / std::max(std::abs(g2), 1e-300);
  if (r2_out) *r2_out = r2;
  return 4e-6 + *eps_part + *ref_part;
}

}  // namespace test
}  // namespace brdfbake
#endif  // BRDFBAKE_SIMD_DIELECTRIC_TEST_ONCE_

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace {

using test::Pairs;
using test::RelErr;

const char* Target() { return hwy::TargetName(HWY_TARGET); }

struct Worst {
  double f32 = 0, f64 = 0;
  size_t checked = 0;
};

// The kernel in double lanes at the float inputs.
template <class Ndf>
void EvalF64(const DielectricConsts<hn::ScalableTag<double>>& k, const Ndf& ndf, bool separable,
             bool cos_weighted, const Pairs& p, std::vector<double>* out) {
  using D64 = hn::ScalableTag<double>;
  const D64 d;
  const size_t N = hn::Lanes(d), n = p.wi.size();
  std::vector<double> buf[6];
  for (auto& b : buf) b.assign((n + N - 1) / N * N, 0.5);
  for (size_t i = 0; i < n; ++i) {
    buf[0][i] = p.wi.x[i], buf[1][i] = p.wi.y[i], buf[2][i] = p.wi.z[i];
    buf[3][i] = p.wo.x[i], buf[4][i] = p.wo.y[i], buf[5][i] = p.wo.z[i];
  }
  out->assign(buf[0].size(), 0);
  for (size_t i = 0; i < buf[0].size(); i += N) {
    const auto v = [&](int j) { return hn::LoadU(d, buf[j].data() + i); };
    hn::StoreU(
        DielectricBsdf(d, k, ndf, separable, cos_weighted, v(0), v(1), v(2), v(3), v(4), v(5)), d,
        out->data() + i);
  }
}

template <class Model>
void Compare(const char* what, const Model& m, bool beckmann, bool cos_weighted, const Pairs& p,
             const std::vector<float>& got, const std::vector<double>& got64, Worst* w) {
  for (size_t i = 0; i < p.wi.size(); ++i) {
    const Vec3<double> wi = p.wi.At(i), wo = p.wo.At(i);
    ASSERT_TRUE(std::isfinite(got[i]) && got[i] >= 0) << what << " " << got[i];
    ASSERT_TRUE(std::isfinite(got64[i]) && got64[i] >= 0) << what << " " << got64[i];
    const double ref = cos_weighted ? m.BsdfCos(wi, wo) : m.Bsdf(wi, wo);
    if (ref == 0) {
      // Where the pair is invalid in exact arithmetic the kernel may keep a
      // lane at a chi+ edge, with a value that vanishes there.
      continue;
    }
    double eps_part = 0, ref_part = 0, r2 = 0;
    const double bound = test::PairBound(m, wi, wo, beckmann, &eps_part, &ref_part, &r2);
    // Float's range: below 1e-20 the factors' product may be subnormal
    // (flushed to 0 by the batch function), and exp(-r2) is below FLT_MIN
    // from r2 = 87.3 on.
    const bool in_float = ref >= 1e-20 && ref <= 1e30 && r2 < 87;
    const double e = RelErr(got[i], ref);
    if (in_float) {
      w->f32 = std::max(w->f32, e / bound);
      ++w->checked;
    }
    ASSERT_TRUE(!in_float || e <= bound)
        << "error " << e << " bound " << bound << " " << Target() << " " << what << " eta "
        << m.eta() << " alpha " << m.ndf().alpha_x() << " wi " << wi.x << " " << wi.y << " " << wi.z
        << " wo " << wo.x << " " << wo.y << " " << wo.z << " got " << got[i] << " ref " << ref;
    // The reference's own error: FresnelDielectric (fresnel.h) forms eta c -
    // cos_t with cancellation, F ~ (eta - 1)^2 / 4 keeps about 1e-16 /
    // |eta_rel - 1| of relative precision (1e-12 at eta = 1.0001).
    const double ref_f = (wi.z > 0) == (wo.z > 0) ? 2e-15 / std::abs(m.eta() - 1) : 0;
    const double bound64 = 2e-12 + 2e-9 * eps_part + ref_f + ref_part;
    if (ref < 1e-290) continue;
    const double e64 = RelErr(got64[i], ref);
    w->f64 = std::max(w->f64, e64 / bound64);
    ASSERT_LE(e64, bound64) << Target() << " " << what << " (double lanes) eta " << m.eta()
                            << " alpha " << m.ndf().alpha_x() << " wi " << wi.x << " " << wi.y
                            << " " << wi.z << " wo " << wo.x << " " << wo.y << " " << wo.z
                            << " got " << got64[i] << " ref " << ref;
  }
}

template <class Ndf, class DNdf, class Consts>
void CheckNdf(const char* name, ModelKind kind, Worst* worst) {
  using D64 = hn::ScalableTag<double>;
  const size_t n = 3000;
  uint64_t seed = 1;
  for (float eta : {1.5f, 1 / 1.5f, 1.0001f, 1 / 1.0001f, 2.4f, 1 / 2.4f, 1.0f}) {
    for (float alpha : {1e-4f, 1e-2f, 0.3f, 1.0f}) {
      const Pairs p = test::MakePairs(n, eta, alpha, seed++);
      for (Masking mk : {Masking::kHeightCorrelated, Masking::kSeparable}) {
        for (DielectricTransport t :
             {DielectricTransport::kRadiance, DielectricTransport::kImportance}) {
          for (DielectricQuantity q : {DielectricQuantity::kBsdf, DielectricQuantity::kBsdfCos}) {
            BatchDielectric b;
            b.ndf = kind;
            b.alpha_x = b.alpha_y = alpha;
            b.eta = eta;
            b.masking = mk;
            b.transport = t;
            std::vector<float> got(n);
            DielectricBsdfBatch(b, q, {p.wi.x.data(), p.wi.y.data(), p.wi.z.data()},
                                {p.wo.x.data(), p.wo.y.data(), p.wo.z.data()}, got.data(), n);
            const RoughDielectric<double, Ndf> m(Ndf(alpha), eta, mk, t);
            const D64 d;
            const Consts c(d, alpha, alpha, 1.0);
            const DielectricConsts<D64> k(d, eta, t);
            std::vector<double> got64;
            const bool cw = q == DielectricQuantity::kBsdfCos;
            EvalF64(k, DNdf{c}, mk == Masking::kSeparable, cw, p, &got64);
            Compare(name, m, kind == ModelKind::kBeckmann, cw, p, got, got64, worst);
          }
        }
      }
    }
  }
}

}  // namespace

void CheckDielectricGgx() {
  Worst w;
  CheckNdf<GgxNdf<double>, GgxDielectricNdf<hn::ScalableTag<double>>,
           GgxConsts<hn::ScalableTag<double>>>("ggx", ModelKind::kGgx, &w);
  std::printf("%s: ggx glass, %zu values, max error / bound: float %.3g, double lanes %.3g\n",
              Target(), w.checked, w.f32, w.f64);
}

#if BRDFBAKE_WITH_BECKMANN
void CheckDielectricBeckmann() {
  Worst w;
  CheckNdf<BeckmannNdf<double>, BeckmannDielectricNdf<hn::ScalableTag<double>>,
           BeckmannConsts<hn::ScalableTag<double>>>("beckmann", ModelKind::kBeckmann, &w);
  std::printf("%s: beckmann glass, %zu values, max error / bound: float %.3g, double lanes %.3g\n",
              Target(), w.checked, w.f32, w.f64);
}
#endif

// Every count from 0 to 40 at four misalignments writes exactly its
// outputs (sentinels around them), the same as one call over the arrays.
void CheckDielectricTails() {
  const Pairs p = test::MakePairs(64, 1.5, 0.3, 99);
  const float* in[6] = {p.wi.x.data(), p.wi.y.data(), p.wi.z.data(),
                        p.wo.x.data(), p.wo.y.data(), p.wo.z.data()};
  BatchDielectric b;
  test::CheckCountsAndSentinels(
      in, 64, 40, 1,
      [&](const float* const* x, float* const* out, size_t n) {
        DielectricBsdfBatch(b, DielectricQuantity::kBsdfCos, {x[0], x[1], x[2]}, {x[3], x[4], x[5]},
                            out[0], n);
      },
      6);
}

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace brdfbake {
HWY_BEFORE_TEST(SimdDielectricTest);
HWY_EXPORT_AND_TEST_P(SimdDielectricTest, CheckDielectricGgx);
#if BRDFBAKE_WITH_BECKMANN
HWY_EXPORT_AND_TEST_P(SimdDielectricTest, CheckDielectricBeckmann);
#endif
HWY_EXPORT_AND_TEST_P(SimdDielectricTest, CheckDielectricTails);

// The batch function checks its parameters before writing anything.
TEST(SimdDielectricTest, RejectsParametersOutsideTheDomain) {
  float x = 0, y = 0, z = 1, out = -1;
  const DirArrays w{&x, &y, &z};
  const auto bad = [&](BatchDielectric b) {
    EXPECT_THROW(DielectricBsdfBatch(b, DielectricQuantity::kBsdf, w, w, &out, 1),
                 std::invalid_argument);
    EXPECT_EQ(out, -1.0f);
  };
  BatchDielectric b;
  b.eta = 0.001f;
  bad(b);
  b = {};
  b.eta = NAN;
  bad(b);
  b = {};
  b.alpha_x = 0;
  bad(b);
  b = {};
  b.alpha_y = 2e4f;
  bad(b);
  b = {};
  b.ndf = ModelKind::kStudentT;
  bad(b);
  b = {};
  DielectricBsdfBatch(b, DielectricQuantity::kBsdf, w, w, &out, 1);  // a reflection at the pole
  EXPECT_GT(out, 0.0f);
}
}  // namespace brdfbake
#endif
