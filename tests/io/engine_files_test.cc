// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Each preset's file consumed the way its engine consumes it, by readers
// brdfbake did not write:
// - Filament's dfg.inc #included inside a `const uint16_t DFG_LUT[] = {...}`
//   initializer and compiled with the system C++ compiler;
// - three.js's DFGLUTData.js dropped into a copy of three's own source tree
//   (tests/js, pinned) and imported by node through three's Three.js, as
//   WebGLRenderer imports getDFGLUT();
// - Cycles' ggx_tables.h compiled with a lookup as Cycles' kernel reads
//   its glass tables;
// - Enterprise PBR's pbrlut.hpp compiled in two translation units, one of
//   them defining PBRLUT_IMPLEMENTATION, read through its extern arrays;
// - Bevy's dfg.ktx2, zstd-supercompressed, decompressed with libzstd and
//   parsed by ktx-parse;
// - a generic EXR with --channels rgba read by three.js's EXRLoader, whose
//   rows come out bottom-up (docs/engines.md#which-way-up).
// The node tests need `npm ci --prefix tests/js` (sh tools/setup.sh test
// runs it): without it they fail, naming the command.

#include <zstd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "brdfbake/bake.h"
#include "brdfbake/containers.h"
#include "brdfbake/presets.h"
#include "util/file_util.h"

