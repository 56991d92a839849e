// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Fresnel reflectance models (docs/models.md): one, schlick (F0, RGB),
// dielectric (real eta), conductor (complex eta = n + i k, RGB). Each is
// evaluated per colour channel at the cosine between the direction and the
// microfacet normal.

#ifndef BRDFBAKE_MODELS_FRESNEL_H_
#define BRDFBAKE_MODELS_FRESNEL_H_

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <string>

namespace brdfbake {

enum class FresnelKind { kOne, kSchlick, kDielectric, kConductor };

// The domain of the Fresnel parameters everywhere (ValidateFresnel in
// model.h, the batch API): F0 in [0, 1]; a dielectric's eta and a
// conductor's n in [kMinFresnelIndex, kMaxFresnelIndex]; a conductor's k in
// [0, kMaxFresnelIndex]. Every value inside is evaluated finitely.
constexpr double kMinFresnelIndex = 0.01;
constexpr double kMaxFresnelIndex = 100;

// Schlick's weight (1 - c)^5; the split-sum DFG tables use it as Fc.
template <typename T>
T SchlickWeight(T cos_theta) {
  const T m = std::clamp(T(1) - cos_theta, T(0), T(1));
  const T m2 = m * m;
  return m2 * m2 * m;
}

template <typename T>
T FresnelSchlick(T f0, T cos_theta) {
  return f0 + (T(1) - f0) * SchlickWeight(cos_theta);
}

// Unpolarized reflectance of a smooth dielectric interface, light arriving
// from the side with index 1 onto index eta (eta = n_t / n_i). Total internal
// reflection (possible when eta < 1) returns 1.
template <typename T>
T FresnelDielectric(T eta, T cos_i) {
  cos_i = std::clamp(cos_i, T(0), T(1));
  const T sin2_t = (T(1) - cos_i * cos_i) / (eta * eta);
  if (sin2_t >= T(1)) return T(1);
  const T cos_t = std::sqrt(T(1) - sin2_t);
  const T r_parl = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
  const T r_perp = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
  return T(0.5) * (r_parl * r_parl + r_perp * r_perp);
}

// Unpolarized reflectance of a conductor with complex index eta = n + i k,
// the same Fresnel equations evaluated in complex arithmetic.
template <typename T>
T FresnelConductor(T n, T k, T cos_i) {
  using C = std::complex<T>;
  cos_i = std::clamp(cos_i, T(0), T(1));
  // Grazing incidence reflects everything (and for eta = 1 the general
  // expression below is 0/0 there).
  if (cos_i == T(0)) return T(1);
  const C eta(n, k);
  const C sin2_t = C(T(1) - cos_i * cos_i) / (eta * eta);
  const C cos_t = std::sqrt(C(T(1)) - sin2_t);
  const C r_parl = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
  const C r_perp = (C(cos_i) - eta * cos_t) / (C(cos_i) + eta * cos_t);
  return T(0.5) * (std::norm(r_parl) + std::norm(r_perp));
}

// A Fresnel model with its parameters, per RGB channel.
struct Fresnel {
  FresnelKind kind = FresnelKind::kOne;
  std::array<double, 3> f0 = {1, 1, 1};    // schlick
  double eta = 1.5;                        // dielectric
  std::array<double, 3> n = {1, 1, 1};     // conductor, real part
  std::array<double, 3> k = {0, 0, 0};     // conductor, imaginary part

  static Fresnel One() { return {}; }
  static Fresnel Schlick(std::array<double, 3> f0) {
    Fresnel f;
    f.kind = FresnelKind::kSchlick;
    f.f0 = f0;
    return f;
  }
  static Fresnel Dielectric(double eta) {
    Fresnel f;
    f.kind = FresnelKind::kDielectric;
    f.eta = eta;
    return f;
  }
  static Fresnel Conductor(std::array<double, 3> n, std::array<double, 3> k) {
    Fresnel f;
    f.kind = FresnelKind::kConductor;
    f.n = n;
    f.k = k;
    return f;
  }

  // Number of distinct channels (1 when all three are equal).
  bool IsGrey() const {
    switch (kind) {
      case FresnelKind::kOne:
      case FresnelKind::kDielectric:
        return true;
      case FresnelKind::kSchlick:
        return f0[0] == f0[1] && f0[1] == f0[2];
      case FresnelKind::kConductor:
        return n[0] == n[1] && n[1] == n[2] && k[0] == k[1] && k[1] == k[2];
    }
    return true;
  }

  template <typename T>
  T Eval(T cos_theta, int channel) const {
    switch (kind) {
      case FresnelKind::kOne:
        return T(1);
      case FresnelKind::kSchlick:
        return FresnelSchlick(T(f0[channel]), cos_theta);
      case FresnelKind::kDielectric:
        return FresnelDielectric(T(eta), cos_theta);
      case FresnelKind::kConductor:
        return FresnelConductor(T(n[channel]), T(k[channel]), cos_theta);
    }
    return T(1);
  }

  std::string Name() const {
    switch (kind) {
      case FresnelKind::kOne: return "one";
      case FresnelKind::kSchlick: return "schlick";
      case FresnelKind::kDielectric: return "dielectric";
      case FresnelKind::kConductor: return "conductor";
    }
    return "one";
  }
};

}  // namespace brdfbake

#endif  // BRDFBAKE_MODELS_FRESNEL_H_
