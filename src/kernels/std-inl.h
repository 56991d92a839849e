// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// STD (Student's t slopes, [Ribardiere17]) SIMD kernels, float lanes; the scalar
// twins are in include/brdfbake/models/std_ndf.h, slope_ndf.h and brdf.h
// (StudentTNdf<T>::D, ::Lambda, SampleNdf, Brdf). gamma is a per-call constant:
// everything that depends on gamma alone is computed once, in double, by
// StudentTConsts; gamma >= kStudentTBeckmannGamma (1e10, and +inf) runs the Beckmann
// kernels (the relative difference is below r2^2 / gamma < 1e-6 wherever D or
// Lambda is a normal float).
//
// D(m) = (1 + r2 / (gamma - 1))^-gamma / (pi ax ay m.z^4) ([Ribardiere17] eq. 13
// stretched by eq. 10), as exp(-gamma log1p(r2 / (gamma - 1))).
//
// Lambda at a = w.z / sqrt(ax^2 w.x^2 + ay^2 w.y^2), u = m^2 = a^2/(gamma - 1),
// with the notation of std_ndf.h (kt = K / sqrt(gamma - 1), computed in double
// per call). Two forms, both evaluated with a fixed number of terms, chosen per
// lane by a select (a branch skips a form only when no lane needs it):
//  (L) a >= 1.25 or u >= 1: form (S) of std_ndf.h,
//        Lambda = kt/(2a) (1 + u)^(3/2 - gamma) [1/(2 gamma - 3) + G (gamma-1)/(2 gamma a^2)],
//      but G = 2F1(1, 3/2; gamma + 1; -(gamma - 1)/a^2) by quadrature instead
//      of the continued fraction (which needs 100+ levels at a = 1.5). From
//      Euler's integral 2F1(1, b; c; z) = (c - 1) int_0^1 (1 - s)^(c-2)
//      (1 - z s)^-b ds and s = 1 - exp(-x / gamma):
//        G = int_0^inf exp(-x) (1 + (gamma - 1)(1 - exp(-x/gamma)) / a^2)^(-3/2) dx,
//      a smooth bounded integrand against exp(-x): 16-point Gauss-Laguerre,
//        G ~ sum_k W_k (1 + E_k / a^2)^(-3/2),  E_k = -(gamma - 1) expm1(-x_k / gamma),
//      E_k per call. The integrand's nearest singularity is at
//      x = -gamma log(1 + a^2/(gamma - 1)) (-> -a^2), so the rule converges
//      fast once a >= 1.25 or u >= 1: quadrature error of the bracket below
//      3.6e-7 relative for any gamma (checked against mpmath quadrature on a
//      (gamma, a) grid, gamma in [1.501, 1e6]). Positive terms only: no
//      cancellation, relative accuracy down to underflow.
//  (Y) a < 1.25 and u < 1: form (Y) of std_ndf.h ([Ribardiere17] eq. 21 after a
//      Pfaff transformation),
//        Lambda = kt/a (1 + u)^(3/2 - gamma) [(gamma-1)/(2 gamma - 3) + w S(w)] - 1/2,
//        w = a^2 / (1 + u),  S = sum_n c_n w^n,  c_(n+1) = c_n (gamma - 1/2 + n) / ((gamma - 1)(n + 3/2)),
//      a positive series whose term ratio is below max(1/2, a^2/(n + 3/2))
//      here; 28 terms (c_n per call, Horner) reach 3e-8 for any gamma. The
//      subtraction of 1/2 costs at most 1/(2 Lambda(1.25)) ulp relative,
//      nothing relative to 1 + Lambda.
// (1 + u)^(3/2 - gamma) = exp(-(gamma - 3/2) log1p(u)).
// Error against the double reference at the same float inputs (asserted on
// every target by tests/kernels/simd_std_test.cc for gamma in {1.5 (clamped),
// 1.501, 1.6, 2, 3, 7.5, 30, 1e4, 1e6, 1e9, inf}, alpha from 1e-4 to 1, anisotropy 1000:1,
// mu down to 1e-7 and a from 1e-7 to 1e8, which prints the observed
// maxima; the bounds are those of kernel_bounds.h):
//   D:      relative 1e-6 + 4.5e-7 E, E = gamma log1p(r2/(gamma-1)) the
//           exponent;
//   Lambda: |err| <= 1e-6 max(1, Lambda) + 3e-7 a^2 Lambda;
//   BRDF:   relative 2e-6 + 4.5e-7 E.
// Where exp(-E) is below FLT_MIN (E > 87.3) it is a subnormal, flushed to 0
// by the batch functions (see beckmann-inl.h).
//
// The BRDF: D(h) from s = wi + wo unnormalized (one division 1/s.z^2, and
// log1p has one more), Lambda(wi), Lambda(wo) as above (per direction one
// square root, three divisions of which one is inside log1p, one exp, 16
// reciprocal square roots with a Newton step, a 28-term Horner), G2 and
// 1/(4 wi.z wo.z) merged into
// one final division; Schlick F at wo.h with one more reciprocal square root.
// Operation count per lane when both forms run: 9 div (one inside each
// log1p), 2 sqrt, 33 rsqrt + Newton, 3 exp, 3 log1p, ~350 other mul/add/FMA;
// a vector whose lanes all take one form skips the other (per direction
// ~115 operations for (L), ~35 and one division for (Y)).

