// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The rough dielectric BSDF of [Walter07]: reflection and refraction by
// the microfacets of one interface between two dielectrics, over any NDF
// of models/ (GgxNdf, BeckmannNdf: D, Lambda and the visible normals).
//
// Conventions (docs/models.md, "glass"):
//  - n = +z; wi (light) and wo (view) point away from the surface and may
//    lie on either side. The side z > 0 has index 1, the side z < 0 the
//    relative index eta = eta_t / eta_i of the medium below: eta > 1 is a
//    view from outside (entering a denser medium), eta < 1 a view from
//    inside the dense medium (leaving it, with total internal reflection).
//    eta_w denotes the index of the side of w: 1 for w.z > 0, eta below.
//  - Reflection (wi, wo on the same side), [Walter07] eq. 13, 20:
//      h = normalize(wi + wo), f_r = F D(h) G2 / (4 |wi.n| |wo.n|).
//  - Refraction (opposite sides), [Walter07] eq. 16, 21 with i = wi, o = wo:
//      h = -(eta_i wi + eta_o wo) / |eta_i wi + eta_o wo|,
//      f_t = eta_o^2 (1 - F) D(h) G2 |wi.h| |wo.h|
//            / (|wi.n| |wo.n| (eta_i wi.h + eta_o wo.h)^2),
//    with eta_i = eta_wi, eta_o = eta_wo. This is the radiance BSDF
//    (kRadiance): a smooth interface carries L_o = (1 - F) (eta_o /
//    eta_i)^2 L_i. It obeys the reciprocity of refraction
//      f_t(wi, wo) / eta_o^2 = f_t(wo, wi) / eta_i^2,
//    and conserves energy over the outgoing directions: integral of
//    f(wi, wo) |wo.n| dwo <= 1 for each wi. Its adjoint (kImportance,
//    pbrt's "importance" transport) swaps the roles, f*(wi, wo) =
//    f(wo, wi): eta_i^2 in place of eta_o^2. The tables' E(wo) = integral
//    of f* |wi.n| dwi over the sphere is the energy albedo of wo, which
//    is 1 minus the energy the single-scattering model loses, and exactly
//    1 for a smooth interface.
//  - h is always turned to +z (D(h) is zero below); a pair counts only if
//    wi.h and wo.h have the signs of wi.n and wo.n (the factor chi+(v.h /
//    v.n) of [Walter07]'s G1); so a refraction pair has wi.h and wo.h of
//    opposite signs, and eta_i wi.h + eta_o wo.h = -+|eta_i wi + eta_o wo|
//    never vanishes for eta != 1.
//  - F is the exact dielectric reflectance (fresnel.h, FresnelDielectric)
//    at |wo.h| for light crossing from the side of wo into the other:
//    relative index eta for wo.z > 0, 1/eta for wo.z < 0. For a refraction
//    pair it equals the value at |wi.h| from the other side ([Walter07]
//    eq. 22 is the same function), and the code takes it from the side
//    above, F(eta, |w.h|) with w the direction above: the same number for
//    both orders of the pair, so reciprocity holds to rounding (from the
//    dense side near the critical angle the reflectance loses digits).
//  - Lambda is the NDF's at the direction turned into z > 0 (|w.n|), the
//    microsurface seen from below being the same surface upside down.
//    G2 separable = G1(wi) G1(wo), height-correlated = 1 / (1 + Lambda(wi)
//    + Lambda(wo)) ([Heitz14], its two forms of G2), on both sides, as
//    pbrt-v4 and Cycles use it for refraction too. Under Smith's
//    assumption the heights a refracted ray must clear are those below the
//    microfacet, not above it, so the exact height-correlated term of a
//    refraction pair is integral_0^1 u^Lambda(wi) (1 - u)^Lambda(wo) du =
//    B(1 + Lambda(wi), 1 + Lambda(wo)) (Beta function; HeightCorrelatedBeta
//    below, derived here and checked by quadrature in the tests); it is at
//    most 1 / (1 + Lambda(wi) + Lambda(wo)), equal when either Lambda is 0.
//    The BSDF uses the engines' form.
//  - eta is clamped to [kMinFresnelIndex, kMaxFresnelIndex] = [0.01, 100],
//    alpha (by the NDF) to at least 1e-4. At eta = 1 there is no interface:
//    F = 0 and refraction is the delta wi = -wo, which f does not
//    represent: f = 0, and the sampler's refraction gives no sample.
//
// Sampling (wi from wo, three uniforms): a visible normal m of wo (the
// NDF's SampleVisible, in the frame turned so that wo.z > 0), then
// reflection with probability F(wo.m), refraction otherwise. Its density
// counts both branches wherever they land ([Walter07] eq. 14, 17 for the
// Jacobians):
//   pdf(wi) = D_wo(m_r) F / (4 |wo.m_r|)
//           + D_wo(m_t) (1 - F) eta_i^2 |wi.m_t| / (eta_i wi.m_t + eta_o wo.m_t)^2,
// m_r = normalize(wi + wo), m_t from the refraction pair (eta_i the index
// of the side opposite to wo, whatever side wi is on), D_wo the visible
// normals' density ([Heitz18] eq. 3). It integrates to 1 over the sphere;
// a sample whose branch lands on the other side (a reflection below the
// horizon, a refraction back to wo's side) is still a sample, where f has
// the value of the other branch's pair (usually 0).

