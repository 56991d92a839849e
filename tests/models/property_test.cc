// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Seeded random sweep over the documented domain (docs/tables.md, "Domain
// and clamping policy"; alpha up to kMaxAlpha and gamma up to the largest
// double): every model quantity stays finite and non-negative (Lambda is
// +inf only on and below the horizon), samplers return unit vectors, in
// double and in float, and small bakes with random settings give finite
// tables within [0, 1].

#include <cmath>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "brdfbake/bake.h"
#include "brdfbake/model.h"
#include "brdfbake/models/beckmann.h"
#include "brdfbake/models/ellipsoid.h"
#include "brdfbake/models/ggx.h"
#include "brdfbake/models/sel.h"
#include "brdfbake/models/std_ndf.h"

namespace brdfbake {
namespace {

struct Sweep {
  std::mt19937_64 rng;
  std::uniform_real_distribution<double> uni{0.0, 1.0};
  explicit Sweep(uint64_t seed) : rng(seed) {}
  double U() { return uni(rng); }
  double LogU(double lo, double hi) { return lo * std::pow(hi / lo, U()); }
  // Directions: random, near the horizon, on it, below it, the pole.
  Vec3<double> Dir() {
    const int kind = static_cast<int>(U() * 6);
    const double phi = 2 * 3.141592653589793 * U();
    switch (kind) {
      case 0: return FromMuPhi(LogU(1e-8, 1e-2), phi);
      case 1: return FromMuPhi(0.0, phi);
      case 2: return FromMuPhi(-U(), phi);
      case 3: return Vec3<double>(0, 0, 1);
      default: return FromMuPhi(U(), phi);
    }
  }
  ModelParams Model() {
    ModelParams p;
    static const char* kNames[] = {"ggx", "beckmann", "std", "ellipsoid"};
    p.kind = ParseModelKind(kNames[static_cast<int>(U() * 4)]);
    // Mostly the tested range [1e-4, 1], also up to the bound kMaxAlpha and
    // at it (docs/tables.md, "Domain and clamping policy").
    const double ka = U();
    p.alpha_x = ka < 0.7 ? LogU(1e-4, 1.0) : (ka < 0.85 ? LogU(1.0, kMaxAlpha) : kMaxAlpha);
    p.alpha_y = std::clamp(p.alpha_x * LogU(1e-3, 1e3), 1e-4, kMaxAlpha);
    const double g = U();
    p.gamma = g < 0.1 ? std::numeric_limits<double>::infinity()
                      : (g < 0.2 ? 1.5 + LogU(1e-3, 1e-1)
                                 : (g < 0.25 ? (g < 0.23 ? LogU(1e15, 1.7e308)
                                                         : std::numeric_limits<double>::max())
                                             : 1.5 + LogU(1e-3, 1e6)));
    const double max_angle = 80.0 * 3.141592653589793 / 180.0;
    p.theta_x = (2 * U() - 1) * max_angle;
    p.theta_y = (2 * U() - 1) * max_angle;
    p.theta_z = (2 * U() - 1) * max_angle;
    return p;
  }
};

bool FiniteNonNegative(double v) { return std::isfinite(v) && v >= 0; }

TEST(PropertyTest, ModelQuantitiesAreFiniteOverTheDomain) {
  Sweep s(2026);
  const Fresnel fresnels[] = {Fresnel::One(), Fresnel::Schlick({0.04, 0.5, 1.0}),
                              Fresnel::Dielectric(1.5), Fresnel::Dielectric(0.5),
                              Fresnel::Conductor({0.2, 1.1, 2.9}, {3.9, 0.5, 0.0})};
  for (int trial = 0; trial < 400; ++trial) {
    const ModelParams p = s.Model();
    const auto model = MakeModel(p);
    for (int i = 0; i < 200; ++i) {
      const Vec3<double> a = s.Dir(), b = i % 17 == 0 ? -a : s.Dir();
      const std::string where = p.ToJson() + " a=(" + std::to_string(a.x) + "," +
                                std::to_string(a.y) + "," + std::to_string(a.z) + ")";
      ASSERT_TRUE(FiniteNonNegative(model->D(a))) << where;
      const double lambda = model->Lambda(a);
      ASSERT_FALSE(std::isnan(lambda)) << where;
      ASSERT_GE(lambda, 0.0) << where;
      if (a.z > 0) {
        ASSERT_TRUE(std::isfinite(lambda)) << where;
      }
      ASSERT_TRUE(FiniteNonNegative(model->G1(a))) << where;
      ASSERT_LE(model->G1(a), 1.0) << where;
      for (Masking m : {Masking::kHeightCorrelated, Masking::kSeparable}) {
        ASSERT_TRUE(FiniteNonNegative(model->G2(a, b, m))) << where;
        const double f = model->Brdf(a, b, fresnels[i % 5], m, i % 3);
        ASSERT_TRUE(FiniteNonNegative(f)) << where;
      }
      if (b.z > 0) {
        const Vec3<double> m = model->Sample(b, s.U(), s.U());
        ASSERT_TRUE(std::isfinite(m.x) && std::isfinite(m.y) && std::isfinite(m.z)) << where;
        ASSERT_NEAR(Length(m), 1.0, 1e-9) << where;
        ASSERT_TRUE(FiniteNonNegative(model->Pdf(b, m))) << where;
      }
    }
  }
}

template <class Ndf>
void CheckFloat(const Ndf& ndf, Sweep& s, const char* name) {
  for (int i = 0; i < 200; ++i) {
    const Vec3<float> a(s.Dir());
    const float d = ndf.D(a), g1 = ndf.G1(a), l = ndf.Lambda(a);
    ASSERT_TRUE(std::isfinite(d) && d >= 0) << name << " D at z=" << a.z;
    ASSERT_TRUE(std::isfinite(g1) && g1 >= 0 && g1 <= 1) << name;
    ASSERT_FALSE(std::isnan(l)) << name;
  }
}

TEST(PropertyTest, FloatReferencesAreFinite) {
  Sweep s(7);
  for (int trial = 0; trial < 200; ++trial) {
    const ModelParams p = s.Model();
    const float ax = float(p.alpha_x), ay = float(p.alpha_y);
    CheckFloat(GgxNdf<float>(ax, ay), s, "ggx");
    CheckFloat(BeckmannNdf<float>(ax, ay), s, "beckmann");
    CheckFloat(StudentTNdf<float>(ax, ay, float(p.gamma)), s, "std");
    CheckFloat(EllipsoidNdf<float>(ax, ay, float(p.theta_x), float(p.theta_y), float(p.theta_z)),
               s, "ellipsoid");
    const SelLobe<float> sel = SelLobe<float>::FromAngles(ax, ay, float(p.theta_x),
                                                          float(p.theta_y), float(p.theta_z));
    for (int i = 0; i < 50; ++i) {
      const float k = sel.K(Vec3<float>(s.Dir()));
      ASSERT_TRUE(std::isfinite(k) && k >= 0) << "sel";
    }
  }
}

TEST(PropertyTest, SmallBakesWithRandomSettingsAreFinite) {
  Sweep s(99);
  for (int trial = 0; trial < 12; ++trial) {
    BakeSpec spec;
    static const char* kNames[] = {"ggx", "beckmann", "std"};
    spec.model.kind = ParseModelKind(kNames[trial % 3]);
    spec.model.gamma = trial % 2 ? 1.5 + s.LogU(1e-3, 1e3) : std::numeric_limits<double>::infinity();
    spec.table = static_cast<TableKind>(trial % 3 == 2 ? 2 : 0);
    spec.integrator = static_cast<IntegratorKind>(trial % 4);
    spec.samples = spec.integrator == IntegratorKind::kQuadrature ? 48 : 256;
    spec.masking = trial % 2 ? Masking::kSeparable : Masking::kHeightCorrelated;
    spec.mu.size = 3;
    spec.roughness.size = 3;
    spec.mu.placement = trial % 2 ? Placement::kEdges : Placement::kCenters;
    spec.roughness.warp = static_cast<Warp>(trial % 3);
    spec.tolerance = 1e-5;
    const Table t = Bake(spec);
    for (const Channel& c : t.channels) {
      for (double v : c.values) {
        ASSERT_TRUE(std::isfinite(v)) << spec.model.name() << " trial " << trial;
        ASSERT_GE(v, -1e-9);
        ASSERT_LE(v, 1.0 + 1e-6);
      }
    }
    ASSERT_TRUE(std::isfinite(t.max_abs_error));
  }
}

}  // namespace
}  // namespace brdfbake