#if defined(BRDFBAKE_SRC_KERNELS_STD_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef BRDFBAKE_SRC_KERNELS_STD_INL_H_
#undef BRDFBAKE_SRC_KERNELS_STD_INL_H_
#else
#define BRDFBAKE_SRC_KERNELS_STD_INL_H_
#endif

#include <cmath>
#include <limits>
#include <type_traits>

#include <hwy/highway.h>
#include <hwy/contrib/math/math-inl.h>

#include "brdfbake/models/std_ndf.h"
#include "kernels/beckmann-inl.h"
#include "kernels/std_f64-inl.h"

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// gamma from which the STD kernels run the Beckmann ones.
constexpr double kStudentTBeckmannGamma = 1e10;
// Terms of the series (Y) and points of the Gauss-Laguerre rule (L).
constexpr int kStudentTSeriesTerms = 28;
constexpr int kStudentTLaguerrePoints = 16;
// Form (Y) for a < kStudentTSeriesMaxA and u < 1, (L) elsewhere.
constexpr float kStudentTSeriesMaxAf = 1.25f;

// 16-point Gauss-Laguerre rule (nodes: roots of L_16; weights
// x / (17 L_17(x))^2), computed with mpmath at 30 digits.
constexpr double kLaguerre16[kStudentTLaguerrePoints][2] = {
    {0.087649410478927839, 0.20615171495780099},  {0.46269632891508083, 0.33105785495088419},
    {1.1410577748312269, 0.26579577764421414},    {2.1292836450983805, 0.13629693429637754},
    {3.4370866338932067, 0.047328928694125222},   {5.0780186145497677, 0.011299900080339454},
    {7.0703385350482337, 0.0018490709435263109},  {9.4383143363919384, 0.00020427191530827845},
    {12.214223368866159, 1.4844586873981299e-05}, {15.441527368781617, 6.8283193308711994e-07},
    {19.180156856753136, 1.8810248410796733e-08}, {23.515905693991908, 2.8623502429738814e-10},
    {28.578729742882139, 2.1270790332241028e-12}, {34.583398702286622, 6.2979670025178679e-15},
    {41.940452647688332, 5.0504737000355127e-18}, {51.701160339543321, 4.1614623703728552e-22}};