#ifndef BRDFBAKE_MODELS_DIELECTRIC_H_
#define BRDFBAKE_MODELS_DIELECTRIC_H_

#include <algorithm>
#include <cmath>

#include "brdfbake/models/brdf.h"
#include "brdfbake/models/fresnel.h"
#include "brdfbake/models/vec3.h"

namespace brdfbake {

// Which side's index multiplies the refraction term: kRadiance, eta_o^2 of
// wo's side ([Walter07] eq. 21); kImportance, eta_i^2 of wi's side (the
// adjoint, f*(wi, wo) = f(wo, wi)).
enum class DielectricTransport { kRadiance, kImportance };

inline const char* DielectricTransportName(DielectricTransport t) {
  return t == DielectricTransport::kRadiance ? "radiance" : "importance";
}

// Which scattering of the dielectric an albedo counts: reflection plus
// refraction (the energy albedo), the reflection lobe alone (the energy a
// rough dielectric reflects, weighted by F) or the refraction lobe alone
// (weighted by 1 - F). Reflection plus refraction is their sum.
// kTransmissionSchlick is the refraction lobe weighted by 1 - (1 -
// |wo.h|)^5 instead of 1 - F, the complement of Schlick's weight with F0 =
// 0 ([Schlick94]): EEVEE's btdf_ggx ([Blender], eevee_lut_comp.glsl's
// ggx_btdf_gt_one), which its renderer multiplies by 1 - F0. It does not
// depend on F, so the index may exceed the Fresnel model's range: it
// takes any eta >= 1 up to inf, where the refraction is -h.
enum class DielectricPart { kBoth, kReflection, kTransmission, kTransmissionSchlick };

inline const char* DielectricPartName(DielectricPart p) {
  switch (p) {
    case DielectricPart::kBoth: return "both";
    case DielectricPart::kReflection: return "reflection";
    case DielectricPart::kTransmission: return "transmission";
    case DielectricPart::kTransmissionSchlick: return "transmission-schlick";
  }
  return "both";
}

// kTransmissionSchlick's weight, as the files' brdfbake.fresnel states it.
inline constexpr const char* kSchlickComplementFresnel =
    "none on the refraction: weighted by 1 - (1 - |wo.h|)^5 (Schlick's complement, F0 = 0)";

// Whether the part counts the refraction lobe alone (with either weight).
inline bool RefractionPart(DielectricPart p) {
  return p == DielectricPart::kTransmission || p == DielectricPart::kTransmissionSchlick;
}

template <typename T>
T ClampDielectricEta(T eta) {
  return std::clamp(eta, T(kMinFresnelIndex), T(kMaxFresnelIndex));
}

// The exact height-correlated masking of a refraction pair under Smith's
// assumption: integral_0^1 u^lambda_i (1 - u)^lambda_o du (the fraction u
// of heights below the microfacet clears the ray above it, 1 - u the ray
// below) = B(1 + lambda_i, 1 + lambda_o) = Gamma(1 + lambda_i) Gamma(1 +
// lambda_o) / Gamma(2 + lambda_i + lambda_o), through log-gamma (relative
// error about 1e-16 times the log-gammas' size).
template <typename T>
T HeightCorrelatedBeta(T lambda_i, T lambda_o) {
  if (!(lambda_i < T(1e300)) || !(lambda_o < T(1e300))) return T(0);
  const T a = T(1) + lambda_i, b = T(1) + lambda_o;
  return std::exp(std::lgamma(a) + std::lgamma(b) - std::lgamma(a + b));
}

// A direction drawn by RoughDielectric::Sample: wi, its density in solid
// angle, and weight = f(wi, wo) |wi.n| / pdf (0 where pdf = 0).
template <typename T>
struct DielectricSample {
  Vec3<T> wi;
  T pdf = 0;
  T weight = 0;
  bool reflected = false;
};

template <typename T, class Ndf>
class RoughDielectric {
 public:
  RoughDielectric(const Ndf& ndf, T eta, Masking masking = Masking::kHeightCorrelated,
                  DielectricTransport transport = DielectricTransport::kRadiance)
      : ndf_(ndf), eta_(ClampDielectricEta(eta)), masking_(masking), transport_(transport) {}