namespace brdfbake {
namespace {

using test::Have;
using test::Numbers;
using test::Slurp;
using test::WriteText;

std::string Scratch(const std::string& name) { return test::Scratch("engine_file_" + name); }

struct BakedPreset {
  std::vector<Table> tables;
  std::vector<Image> images;
};

// Bakes a preset's tables and writes its files into `dir` as the tool does.
BakedPreset WritePreset(const std::string& name, const std::string& dir) {
  const Preset& p = FindPreset(name);
  BakedPreset b;
  for (const PresetTable& pt : p.tables) {
    b.tables.push_back(Bake(pt.spec));
    b.images.push_back(ArrangePresetTable(pt, b.tables.back()));
  }
  PresetRun run;
  run.dir = dir;
  WritePresetFiles(p, run, b.tables, b.images);
  return b;
}

// Runs a shell command; its stdout.
std::string Shell(const std::string& cmd, const std::string& dir, int* status) {
  *status = std::system((cmd + " > " + dir + "/out.txt 2> " + dir + "/err.txt").c_str());
  return Slurp(dir + "/out.txt");
}

// tests/js/node_modules, installed by `npm ci --prefix tests/js`.
std::string JsModules() {
  const std::string dir = std::string(BRDFBAKE_TEST_JS) + "/node_modules";
  if (!Have("node") || !std::filesystem::exists(dir + "/three/package.json") ||
      !std::filesystem::exists(dir + "/ktx-parse/package.json")) {
    ADD_FAILURE() << "node and the pinned JS readers are needed: sh tools/setup.sh test installs them "
                     "(or apt-get install nodejs npm; npm ci --prefix tests/js)";
    return "";
  }
  return dir;
}

TEST(EngineFileTest, FilamentIncludesDfgIncInsideItsArray) {
  if (!PresetBuilt(FindPreset("filament"))) GTEST_SKIP() << "filament needs charlie (BRDFBAKE_MODELS)";
  if (!Have("c++")) GTEST_SKIP() << "no C++ compiler";
  const std::string dir = Scratch("filament");
  const BakedPreset b = WritePreset("filament", dir);
  ASSERT_TRUE(std::filesystem::exists(dir + "/dfg.inc"));
  // As filament/src/DFG.cpp includes it, with DFG::init's size check.
  WriteText(dir + "/dfg.cc",
            "#include <cstddef>\n#include <cstdint>\n#include <cstdio>\n"
            "constexpr std::size_t DFG_LUT_SIZE = 128;\n"
            "const uint16_t DFG_LUT[] = {\n#include \"dfg.inc\"\n};\n"
            "static_assert(sizeof(DFG_LUT) == DFG_LUT_SIZE * DFG_LUT_SIZE * 3 * sizeof(uint16_t), \"size\");\n"
            "int main() { for (uint16_t v : DFG_LUT) std::printf(\"%u\\n\", unsigned(v)); }\n");
  int status = 0;
  Shell("c++ -std=c++17 -Wall -Wextra -Werror -o " + dir + "/dfg " + dir + "/dfg.cc", dir, &status);
  ASSERT_EQ(status, 0) << Slurp(dir + "/err.txt");
  const std::vector<double> codes = Numbers(Shell(dir + "/dfg", dir, &status));
  ASSERT_EQ(status, 0);
  ASSERT_EQ(codes.size(), b.images[0].bits16.size());
  for (size_t i = 0; i < codes.size(); ++i) ASSERT_EQ(uint16_t(codes[i]), b.images[0].bits16[i]) << i;
  // Row 0 is the smooth end: at r = 0.5 / 128 and NoV = 0.5 / 128 the bias
  // (R) is small and E (G) near 1; the last row (r ~ 1) has E near 0.4.
  const Image& im = b.images[0];
  EXPECT_GT(im.values[1], 0.9);
  EXPECT_LT(im.values[(size_t(127) * 128 + 127) * 3 + 1], 0.5);
}

TEST(EngineFileTest, ThreeImportsItsDfgModule) {
  const std::string modules = JsModules();
  if (modules.empty()) return;
  const std::string dir = Scratch("three");
  const BakedPreset b = WritePreset("three", dir);
  // A copy of three's source tree with our module in the place of its own.
  std::filesystem::create_directories(dir + "/three");
  std::filesystem::copy(modules + "/three/src", dir + "/three/src", std::filesystem::copy_options::recursive);
  std::filesystem::copy_file(modules + "/three/package.json", dir + "/three/package.json");
  std::filesystem::copy_file(dir + "/DFGLUTData.js", dir + "/three/src/renderers/shaders/DFGLUTData.js",
                             std::filesystem::copy_options::overwrite_existing);
  WriteText(dir + "/run.mjs",
            "import * as THREE from './three/src/Three.js';\n"  // WebGLRenderer imports getDFGLUT
            "import { getDFGLUT } from './three/src/renderers/shaders/DFGLUTData.js';\n"
            "const t = getDFGLUT();\n"
            "console.log(JSON.stringify({ same: getDFGLUT() === t, data_texture: t.isDataTexture === true,\n"
            "  width: t.image.width, height: t.image.height, rg: t.format === THREE.RGFormat,\n"
            "  half: t.type === THREE.HalfFloatType, linear: t.minFilter === THREE.LinearFilter &&\n"
            "  t.magFilter === THREE.LinearFilter, clamp: t.wrapS === THREE.ClampToEdgeWrapping &&\n"
            "  t.wrapT === THREE.ClampToEdgeWrapping, mipmaps: t.generateMipmaps,\n"
            "  renderer: typeof THREE.WebGLRenderer === 'function', data: Array.from(t.image.data) }));\n");
  int status = 0;
  const std::string out = Shell("cd " + dir + " && node run.mjs", dir, &status);
  ASSERT_EQ(status, 0) << Slurp(dir + "/err.txt");
  const nlohmann::json j = nlohmann::json::parse(out);
  EXPECT_TRUE(j.at("same"));
  EXPECT_TRUE(j.at("data_texture"));
  EXPECT_EQ(j.at("width"), 16);
  EXPECT_EQ(j.at("height"), 16);
  EXPECT_TRUE(j.at("rg"));
  EXPECT_TRUE(j.at("half"));
  EXPECT_TRUE(j.at("linear"));
  EXPECT_TRUE(j.at("clamp"));
  EXPECT_FALSE(j.at("mipmaps"));
  EXPECT_TRUE(j.at("renderer"));
  const std::vector<uint16_t> data = j.at("data").get<std::vector<uint16_t>>();
  EXPECT_EQ(data, b.images[0].bits16);
}

TEST(EngineFileTest, EnterprisePbrHeaderServesItsApi) {
  if (!Have("c++")) GTEST_SKIP() << "no C++ compiler";
  if (!PresetBuilt(FindPreset("enterprise-pbr"))) GTEST_SKIP() << "enterprise-pbr needs charlie";
  const std::string dir = Scratch("enterprise");
  const BakedPreset b = WritePreset("enterprise-pbr", dir);
  // One translation unit defines the arrays; another reads them through
  // the extern declarations, as a renderer uploads them (width, height,
  // a pointer to the first float).
  WriteText(dir + "/impl.cc", "#define PBRLUT_IMPLEMENTATION\n#include \"pbrlut.hpp\"\n");
  WriteText(dir + "/use.cc",
            "#include <cstdio>\n#include \"pbrlut.hpp\"\n"
            "static void Upload(int w, int h, const float* data) {\n"
            "  std::printf(\"%d %d\\n\", w, h);\n"
            "  for (int i = 0; i < w * h; ++i) std::printf(\"%.9g\\n\", double(data[i]));\n}\n"
            "int main() {\n"
            "  Upload(GGX_E_size[0], GGX_E_size[1], &GGX_E[0][0]);\n"
            "  Upload(GGX_E_avg_size, 1, GGX_E_avg);\n"
            "  std::printf(\"%.9g\\n\", double(GGX_E[31][0]));  // [roughness][cos_theta]\n"
            "  std::printf(\"%d %d %d\\n\", Base_E_size[0], Base_E_size[1], Base_E_size[2]);\n"
            "  std::printf(\"%.9g\\n\", double(Base_E[15][3][7]));  // [f0][roughness][cos_theta]\n"
            "  std::printf(\"%d %d\\n\", Base_E_avg_size[0], Base_E_avg_size[1]);\n"
            "  std::printf(\"%.9g\\n\", double(Base_E_avg[5][9]));  // [f0][roughness]\n"
            "  std::printf(\"%.9g %.9g\\n\", double(Sheen_E[2][3]), double(Sheen_ash_E[0][0]));  // [alpha][cos]\n}\n");
  int status = 0;
  Shell("c++ -std=c++17 -Wall -Wextra -Werror -o " + dir + "/use " + dir + "/impl.cc " + dir + "/use.cc", dir,
      &status);
  ASSERT_EQ(status, 0) << Slurp(dir + "/err.txt");
  const std::vector<double> v = Numbers(Shell(dir + "/use", dir, &status));
  ASSERT_EQ(status, 0);
  ASSERT_EQ(v.size(), 2 + 1024 + 2 + 32 + 1 + 3 + 1 + 2 + 1 + 2u);
  EXPECT_EQ(v[0], 32);
  EXPECT_EQ(v[1], 32);
  for (size_t i = 0; i < 1024; ++i) ASSERT_EQ(float(v[2 + i]), float(b.images[0].values[i])) << i;
  EXPECT_EQ(v[1026], 32);
  EXPECT_EQ(v[1027], 1);
  for (size_t i = 0; i < 32; ++i) ASSERT_EQ(float(v[1028 + i]), float(b.images[1].values[i])) << i;
  // GGX_E[31][0]: the roughest row, the most grazing column.
  EXPECT_EQ(float(v[1060]), float(b.images[0].values[31 * 32]));
  EXPECT_EQ(v[1061], 16);
  EXPECT_EQ(v[1062], 16);
  EXPECT_EQ(v[1063], 16);
  EXPECT_EQ(float(v[1064]), float(b.images[2].values[(15 * 16 + 3) * 16 + 7]));
  EXPECT_EQ(v[1065], 16);
  EXPECT_EQ(v[1066], 16);
  EXPECT_EQ(float(v[1067]), float(b.images[3].values[5 * 16 + 9]));
  EXPECT_EQ(float(v[1068]), float(b.images[4].values[2 * 16 + 3]));
  EXPECT_EQ(float(v[1069]), float(b.images[5].values[0]));
  EXPECT_EQ(float(v[1069]), 1.0f);  // capped, as the shipped table
}

// Cycles' ggx_tables.h compiled with a lookup written as Cycles' kernel
// reads its tables ([Cycles]; docs/engines.md): each coordinate clamped to
// [0, 1] and scaled by size - 1 (texels at the edges), bilinear within a
// slice of 16 x 16 (x = roughness, y = NoV), linear across the slices of
// z = sqrt(|ior - 1| / (ior + 1)), light inside the medium (ior < 1) read
// from the inverse tables at 1 / ior. The lookups agree with the glass rule
// within the 16^3 tables' interpolation error there.
TEST(EngineFileTest, CyclesHeaderServesItsKernelLookups) {
  if (!Have("c++")) GTEST_SKIP() << "no C++ compiler";
  if (!PresetBuilt(FindPreset("cycles"))) GTEST_SKIP() << "cycles needs glass (BRDFBAKE_MODELS)";
  const std::string dir = Scratch("cycles");
  const BakedPreset b = WritePreset("cycles", dir);
  WriteText(dir + "/use.cc",
            "#include <algorithm>\n#include <cmath>\n#include <cstdio>\n#include \"ggx_tables.h\"\n"
            "static_assert(sizeof(table_ggx_E) == 1024 * sizeof(float), \"E\");\n"
            "static_assert(sizeof(table_ggx_Eavg) == 32 * sizeof(float), \"E_avg\");\n"
            "static_assert(sizeof(table_ggx_glass_E) == 4096 * sizeof(float), \"glass E\");\n"
            "static_assert(sizeof(table_ggx_glass_inv_E) == 4096 * sizeof(float), \"inv E\");\n"
            "static_assert(sizeof(table_ggx_glass_Eavg) == 256 * sizeof(float), \"glass E_avg\");\n"
            "static_assert(sizeof(table_ggx_glass_inv_Eavg) == 256 * sizeof(float), \"inv E_avg\");\n"
            "static float Row(const float* t, float x, int n) {\n"
            "  x = std::clamp(x, 0.0f, 1.0f) * float(n - 1);\n"
            "  const int i = std::min(int(x), n - 2);\n"
            "  return t[i] + (x - float(i)) * (t[i + 1] - t[i]);\n}\n"
            "static float Read2(const float* t, float x, float y, int nx, int ny) {\n"
            "  y = std::clamp(y, 0.0f, 1.0f) * float(ny - 1);\n"
            "  const int j = std::min(int(y), ny - 2);\n"
            "  const float a = Row(t + j * nx, x, nx), b = Row(t + (j + 1) * nx, x, nx);\n"
            "  return a + (y - float(j)) * (b - a);\n}\n"
            "static float Read3(const float* t, float x, float y, float z) {\n"
            "  z = std::clamp(z, 0.0f, 1.0f) * 15.0f;\n"
            "  const int k = std::min(int(z), 14);\n"
            "  const float a = Read2(t + 256 * k, x, y, 16, 16), b = Read2(t + 256 * (k + 1), x, y, 16, 16);\n"
            "  return a + (z - float(k)) * (b - a);\n}\n"
            "int main() {\n"
            "  const float r = 0.5f, mu = 0.5f;\n"
            "  for (float ior : {1.5f, 1.0f / 1.5f}) {\n"
            "    const bool inside = ior < 1.0f;\n"
            "    const float eta = inside ? 1.0f / ior : ior, z = std::sqrt((eta - 1.0f) / (eta + 1.0f));\n"
            "    std::printf(\"%.9g\\n\", double(Read3(inside ? table_ggx_glass_inv_E : table_ggx_glass_E, r, mu, z)));\n"
            "    std::printf(\"%.9g\\n\", double(Read2(inside ? table_ggx_glass_inv_Eavg : table_ggx_glass_Eavg, r, z, 16, 16)));\n"
            "  }\n"
            "  for (float v : table_ggx_glass_inv_E) std::printf(\"%.9g\\n\", double(v));\n}\n");
  int status = 0;
  Shell("c++ -std=c++17 -Wall -Wextra -Werror -o " + dir + "/use " + dir + "/use.cc", dir, &status);
  ASSERT_EQ(status, 0) << Slurp(dir + "/err.txt");
  const std::vector<double> v = Numbers(Shell(dir + "/use", dir, &status));
  ASSERT_EQ(status, 0);
  ASSERT_EQ(v.size(), 4 + 4096u);
  // The arrays as the preset arranged them (table 4: the inverse E).
  for (size_t i = 0; i < 4096; ++i) ASSERT_EQ(float(v[4 + i]), float(b.images[4].values[i])) << i;
  // The exact values at roughness 0.5 (alpha 0.25), NoV 0.5, ior 1.5 and
  // inside (eta = 1 / 1.5).
  for (const bool inside : {false, true}) {
    BakeSpec s;
    s.model.kind = ModelKind::kGgxGlass;
    s.model.ior = inside ? 1 / 1.5 : 1.5;
    const double e = IntegrateTexel(s, 0.5, 0.5).e, e_avg = IntegrateEavg(s, 0.5).value;
    const double lookup_e = v[inside ? 2 : 0], lookup_avg = v[inside ? 3 : 1];
    EXPECT_NEAR(lookup_e, e, 2e-3) << (inside ? "inside" : "outside");
    EXPECT_NEAR(lookup_avg, e_avg, 2e-3) << (inside ? "inside" : "outside");
    std::printf("cycles lookup at r 0.5, NoV 0.5, eta %.4f: E %.6f (exact %.6f), E_avg %.6f (exact %.6f)\n",
                s.model.ior, lookup_e, e, lookup_avg, e_avg);
  }
}

uint32_t U32(const std::string& s, size_t at) {
  uint32_t v = 0;
  for (int k = 3; k >= 0; --k) v = (v << 8) | uint8_t(s[at + k]);
  return v;
}
uint64_t U64(const std::string& s, size_t at) { return U32(s, at) | (uint64_t(U32(s, at + 4)) << 32); }

TEST(EngineFileTest, BevyKtx2IsZstdSupercompressed) {
  const std::string dir = Scratch("bevy");
  const BakedPreset b = WritePreset("bevy", dir);
  const std::string f = Slurp(dir + "/dfg.ktx2");
  // KTX 2.0 section 3: supercompressionScheme at byte 44 (2 = Zstandard),
  // the level index from byte 80: offset, compressed and full lengths.
  ASSERT_GT(f.size(), 104u);
  EXPECT_EQ(U32(f, 12), 83u);  // VK_FORMAT_R16G16_SFLOAT
  EXPECT_EQ(U32(f, 44), 2u);
  const uint64_t offset = U64(f, 80), length = U64(f, 88), full = U64(f, 96);
  ASSERT_EQ(full, 64u * 64 * 2 * 2);
  ASSERT_LT(length, full);
  ASSERT_LE(offset + length, f.size());
  std::string pixels(full, '\0');
  const size_t n = ZSTD_decompress(pixels.data(), pixels.size(), f.data() + offset, length);
  ASSERT_FALSE(ZSTD_isError(n)) << ZSTD_getErrorName(n);
  ASSERT_EQ(n, full);
  for (size_t i = 0; i < full / 2; ++i) {
    const uint16_t bits = uint16_t(uint8_t(pixels[2 * i]) | (uint8_t(pixels[2 * i + 1]) << 8));
    ASSERT_EQ(bits, b.images[0].bits16[i]) << i;
  }
  // ktx-parse, a reader brdfbake did not write.
  const std::string modules = JsModules();
  if (modules.empty()) return;
  WriteText(dir + "/read.mjs",
            "import { read } from '" + modules + "/ktx-parse/dist/ktx-parse.esm.js';\n"
            "import { readFileSync } from 'fs';\n"
            "const c = read(new Uint8Array(readFileSync('" + dir + "/dfg.ktx2')));\n"
            "console.log(JSON.stringify({ vk: c.vkFormat, w: c.pixelWidth, h: c.pixelHeight,\n"
            "  scheme: c.supercompressionScheme, levels: c.levels.length,\n"
            "  bytes: c.levels[0].levelData.length, full: c.levels[0].uncompressedByteLength,\n"
            "  orientation: c.keyValue['KTXorientation'], table: c.keyValue['brdfbake.table'] }));\n");
  int status = 0;
  const std::string out = Shell("node " + dir + "/read.mjs", dir, &status);
  ASSERT_EQ(status, 0) << Slurp(dir + "/err.txt");
  const nlohmann::json j = nlohmann::json::parse(out);
  EXPECT_EQ(j.at("vk"), 83);
  EXPECT_EQ(j.at("w"), 64);
  EXPECT_EQ(j.at("h"), 64);
  EXPECT_EQ(j.at("scheme"), 2);
  EXPECT_EQ(j.at("levels"), 1);
  EXPECT_EQ(j.at("bytes"), length);
  EXPECT_EQ(j.at("full"), full);
  // ktx-parse keeps string values with their terminating NUL.
  EXPECT_EQ(j.at("orientation").get<std::string>().substr(0, 2), "rd");
}

TEST(EngineFileTest, RgbaExrLoadsInThreeExrLoaderBottomUp) {
  const std::string modules = JsModules();
  if (modules.empty()) return;
  const std::string dir = Scratch("exrloader");
  BakeSpec spec;
  spec.table = TableKind::kDfg;
  spec.mu.size = 8;
  spec.roughness.size = 6;
  spec.half = true;
  const Table t = Bake(spec);
  const Image im = ArrangeTable(t, RgbaLayout(DefaultLayout(t)));
  ASSERT_EQ(im.channel_names, (std::vector<std::string>{"R", "G", "B", "A"}));
  WriteImage(t, im, Container::kExr, dir + "/dfg.exr", "dfg", "");
  WriteText(dir + "/load.mjs",
            "import { EXRLoader } from '" + modules + "/three/examples/jsm/loaders/EXRLoader.js';\n"
            "import { FloatType } from '" + modules + "/three/src/constants.js';\n"
            "import { readFileSync } from 'fs';\n"
            "const loader = new EXRLoader().setDataType(FloatType);\n"
            "const b = readFileSync('" + dir + "/dfg.exr');\n"
            "const r = loader.parse(b.buffer.slice(b.byteOffset, b.byteOffset + b.byteLength));\n"
            "console.log(JSON.stringify({ w: r.width, h: r.height, data: Array.from(r.data) }));\n");
  int status = 0;
  const std::string out = Shell("node " + dir + "/load.mjs", dir, &status);
  ASSERT_EQ(status, 0) << Slurp(dir + "/err.txt");
  const nlohmann::json j = nlohmann::json::parse(out);
  ASSERT_EQ(j.at("w"), 8);
  ASSERT_EQ(j.at("h"), 6);
  const std::vector<double> data = j.at("data").get<std::vector<double>>();
  ASSERT_EQ(data.size(), size_t(8 * 6 * 4));
  // EXRLoader's row 0 is the file's last row (r = 1): upload it as is and
  // sample with v = 1 - v, or flip it back (docs/engines.md#which-way-up).
  for (int y = 0; y < 6; ++y) {
    for (int x = 0; x < 8; ++x) {
      for (int c = 0; c < 4; ++c) {
        ASSERT_EQ(float(data[(size_t(5 - y) * 8 + x) * 4 + c]), float(im.values[(size_t(y) * 8 + x) * 4 + c]))
            << x << " " << y << " " << c;
      }
    }
  }
}

}  // namespace
}  // namespace brdfbake
