// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0

#include "rules/glass/gen_schlick.h"

#include <algorithm>
#include <cmath>

#include "brdfbake/models/fresnel.h"
#include "brdfbake/models/ggx.h"
#include "rules/glass/glass_albedo_rule.h"

namespace brdfbake {

double GenSchlickWeight(const GenSchlickShape& shape, double c) {
  c = std::clamp(c, 0.0, 1.0);
  if (shape.exponent >= 0) return shape.exponent == 0 ? 1.0 : std::pow(1 - c, shape.exponent);
  const double f0 = (shape.eta - 1) * (shape.eta - 1) / ((shape.eta + 1) * (shape.eta + 1));
  return std::clamp((FresnelDielectric(shape.eta, c) - f0) / (1 - f0), 0.0, 1.0);
}

namespace {

// The integrand cos(theta) sin(theta) W(h) 1{r.z > 0} along a ray of the
// lune (glass_albedo_rule.h) at the 15 angles of each of k pieces, r the
// reflection of wo about h; weight(h, c) is W at c = wo.h.
template <class Weight>
void ReflectionNodes(const GlassFrame& f, const GlassRay& ray, const double* theta, double* v, int k,
                     const Weight& weight) {
  for (int i = 0; i < 15 * k; ++i) {
    const double ct = std::cos(theta[i]), st = std::sin(theta[i]);
    const Vec3<double> m = f.M(ct, st, ray.cp, ray.sp);
    const double len = std::sqrt(Dot(m, m));
    v[i] = 0;
    if (!(len > 0) || m.z < 0) continue;
    const Vec3<double> h = m / len;
    const double c = std::clamp(f.so * h.x + f.mu * h.z, 0.0, 1.0);
    // r.z = 2 c h.z - mu.
    if (!(2 * c * h.z - f.mu > 0)) continue;
    v[i] = ct * st * weight(h, c);
  }
}

// W = s_h(wo.h) (GenSchlickFactor).
struct GenSchlickNodes {
  const GlassFrame* frame;
  GenSchlickShape shape;
  void operator()(const GlassRay& ray, const double* theta, double* v, int k) const {
    ReflectionNodes(*frame, ray, theta, v, k, [&](const Vec3<double>&, double c) { return GenSchlickWeight(shape, c); });
  }
};

// W = b(wo.h) G2(wo, r) / G1(wo) (F82TintBias).
struct F82Nodes {
  const GlassFrame* frame;
  GgxNdf<double> ndf;
  Masking masking;
  double lambda_o;
  void operator()(const GlassRay& ray, const double* theta, double* v, int k) const {
    ReflectionNodes(*frame, ray, theta, v, k, [&](const Vec3<double>& h, double c) {
      const double li = ndf.Lambda(h * (2 * c) - Vec3<double>{frame->so, 0, frame->mu});
      // Separable: G1(r); height-correlated: (1 + Lambda(wo)) / (1 +
      // Lambda(wo) + Lambda(r)).
      const double g = masking == Masking::kSeparable ? 1 / (1 + li) : (1 + lambda_o) / (1 + lambda_o + li);
      return F82TintWeight(c) * g;
    });
  }
};

}  // namespace

double F82TintWeight(double c) {
  c = std::clamp(c, 0.0, 1.0);
  const double m = 1 - c, m2 = m * m;
  return c * m2 * m2 * m2;
}

RuleResult F82TintBias(double alpha, Masking masking, double mu, double tol, int max_pieces) {
  // eta 1: the reflection's horizon alone (as GenSchlickFactor).
  const GlassFrame frame(alpha, 1.0, mu);
  const GgxNdf<double> ndf(alpha);
  const double lambda_o = ndf.Lambda(Vec3<double>{frame.so, 0, frame.mu});
  return GlassAlbedoWith(frame, tol, max_pieces, F82Nodes{&frame, ndf, masking, lambda_o});
}

RuleResult GenSchlickFactor(double alpha, const GenSchlickShape& shape, double mu, double tol,
                            int max_pieces) {
  // The frame's eta only places the refraction's curves, which a
  // reflection lobe does not have: eta 1 leaves the reflection's horizon.
  // A large exponent confines (1 - c)^exponent to c below about 40 /
  // exponent (beyond, it is below e^-40): the rays are cut on that cone
  // wo.h = c_cut, which is the critical curve (wo.h)^2 = 1 - eta^2 of a
  // frame with eta = sqrt(1 - c_cut^2) (its refraction curves add cuts,
  // never error). Without the cut, at exponent 49995, r 0.5, mu 1e-4, the
  // claim was 2.6 times short of the true error.
  double eta = 1;
  if (shape.exponent > 40) {
    const double c_cut = 40 / shape.exponent;
    eta = std::sqrt((1 - c_cut) * (1 + c_cut));
  }
  const GlassFrame frame(alpha, eta, mu);
  return GlassAlbedoWith(frame, tol, max_pieces, GenSchlickNodes{&frame, shape});
}

}  // namespace brdfbake