  const Ndf& ndf() const { return ndf_; }
  T eta() const { return eta_; }
  Masking masking() const { return masking_; }
  DielectricTransport transport() const { return transport_; }

  // The index of the side of w (1 above, eta below).
  T IndexOf(const Vec3<T>& w) const { return w.z > T(0) ? T(1) : eta_; }
  // The relative index seen from the side of w: (other side) / (w's side).
  T RelativeEta(const Vec3<T>& w) const { return w.z > T(0) ? eta_ : T(1) / eta_; }
  // F for light meeting a microfacet from the side of w at cosine c = |w.m|.
  T Fresnel(const Vec3<T>& w, T c) const { return FresnelDielectric(RelativeEta(w), c); }

  // Lambda and G1 of w on either side (the NDF's at w turned to z > 0).
  T Lambda(const Vec3<T>& w) const { return ndf_.Lambda(Up(w)); }
  T G1(const Vec3<T>& w) const { return ndf_.G1(Up(w)); }

  // The half vector of the pair, turned to +z: the reflection half vector
  // for wi, wo on one side, the refraction one ([Walter07] eq. 16) across.
  // False when it is undefined (wi = -wo on one side, a horizontal h, a
  // direction on the horizon).
  bool HalfVector(const Vec3<T>& wi, const Vec3<T>& wo, Vec3<T>* h) const {
    if (wi.z == T(0) || wo.z == T(0)) return false;
    const Vec3<T> s = HalfSum(wi, wo);
    const T len2 = Dot(s, s);
    if (!(len2 > T(0)) || s.z == T(0)) return false;
    *h = (s.z > T(0) ? s : -s) / std::sqrt(len2);
    return true;
  }

  // G2 of the pair at its half vector h (zero unless wi.h and wo.h have the
  // signs of wi.n and wo.n).
  T G2(const Vec3<T>& wi, const Vec3<T>& wo, const Vec3<T>& h) const {
    if (!(Dot(wi, h) * wi.z > T(0)) || !(Dot(wo, h) * wo.z > T(0))) return T(0);
    if (masking_ == Masking::kSeparable) return G1(wi) * G1(wo);
    return T(1) / (T(1) + Lambda(wi) + Lambda(wo));
  }

  // f(wi, wo) over the whole sphere of both directions: f_r on one side,
  // f_t across (with the transport's index factor); 0 on the horizon.
  T Bsdf(const Vec3<T>& wi, const Vec3<T>& wo) const {
    if (eta_ == T(1)) return T(0);  // no interface (F = 0; refraction is a delta)
    Vec3<T> h;
    if (!HalfVector(wi, wo, &h)) return T(0);
    const T g2 = G2(wi, wo, h);
    if (!(g2 > T(0))) return T(0);
    const T d = ndf_.D(h);
    const T ci = Dot(wi, h), co = Dot(wo, h);
    const T nn = std::abs(wi.z) * std::abs(wo.z);
    if (SameSide(wi, wo)) {
      // wi.h = wo.h in exact arithmetic; their mean is the same number for
      // both orders of the pair (F is steep next to the critical angle).
      const T c = T(0.5) * (std::abs(ci) + std::abs(co));
      return Fresnel(wo, std::min(c, T(1))) * d * g2 / (T(4) * nn);
    }
    // A refraction pair's F from the side above (the same value as from
    // below, computed once for both orders of the pair).
    const T f = FresnelDielectric(eta_, std::abs(wo.z > T(0) ? co : ci));
    // Eq. 21's (eta_i wi.h + eta_o wo.h)^2 = |s|^2 (h = -+s / |s|), taken
    // from s: the two terms cancel when eta is near 1.
    const Vec3<T> s = HalfSum(wi, wo);
    const T k = transport_ == DielectricTransport::kRadiance ? IndexOf(wo) : IndexOf(wi);
    return k * k * (T(1) - f) * d * g2 * std::abs(ci * co) / (nn * Dot(s, s));
  }
  // The reflection and refraction parts (each 0 where the other applies).
  T Reflection(const Vec3<T>& wi, const Vec3<T>& wo) const {
    return SameSide(wi, wo) ? Bsdf(wi, wo) : T(0);
  }
  T Transmission(const Vec3<T>& wi, const Vec3<T>& wo) const {
    return SameSide(wi, wo) ? T(0) : Bsdf(wi, wo);
  }
  // The cosine-weighted value f(wi, wo) |wi.n|, the integrand of E(wo).
  T BsdfCos(const Vec3<T>& wi, const Vec3<T>& wo) const { return Bsdf(wi, wo) * std::abs(wi.z); }