// Per-call constants of the STD kernels, in the lanes' type (the kernels
// below are generic over the descriptor D). Float lanes take Lambda from the
// series and Gauss-Laguerre forms below; double lanes from StudentTLambdaF64
// (std_f64-inl.h), whose constants `f64` holds.
template <class D>
struct StudentTConsts {
  using T = hn::TFromD<D>;
  struct NoF64 {};
  BeckmannConsts<D> b;  // alphas, F0; the whole model when beckmann is true
  bool beckmann;
  hn::Vec<D> gamma, gm1, inv_gm1, gm32, kt, half_kt, c1, c2, cy;
  float series[kStudentTSeriesTerms];        // c_n, highest degree first
  float lag_e[kStudentTLaguerrePoints];      // E_k
  float lag_w[kStudentTLaguerrePoints];      // W_k
  std::conditional_t<sizeof(T) == 8, StudentTLambdaF64Consts, NoF64> f64;
  StudentTConsts(D d, T ax, T ay, T f0, T gamma_f) : b(d, ax, ay, f0), f64(MakeF64(gamma_f)) {
    double g = gamma_f;
    if (!(g >= kMinStudentTGamma<double>)) g = kMinStudentTGamma<double>;
    beckmann = g >= kStudentTBeckmannGamma;
    if (beckmann) g = 3.0;  // placeholder values, unused
    const double k = student_t_detail::StudentTKt(g);
    gamma = hn::Set(d, static_cast<T>(g));
    gm1 = hn::Set(d, static_cast<T>(g - 1));
    inv_gm1 = hn::Set(d, static_cast<T>(1 / (g - 1)));
    gm32 = hn::Set(d, static_cast<T>(g - 1.5));
    kt = hn::Set(d, static_cast<T>(k));
    half_kt = hn::Set(d, static_cast<T>(k / 2));
    c1 = hn::Set(d, static_cast<T>(1 / (2 * g - 3)));
    c2 = hn::Set(d, static_cast<T>((g - 1) / (2 * g)));
    cy = hn::Set(d, static_cast<T>((g - 1) / (2 * g - 3)));
    double cn = 1;
    for (int n = 0; n < kStudentTSeriesTerms; ++n) {
      series[kStudentTSeriesTerms - 1 - n] = static_cast<float>(cn);
      cn *= (g - 0.5 + n) / ((g - 1) * (n + 1.5));
    }
    for (int i = 0; i < kStudentTLaguerrePoints; ++i) {
      lag_e[i] = static_cast<float>(-(g - 1) * std::expm1(-kLaguerre16[i][0] / g));
      lag_w[i] = static_cast<float>(kLaguerre16[i][1]);
    }
  }

 private:
  static auto MakeF64(double gamma) {
    if constexpr (sizeof(T) == 8) {
      const double g = gamma >= kStudentTBeckmannGamma ? 3.0 : gamma;  // unused at the limit
      return StudentTLambdaF64Consts(g);
    } else {
      return NoF64{};
    }
  }
};

// exp(-gamma log1p(r2 / (gamma - 1))), the standard slope density times pi.
template <class D, class V>
HWY_INLINE V StudentTP22Pi(D d, const StudentTConsts<D>& c, V r2) {
  using T = hn::TFromD<D>;
  const V x = hn::Min(hn::Mul(r2, c.inv_gm1), hn::Set(d, T(sizeof(T) == 8 ? 1e300 : 1e37)));
  return hn::Exp(d, hn::Neg(hn::Mul(c.gamma, hn::Log1p(d, x))));
}

template <class D, class V>
HWY_INLINE V StudentTD(D d, const StudentTConsts<D>& c, V mx, V my, V mz) {
  const V iz2 = hn::Div(hn::Set(d, hn::TFromD<D>(1)), hn::Mul(mz, mz));
  const V q = hn::MulAdd(hn::Mul(mx, mx), c.b.inv_ax2, hn::Mul(hn::Mul(my, my), c.b.inv_ay2));
  const V p = StudentTP22Pi(d, c, hn::Mul(q, iz2));
  // p first: p / m.z^4 stays finite for grazing m at small gamma, where
  // 1 / m.z^4 alone would overflow (p ~ (m.z^2)^gamma there).
  const V dv = hn::Mul(hn::Mul(hn::Mul(p, iz2), iz2), c.b.inv_pi_axay);
  return hn::IfThenElseZero(hn::Gt(mz, hn::Zero(d)), dv);
}

