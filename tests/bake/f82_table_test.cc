// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The f82_bias table: its texels are the rule's (rules/glass/gen_schlick.h,
// checked against independent integration in tests/rules/
// gen_schlick_test.cc) at any thread count, its refusals, and its values
// against the third channel of Blender EEVEE's shipped brdf_ggx.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "brdfbake/bake.h"
#include "util/file_util.h"

namespace brdfbake {
namespace {

BakeSpec F82(Masking masking) {
  BakeSpec s;
  s.table = TableKind::kF82Bias;
  s.masking = masking;
  s.mu.size = 12;
  s.roughness.size = 9;
  s.error_channel = true;
  return s;
}

// Each texel is the rule's value at its (mu, roughness), bit for bit at
// one thread and at two, and its claim is within the tolerance.
TEST(F82TableTest, TexelsAreTheRuleAtAnyThreadCount) {
  for (Masking masking : {Masking::kSeparable, Masking::kHeightCorrelated}) {
    BakeSpec s = F82(masking);
    s.threads = 1;
    const Table one = Bake(s);
    s.threads = 2;
    const Table two = Bake(s);
    ASSERT_EQ(one.channels.size(), 2u);
    EXPECT_EQ(one.channels[0].name, "f82_bias");
    EXPECT_EQ(one.channels[0].values, two.channels[0].values);
    for (int y = 0; y < one.height; ++y) {
      for (int x = 0; x < one.width; ++x) {
        const size_t at = size_t(y) * size_t(one.width) + size_t(x);
        const TexelEstimate v = IntegrateTexel(s, one.axes[1].Value(y), one.axes[0].Value(x));
        EXPECT_EQ(one.channels[0].values[at], v.e) << x << ", " << y;
        EXPECT_LE(one.channels[1].values[at], s.tolerance);
        EXPECT_GE(one.channels[0].values[at], 0.0);
      }
    }
  }
}

TEST(F82TableTest, RefusesOtherModelsComplementAndSampling) {
  BakeSpec s = F82(Masking::kSeparable);
  s.model.kind = ModelKind::kBeckmann;
  EXPECT_THROW(ValidateBakeSpec(s), std::invalid_argument);
  s = F82(Masking::kSeparable);
  s.complement = true;
  EXPECT_THROW(ValidateBakeSpec(s), std::invalid_argument);
  s = F82(Masking::kSeparable);
  s.integrator = IntegratorKind::kQmc;
  try {
    ValidateBakeSpec(s);
    ADD_FAILURE() << "qmc accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("f82_bias tables are baked with the quadrature only"), std::string::npos)
        << e.what();
  }
  EXPECT_EQ(ParseTable("f82_bias"), TableKind::kF82Bias);
}

// Blender EEVEE (5.x) stores the term in brdf_ggx's third channel
// (metal_bias of its generator, 512^2 samples per texel, six printed
// decimals): at the generator's own coordinates (NoV = clamp(1 - y^2,
// 1e-4, 0.9999), alpha = x^2) it agrees with brdfbake's separable term to
// the printing, and the bias channel within its noise. Its scale channel
// is off by up to 3.5e-3 (at alpha = 0 too, where scale is exactly 1 - (1
// - NoV)^5): reported, not required.
TEST(F82TableTest, AgreesWithEeveesShippedChannel) {
  const nlohmann::json data =
      nlohmann::json::parse(test::Slurp(std::string(BRDFBAKE_TEST_DATA) + "/eevee_brdf_ggx_rows.json"));
  BakeSpec dfg;
  dfg.table = TableKind::kDfg;
  dfg.masking = Masking::kSeparable;
  BakeSpec f82 = dfg;
  f82.table = TableKind::kF82Bias;
  double worst[3] = {0, 0, 0}, sum2[3] = {0, 0, 0};
  int n = 0;
  for (const auto& [row, texels] : data["rows"].items()) {
    const int j = std::stoi(row);
    const double nov = std::clamp(1 - (j / 63.0) * (j / 63.0), 1e-4, 0.9999);
    for (size_t i = 0; i < texels.size(); ++i) {
      const double r = double(i) / 63;
      const TexelEstimate a = IntegrateTexel(dfg, r, nov), b = IntegrateTexel(f82, r, nov);
      const double ours[3] = {a.scale, a.bias, b.e};
      for (int c = 0; c < 3; ++c) {
        const double d = std::abs(ours[c] - texels[i][size_t(c)].get<double>());
        worst[c] = std::max(worst[c], d);
        sum2[c] += d * d;
      }
      ++n;
      EXPECT_LE(std::abs(b.e - texels[i][2].get<double>()), 5e-7 + b.err_e + 1e-7) << "row " << j << " column " << i;
      EXPECT_LE(std::abs(a.bias - texels[i][1].get<double>()), 3e-5) << "row " << j << " column " << i;
    }
  }
  EXPECT_EQ(n, 84);
  for (int c = 0; c < 3; ++c) {
    std::printf("%s: RMS %.2e, max %.2e over %d texels\n",
                c == 0   ? "scale"
                : c == 1 ? "bias"
                         : "F82 tint",
                std::sqrt(sum2[c] / n), worst[c], n);
  }
}

}  // namespace
}  // namespace brdfbake
