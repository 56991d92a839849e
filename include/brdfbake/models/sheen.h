// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The Charlie sheen BRDF of [EstevezKulla17]: an inverted microfacet
// distribution whose normals lie near the surface plane,
//   D(m) = (2 + 1/alpha) sin(theta_m)^(1/alpha) / (2 pi)        (eq. 2),
// normalised so that its projected area is one, integral D(m) cos(theta_m)
// dm = 1 (with s = sin(theta_m): integral_0^1 (2 + 1/alpha) s^(1/alpha + 1)
// ds = 1). alpha is the width the engines pass, alpha = r^2 of the
// perceptual sheen roughness r; it is taken in [kMinSheenAlpha, 1].
//
// f(wi, wo) = F D(h) V with one of these visibility terms V
// (SheenVisibility; docs/models.md names the engines that use each):
//  - neubelt ([Neubelt13]): V = 1 / (4 (NoL + NoV - NoL NoV)), a smooth
//    replacement of the Cook-Torrance denominator with no masking;
//  - conty-kulla ([EstevezKulla17] section 3): V = G2 / (4 NoL NoV), the
//    height-correlated G2 = 1 / (1 + Lambda(NoV) + Lambda(NoL)) of the
//    paper's fitted Lambda,
//      Lambda(c) = exp(L(c))                  for c < 1/2,
//                  exp(2 L(1/2) - L(1 - c))   for c >= 1/2,
//      L(x) = a / (1 + b x^p) + d x + e,
//    each of (a, b, p, d, e) interpolated between the paper's fits at
//    alpha = 0 and alpha = 1 with the weight (1 - alpha)^2 on the first
//    (the paper's Table 1 and the line below it, whose "r" is this alpha).
//    Lambda grows without bound at grazing cosines, but not fast enough
//    to keep V below 1 where both cosines are small (V(0.01, 0.01) > 1).
//  - enterprise-pbr ([EnterprisePbr]): the same G2 with a refined fit of
//    L, its coefficients interpolated by another weight (CharlieLFit);
//  - neubelt-clamped, conty-kulla-clamped: min(V, 1) of the first two
//    ([KhronosSampleRenderer]'s V_Ashikhmin and V_Sheen).
// The "terminator softening" of the paper's section 4 is not part of
// any V.

#ifndef BRDFBAKE_MODELS_SHEEN_H_
#define BRDFBAKE_MODELS_SHEEN_H_

#include <algorithm>
#include <cmath>
#include <limits>

#include "brdfbake/models/constants.h"
#include "brdfbake/models/vec3.h"