// Lambda for w.z > 0 (the caller selects +inf below the horizon).
template <class D, class V>
HWY_INLINE V StudentTLambdaAbove(D d, const StudentTConsts<D>& c, V wx, V wy, V wz) {
  using T = hn::TFromD<D>;
  const V p2 = hn::MulAdd(hn::Mul(wx, wx), c.b.ax2, hn::Mul(hn::Mul(wy, wy), c.b.ay2));
  const V proj = hn::Sqrt(p2);
  const V rinv = hn::Div(hn::Set(d, T(1)), hn::Mul(wz, proj));
  const V a = hn::Mul(hn::Mul(wz, wz), rinv);   // w.z / proj
  if constexpr (sizeof(T) == 8) {
    // Double lanes: StudentTLambdaF64 (std_f64-inl.h), 8e-15 of max(1, Lambda).
    return hn::IfThenElseZero(hn::Gt(p2, hn::Zero(d)), StudentTLambdaF64(d, c.f64, a));
  } else {
    const V ia = hn::Mul(p2, rinv);               // proj / w.z
    const V a2 = hn::Min(hn::Mul(a, a), hn::Set(d, 1e36f));
    const V u = hn::Mul(a2, c.inv_gm1);
    const V e = hn::Exp(d, hn::Neg(hn::Mul(c.gm32, hn::Log1p(d, u))));
    const auto use_y = hn::And(hn::Lt(a, hn::Set(d, kStudentTSeriesMaxAf)),
                               hn::Lt(u, hn::Set(d, 1.0f)));
    V lam_y = hn::Zero(d), lam_l = hn::Zero(d);
    if (!hn::AllFalse(d, use_y)) {
      const V w = hn::Div(a2, hn::Add(hn::Set(d, 1.0f), u));
      V s = hn::Set(d, c.series[0]);
      for (int n = 1; n < kStudentTSeriesTerms; ++n) s = hn::MulAdd(s, w, hn::Set(d, c.series[n]));
      const V br = hn::MulAdd(w, s, c.cy);
      lam_y = hn::Max(hn::MulSub(hn::Mul(hn::Mul(c.kt, ia), e), br, hn::Set(d, 0.5f)),
                      hn::Zero(d));
    }
    if (!hn::AllTrue(d, use_y)) {
      const V ia2 = hn::Mul(ia, ia);
      const V one = hn::Set(d, 1.0f);
      V g = hn::Zero(d);
      for (int k = 0; k < kStudentTLaguerrePoints; ++k) {
        const V r = RsqrtNewton(d, hn::MulAdd(hn::Set(d, c.lag_e[k]), ia2, one));
        g = hn::MulAdd(hn::Set(d, c.lag_w[k]), hn::Mul(hn::Mul(r, r), r), g);
      }
      const V br = hn::MulAdd(hn::Mul(g, c.c2), ia2, c.c1);
      lam_l = hn::Mul(hn::Mul(hn::Mul(c.half_kt, e), ia), br);
    }
    const V lam = hn::IfThenElse(use_y, lam_y, lam_l);
    return hn::IfThenElseZero(hn::Gt(p2, hn::Zero(d)), lam);
  }
}

template <class D, class V>
HWY_INLINE V StudentTLambda(D d, const StudentTConsts<D>& c, V wx, V wy, V wz) {
  return hn::IfThenElse(hn::Gt(wz, hn::Zero(d)), StudentTLambdaAbove(d, c, wx, wy, wz),
                        hn::Set(d, std::numeric_limits<hn::TFromD<D>>::infinity()));
}

