// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Tables of the STD model over a gamma axis: the tail warp, every slice
// equal to the table baked at its gamma (the last one, gamma = inf, to the
// Beckmann table), agreement with the independent half-vector integration
// at sampled texels within the claimed error, and the file header.

#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "brdfbake/bake.h"
#include "brdfbake/exr.h"
#include "brdfbake/models/beckmann.h"
#include "brdfbake/models/std_ndf.h"
#include "reference/reference_albedo.h"

namespace brdfbake {
namespace {

BakeSpec GammaSpec(TableKind table, int w, int h, int d) {
  BakeSpec s;
  s.table = table;
  s.model.kind = ModelKind::kStudentT;
  s.mu.size = w;
  s.roughness.size = h;
  s.gamma.size = d;
  return s;
}

double LogU(double g) { return std::isinf(g) ? 0.0 : std::log((g - 1.5) / (g - 0.5)); }

TEST(GammaAxisTest, TailWarpSpansTheRangeLogLinearInU) {
  Axis a = BakeSpec().gamma;
  a.size = 16;
  EXPECT_NEAR(a.Value(0), 1.501, 1e-14);
  EXPECT_TRUE(std::isinf(a.Value(15)));
  for (int i = 0; i + 1 < a.size; ++i) {
    EXPECT_LT(a.Value(i), a.Value(i + 1)) << i;
    // ln u steps evenly from ln u(1.501) to ln u(inf) = 0.
    EXPECT_NEAR(LogU(a.Value(i + 1)) - LogU(a.Value(i)), -LogU(1.501) / 15, 1e-12) << i;
  }
  // A finite end is reached; centers placement never touches the ends.
  a.max = 4;
  EXPECT_NEAR(a.Value(15), 4.0, 1e-12);
  a.placement = Placement::kCenters;
  a.max = kInfinity;
  EXPECT_GT(a.Value(0), 1.501);
  EXPECT_TRUE(std::isfinite(a.Value(15)));
  EXPECT_NEAR(LogU(a.ValueAt(-0.5)), LogU(1.501), 1e-13);
}

// Each slice is the table at that gamma, value for value; the last slice
// (gamma = inf) agrees with the Beckmann table within the two claims.
TEST(GammaAxisTest, SlicesAreTheTablesAtTheirGamma) {
  for (TableKind kind : {TableKind::kE, TableKind::kDfg, TableKind::kEavg}) {
    const BakeSpec spec = GammaSpec(kind, 5, 4, 4);
    const Table t = Bake(spec);
    const bool eavg = kind == TableKind::kEavg;
    const size_t slice = eavg ? 4 : 5 * 4;
    ASSERT_EQ(t.axes.size(), eavg ? 2u : 3u);
    ASSERT_EQ(t.height, eavg ? 4 : 16);
    for (int k = 0; k < 4; ++k) {
      BakeSpec one = spec;
      one.gamma.size = 0;
      one.model.gamma = spec.gamma.Value(k);
      const Table tk = Bake(one);
      for (size_t c = 0; c < t.channels.size(); ++c) {
        for (size_t i = 0; i < slice; ++i) {
          ASSERT_EQ(t.channels[c].values[k * slice + i], tk.channels[c].values[i])
              << TableName(kind) << " slice " << k << " channel " << c << " texel " << i;
        }
      }
    }
    BakeSpec beckmann = spec;
    beckmann.gamma.size = 0;
    beckmann.model.kind = ModelKind::kBeckmann;
    const Table tb = Bake(beckmann);
    for (size_t c = 0; c < t.channels.size(); ++c) {
      for (size_t i = 0; i < slice; ++i) {
        EXPECT_NEAR(t.channels[c].values[3 * slice + i], tb.channels[c].values[i],
                    t.integration_error + tb.integration_error)
            << TableName(kind) << " channel " << c << " texel " << i;
      }
    }
  }
}

// Sampled texels of a 3D table against the independent half-vector
// integration (Boost tanh-sinh), within the table's claimed error: every
// slice, including the heavy-tailed end at 1.501 and gamma = inf.
TEST(GammaAxisTest, AgreesWithIndependentIntegration) {
  const BakeSpec spec = GammaSpec(TableKind::kE, 4, 4, 6);
  const Table t = Bake(spec);
  double worst = 0;
  for (int k = 0; k < spec.gamma.size; ++k) {
    const double gamma = spec.gamma.Value(k);
    for (int y : {1, 3}) {
      for (int x : {0, 2, 3}) {
        const double r = spec.roughness.Value(y), mu = spec.mu.Value(x);
        const double alpha = r * r;
        const double ref = std::isinf(gamma)
                               ? ReferenceEFor(BeckmannNdf<double>(alpha), mu, spec.masking, 1e-10)
                               : ReferenceEFor(StudentTNdf<double>(alpha, alpha, gamma), mu,
                                               spec.masking, 1e-10);
        const double v = t.channels[0].values[(k * 4 + y) * 4 + x];
        worst = std::max(worst, std::abs(v - ref));
        EXPECT_NEAR(v, ref, t.integration_error + 1e-9)
            << "gamma " << gamma << " r " << r << " mu " << mu;
      }
    }
  }
  std::printf("max |table - reference| %.3g, claimed %.3g\n", worst, t.integration_error);
}

TEST(GammaAxisTest, ExrHeaderListsTheGammaValues) {
  const BakeSpec spec = GammaSpec(TableKind::kE, 4, 3, 5);
  const Table t = Bake(spec);
  const std::string path = ::testing::TempDir() + "/brdfbake_gamma_axis.exr";
  WriteExr(t, path);
  const ExrContents c = ReadExr(path);
  EXPECT_EQ(c.width, 4);
  EXPECT_EQ(c.height, 15);
  const nlohmann::json axes = nlohmann::json::parse(c.Attribute("brdfbake.axes"));
  ASSERT_EQ(axes.size(), 3u);
  const nlohmann::json& g = axes[2];
  EXPECT_EQ(g["name"], "gamma");
  EXPECT_EQ(g["warp"], "tail");
  EXPECT_EQ(g["max"], "inf");
  ASSERT_EQ(g["values"].size(), 5u);
  EXPECT_EQ(g["values"][4], "inf");
  for (int k = 0; k < 4; ++k) EXPECT_EQ(g["values"][k].get<double>(), spec.gamma.Value(k));
  const nlohmann::json model = nlohmann::json::parse(c.Attribute("brdfbake.model"));
  EXPECT_NE(model["gamma"].get<std::string>().find("gamma axis"), std::string::npos);
  std::remove(path.c_str());
}

TEST(GammaAxisTest, RejectsBadGammaAxes) {
  BakeSpec spec = GammaSpec(TableKind::kE, 4, 4, 4);
  EXPECT_NO_THROW(ValidateBakeSpec(spec));
  spec.model.kind = ModelKind::kGgx;
  EXPECT_THROW(ValidateBakeSpec(spec), std::invalid_argument);
  spec.model.kind = ModelKind::kStudentT;
  spec.gamma.min = 1.5;
  EXPECT_THROW(ValidateBakeSpec(spec), std::invalid_argument);
  spec.gamma.min = 3;
  spec.gamma.max = 2;
  EXPECT_THROW(ValidateBakeSpec(spec), std::invalid_argument);
  spec.gamma.max = kInfinity;
  spec.gamma.warp = Warp::kLinear;
  EXPECT_THROW(ValidateBakeSpec(spec), std::invalid_argument);
  spec.gamma.warp = Warp::kTail;
  spec.gamma.size = 1;  // edges need 2
  EXPECT_THROW(ValidateBakeSpec(spec), std::invalid_argument);
  spec.gamma.size = 4;
  spec.mu.warp = Warp::kTail;
  EXPECT_THROW(ValidateBakeSpec(spec), std::invalid_argument);
}

}  // namespace
}  // namespace brdfbake