  // The density of Sample (see the header comment); 0 for wo on the horizon.
  T Pdf(const Vec3<T>& wi, const Vec3<T>& wo) const {
    if (wo.z == T(0)) return T(0);
    // The frame turned so that wo.z > 0.
    const Vec3<T> o = Up(wo), i = wo.z > T(0) ? wi : Flip(wi);
    const T eta_t = wo.z > T(0) ? eta_ : T(1) / eta_;  // relative index of the other side
    T pdf = 0;
    // Reflection about m_r = normalize(wi + wo).
    const Vec3<T> sr = i + o;
    const T lr2 = Dot(sr, sr);
    if (lr2 > T(0)) {
      const Vec3<T> m = sr / std::sqrt(lr2);
      const T c = Dot(o, m);
      if (c > T(0) && m.z > T(0)) {
        pdf += ndf_.DVisible(o, m) * FresnelDielectric(eta_t, c) / (T(4) * c);
      }
    }
    // Refraction through m_t, -(eta_t i + o) turned to o's side.
    Vec3<T> st = eta_t * i + o;
    const T lt2 = Dot(st, st);
    if (lt2 > T(0) && eta_ != T(1)) {
      st = st / std::sqrt(lt2);
      if (Dot(o, st) < T(0)) st = -st;
      const T c = Dot(o, st), ci = Dot(i, st);
      if (c > T(0) && ci < T(0) && st.z > T(0)) {
        const T den = eta_t * ci + c;
        pdf += ndf_.DVisible(o, st) * (T(1) - FresnelDielectric(eta_t, c)) * eta_t * eta_t *
               std::abs(ci) / (den * den);
      }
    }
    return pdf;
  }

  // wi drawn from wo with (u1, u2) for the visible normal and u3 for the
  // branch; pdf = 0 (no sample) for wo on the horizon.
  DielectricSample<T> Sample(const Vec3<T>& wo, T u1, T u2, T u3) const {
    DielectricSample<T> s;
    if (wo.z == T(0)) return s;
    const Vec3<T> o = Up(wo);
    const Vec3<T> m = ndf_.SampleVisible(o, u1, u2);
    const T eta_t = wo.z > T(0) ? eta_ : T(1) / eta_;
    const T c = std::min(Dot(o, m), T(1));
    const T f = FresnelDielectric(eta_t, std::max(c, T(0)));
    Vec3<T> i;
    if (u3 < f) {
      i = Reflect(o, m);
      s.reflected = true;
    } else {
      // Snell: eta_t^2 (1 - c_t^2) = 1 - c^2, wi = -o / eta_t + (c / eta_t - c_t) m.
      const T c_t2 = T(1) - (T(1) - c * c) / (eta_t * eta_t);
      // Total internal reflection (F = 1 took the other branch but for u3 =
      // 1), or no interface (eta = 1: the delta f does not hold).
      if (!(c_t2 >= T(0)) || eta_ == T(1)) return s;
      i = Normalize(o * (-T(1) / eta_t) + m * (c / eta_t - std::sqrt(c_t2)));
    }
    s.wi = wo.z > T(0) ? i : Flip(i);
    s.pdf = Pdf(s.wi, wo);
    s.weight = s.pdf > T(0) ? BsdfCos(s.wi, wo) / s.pdf : T(0);
    return s;
  }

 private:
  static bool SameSide(const Vec3<T>& a, const Vec3<T>& b) { return (a.z > T(0)) == (b.z > T(0)); }
  // The unnormalized half vector: wi + wo on one side; across, eta_i wi +
  // eta_o wo = eta w_below + w_above in one rounding per component (fma),
  // which keeps the digits of s when eta is near 1 and wi near -wo.
  Vec3<T> HalfSum(const Vec3<T>& wi, const Vec3<T>& wo) const {
    if (SameSide(wi, wo)) return wi + wo;
    const Vec3<T>& a = wi.z > T(0) ? wi : wo;  // above
    const Vec3<T>& b = wi.z > T(0) ? wo : wi;  // below
    return {std::fma(eta_, b.x, a.x), std::fma(eta_, b.y, a.y), std::fma(eta_, b.z, a.z)};
  }
  static Vec3<T> Flip(const Vec3<T>& w) { return {w.x, w.y, -w.z}; }
  static Vec3<T> Up(const Vec3<T>& w) { return {w.x, w.y, std::abs(w.z)}; }

  Ndf ndf_;
  T eta_;
  Masking masking_;
  DielectricTransport transport_;
};

template <typename T, class Ndf>
RoughDielectric<T, Ndf> MakeRoughDielectric(
    const Ndf& ndf, T eta, Masking masking = Masking::kHeightCorrelated,
    DielectricTransport t = DielectricTransport::kRadiance) {
  return RoughDielectric<T, Ndf>(ndf, eta, masking, t);
}

}  // namespace brdfbake

#endif  // BRDFBAKE_MODELS_DIELECTRIC_H_