namespace brdfbake {

// The visibility term V of f = F D(h) V, as the engines write it:
//  - kNeubelt: [Neubelt13]'s 1 / (4 (NoL + NoV - NoL NoV));
//  - kContyKulla: G2 / (4 NoL NoV) with [EstevezKulla17]'s fitted Lambda;
//  - kNeubeltClamped, kContyKullaClamped: the same capped at V <= 1, as the
//    Khronos sample renderer's V_Ashikhmin and V_Sheen are (docs/models.md);
//  - kEnterprisePbr: G2 / (4 NoL NoV) with [EnterprisePbr]'s refined fit of
//    the same Lambda (its coefficients interpolated by w(alpha), CharlieLFit).
enum class SheenVisibility { kNeubelt, kContyKulla, kNeubeltClamped, kContyKullaClamped, kEnterprisePbr };

inline constexpr SheenVisibility kSheenVisibilities[] = {
    SheenVisibility::kNeubelt, SheenVisibility::kContyKulla, SheenVisibility::kNeubeltClamped,
    SheenVisibility::kContyKullaClamped, SheenVisibility::kEnterprisePbr};

// "neubelt", "conty-kulla", "neubelt-clamped", "conty-kulla-clamped",
// "enterprise-pbr".
inline const char* SheenVisibilityName(SheenVisibility v) {
  switch (v) {
    case SheenVisibility::kNeubelt: return "neubelt";
    case SheenVisibility::kContyKulla: return "conty-kulla";
    case SheenVisibility::kNeubeltClamped: return "neubelt-clamped";
    case SheenVisibility::kContyKullaClamped: return "conty-kulla-clamped";
    case SheenVisibility::kEnterprisePbr: return "enterprise-pbr";
  }
  return "?";
}

// Whether V holds a masking term G2 of a Lambda (every variant but the
// neubelt ones).
inline constexpr bool SheenHasLambda(SheenVisibility v) {
  return v != SheenVisibility::kNeubelt && v != SheenVisibility::kNeubeltClamped;
}

// Whether V is capped at 1.
inline constexpr bool SheenClampsVisibility(SheenVisibility v) {
  return v == SheenVisibility::kNeubeltClamped || v == SheenVisibility::kContyKullaClamped;
}

// The smallest alpha the Charlie model evaluates; below it the lobe is
// evaluated at this width. E(mu) vanishes as alpha -> 0 for every mu > 0
// but converges ever more slowly at grazing mu (at alpha = 1e-6 it still
// differs from 0 for mu below about 1e-3).
template <typename T>
inline constexpr T kMinSheenAlpha = T(1e-6);

template <typename T>
T ClampSheenAlpha(T alpha) {
  return std::clamp(alpha, kMinSheenAlpha<T>, T(1));
}

// The coefficients of the fitted L(x) = a / (1 + b x^p) + d x + e of the
// Lambda at width alpha. The one place the fits are written: the scalar
// model and the kernels (kernels/sheen-inl.h) take them here.
//  - [EstevezKulla17] Table 1: t = (1 - alpha)^2 weighs the alpha = 0 fit
//    against the alpha = 1 fit.
//  - [EnterprisePbr] (section "Sheen", the refined fit): w(alpha) = -1.59612
//    / (1 + 0.20375 alpha^-0.55825) + 1.32805 weighs the second row of its
//    table against the first, p = (1 - w) p0 + w p1 (its caption has p0 and
//    p1 the other way round; its shipped Sheen_E follows this order,
//    tests/engines/engine_tables_test.cc).
template <typename T>
struct CharlieLFit {
  T a, b, p, d, e;
  explicit CharlieLFit(T alpha, SheenVisibility v = SheenVisibility::kContyKulla) {
    if (v == SheenVisibility::kEnterprisePbr) {
      const T w = T(-1.59612) / (T(1) + T(0.20375) * std::pow(alpha, T(-0.55825))) + T(1.32805);
      a = T(11.9095) + w * (T(13.7000) - T(11.9095));
      b = T(4.68753) + w * (T(2.92754) - T(4.68753));
      p = T(0.33467) + w * (T(0.28670) - T(0.33467));
      d = T(-2.22664) + w * (T(-0.81757) - T(-2.22664));
      e = T(-1.76591) + w * (T(-1.22466) - T(-1.76591));
      return;
    }
    const T t = (T(1) - alpha) * (T(1) - alpha);
    a = T(21.5473) + t * (T(25.3245) - T(21.5473));
    b = T(3.82987) + t * (T(3.32435) - T(3.82987));
    p = T(0.19823) + t * (T(0.16801) - T(0.19823));
    d = T(-1.97760) + t * (T(-1.27393) - T(-1.97760));
    e = T(-4.32054) + t * (T(-4.85967) - T(-4.32054));
  }
  T operator()(T x) const { return a / (T(1) + b * std::pow(x, p)) + d * x + e; }
};

// L(x) at width alpha.
template <typename T>
T CharlieL(T alpha, T x, SheenVisibility v = SheenVisibility::kContyKulla) {
  return CharlieLFit<T>(alpha, v)(x);
}

// The power p of x in L(x) at width alpha.
template <typename T>
T CharlieLPower(T alpha, SheenVisibility v = SheenVisibility::kContyKulla) {
  return CharlieLFit<T>(alpha, v).p;
}

template <typename T>
class CharlieSheen {
 public:
  CharlieSheen(T alpha, SheenVisibility visibility)
      : alpha_(ClampSheenAlpha(alpha)), visibility_(visibility), fit_(alpha_, visibility) {
    q_ = T(0.5) / alpha_;
    k_ = (T(2) + T(1) / alpha_) / kTwoPi<T>;
  }

