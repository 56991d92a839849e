// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Tests of the squared ellipsoidal lobe ([TokuyoshiHarada]): its isotropic case
// against GGX, its geometric definition (the squared distance from the origin
// to an ellipsoid), and its frame convention.

#include "brdfbake/bake.h"
#include "brdfbake/models/sel.h"
#include "lanes/sel_lanes.h"
#include "rules/sel/sel_norm.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "brdfbake/models/ggx.h"
#include "util/test_util.h"

namespace brdfbake {
namespace {

using test::Dir;

double RelDiff(double a, double b) {
  if (a == b) return 0;
  return std::abs(a - b) / std::max(std::abs(a), std::abs(b));
}

// Uniform random direction on the sphere.
Dir RandomDir(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  return FromMuPhi(2.0 * uni(rng) - 1.0, 2.0 * kPi<double> * uni(rng));
}

// Random rotation Q = Rx Ry Rz with uniform angles.
Mat3<double> RandomRotation(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> ang(-kPi<double>, kPi<double>);
  return Mat3<double>::RotX(ang(rng)) * Mat3<double>::RotY(ang(rng)) *
         Mat3<double>::RotZ(ang(rng));
}

// [TokuyoshiHarada] section 1: the written-out SSL is pi alpha^2 D_GGX(cos(theta/2)),
// with D_GGX evaluated by the library's GGX (slope form, [Ribardiere17] eq. 3).
// The inputs are chosen so that both sides see the same angle exactly:
// sin^2(theta/2) = s2 is dyadic, so cos(theta) = 1 - 2 s2 is exact (a
// rounded cos(theta) would limit the agreement to eps / alpha^2).
TEST(SelTest, SquaredSpheroidalLobeEqualsScaledGgxAtHalfAngle) {
  double max_err = 0;
  for (double alpha : {1e-3, 0.01, 0.05, 0.2, 0.5, 1.0}) {
    const GgxNdf<double> ggx(alpha);
    for (double s2 : {0.0, 0x1p-30, 0x1p-20, 0x1p-12, 0x1p-6, 0.25, 0.5, 0.75,
                      1.0 - 0x1p-10}) {
      const Dir half(std::sqrt(s2), 0.0, std::sqrt(1.0 - s2));
      const double want = kPi<double> * alpha * alpha * ggx.D(half);
      const double got = SquaredSpheroidalLobe(alpha, 1.0 - 2.0 * s2);
      max_err = std::max(max_err, RelDiff(got, want));
      EXPECT_LE(RelDiff(got, want), 1e-12) << "alpha=" << alpha << " s2=" << s2;
    }
    EXPECT_DOUBLE_EQ(SquaredSpheroidalLobe(alpha, 1.0), 1.0);
    EXPECT_NEAR(SquaredSpheroidalLobe(alpha, -1.0), std::pow(alpha, 4), 1e-15);
  }
  std::printf("SSL vs pi a^2 D_GGX(cos(theta/2)): max relative error %.2e\n", max_err);
  // alpha is clamped like every model's: no 0/0 at alpha = 0.
  EXPECT_DOUBLE_EQ(SquaredSpheroidalLobe(0.0, 1.0), 1.0);
}

// alpha_x = alpha_y: the SEL is the SSL of the angle to the lobe axis.
TEST(SelTest, IsotropicEqualsSquaredSpheroidalLobe) {
  std::mt19937_64 rng(1);
  double max_err = 0;
  for (double alpha : {0.05, 0.1, 0.3, 0.6, 1.0}) {
    for (int q = 0; q < 5; ++q) {
      const SelLobe<double> lobe(alpha, alpha, RandomRotation(rng));
      for (int i = 0; i < 400; ++i) {
        // Half uniform, half within a few alpha of the axis.
        Dir w = RandomDir(rng);
        if (i % 2) w = Normalize(lobe.Axis() + w * (3.0 * alpha * std::abs(w.z)));
        const double cos_theta = (lobe.q() * w).z;
        const double err =
            RelDiff(lobe.K(w), SquaredSpheroidalLobe(alpha, cos_theta));
        max_err = std::max(max_err, err);
        EXPECT_LE(err, 1e-12) << "alpha=" << alpha;
      }
    }
  }
  std::printf("SEL(alpha, alpha) vs SSL: max relative error %.2e\n", max_err);
}

// On the axis K = 1; opposite it K = amax^4; in between 0 < K <= 1 (for
// alphas in [TokuyoshiHarada]'s range [0, 1]).
TEST(SelTest, RangeAndAxisValues) {
  std::mt19937_64 rng(2);
  const double alphas[][2] = {{0.3, 0.05}, {0.05, 0.8}, {1.0, 0.2},
                              {0.02, 0.02}, {1e-4, 0.1}, {0.5, 5e-4}};
  for (const auto& a : alphas) {
    for (int q = 0; q < 4; ++q) {
      const SelLobe<double> lobe(a[0], a[1], RandomRotation(rng));
      const double amax = std::max(a[0], a[1]);
      EXPECT_NEAR(lobe.K(lobe.Axis()), 1.0, 1e-14);
      EXPECT_LE(RelDiff(lobe.K(-lobe.Axis()), std::pow(amax, 4)), 1e-13);
      for (int i = 0; i < 2000; ++i) {
        const double k = lobe.K(RandomDir(rng));
        ASSERT_GT(k, 0.0);
        ASSERT_LE(k, 1.0);
      }
    }
  }
}

// K(w; Q) = K(Q w; I), and FromAngles builds Q = Rx Ry Rz.
TEST(SelTest, RotationEquivariance) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> ang(-kPi<double>, kPi<double>);
  for (int q = 0; q < 20; ++q) {
    const double tx = ang(rng), ty = ang(rng), tz = ang(rng);
    const SelLobe<double> rotated = SelLobe<double>::FromAngles(0.4, 0.07, tx, ty, tz);
    const Mat3<double> qm =
        Mat3<double>::RotX(tx) * Mat3<double>::RotY(ty) * Mat3<double>::RotZ(tz);
    const SelLobe<double> unrotated(0.4, 0.07, Mat3<double>());
    for (int i = 0; i < 200; ++i) {
      const Dir w = RandomDir(rng);
      EXPECT_LE(RelDiff(rotated.K(w), unrotated.K(qm * w)), 1e-14);
    }
    // The lobe axis is Q^T z.
    EXPECT_NEAR(Length(rotated.Axis() - qm.Transposed() * Dir(0, 0, 1)), 0.0, 1e-15);
  }
  // Convention spelled out: a positive theta_y turns the axis towards -x
  // (Ry^T z = (-sin, 0, cos)), and alpha_x stays along the first row of Q.
  const SelLobe<double> tilted = SelLobe<double>::FromAngles(0.3, 0.1, 0.0, 0.5, 0.0);
  EXPECT_NEAR(tilted.K(Dir(-std::sin(0.5), 0.0, std::cos(0.5))), 1.0, 1e-14);
  const SelLobe<double> plain(0.3, 0.1, Mat3<double>());
  const Dir wx = FromMuPhi(0.9, 0.0), wy = FromMuPhi(0.9, 0.5 * kPi<double>);
  EXPECT_GT(plain.K(wx), plain.K(wy));  // wider along x (alpha_x > alpha_y)
}

// [TokuyoshiHarada] section 2 from the definition: sqrt(K(w)) v lies on the ellipsoid
// with centre c = (0, 0, (1 - amax^2) / 2) and semi-axes
// r = (alpha_x, alpha_y, (1 + amax^2) / 2) in lobe space.
TEST(SelTest, PointLiesOnTheEllipsoid) {
  std::mt19937_64 rng(4);
  const double alphas[][2] = {{0.3, 0.05}, {0.05, 0.8}, {1.0, 0.2}, {0.02, 0.02},
                              {0.7, 0.7},  {1e-3, 0.5}, {0.25, 0.6}};
  double max_err = 0;
  for (const auto& a : alphas) {
    const double amax = std::max(a[0], a[1]);
    const double cz = 0.5 * (1.0 - amax * amax), rz = 0.5 * (1.0 + amax * amax);
    for (int q = 0; q < 4; ++q) {
      const Mat3<double> qm = RandomRotation(rng);
      const SelLobe<double> lobe(a[0], a[1], qm);
      for (int i = 0; i < 1000; ++i) {
        const Dir w = RandomDir(rng);
        const Dir p = (qm * w) * std::sqrt(lobe.K(w));
        const double ex = p.x / a[0], ey = p.y / a[1], ez = (p.z - cz) / rz;
        const double f = ex * ex + ey * ey + ez * ez;
        max_err = std::max(max_err, std::abs(f - 1.0));
        EXPECT_NEAR(f, 1.0, 1e-12) << a[0] << " " << a[1];
      }
    }
  }
  std::printf("SEL ellipsoid implicit equation: max |f - 1| = %.2e\n", max_err);
}

// Float instantiations stay close to the double ones, with no NaN or Inf even
// for alpha = 1e-4 and 1000:1 anisotropy.
TEST(SelTest, FloatMatchesDoubleAndIsFinite) {
  std::mt19937_64 rng(5);
  const double alphas[][2] = {{0.3, 0.05}, {1e-4, 1e-4}, {0.5, 5e-4}, {1.0, 1.0}};
  double max_err = 0;
  for (const auto& a : alphas) {
    const Mat3<double> qd = RandomRotation(rng);
    Mat3<float> qf;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) qf.m[i][j] = static_cast<float>(qd.m[i][j]);
    const SelLobe<double> ld(a[0], a[1], qd);
    const SelLobe<float> lf(static_cast<float>(a[0]), static_cast<float>(a[1]), qf);
    for (int i = 0; i < 2000; ++i) {
      const Vec3<float> wf(RandomDir(rng));
      const float kf = lf.K(wf);
      ASSERT_TRUE(std::isfinite(kf));
      ASSERT_GT(kf, 0.0f);
      ASSERT_LE(kf, 1.0f + 1e-6f);  // w and Q w are unit only to float rounding
      // Compare at the float inputs (Q rounded too), so only float
      // arithmetic inside K is measured.
      Mat3<double> qfd;
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) qfd.m[r][c] = qf.m[r][c];
      const SelLobe<double> ref(static_cast<float>(a[0]), static_cast<float>(a[1]), qfd);
      const double err = RelDiff(kf, ref.K(Dir(wf)));
      if (a[0] >= 1e-3 && a[1] >= 1e-3) max_err = std::max(max_err, err);
    }
    const float ssl = SquaredSpheroidalLobe(static_cast<float>(a[0]), 0.3f);
    EXPECT_LE(RelDiff(ssl, SquaredSpheroidalLobe(static_cast<double>(static_cast<float>(a[0])),
                                                 static_cast<double>(0.3f))),
              1e-5);
  }
  std::printf("SEL float vs double: max relative error %.2e\n", max_err);
  EXPECT_LE(max_err, 1e-5);
}

}  // namespace
}  // namespace brdfbake