template <class D, class V, class Fr>
HWY_INLINE V StudentTBrdf(D d, const StudentTConsts<D>& c, bool separable, V ix, V iy, V iz, V ox,
                          V oy, V oz, const Fr& fresnel) {
  using T = hn::TFromD<D>;
  const V sx = hn::Add(ix, ox), sy = hn::Add(iy, oy), sz = hn::Add(iz, oz);
  const V len2 = hn::MulAdd(sx, sx, hn::MulAdd(sy, sy, hn::Mul(sz, sz)));
  const V iz2 = hn::Div(hn::Set(d, T(1)), hn::Mul(sz, sz));
  const V q = hn::MulAdd(hn::Mul(sx, sx), c.b.inv_ax2, hn::Mul(hn::Mul(sy, sy), c.b.inv_ay2));
  const V l_iz2 = hn::Mul(len2, iz2);
  // D(h) = P22(r2) (L / s.z^2)^2 / (ax ay), r2 = q / s.z^2.
  // p22 first, then the factors >= 1: (L / s.z^2)^2 = 1 / h.z^4 alone would
  // overflow for grazing pairs at small gamma, where p22 ~ h.z^(2 gamma), and a
  // subnormal p22 is not rounded again on its own scale.
  const V d_h = hn::Mul(hn::Mul(hn::Mul(StudentTP22Pi(d, c, hn::Mul(q, iz2)), l_iz2), l_iz2),
                        c.b.inv_pi_axay);
  const V li = StudentTLambdaAbove(d, c, ix, iy, iz);
  const V lo = StudentTLambdaAbove(d, c, ox, oy, oz);
  const V one = hn::Set(d, T(1));
  const V g_den = separable ? hn::Mul(hn::Add(one, li), hn::Add(one, lo))
                            : hn::Add(one, hn::Add(li, lo));
  const V f = fresnel(d, CosAtHalf(d, ox, oy, oz, sx, sy, sz, len2));
  const V four_zz = hn::Mul(hn::Set(d, T(4)), hn::Mul(iz, oz));
  const V val = hn::Mul(d_h, hn::Div(f, hn::Mul(g_den, four_zz)));
  const auto valid = hn::And(hn::And(hn::Gt(iz, hn::Zero(d)), hn::Gt(oz, hn::Zero(d))),
                             hn::Gt(len2, hn::Set(d, T(1e-30))));
  return hn::IfThenElseZero(valid, val);
}

// NDF sampling (slope_ndf.h SampleNdf with StudentTNdf::UnitSampleR2): the
// inverse radial CDF r^2 = (gamma - 1) expm1(-log1p(-u2) / (gamma - 1))
// ([Ribardiere17] eq. 42, sigma = 1), then the stretch of beckmann-inl.h.
// Error: 2e-6 absolute per component in float lanes (log1p near u2 = 1 is
// amplified by expm1's exponent, up to 33 at gamma = 1.501); 1e-14 times
// alpha_x / alpha_y in double lanes (CheckStudentTSampleNdfF64: 5e-13 at
// 1000:1, where the reference's rounding of 2 pi u1 dominates).
template <class D, class V>
HWY_INLINE void StudentTSampleNdf(D d, const StudentTConsts<D>& c, V u1, V u2, V* mx, V* my,
                                  V* mz) {
  const V uc = hn::Min(u2, hn::Set(d, SlopeSampleMaxU<hn::TFromD<D>>()));
  const V e = hn::Neg(hn::Log1p(d, hn::Neg(uc)));
  const V r2 = hn::Mul(c.gm1, hn::Expm1(d, hn::Mul(e, c.inv_gm1)));
  SampleSlopeNormal(d, c.b.ax, c.b.ay, r2, u1, mx, my, mz);
}

// The STD kernels as the batch loops take them (kernels/batch_rows-inl.h,
// MicrofacetRows): D, Lambda and the BRDF over its constants (G1 = 1 / (1 +
// Lambda), the NDF density D(m) m.z; below the Beckmann limit only: from gamma
// = 1e10 on the batch runs BeckmannKernels over c.b).
template <class D>
struct StudentTKernels {
  static constexpr bool kOwnG1 = false;
  static constexpr bool kPdfNdfFromD = true;
  const StudentTConsts<D>& c;
  template <class V>
  HWY_INLINE V Ndf(D d, V x, V y, V z) const {
    return StudentTD(d, c, x, y, z);
  }
  template <class V>
  HWY_INLINE V Lambda(D d, V x, V y, V z) const {
    return StudentTLambda(d, c, x, y, z);
  }
  template <class V, class Fr>
  HWY_INLINE V Brdf(D d, bool separable, V ix, V iy, V iz, V ox, V oy, V oz, const Fr& fr) const {
    return StudentTBrdf(d, c, separable, ix, iy, iz, ox, oy, oz, fr);
  }
};

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#endif  // BRDFBAKE_SRC_KERNELS_STD_INL_H_
