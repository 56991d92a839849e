// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The eevee preset (docs/engines.md#eevees-glass-table): Blender EEVEE's
// eevee_lut.cc with btdf_ggx[16][64][64][1] baked ([Blender]).
// - Its layout: the axes entry by entry at EEVEE's coordinates (column i at
//   F0^(1/4) = i / 63, row j at sqrt(1 - NoV) = j / 63, slice k at
//   roughness k / 16), and texels against the scalar rule within the claim.
// - The file consumed as Blender consumes it: compiled by the system C++
//   compiler with a stand-in for eevee_lut.hh and for Blender's own file
//   (kept as eevee_lut_blender.cc), read through EEVEE's lookup
//   (utility_tx_sample_bsdf_lut, written out here from its GLSL): at the
//   coordinates the renderer reads a node at, it returns that node.
// - Against the values Blender ships (tests/data/eevee_btdf_ggx.json, five
//   slices and the grazing rows of two more), texel by texel: the preset's
//   array as it is, and the rule at the generator's own coordinates.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "brdfbake/bake.h"
#include "brdfbake/presets.h"
#include "lanes/glass_lanes.h"
#include "rules/glass/glass_albedo.h"
#include "util/file_util.h"
#include "util/preset_util.h"

namespace brdfbake {
namespace {

using test::Have;
using test::Numbers;
using test::Slurp;
using test::WriteText;

using Baked = test::BakedPreset;

// The preset, baked once for every test here.
const Baked& Eevee() {
  static const Baked b = test::BakePreset("eevee");
  return b;
}

bool Built() { return PresetBuilt(FindPreset("eevee")); }

// EEVEE's coordinates of btdf_ggx[k][j][i] as its renderer reads them
// (lut_coords_btdf, utility_tx_sample_bsdf_lut).
double Ior(int i) {
  const double z = i / 63.0;
  return i == 63 ? std::numeric_limits<double>::infinity() : (1 + z * z) / (1 - z * z);
}
double Mu(int j) { return 1 - (j / 63.0) * (j / 63.0); }
double Roughness(int k) { return k / 16.0; }

// The stored btdf_ggx[k][j][i][0] in the preset's image (x = mu, y =
// roughness, slices over ior; mu entry 63 - j).
double Stored(const Image& im, int k, int j, int i) { return im.values[(size_t(i) * 16 + k) * 64 + (63 - j)]; }

TEST(EeveePresetTest, AxesAreEeveesAndClaimsBoundTheError) {
  if (!Built()) GTEST_SKIP() << "eevee needs ggx-glass";
  const Preset& p = FindPreset("eevee");
  ASSERT_EQ(p.tables.size(), 1u);
  EXPECT_EQ(p.header_file, "eevee_lut.cc");
  EXPECT_EQ(p.tables[0].symbol, "btdf_ggx");
  const Baked& b = Eevee();
  const Image& im = b.images[0];
  ASSERT_EQ(im.axes.size(), 3u);
  EXPECT_EQ(im.width, 64);
  EXPECT_EQ(im.height, 16 * 64);
  EXPECT_EQ(im.pixel, PixelType::kFloat);
  EXPECT_LT(im.max_abs_error, 2e-6);
  for (int j = 0; j < 64; ++j) EXPECT_NEAR(im.axes[0].Value(63 - j), Mu(j), 1e-15) << j;
  for (int k = 0; k < 16; ++k) EXPECT_NEAR(im.axes[1].Value(k), Roughness(k), 1e-15) << k;
  for (int i = 0; i < 63; ++i) EXPECT_NEAR(im.axes[2].Value(i), Ior(i), 1e-12 * Ior(i)) << i;
  EXPECT_TRUE(std::isinf(im.axes[2].Value(63)));
  // The smooth slice is 1 - (1 - NoV)^5 exactly (rounded to float).
  for (int j : {0, 31, 62, 63}) {
    for (int i : {0, 20, 63}) {
      EXPECT_EQ(Stored(im, 0, j, i), double(float(1 - std::pow(1 - Mu(j), 5)))) << j << " " << i;
    }
  }
  // Texels at the hard places: ior 1 and inf, grazing and normal views,
  // the first rough slice and the last.
  double worst = 0;
  for (int k : {1, 8, 15}) {
    for (int j : {0, 40, 62, 63}) {
      for (int i : {0, 1, 30, 62, 63}) {
        const double r = Roughness(k);
        const RuleResult want = GlassAlbedo(r * r, Ior(i), Masking::kSeparable, std::max(Mu(j), 1e-7), 1e-9, 2048,
                                            DielectricPart::kTransmissionSchlick);
        const double d = std::abs(Stored(im, k, j, i) - want.value);
        worst = std::max(worst, d);
        EXPECT_LE(d, im.max_abs_error + want.error) << "k " << k << " j " << j << " i " << i;
      }
    }
  }
  std::printf("eevee: largest |stored - T| at the hard texels %.3g (claims at most %.3g)\n", worst,
              im.max_abs_error);
}

// EEVEE's lookup of the transmission factor (eevee_nodetree_lib.glsl's
// bsdf_lut for ior > 1 and eevee_utility_tx_lib's utility_tx_sample_bsdf_lut),
// written out from its GLSL: x = sqrt((ior - 1) / (ior + 1)), y = sqrt(1 -
// cos_theta), uv = (x, y) * 63 / 64 + 0.5 / 64 bilinear over the 64x64
// layer (a fractional texel index of x * 63), layer = 16 roughness + 4 with
// the two nearest layers blended by hand, the array texture clamping the
// layer index to its last (btdf_ggx[15]).
std::string ConsumerSource() {
  return R"(#include <cmath>
#include <cstdio>
#include "eevee_lut.hh"

using blender::eevee::lut::btdf_ggx;

static float Layer(int k, float x, float y) {
  k = k > 15 ? 15 : k;
  const float fx = x * 63.0f, fy = y * 63.0f;
  int x0 = int(std::floor(fx)), y0 = int(std::floor(fy));
  x0 = x0 < 0 ? 0 : x0 > 63 ? 63 : x0;
  y0 = y0 < 0 ? 0 : y0 > 63 ? 63 : y0;
  const int x1 = x0 + 1 > 63 ? 63 : x0 + 1, y1 = y0 + 1 > 63 ? 63 : y0 + 1;
  const float tx = fx - x0, ty = fy - y0;
  auto at = [&](int yy, int xx) { return btdf_ggx[k][yy][xx][0]; };
  const float a = at(y0, x0) + (at(y0, x1) - at(y0, x0)) * tx;
  const float b = at(y1, x0) + (at(y1, x1) - at(y1, x0)) * tx;
  return a + (b - a) * ty;
}
static float TransmissionFactor(float cos_theta, float roughness, float ior) {
  const float x = std::sqrt((ior - 1.0f) / (ior + 1.0f));
  const float y = std::sqrt(1.0f - cos_theta);
  const float layer = roughness * 16.0f;
  const float k0 = std::floor(layer);
  return Layer(int(k0), x, y) + (Layer(int(k0) + 1, x, y) - Layer(int(k0), x, y)) * (layer - k0);
}
int main() {
  std::printf("%d %d %d\n", int(sizeof(btdf_ggx) / sizeof(btdf_ggx[0])), int(sizeof(btdf_ggx[0]) / sizeof(btdf_ggx[0][0])),
              int(sizeof(btdf_ggx[0][0]) / sizeof(btdf_ggx[0][0][0])));
  std::printf("%.9g\n", double(blender::eevee::lut::ltc_mat_ggx[0][0][0]));
  const int ks[] = {0, 1, 7, 15};
  const int js[] = {0, 20, 62, 63};
  const int is[] = {1, 9, 40, 62};
  for (int k : ks) {
    for (int j : js) {
      for (int i : is) {
        const float z = float(i) / 63.0f, cos_theta = 1.0f - (float(j) / 63.0f) * (float(j) / 63.0f);
        const float ior = (1.0f + z * z) / (1.0f - z * z);
        std::printf("%.9g %.9g\n", double(btdf_ggx[k][j][i][0]), double(TransmissionFactor(cos_theta, float(k) / 16.0f, ior)));
      }
    }
  }
  // Between the nodes: roughness 0.3 and 0.99, cos 0.5, ior 1.45.
  std::printf("%.9g %.9g\n", double(TransmissionFactor(0.5f, 0.3f, 1.45f)), double(TransmissionFactor(0.5f, 0.99f, 1.45f)));
}
)";
}

TEST(EeveePresetTest, EngineFileCompilesAndServesEeveesLookup) {
  if (!Have("c++")) GTEST_SKIP() << "no C++ compiler";
  if (!Built()) GTEST_SKIP() << "eevee needs ggx-glass";
  const std::string dir = test::Scratch("eevee_lut");
  std::filesystem::create_directories(dir);
  const Baked& b = Eevee();
  PresetRun run;
  run.dir = dir;
  WritePresetFiles(FindPreset("eevee"), run, b.tables, b.images);
  ASSERT_TRUE(std::filesystem::exists(dir + "/eevee_lut.cc"));
  // eevee_lut.hh as Blender declares the tables (the plain float arrays of
  // eevee_next at bfc69786), and a stand-in for Blender's own file: every
  // table, its btdf_ggx filled with a sentinel that must not be read.
  WriteText(dir + "/eevee_lut.hh",
            "#pragma once\nnamespace blender::eevee::lut {\n"
            "extern const float ltc_mat_ggx[64][64][4];\nextern const float ltc_mag_ggx[64][64][2];\n"
            "extern const float ltc_disk_integral[64][64][1];\nextern const float brdf_ggx[64][64][3];\n"
            "extern const float bsdf_ggx[16][64][64][3];\nextern const float btdf_ggx[16][64][64][1];\n"
            "extern const float blue_noise[64][64][4];\nextern const float burley_sss_profile[64][1];\n"
            "extern const float random_walk_sss_profile[64][1];\n}\n");
  WriteText(dir + "/eevee_lut_blender.cc",
            "#include \"eevee_lut.hh\"\nnamespace blender::eevee::lut {\n"
            "const float ltc_mat_ggx[64][64][4] = {{{0.25f}}};\nconst float ltc_mag_ggx[64][64][2] = {};\n"
            "const float ltc_disk_integral[64][64][1] = {};\nconst float brdf_ggx[64][64][3] = {};\n"
            "const float bsdf_ggx[16][64][64][3] = {};\nconst float btdf_ggx[16][64][64][1] = {{{{-7.0f}}}};\n"
            "const float blue_noise[64][64][4] = {};\nconst float burley_sss_profile[64][1] = {};\n"
            "const float random_walk_sss_profile[64][1] = {};\n}\n");
  WriteText(dir + "/use.cc", ConsumerSource());
  // Two translation units, as Blender links them: the tables and their user.
  const std::string cmd = "c++ -std=c++17 -Wall -Wextra -Werror -I" + dir + " -o " + dir + "/use " + dir +
                          "/use.cc " + dir + "/eevee_lut.cc > " + dir + "/err.txt 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << Slurp(dir + "/err.txt");
  ASSERT_EQ(std::system((dir + "/use > " + dir + "/out.txt").c_str()), 0);
  const std::vector<double> v = Numbers(Slurp(dir + "/out.txt"));
  ASSERT_EQ(v.size(), 4 + 4 * 4 * 4 * 2 + 2u);
  EXPECT_EQ(v[0], 16);
  EXPECT_EQ(v[1], 64);
  EXPECT_EQ(v[2], 64);
  EXPECT_EQ(v[3], 0.25);  // Blender's own tables are there
  const Image& im = b.images[0];
  size_t n = 4;
  double worst = 0;
  for (int k : {0, 1, 7, 15}) {
    for (int j : {0, 20, 62, 63}) {
      for (int i : {1, 9, 40, 62}) {
        EXPECT_EQ(float(v[n]), float(Stored(im, k, j, i))) << k << " " << j << " " << i;
        // The renderer's lookup at the node's own coordinates returns it:
        // slice k is what EEVEE reads at roughness k / 16.
        EXPECT_NEAR(v[n + 1], Stored(im, k, j, i), 2e-5) << k << " " << j << " " << i;
        worst = std::max(worst, std::abs(v[n + 1] - Stored(im, k, j, i)));
        n += 2;
      }
    }
  }
  // Off the nodes the lookup blends the neighbours: close to T at (cos
  // 0.5, ior 1.45) for roughness 0.3 (between slices 4 and 5); at 0.99 the
  // clamped layer holds slice 15, T of roughness 15/16, as any table in
  // this texture would (T of 0.99 is 0.04 lower there).
  for (double r : {0.3, 0.99}) {
    const double held = std::min(r, 15.0 / 16);
    const RuleResult t = GlassAlbedo(held * held, 1.45, Masking::kSeparable, 0.5, 1e-9, 2048,
                                     DielectricPart::kTransmissionSchlick);
    std::printf("eevee lookup at roughness %.2f, cos 0.5, ior 1.45: %.6f, T at roughness %.4f there %.6f\n", r, v[n],
                held, t.value);
    EXPECT_NEAR(v[n++], t.value, 2e-3);
  }
  std::printf("eevee_lut.cc: EEVEE's lookup at the nodes within %.3g of the stored texels\n", worst);
}

struct Diff {
  double rms = 0, max = 0;
  int n = 0;
  double sum2 = 0;
  void Add(double d) {
    sum2 += d * d;
    max = std::max(max, std::abs(d));
    ++n;
    rms = std::sqrt(sum2 / n);
  }
};

// Blender's shipped btdf_ggx against brdfbake's, texel by texel:
// - the preset's array as it is (slice k at roughness k / 16, where the
//   renderer reads it; the generator wrote k / 15, so the two differ by the
//   roughness step as well as by the generator's error);
// - the rule at the generator's own coordinates (roughness k / 15, NoV and
//   F0 clamped to [1e-4, 0.9999]: ior 1.0002 to 19999), which isolates the
//   generator's error: 512^2 Hammersley samples per texel.
TEST(EeveePresetTest, AgreesWithBlendersShippedTable) {
  if (!Built()) GTEST_SKIP() << "eevee needs ggx-glass";
  const nlohmann::json shipped =
      nlohmann::json::parse(Slurp(std::string(BRDFBAKE_TEST_DATA) + "/eevee_btdf_ggx.json"));
  const std::vector<int> cols = shipped["columns"].get<std::vector<int>>();
  const Image& im = Eevee().images[0];
  Diff as_is, at_generator, inner, transposed;
  std::printf("| slice k | texels | preset RMS | preset max | generator's coordinates RMS | max | the same, rows j "
              "< 62 | max |\n");
  for (const auto& slice : shipped["slices"]) {
    const int k = slice["k"].get<int>();
    const std::vector<int> rows = slice["rows"].get<std::vector<int>>();
    Diff a, g, gi;
    for (size_t r = 0; r < rows.size(); ++r) {
      const int j = rows[r];
      for (size_t c = 0; c < cols.size(); ++c) {
        const auto& cell = slice["values"][r][c];
        if (cell.is_null()) continue;
        const int i = cols[c];
        const double blender = cell.get<double>();
        a.Add(Stored(im, k, j, i) - blender);
        as_is.Add(Stored(im, k, j, i) - blender);
        transposed.Add(Stored(im, k, i, j) - blender);
        const double rough = k / 15.0;
        const double nv = std::clamp(1 - (j / 63.0) * (j / 63.0), 1e-4, 0.9999);
        const double f = std::clamp((i / 63.0) * (i / 63.0), 1e-4, 0.9999);
        const RuleResult t = SimdGlassAlbedo(rough * rough, (1 + f) / (1 - f), Masking::kSeparable, nv, 1e-7, 512,
                                             DielectricPart::kTransmissionSchlick);
        g.Add(t.value - blender);
        at_generator.Add(t.value - blender);
        if (j < 62) {
          gi.Add(t.value - blender);
          inner.Add(t.value - blender);
        }
      }
    }
    std::printf("| %d | %d | %.2g | %.2g | %.2g | %.2g | %.2g | %.2g |\n", k, a.n, a.rms, a.max, g.rms, g.max, gi.rms,
                gi.max);
  }
  std::printf("| all | %d | %.2g | %.2g | %.2g | %.2g | %.2g | %.2g |\n", as_is.n, as_is.rms, as_is.max,
              at_generator.rms, at_generator.max, inner.rms, inner.max);
  std::printf("rows and columns swapped: RMS %.3g\n", transposed.rms);
  EXPECT_GT(as_is.n, 700);
  EXPECT_LT(at_generator.rms, 5e-3);
  EXPECT_LT(inner.max, 5e-3);
  EXPECT_LT(as_is.rms, 2e-2);
  EXPECT_GT(transposed.rms, 0.1);
}

}  // namespace
}  // namespace brdfbake