namespace brdfbake {
namespace {

// N = int K dw over the sphere (src/rules/sel/sel_norm.h) against the sphere
// integral of SelLobe::K by nested adaptive Gauss-Kronrod (Boost), with
// the lobe turned by a rotation Q (N does not depend on it).
TEST(SelTest, IntegralMatchesTheSphereIntegral) {
  struct Case {
    double ax, ay;
  };
  for (const Case& c : {Case{0.3, 0.6}, Case{1.0, 0.1}, Case{0.2, 1.0}, Case{0.5, 0.5},
                        Case{0.15, 0.4}}) {
    const SelLobe<double> lobe = SelLobe<double>::FromAngles(c.ax, c.ay, 0.3, -1.1, 0.7);
    const double ref = test::IntegrateHemisphereTheta(
        [&](const test::Dir& w) { return lobe.K(w); }, 0.0, kPi<double>, 1e-11);
    const SelIntegral n = SelLobeIntegral(c.ax, c.ay, 1e-10);
    EXPECT_NEAR(n.n, ref, 1e-9 * ref + n.n_error) << c.ax << " " << c.ay;
    std::printf("alpha %.2f x %.2f: N %.12f, sphere integral %.12f, claimed %.1e\n", c.ax, c.ay,
                n.n, ref, n.n_error);
  }
}

// The closed forms: alpha_x = alpha_y gives the squared spheroidal lobe's
// 4 pi alpha^2; as both widths go to 0, N / (4 pi alpha_x alpha_y) -> 1.
TEST(SelTest, IntegralClosedForms) {
  for (double a : {1e-3, 0.05, 0.5, 1.0}) {
    const SelIntegral n = SelLobeIntegral(a, a, 1e-10);
    EXPECT_NEAR(n.n, 4 * kPi<double> * a * a, 1e-13 * n.n) << a;
  }
  for (double a : {1e-3, 1e-2}) {
    const SelIntegral n = SelLobeIntegral(a, 3 * a, 1e-10);
    EXPECT_GT(n.ratio, 1.0);
    EXPECT_LT(n.ratio - 1, 10 * 9 * a * a) << a;
  }
}

// The sel_norm table holds N and the ratio at its axes' values.
TEST(SelTest, NormTable) {
  BakeSpec spec;
  spec.table = TableKind::kSelNorm;
  spec.model.kind = ModelKind::kSel;
  spec.alpha_x.size = 4;
  spec.alpha_y.size = 3;
  spec.alpha_x.min = 0.1;
  // Lanes (the default) and the scalar reference (--target scalar).
  for (bool simd : {true, false}) {
    spec.simd = simd;
    const Table t = Bake(spec);
    ASSERT_EQ(t.channels.size(), 2u);
    EXPECT_EQ(t.channels[0].name, "sel.0_integral");
    EXPECT_EQ(t.channels[1].name, "sel.1_ratio");
    for (int y = 0; y < 3; ++y) {
      for (int x = 0; x < 4; ++x) {
        const double ax = spec.alpha_x.Value(x), ay = spec.alpha_y.Value(y);
        const SelIntegral n =
            simd ? SimdSelLobeIntegral(ax, ay, 1e-7) : SelLobeIntegral(ax, ay, 1e-7);
        EXPECT_EQ(t.channels[0].values[y * 4 + x], n.n);
        EXPECT_EQ(t.channels[1].values[y * 4 + x], n.ratio);
      }
    }
  }
  spec.model.kind = ModelKind::kGgx;
  EXPECT_THROW(ValidateBakeSpec(spec), std::invalid_argument);
}

}  // namespace
}  // namespace brdfbake
