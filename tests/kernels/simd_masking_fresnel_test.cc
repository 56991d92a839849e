// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// On every compiled target: the SIMD G1 and G2 (both maskings) of every
// model, the NDF sampling densities of Beckmann and STD, and every model's
// BRDF with the dielectric and conductor Fresnel, against the double scalar
// reference at the same float inputs, each sample within its documented
// bound (include/brdfbake/models/kernel_bounds.h).

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "brdfbake/batch.h"
#include "brdfbake/models/beckmann.h"
#include "brdfbake/models/brdf.h"
#include "brdfbake/models/ellipsoid.h"
#include "brdfbake/models/fresnel.h"
#include "brdfbake/models/ggx.h"
#include "brdfbake/models/kernel_bounds.h"
#include "brdfbake/models/std_ndf.h"

#include "util/simd_test_util.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "tests/kernels/simd_masking_fresnel_test.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>
#include <hwy/tests/hwy_gtest.h>

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace {  // internal linkage: other test files define their own helpers

using test::Dirs;
Dirs RandomDirs(size_t n, uint64_t seed) { return test::RandomDirs(n, seed, 53); }
using test::RelErr;

// The rounding of the final division and sum of G2, and of the Fresnel
// factor's product with the rest of the BRDF.
constexpr double kG2Rounding = 4e-7;
// src/kernels/fresnel-inl.h: dielectric 2e-6 relative; conductor 2e-6
// relative plus 1e-7 absolute.
constexpr double kFresnelRel = 2e-6, kConductorAbs = 1e-7;
// Rounding of the BRDF kernels' wo.h = (wo.s) rsqrt(|s|^2) (a Newton-refined
// reciprocal square root and a dot product): 4 ulp.
constexpr double kCosAbs = 2.4e-7;




// One model: its batch calls and its double reference, plus the per-sample
// bound of 1 + Lambda (relative) and of the BRDF (relative).
struct Model {
  std::string name;
  std::function<void(Masking, const Dirs&, std::vector<float>*)> g1;
  std::function<void(Masking, const Dirs&, const Dirs&, std::vector<float>*)> g2;
  std::function<void(Masking, BatchFresnel, float, float, const Dirs&, const Dirs&,
                     std::vector<float>*)>
      brdf;
  std::function<double(const Vec3<double>&)> lambda;
  std::function<double(const Vec3<double>&, const Vec3<double>&, Masking)> g2_ref;
  std::function<double(const Fresnel&, const Vec3<double>&, const Vec3<double>&, Masking)>
      brdf_ref;
  std::function<double(const Vec3<double>&)> lambda_bound;  // of 1 + Lambda, relative
  std::function<double(const Vec3<double>&, const Vec3<double>&)> brdf_bound;
  // Whether a zero BRDF may stand for a subnormal exponential (exponent > 87).
  std::function<bool(const Vec3<double>&, const Vec3<double>&)> may_flush;
};

template <class P>
void SetFresnel(P* p, Masking masking, BatchFresnel kind, float eta, float k) {
  p->masking = masking;
  p->fresnel = kind;
  p->eta = eta;
  p->k = k;
}

// Squared standard slope of the half vector of (wi, wo).
double HalfSlope2(const Vec3<double>& wi, const Vec3<double>& wo, double ax, double ay) {
  const Vec3<double> s = wi + wo;
  const double sx = s.x / ax, sy = s.y / ay;
  return (sx * sx + sy * sy) / (s.z * s.z);
}

double SlopeLambdaBound(const Vec3<double>& w, double ax, double ay, double lambda) {
  if (std::isinf(lambda)) return 0;
  const double px = ax * w.x, py = ay * w.y;
  const double a = w.z / std::sqrt(std::max(px * px + py * py, 1e-300));
  return bounds::SlopeLambdaAbs(a, lambda) / (1 + lambda);
}

Model Ggx(float ax, float ay) {
  BatchModel p{ModelKind::kGgx};
  p.alpha_x = ax;
  p.alpha_y = ay;
  const GgxNdf<double> ndf(ax, ay);
  Model m;
  m.name = "ggx";
  m.g1 = [p](Masking, const Dirs& w, std::vector<float>* o) {
    EvalBatch(p, Quantity::kG1, {w.x.data(), w.y.data(), w.z.data()}, o->data(), w.x.size());
  };
  m.g2 = [p](Masking mk, const Dirs& i, const Dirs& o, std::vector<float>* out) {
    BatchModel q = p;
    q.masking = mk;
    EvalBatch(q, Quantity::kG2, {i.x.data(), i.y.data(), i.z.data()},
              {o.x.data(), o.y.data(), o.z.data()}, out->data(), i.x.size());
  };
  m.brdf = [p](Masking mk, BatchFresnel kind, float eta, float k, const Dirs& i, const Dirs& o,
               std::vector<float>* out) {
    BatchModel q = p;
    SetFresnel(&q, mk, kind, eta, k);
    EvalBatch(q, Quantity::kBrdf, {i.x.data(), i.y.data(), i.z.data()},
              {o.x.data(), o.y.data(), o.z.data()}, out->data(), i.x.size());
  };
  m.lambda = [ndf](const Vec3<double>& w) { return ndf.Lambda(w); };
  m.g2_ref = [ndf](const Vec3<double>& wi, const Vec3<double>& wo, Masking mk) {
    Vec3<double> h;
    return HalfVector(wi, wo, &h) ? G2(ndf, wi, wo, h, mk) : 0.0;
  };
  m.brdf_ref = [ndf](const Fresnel& f, const Vec3<double>& wi, const Vec3<double>& wo,
                     Masking mk) { return Brdf(ndf, f, wi, wo, mk); };
  m.lambda_bound = [](const Vec3<double>&) { return bounds::kGgxRel; };
  m.brdf_bound = [](const Vec3<double>&, const Vec3<double>&) { return bounds::kGgxRel; };
  m.may_flush = [](const Vec3<double>&, const Vec3<double>&) { return false; };
  return m;
}

// Beckmann (gamma = inf) or STD.
Model Slope(float ax, float ay, float gamma) {
  const bool beck = std::isinf(gamma);
  const StudentTNdf<double> ndf(ax, ay, gamma);
  Model m;
  m.name = beck ? "beckmann" : "std gamma " + std::to_string(gamma);
  if (beck) {
    BatchModel p{ModelKind::kBeckmann};
    p.alpha_x = ax;
    p.alpha_y = ay;
    m.g1 = [p](Masking, const Dirs& w, std::vector<float>* o) {
      EvalBatch(p, Quantity::kG1, {w.x.data(), w.y.data(), w.z.data()}, o->data(), w.x.size());
    };
    m.g2 = [p](Masking mk, const Dirs& i, const Dirs& o, std::vector<float>* out) {
      BatchModel q = p;
      q.masking = mk;
      EvalBatch(q, Quantity::kG2, {i.x.data(), i.y.data(), i.z.data()},
                {o.x.data(), o.y.data(), o.z.data()}, out->data(), i.x.size());
    };
    m.brdf = [p](Masking mk, BatchFresnel kind, float eta, float k, const Dirs& i,
                 const Dirs& o, std::vector<float>* out) {
      BatchModel q = p;
      SetFresnel(&q, mk, kind, eta, k);
      EvalBatch(q, Quantity::kBrdf, {i.x.data(), i.y.data(), i.z.data()},
                {o.x.data(), o.y.data(), o.z.data()}, out->data(), i.x.size());
    };
  } else {
    BatchModel p{ModelKind::kStudentT};
    p.alpha_x = ax;
    p.alpha_y = ay;
    p.gamma = gamma;
    m.g1 = [p](Masking, const Dirs& w, std::vector<float>* o) {
      EvalBatch(p, Quantity::kG1, {w.x.data(), w.y.data(), w.z.data()}, o->data(), w.x.size());
    };
    m.g2 = [p](Masking mk, const Dirs& i, const Dirs& o, std::vector<float>* out) {
      BatchModel q = p;
      q.masking = mk;
      EvalBatch(q, Quantity::kG2, {i.x.data(), i.y.data(), i.z.data()},
                {o.x.data(), o.y.data(), o.z.data()}, out->data(), i.x.size());
    };
    m.brdf = [p](Masking mk, BatchFresnel kind, float eta, float k, const Dirs& i,
                 const Dirs& o, std::vector<float>* out) {
      BatchModel q = p;
      SetFresnel(&q, mk, kind, eta, k);
      EvalBatch(q, Quantity::kBrdf, {i.x.data(), i.y.data(), i.z.data()},
                {o.x.data(), o.y.data(), o.z.data()}, out->data(), i.x.size());
    };
  }
  m.lambda = [ndf](const Vec3<double>& w) { return ndf.Lambda(w); };
  m.g2_ref = [ndf](const Vec3<double>& wi, const Vec3<double>& wo, Masking mk) {
    Vec3<double> h;
    return HalfVector(wi, wo, &h) ? G2(ndf, wi, wo, h, mk) : 0.0;
  };
  m.brdf_ref = [ndf](const Fresnel& f, const Vec3<double>& wi, const Vec3<double>& wo,
                     Masking mk) { return Brdf(ndf, f, wi, wo, mk); };
  const double dax = ax, day = ay, g = gamma;
  m.lambda_bound = [ndf, dax, day](const Vec3<double>& w) {
    return SlopeLambdaBound(w, dax, day, ndf.Lambda(w));
  };
  auto exponent = [beck, dax, day, g](const Vec3<double>& wi, const Vec3<double>& wo) {
    const double r2 = HalfSlope2(wi, wo, dax, day);
    return beck ? r2 : g * std::log1p(r2 / (g - 1));
  };
  m.brdf_bound = [exponent, beck](const Vec3<double>& wi, const Vec3<double>& wo) {
    return bounds::SlopeBrdf(exponent(wi, wo),
                             beck ? bounds::kBeckmannBrdfExpSlope : bounds::kStudentTExpSlope);
  };
  m.may_flush = [exponent](const Vec3<double>& wi, const Vec3<double>& wo) {
    return exponent(wi, wo) > bounds::kFlushExponent;
  };
  return m;
}

Model Ellipsoid(float ax, float ay, float tx, float ty, float tz) {
  BatchModel p{ModelKind::kEllipsoid};
  p.alpha_x = ax;
  p.alpha_y = ay;
  p.theta_x = tx;
  p.theta_y = ty;
  p.theta_z = tz;
  const EllipsoidNdf<double> ndf(ax, ay, tx, ty, tz);
  const Mat3<double> a = ndf.shape_matrix();
  const Mat3<double> ait = bounds::EllipsoidKernelInvT(ax, ay, tx, ty, tz);
  Model m;
  m.name = "ellipsoid";
  m.g1 = [p](Masking, const Dirs& w, std::vector<float>* o) {
    EvalBatch(p, Quantity::kG1, {w.x.data(), w.y.data(), w.z.data()}, o->data(), w.x.size());
  };
  m.g2 = [p](Masking mk, const Dirs& i, const Dirs& o, std::vector<float>* out) {
    BatchModel q = p;
    q.masking = mk;
    EvalBatch(q, Quantity::kG2, {i.x.data(), i.y.data(), i.z.data()},
              {o.x.data(), o.y.data(), o.z.data()}, out->data(), i.x.size());
  };
  m.brdf = [p](Masking mk, BatchFresnel kind, float eta, float k, const Dirs& i, const Dirs& o,
               std::vector<float>* out) {
    BatchModel q = p;
    SetFresnel(&q, mk, kind, eta, k);
    EvalBatch(q, Quantity::kBrdf, {i.x.data(), i.y.data(), i.z.data()},
              {o.x.data(), o.y.data(), o.z.data()}, out->data(), i.x.size());
  };
  m.lambda = [ndf](const Vec3<double>& w) { return ndf.Lambda(w); };
  m.g2_ref = [ndf](const Vec3<double>& wi, const Vec3<double>& wo, Masking mk) {
    Vec3<double> h;
    return HalfVector(wi, wo, &h) ? G2(ndf, wi, wo, h, mk) : 0.0;
  };
  m.brdf_ref = [ndf](const Fresnel& f, const Vec3<double>& wi, const Vec3<double>& wo,
                     Masking mk) { return Brdf(ndf, f, wi, wo, mk); };
  m.lambda_bound = [ndf, a](const Vec3<double>& w) {
    const double l = ndf.Lambda(w);
    if (std::isinf(l)) return 0.0;
    return bounds::kEllipsoidLambdaRel * bounds::Kappa(a, w) *
           bounds::EllipsoidLambdaScale(a, w, l) / (1 + l);
  };
  m.brdf_bound = [ndf, a, ait](const Vec3<double>& wi, const Vec3<double>& wo) {
    return bounds::kEllipsoidBrdfRel *
           bounds::EllipsoidBrdfCondition(a, ait, wi, wo, ndf.Lambda(wi), ndf.Lambda(wo));
  };
  m.may_flush = [](const Vec3<double>&, const Vec3<double>&) { return false; };
  return m;
}

std::vector<Model> Models() {
  const double deg = 3.141592653589793 / 180;
  std::vector<Model> ms;
  for (const auto& a : std::vector<std::pair<float, float>>{
           {1e-4f, 1e-4f}, {0.05f, 0.05f}, {0.5f, 0.5f}, {1.0f, 1e-3f}}) {
    ms.push_back(Ggx(a.first, a.second));
    ms.push_back(Slope(a.first, a.second, INFINITY));
    ms.push_back(Slope(a.first, a.second, 1.6f));
    ms.push_back(Slope(a.first, a.second, 3.0f));
    ms.push_back(Ellipsoid(a.first, a.second, 0, 0, 0));
  }
  ms.push_back(Ellipsoid(0.3f, 0.05f, float(60 * deg), float(-30 * deg), float(20 * deg)));
  return ms;
}

void CheckMaskingAgainstScalar() {
  const size_t n = 8000;
  const Dirs wi = RandomDirs(n, 31), wo = RandomDirs(n, 32);
  std::vector<float> out(n);
  double worst_g1 = 0, worst_g2 = 0;
  for (const Model& m : Models()) {
    m.g1(Masking::kHeightCorrelated, wi, &out);
    for (size_t i = 0; i < n; ++i) {
      const double l = m.lambda(wi.At(i));
      const double ref = std::isinf(l) ? 0.0 : 1 / (1 + l);
      const double bound = m.lambda_bound(wi.At(i)) + kG2Rounding;
      const double err = ref == 0 ? std::abs(out[i]) : RelErr(out[i], ref);
      worst_g1 = std::max(worst_g1, err / bound);
      ASSERT_LE(err, bound) << m.name << " G1 i=" << i << " got " << out[i] << " ref " << ref;
    }
    for (Masking mk : {Masking::kHeightCorrelated, Masking::kSeparable}) {
      m.g2(mk, wi, wo, &out);
      for (size_t i = 0; i < n; ++i) {
        const double ref = m.g2_ref(wi.At(i), wo.At(i), mk);
        const double bound =
            m.lambda_bound(wi.At(i)) + m.lambda_bound(wo.At(i)) + kG2Rounding;
        const double err = ref == 0 ? std::abs(out[i]) : RelErr(out[i], ref);
        worst_g2 = std::max(worst_g2, err / bound);
        ASSERT_LE(err, bound) << m.name << " G2 " << MaskingName(mk) << " i=" << i << " got "
                              << out[i] << " ref " << ref;
      }
    }
  }
  std::printf("%s: G1 max error / bound %.3g, G2 %.3g\n", hwy::TargetName(HWY_TARGET),
              worst_g1, worst_g2);
}

void CheckPdfNdfAgainstScalar() {
  const size_t n = 8000;
  const Dirs m = RandomDirs(n, 33);
  std::vector<float> out(n);
  double worst = 0;
  for (float gamma : {INFINITY, 1.6f, 3.0f}) {
    for (float alpha : {1e-3f, 0.1f, 0.7f}) {
      const StudentTNdf<double> ndf(alpha, alpha, gamma);
      if (std::isinf(gamma)) {
        BatchModel p{ModelKind::kBeckmann};
        p.alpha_x = p.alpha_y = alpha;
        EvalBatch(p, Quantity::kPdfNdf, {m.x.data(), m.y.data(), m.z.data()}, out.data(), n);
      } else {
        BatchModel p{ModelKind::kStudentT};
        p.alpha_x = p.alpha_y = alpha;
        p.gamma = gamma;
        EvalBatch(p, Quantity::kPdfNdf, {m.x.data(), m.y.data(), m.z.data()}, out.data(), n);
      }
      for (size_t i = 0; i < n; ++i) {
        const Vec3<double> v = m.At(i);
        const double ref = ndf.PdfNdf(v);
        if (!(v.z > 0)) {
          ASSERT_EQ(out[i], 0.0f);
          continue;
        }
        const double r2 = (v.x * v.x + v.y * v.y) / (double(alpha) * alpha * v.z * v.z);
        const double e = std::isinf(gamma) ? r2 : gamma * std::log1p(r2 / (gamma - 1));
        if (e > bounds::kFlushExponent) continue;  // subnormal exponential, may be 0
        const double bound =
            bounds::SlopeD(e, std::isinf(gamma) ? bounds::kBeckmannExpSlope
                                                : bounds::kStudentTExpSlope) + kG2Rounding;
        const double err = RelErr(out[i], ref);
        worst = std::max(worst, err / bound);
        ASSERT_LE(err, bound) << "gamma " << gamma << " alpha " << alpha << " i=" << i;
      }
    }
  }
  std::printf("%s: PdfNdf (Beckmann, STD) max error / bound %.3g\n",
              hwy::TargetName(HWY_TARGET), worst);
}

void CheckBrdfWithFresnel() {
  const size_t n = 6000;
  const Dirs wi = RandomDirs(n, 34), wo = RandomDirs(n, 35);
  std::vector<float> out(n);
  struct Case {
    BatchFresnel kind;
    float eta, k;
  };
  const Case cases[] = {{BatchFresnel::kDielectric, 1.5f, 0},
                        {BatchFresnel::kDielectric, 0.7f, 0},
                        {BatchFresnel::kDielectric, 1.01f, 0},
                        {BatchFresnel::kConductor, 0.2f, 3.0f},
                        {BatchFresnel::kConductor, 1.5f, 0.5f}};
  double worst = 0;
  for (const Model& m : Models()) {
    for (const Case& c : cases) {
      for (Masking mk : {Masking::kHeightCorrelated, Masking::kSeparable}) {
        m.brdf(mk, c.kind, c.eta, c.k, wi, wo, &out);
        const Fresnel fr = c.kind == BatchFresnel::kDielectric
                               ? Fresnel::Dielectric(c.eta)
                               : Fresnel::Conductor({c.eta, c.eta, c.eta}, {c.k, c.k, c.k});
        for (size_t i = 0; i < n; ++i) {
          const Vec3<double> a = wi.At(i), b = wo.At(i);
          const double ref = m.brdf_ref(fr, a, b, mk);
          if (!(ref > 0)) {
            ASSERT_EQ(out[i], 0.0f) << m.name << " i=" << i;
            continue;
          }
          if (m.may_flush(a, b)) continue;
          Vec3<double> h;
          HalfVector(a, b, &h);
          const double cos_d = Dot(b, h), f = fr.Eval(cos_d, 0);
          // The kernel's wo.h carries a few ulps (kCosAbs) of rounding, which
          // F amplifies by its slope (unbounded at the critical angle of
          // eta < 1): the secant over that width.
          const double lo = std::max(0.0, cos_d - kCosAbs), hi = std::min(1.0, cos_d + kCosAbs);
          const double slope = std::abs(fr.Eval(hi, 0) - fr.Eval(lo, 0)) / (hi - lo);
          const double fres = kFresnelRel + slope * kCosAbs / f +
                              (c.kind == BatchFresnel::kConductor ? kConductorAbs / f : 0.0);
          const double bound = m.brdf_bound(a, b) + fres;
          const double err = RelErr(out[i], ref);
          worst = std::max(worst, err / bound);
          ASSERT_LE(err, bound) << m.name << " eta " << c.eta << " k " << c.k << " "
                                << MaskingName(mk) << " i=" << i << " got " << out[i]
                                << " ref " << ref;
        }
      }
    }
  }
  std::printf("%s: BRDF with dielectric / conductor Fresnel, max error / bound %.3g\n",
              hwy::TargetName(HWY_TARGET), worst);
}

}  // namespace
}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace brdfbake {
HWY_BEFORE_TEST(SimdMaskingFresnelTest);
HWY_EXPORT_AND_TEST_P(SimdMaskingFresnelTest, CheckMaskingAgainstScalar);
HWY_EXPORT_AND_TEST_P(SimdMaskingFresnelTest, CheckPdfNdfAgainstScalar);
HWY_EXPORT_AND_TEST_P(SimdMaskingFresnelTest, CheckBrdfWithFresnel);
}  // namespace brdfbake
#endif