  T alpha() const { return alpha_; }
  SheenVisibility visibility() const { return visibility_; }

  // D at cos(theta_m) = c in [0, 1]: k (1 - c^2)^(1 / (2 alpha)), the
  // power as exp(q log1p(-c^2)) so that a c near 0 keeps its digits.
  T DCos(T c) const { return DCos2(c * c); }
  // The same at c^2 = cos(theta_m)^2.
  T DCos2(T c2) const {
    if (!(c2 < T(1))) return T(0);
    return k_ * std::exp(q_ * std::log1p(-c2));
  }
  T D(const Vec3<T>& m) const { return m.z > T(0) ? DCos(std::min(m.z, T(1))) : T(0); }

  // The fitted Lambda at a cosine c in (0, 1] (the enterprise-pbr fit
  // for that visibility, else conty-kulla's); +inf at c <= 0.
  T LambdaCos(T c) const {
    if (!(c > T(0))) return std::numeric_limits<T>::infinity();
    c = std::min(c, T(1));
    if (c < T(0.5)) return std::exp(fit_(c));
    return std::exp(T(2) * fit_(T(0.5)) - fit_(T(1) - c));
  }
  T Lambda(const Vec3<T>& w) const { return LambdaCos(w.z); }
  T G1(const Vec3<T>& w) const { return w.z > T(0) ? T(1) / (T(1) + LambdaCos(w.z)) : T(0); }
  // The height-correlated G2 of the Lambda.
  T G2Cos(T nol, T nov) const {
    if (!(nol > T(0)) || !(nov > T(0))) return T(0);
    return T(1) / (T(1) + LambdaCos(nov) + LambdaCos(nol));
  }

  // V such that f = F D(h) V, for NoL, NoV in (0, 1].
  T Visibility(T nol, T nov) const {
    if (!(nol > T(0)) || !(nov > T(0))) return T(0);
    const T v = SheenHasLambda(visibility_) ? G2Cos(nol, nov) / (T(4) * nol * nov)
                                            : T(1) / (T(4) * (nol + nov - nol * nov));
    return SheenClampsVisibility(visibility_) ? std::min(v, T(1)) : v;
  }

  // f(wi, wo) with F = 1: D(h) V for wi, wo above the horizon, 0 else.
  T Brdf(const Vec3<T>& wi, const Vec3<T>& wo) const {
    if (!(wi.z > T(0)) || !(wo.z > T(0))) return T(0);
    const Vec3<T> s = wi + wo;
    const T len = Length(s);
    if (!(len > T(0))) return T(0);
    return DCos(std::min(s.z / len, T(1))) * Visibility(std::min(wi.z, T(1)), std::min(wo.z, T(1)));
  }

  // Normals with density D(m) m.z: phi = 2 pi u1 and, with s =
  // sin(theta_m), whose density is (2 + 1/alpha) s^(1/alpha + 1), the CDF
  // s^(2 + 1/alpha) inverted at u2.
  Vec3<T> SampleNdf(T u1, T u2) const {
    const T s = std::pow(std::clamp(u2, T(0), T(1)), alpha_ / (T(2) * alpha_ + T(1)));
    const T c = std::sqrt(std::max(T(0), (T(1) - s) * (T(1) + s)));
    const T phi = kTwoPi<T> * u1;
    return {s * std::cos(phi), s * std::sin(phi), c};
  }
  T PdfNdf(const Vec3<T>& m) const { return m.z > T(0) ? D(m) * std::min(m.z, T(1)) : T(0); }

 private:
  T alpha_;
  SheenVisibility visibility_;
  CharlieLFit<T> fit_;
  T q_, k_;
};

}  // namespace brdfbake

#endif  // BRDFBAKE_MODELS_SHEEN_H_
