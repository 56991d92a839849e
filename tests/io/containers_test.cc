// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Engine presets and containers. Each preset's texels are checked against
// the engine's own layout written out independently here (which axis is x,
// texel placement, warps, row order, channel meaning, clamps), each
// container is read back by a reader written from its specification (KTX
// 2.0, DDS with the DX10 header, the C header and ES module as text) or by
// OpenImageIO where Debian's version reads the format (OpenEXR), and the
// three.js and Bevy presets are compared with the tables those engines ship.

#include <algorithm>
#include <cmath>
#include <functional>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <Imath/half.h>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "brdfbake/bake.h"
#include "brdfbake/containers.h"
#include "brdfbake/exr.h"
#include "brdfbake/presets.h"
#include "brdfbake/shaders.h"
#include "util/file_util.h"

namespace brdfbake {
namespace {

using test::Have;
using test::Slurp;
using test::WriteText;

std::string Scratch(const std::string& name) { return test::Scratch("engine_" + name); }

// Presets whose channels need a model family this build leaves out
// (BRDFBAKE_MODELS) are skipped.
#define SKIP_UNLESS_BUILT(preset)                                                     \
  if (!PresetBuilt(FindPreset(preset))) GTEST_SKIP() << preset << " needs a model family this build leaves out"

struct Baked {
  Table table;
  Image image;
};

Baked BakePreset(const PresetTable& pt) {
  Baked b{Bake(pt.spec), {}};
  b.image = ArrangePresetTable(pt, b.table);
  return b;
}

const PresetTable& TableOf(const std::string& preset, size_t i = 0) {
  return FindPreset(preset).tables.at(i);
}

// The exact values at a physical (NoV, r): E, dfg.scale, dfg.bias.
TexelEstimate Exact(double nov, double r, TableKind kind = TableKind::kDfg) {
  BakeSpec spec;
  spec.table = kind;
  return IntegrateTexel(spec, r, nov);
}

// The other lobes engines store beside the GGX terms, at the same (NoV, r):
// the Charlie sheen's E with the neubelt visibility (Filament's and
// Godot's cloth, MaterialX's sheen) and the Disney diffuse E (HDRP).
struct Lobes {
  double cloth = 0, diffuse = 0;
};
Lobes LobesAt(double nov, double r) {
  if (!ModelBuilt(ModelKind::kCharlie) || !ModelBuilt(ModelKind::kDisneyDiffuse)) return {};
  BakeSpec s;
  s.model.kind = ModelKind::kCharlie;
  s.model.visibility = SheenVisibility::kNeubelt;
  Lobes l;
  l.cloth = IntegrateTexel(s, r, nov).e;
  s.model.kind = ModelKind::kDisneyDiffuse;
  l.diffuse = IntegrateTexel(s, r, nov).e;
  return l;
}

double Value(const Image& im, int x, int y, int c) {
  return im.values[(size_t(y) * im.width + x) * im.channels + c];
}

// Checks sampled texels of a preset's image against the engine's layout:
// `where(x, y)` gives the texel's physical (NoV, r) as the engine defines
// them, `expect(exact)` the channel values.
void CheckLayout(const Image& im, int width, int height,
                 const std::function<std::pair<double, double>(int, int)>& where,
                 const std::function<std::vector<double>(const TexelEstimate&, const Lobes&)>& expect,
                 double rel_tol, const char* what, double abs_tol = 1e-6) {
  ASSERT_EQ(im.width, width) << what;
  ASSERT_EQ(im.height, height) << what;
  for (int y = 0; y < height; y += std::max(1, height / 7)) {
    for (int x = 0; x < width; x += std::max(1, width / 9)) {
      for (const auto& p : {std::pair<int, int>{x, y}, {width - 1, y}, {x, height - 1}}) {
        const auto [nov, r] = where(p.first, p.second);
        const std::vector<double> want = expect(Exact(nov, r), LobesAt(nov, r));
        ASSERT_EQ(int(want.size()), im.channels) << what;
        for (int c = 0; c < im.channels; ++c) {
          EXPECT_NEAR(Value(im, p.first, p.second, c), want[c], rel_tol * std::abs(want[c]) + abs_tol)
              << what << " texel (" << p.first << ", " << p.second << ") channel " << c << " NoV " << nov
              << " r " << r;
        }
      }
    }
  }
}

double Centre(int i, int n) { return (i + 0.5) / n; }
double Edge(int i, int n) { return double(i) / (n - 1); }

constexpr double kHalfRel = 0x1p-10;  // half rounding (with the double-to-float step)

// Every meaning an image can hold is a layout source of the same name,
// without an enumerator of its own (containers.h); the others are
// refused by name.
TEST(ContainersTest, EveryMeaningIsASource) {
  for (int k = 0; k < kMeaningCount; ++k) {
    const Meaning m = Meaning(k);
    if (m == Meaning::kSelIntegral || m == Meaning::kSelRatio || m == Meaning::kError) {
      EXPECT_THROW(SourceOfMeaning(m), std::invalid_argument) << MeaningName(m);
      continue;
    }
    EXPECT_STREQ(SourceName(SourceOfMeaning(m)), MeaningName(m));
  }
  EXPECT_STREQ(SourceName(Source::kScale), "dfg.scale");
  EXPECT_STREQ(SourceName(Source::kZero), "0");
  EXPECT_STREQ(SourceName(Source::kOne), "1");
  // An f82_bias table's default layout reads its one channel.
  BakeSpec spec;
  spec.table = TableKind::kF82Bias;
  spec.mu.size = spec.roughness.size = 3;
  const Table t = Bake(spec);
  const Image im = ArrangeTable(t, DefaultLayout(t));
  ASSERT_EQ(im.channel_sources.size(), 1u);
  EXPECT_EQ(im.channel_sources[0], "f82_bias");
  for (size_t i = 0; i < im.values.size(); ++i) EXPECT_EQ(float(im.values[i]), t.channels[0].stored[i]);
}

TEST(PresetTest, Filament) {
  SKIP_UNLESS_BUILT("filament");
  const Baked b = BakePreset(TableOf("filament"));
  // x = NoV at centres; row 0 is the smooth end, r = 0.5 / 128 (cmgen
  // writes file row y from image row H - 1 - y of CubemapIBL::DFG, whose
  // row 0 is the rough end); R = bias, G = E, B = the cloth E.
  CheckLayout(b.image, 128, 128, [](int x, int y) {
    return std::pair{Centre(x, 128), Centre(y, 128)};
  }, [](const TexelEstimate& v, const Lobes& l) { return std::vector<double>{v.bias, v.scale + v.bias, l.cloth}; },
  kHalfRel, "filament");
}

TEST(PresetTest, Unreal) {
  const Baked b = BakePreset(TableOf("unreal"));
  CheckLayout(b.image, 128, 32, [](int x, int y) { return std::pair{Centre(x, 128), Centre(y, 32)}; },
              [](const TexelEstimate& v, const Lobes& l) { return std::vector<double>{v.scale, v.bias}; }, 0.0, "unreal",
              0.5 / 65535 + 1e-7);
  // unorm16 codes: round(v * 65535).
  const TexelEstimate v = Exact(Centre(5, 128), Centre(7, 32));
  EXPECT_EQ(b.image.bits16[(7 * 128 + 5) * 2], uint16_t(std::lround(v.scale * 65535)));
}

TEST(PresetTest, Hdrp) {
  SKIP_UNLESS_BUILT("hdrp");
  const Baked b = BakePreset(TableOf("hdrp"));
  // Texel i holds coordinate c = i / (N - 1) (endpoints on texel centres);
  // x = sqrt(NoV), so NoV = c^2; R = bias, G = E, B = the Disney diffuse
  // E / 1.03571 - 0.5.
  CheckLayout(b.image, 64, 64, [](int x, int y) {
    const double c = Edge(x, 64);
    return std::pair{c * c, Edge(y, 64)};
  }, [](const TexelEstimate& v, const Lobes& l) {
    return std::vector<double>{v.bias, v.scale + v.bias, l.diffuse / 1.03571 - 0.5};
  },
  kHalfRel, "hdrp");
}

TEST(PresetTest, Godot) {
  SKIP_UNLESS_BUILT("godot");
  const Baked b = BakePreset(TableOf("godot"));
  CheckLayout(b.image, 128, 128, [](int x, int y) {
    return std::pair{Centre(x, 128), 1.0 - Centre(y, 128)};
  }, [](const TexelEstimate& v, const Lobes& l) { return std::vector<double>{v.bias, v.scale + v.bias, l.cloth, 1.0}; },
  kHalfRel, "godot");
}

TEST(PresetTest, Bevy) {
  const Baked b = BakePreset(TableOf("bevy"));
  CheckLayout(b.image, 64, 64, [](int x, int y) { return std::pair{Centre(x, 64), Centre(y, 64)}; },
              [](const TexelEstimate& v, const Lobes& l) { return std::vector<double>{v.scale, v.bias}; }, kHalfRel, "bevy");
}

TEST(PresetTest, Three) {
  const Baked b = BakePreset(TableOf("three"));
  // x = roughness, y = NoV.
  CheckLayout(b.image, 16, 16, [](int x, int y) { return std::pair{Centre(y, 16), Centre(x, 16)}; },
              [](const TexelEstimate& v, const Lobes& l) { return std::vector<double>{v.scale, v.bias}; }, kHalfRel, "three");
}

TEST(PresetTest, Materialx) {
  SKIP_UNLESS_BUILT("materialx");
  const Baked b = BakePreset(TableOf("materialx"));
  // y = alpha at centres: r = sqrt(alpha).
  CheckLayout(b.image, 64, 64, [](int x, int y) { return std::pair{Centre(x, 64), std::sqrt(Centre(y, 64))}; },
              [](const TexelEstimate& v, const Lobes& l) {
                return std::vector<double>{v.scale, v.bias, std::min(l.cloth, 1.0)};
              },
              1e-7, "materialx");
}

TEST(PresetTest, CyclesAndEnterprisePbr) {
  const Baked e = BakePreset(TableOf("cycles", 0));
  // x = r, y = NoV, edges, both clamped at 1e-4.
  CheckLayout(e.image, 32, 32, [](int x, int y) {
    return std::pair{std::max(Edge(y, 32), 1e-4), std::max(Edge(x, 32), 1e-4)};
  }, [](const TexelEstimate& v, const Lobes& l) { return std::vector<double>{v.e}; }, 1e-7, "cycles E");
  const Baked a = BakePreset(TableOf("cycles", 1));
  ASSERT_EQ(a.image.width, 32);
  ASSERT_EQ(a.image.height, 1);
  EXPECT_NEAR(a.image.values[31], IntegrateEavg(BakeSpec(), 1.0).value, 1e-7);
  // Cycles' own E_avg at r = 1 is 0.409137 (its table, six decimals).
  EXPECT_NEAR(a.image.values[31], 0.409137, 5e-6);
  const Baked p = BakePreset(TableOf("enterprise-pbr", 0));
  CheckLayout(p.image, 32, 32, [](int x, int y) { return std::pair{Centre(x, 32), Centre(y, 32)}; },
              [](const TexelEstimate& v, const Lobes& l) { return std::vector<double>{v.e}; }, 1e-7, "enterprise-pbr E");
}

// The first `n` numbers OpenImageIO's `oiiotool --dumpdata` prints for
// pixel (x, y) (codes for integer pixels), or none if the dump has no
// such pixel.
std::vector<double> DumpedPixel(const std::string& dump, int x, int y, int n) {
  const std::string key = "Pixel (" + std::to_string(x) + ", " + std::to_string(y) + "):";
  const size_t at = dump.find(key);
  if (at == std::string::npos) return {};
  std::stringstream ss(dump.substr(at + key.size(), 80));
  std::vector<double> v(n);
  for (double& e : v) ss >> e;
  return v;
}

// A preset table at another size (the same axes, placement and layout).
PresetTable Resized(PresetTable pt, int n) {
  pt.spec.mu.size = pt.spec.roughness.size = n;
  return pt;
}

// The Charlie E of a visibility at (NoV, r).
double SheenE(SheenVisibility v, double nov, double r) {
  BakeSpec s;
  s.model.kind = ModelKind::kCharlie;
  s.model.visibility = v;
  return IntegrateTexel(s, r, nov).e;
}

// The khronos preset: three 1024x1024 PNGs (x = NoV, y = r, centres, row 0
// the smooth end). The same tables at 32x32 are checked texel by texel
// against each definition, written as the preset writes them, and read
// back by OpenImageIO.
TEST(PresetTest, Khronos) {
  SKIP_UNLESS_BUILT("khronos");
  const Preset& k = FindPreset("khronos");
  ASSERT_EQ(k.tables.size(), 3u);
  const char* files[] = {"lut_ggx.png", "lut_charlie.png", "lut_sheen_E.png"};
  const PixelType pixels[] = {PixelType::kUnorm8, PixelType::kUnorm8, PixelType::kUnorm16};
  for (int t = 0; t < 3; ++t) {
    const PresetTable& pt = k.tables[t];
    EXPECT_EQ(pt.file, files[t]);
    EXPECT_EQ(pt.container, Container::kPng);
    EXPECT_EQ(pt.layout.pixel, pixels[t]);
    EXPECT_EQ(pt.spec.mu.size, 1024);
    EXPECT_EQ(pt.spec.roughness.size, 1024);
    EXPECT_EQ(pt.layout.channels.size(), 3u);
    EXPECT_FALSE(pt.layout.flip_rows);
    EXPECT_FALSE(pt.layout.roughness_on_x);
  }
  EXPECT_EQ(k.tables[1].spec.model.visibility, SheenVisibility::kNeubeltClamped);     // V_Ashikhmin
  EXPECT_EQ(k.tables[2].spec.model.visibility, SheenVisibility::kContyKullaClamped);  // V_Sheen
  const int n = 32;
  Preset small = k;
  for (PresetTable& pt : small.tables) pt = Resized(pt, n);
  std::vector<Table> tables;
  std::vector<Image> images;
  for (const PresetTable& pt : small.tables) {
    const Baked b = BakePreset(pt);
    tables.push_back(b.table);
    images.push_back(b.image);
  }
  // lut_ggx: R = scale, G = bias, B = E.
  CheckLayout(images[0], n, n, [&](int x, int y) { return std::pair{Centre(x, n), Centre(y, n)}; },
              [](const TexelEstimate& v, const Lobes&) { return std::vector<double>{v.scale, v.bias, v.e}; }, 0,
              "khronos lut_ggx", 0.5 / 255 + 2e-5);
  // The sheen tables: R = G = B = the capped-V Charlie E, at most 1.
  double cap_effect = 0;
  for (int t = 1; t <= 2; ++t) {
    const double step = t == 1 ? 1 / 255.0 : 1 / 65535.0;
    const SheenVisibility v = small.tables[t].spec.model.visibility;
    const SheenVisibility open = t == 1 ? SheenVisibility::kNeubelt : SheenVisibility::kContyKulla;
    for (int y = 0; y < n; y += 3) {
      for (int x = 0; x < n; x += 3) {
        const double nov = Centre(x, n), r = Centre(y, n);
        const double want = std::min(1.0, SheenE(v, nov, r));
        cap_effect = std::max(cap_effect, std::abs(std::min(1.0, SheenE(open, nov, r)) - want));
        for (int c = 0; c < 3; ++c) {
          EXPECT_NEAR(Value(images[t], x, y, c), want, 0.5 * step + 2 * small.tables[t].spec.tolerance + 1e-7)
              << files[t] << " (" << x << ", " << y << ") channel " << c;
        }
      }
    }
  }
  // The cap of V changes the tables by far more than a pixel step.
  EXPECT_GT(cap_effect, 0.05);
  // Written as the preset writes them and read back by OpenImageIO: the
  // pixel codes the image holds, top row first.
  if (std::system("command -v oiiotool >/dev/null 2>&1") != 0) GTEST_SKIP() << "no oiiotool";
  const std::string dir = Scratch("khronos");
  PresetRun run;
  run.dir = dir;
  WritePresetFiles(small, run, tables, images);
  for (int t = 0; t < 3; ++t) {
    const std::string path = dir + "/" + files[t];
    ASSERT_EQ(std::system(("oiiotool --dumpdata " + path + " > " + dir + "/dump.txt 2>&1").c_str()), 0);
    const std::string dump = Slurp(dir + "/dump.txt");
    EXPECT_NE(dump.find(t == 2 ? "uint16 png" : "uint8 png"), std::string::npos) << dump.substr(0, 200);
    for (const auto& [x, y] : {std::pair{0, 0}, {n - 1, 0}, {3, n - 1}, {n / 2, n / 3}}) {
      const std::vector<double> codes = DumpedPixel(dump, x, y, 3);
      ASSERT_EQ(codes.size(), 3u) << path << " pixel (" << x << ", " << y << ")";
      for (int c = 0; c < 3; ++c) {
        ASSERT_EQ(int(codes[c]), images[t].bits16[(size_t(y) * n + x) * 3 + c])
            << path << " pixel (" << x << ", " << y << ") channel " << c;
      }
    }
  }
}

// Which engines fix their tables' size in code (a scene may not choose
// another): header arrays, Filament's .inc, HDRP's edges remap.
TEST(PresetTest, SizeFixedByTheEngine) {
  for (const Preset& p : Presets()) {
    const bool fixed = p.name == "filament" || p.name == "cycles" || p.name == "enterprise-pbr" || p.name == "hdrp" ||
                       p.name == "openpbr" || p.name == "eevee";
    for (const PresetTable& pt : p.tables) EXPECT_EQ(pt.size_fixed, fixed) << p.name << " " << pt.symbol;
  }
}

// Enterprise PBR's pbrlut.hpp tables beyond GGX_E and GGX_E_avg: Base_E
// and Base_E_avg (GGX with Schlick's Fresnel and the multiple-scattering
// lobe, over F0), Sheen_E (its refined Lambda fit) and Sheen_ash_E
// (neubelt, at most 1), each against its definition evaluated here.
TEST(PresetTest, EnterprisePbrEveryTable) {
  SKIP_UNLESS_BUILT("enterprise-pbr");
  const Preset& p = FindPreset("enterprise-pbr");
  std::vector<std::string> symbols;
  for (const PresetTable& pt : p.tables) symbols.push_back(pt.symbol);
  EXPECT_EQ(symbols, (std::vector<std::string>{"GGX_E", "GGX_E_avg", "Base_E", "Base_E_avg", "Sheen_E", "Sheen_ash_E"}));
  auto f_ms = [](double f0, double e_avg) {
    const double f_avg = (20 * f0 + 1) / 21;
    return f_avg * f_avg * e_avg / (1 - f_avg * (1 - e_avg));
  };
  const Baked base = BakePreset(p.tables[2]);
  ASSERT_EQ(base.image.width, 16);
  ASSERT_EQ(base.image.height, 256);
  ASSERT_EQ(base.image.axes.size(), 3u);
  EXPECT_EQ(base.image.axes[2].name, "f0");
  for (int kf : {0, 6, 15}) {
    const double f0 = Centre(kf, 16);
    for (int j : {0, 7, 15}) {
      const double r = Centre(j, 16), ea = IntegrateEavg(BakeSpec(), r).value;
      for (int i : {0, 9, 15}) {
        const TexelEstimate v = Exact(Centre(i, 16), r);
        const double want = std::min(1.0, f0 * v.scale + v.bias + f_ms(f0, ea) * (1 - v.e));
        EXPECT_NEAR(base.image.values[(size_t(kf) * 16 + j) * 16 + i], want, 1e-6) << kf << " " << j << " " << i;
      }
    }
  }
  // Base_E_avg = 2 int Base_E mu dmu (unclamped), by Boost's adaptive
  // Gauss-Kronrod over the definition.
  const Baked avg = BakePreset(p.tables[3]);
  ASSERT_EQ(avg.image.width, 16);
  ASSERT_EQ(avg.image.height, 16);
  for (const auto& [kf, j] : {std::pair{0, 5}, {9, 10}, {15, 15}}) {
    const double f0 = Centre(kf, 16), r = Centre(j, 16), fm = f_ms(f0, IntegrateEavg(BakeSpec(), r).value);
    const double want = 2 * boost::math::quadrature::gauss_kronrod<double, 31>::integrate(
                                [&](double mu) {
                                  const TexelEstimate v = Exact(std::max(mu, 1e-9), r);
                                  return (f0 * v.scale + v.bias + fm * (1 - v.e)) * mu;
                                },
                                0.0, 1.0, 8, 1e-10);
    EXPECT_NEAR(avg.image.values[size_t(kf) * 16 + j], std::min(1.0, want), 2e-6) << kf << " " << j;
  }
  // Sheen_E and Sheen_ash_E: rows at alpha = (j + 0.5) / 16.
  const Baked sheen = BakePreset(p.tables[4]), ash = BakePreset(p.tables[5]);
  for (int j : {0, 5, 15}) {
    const double r = std::sqrt(Centre(j, 16));
    for (int i : {0, 4, 15}) {
      const double nov = Centre(i, 16);
      EXPECT_NEAR(sheen.image.values[size_t(j) * 16 + i], SheenE(SheenVisibility::kEnterprisePbr, nov, r), 1e-6);
      EXPECT_NEAR(ash.image.values[size_t(j) * 16 + i], std::min(1.0, SheenE(SheenVisibility::kNeubelt, nov, r)),
                  1e-6);
    }
  }
}

// ------------------------------------------------------------ containers

// KTX 2.0, read as its specification lays it out (section 3: header,
// index, level index; section 4: the data format descriptor; section 5:
// key/value data).
struct Ktx2 {
  uint32_t vk_format = 0, type_size = 0, width = 0, height = 0, depth = 0, layers = 0, faces = 0, levels = 0,
           supercompression = 0;
  std::map<std::string, std::string> kv;
  std::vector<std::string> kv_order;
  uint32_t dfd_block_size = 0, bytes_plane0 = 0, color_model = 0, transfer = 0;
  std::vector<uint32_t> sample_words;
  std::string data;
  uint64_t data_offset = 0;
};

uint32_t U32(const std::string& s, size_t at) {
  uint32_t v = 0;
  for (int k = 3; k >= 0; --k) v = (v << 8) | uint8_t(s[at + k]);
  return v;
}
uint64_t U64(const std::string& s, size_t at) { return U32(s, at) | (uint64_t(U32(s, at + 4)) << 32); }

Ktx2 ReadKtx2(const std::string& f) {
  Ktx2 k;
  const unsigned char id[12] = {0xAB, 0x4B, 0x54, 0x58, 0x20, 0x32, 0x30, 0xBB, 0x0D, 0x0A, 0x1A, 0x0A};
  EXPECT_EQ(std::memcmp(f.data(), id, 12), 0) << "KTX2 identifier";
  uint32_t* fields[] = {&k.vk_format, &k.type_size, &k.width, &k.height, &k.depth,
                        &k.layers,    &k.faces,     &k.levels, &k.supercompression};
  for (int i = 0; i < 9; ++i) *fields[i] = U32(f, 12 + 4 * i);
  const uint32_t dfd_off = U32(f, 48), dfd_len = U32(f, 52), kvd_off = U32(f, 56), kvd_len = U32(f, 60);
  EXPECT_EQ(U64(f, 64), 0u);  // no supercompression global data
  EXPECT_EQ(U64(f, 72), 0u);
  k.data_offset = U64(f, 80);
  const uint64_t len = U64(f, 88), ulen = U64(f, 96);
  EXPECT_EQ(len, ulen);
  EXPECT_EQ(U32(f, dfd_off), dfd_len);
  EXPECT_EQ(U32(f, dfd_off + 4), 0u);  // vendor Khronos, basic descriptor
  const uint32_t w2 = U32(f, dfd_off + 8);
  EXPECT_EQ(w2 & 0xffff, 2u);  // version 1.3
  k.dfd_block_size = w2 >> 16;
  EXPECT_EQ(dfd_len, 4 + k.dfd_block_size);
  const uint32_t w3 = U32(f, dfd_off + 12);
  k.color_model = w3 & 0xff;
  k.transfer = (w3 >> 16) & 0xff;
  k.bytes_plane0 = U32(f, dfd_off + 20) & 0xff;
  for (uint32_t at = dfd_off + 28; at < dfd_off + dfd_len; at += 4) k.sample_words.push_back(U32(f, at));
  for (size_t at = kvd_off; at < kvd_off + kvd_len;) {
    const uint32_t n = U32(f, at);
    const std::string entry = f.substr(at + 4, n);
    const size_t nul = entry.find('\0');
    const std::string key = entry.substr(0, nul);
    std::string value = entry.substr(nul + 1);
    if (!value.empty() && value.back() == '\0') value.pop_back();
    k.kv[key] = value;
    k.kv_order.push_back(key);
    at += 4 + n;
    at = (at + 3) & ~size_t(3);
  }
  k.data = f.substr(k.data_offset, len);
  return k;
}

TEST(ContainerTest, Ktx2FollowsTheSpecification) {
  const Baked b = BakePreset(TableOf("bevy"));
  const std::string dir = Scratch("ktx2");
  WriteImage(b.table, b.image, Container::kKtx2, dir + "/dfg.ktx2", "dfg", "bevy");
  const Ktx2 k = ReadKtx2(Slurp(dir + "/dfg.ktx2"));
  EXPECT_EQ(k.vk_format, 83u);  // VK_FORMAT_R16G16_SFLOAT
  EXPECT_EQ(k.type_size, 2u);
  EXPECT_EQ(k.width, 64u);
  EXPECT_EQ(k.height, 64u);
  EXPECT_EQ(k.depth, 0u);
  EXPECT_EQ(k.layers, 0u);
  EXPECT_EQ(k.faces, 1u);
  EXPECT_EQ(k.levels, 1u);
  EXPECT_EQ(k.supercompression, 0u);
  EXPECT_EQ(k.color_model, 1u);  // RGBSDA
  EXPECT_EQ(k.transfer, 1u);     // linear
  EXPECT_EQ(k.dfd_block_size, 24u + 16u * 2);
  EXPECT_EQ(k.bytes_plane0, 4u);
  ASSERT_EQ(k.sample_words.size(), 8u);
  // Sample 0: R at bit 0, 16 bits, float | signed; sample 1: G at bit 16.
  EXPECT_EQ(k.sample_words[0], 0u | (15u << 16) | (0xC0u << 24));
  EXPECT_EQ(k.sample_words[4], 16u | (15u << 16) | ((0xC0u | 1u) << 24));
  EXPECT_EQ(k.sample_words[2], 0xBF800000u);
  EXPECT_EQ(k.sample_words[3], 0x3F800000u);
  EXPECT_EQ(k.data_offset % 4, 0u);
  EXPECT_TRUE(std::is_sorted(k.kv_order.begin(), k.kv_order.end()));
  EXPECT_EQ(k.kv.at("KTXorientation"), "rd");
  EXPECT_EQ(k.kv.at("brdfbake.table"), "dfg");
  EXPECT_EQ(k.kv.at("brdfbake.preset"), "bevy");
  EXPECT_FALSE(k.kv.at("brdfbake.axes").empty());
  ASSERT_EQ(k.data.size(), 64u * 64 * 2 * 2);
  for (size_t i = 0; i < 64 * 64 * 2; ++i) {
    const uint16_t bits = uint16_t(uint8_t(k.data[2 * i]) | (uint8_t(k.data[2 * i + 1]) << 8));
    ASSERT_EQ(bits, b.image.bits16[i]) << i;
  }
  // The float variant: R32G32_SFLOAT.
  ImageLayout l = TableOf("bevy").layout;
  l.pixel = PixelType::kFloat;
  const Image fim = ArrangeTable(b.table, l);
  WriteImage(b.table, fim, Container::kKtx2, dir + "/dfg32.ktx2", "dfg", "");
  const Ktx2 k32 = ReadKtx2(Slurp(dir + "/dfg32.ktx2"));
  EXPECT_EQ(k32.vk_format, 103u);  // VK_FORMAT_R32G32_SFLOAT
  EXPECT_EQ(k32.type_size, 4u);
  float first;
  std::memcpy(&first, k32.data.data(), 4);
  EXPECT_EQ(double(first), fim.values[0]);
}

// DDS: "DDS ", DDS_HEADER (124 bytes), DDS_HEADER_DXT10 (20 bytes), data.
TEST(ContainerTest, DdsFollowsTheDx10Layout) {
  const Baked b = BakePreset(TableOf("unreal"));
  const std::string dir = Scratch("dds");
  WriteImage(b.table, b.image, Container::kDds, dir + "/gf.dds", "gf", "unreal");
  const std::string f = Slurp(dir + "/gf.dds");
  ASSERT_EQ(f.substr(0, 4), "DDS ");
  EXPECT_EQ(U32(f, 4), 124u);
  EXPECT_EQ(U32(f, 4 + 8), 32u);    // height
  EXPECT_EQ(U32(f, 4 + 12), 128u);  // width
  EXPECT_EQ(U32(f, 4 + 16), 128u * 4);  // pitch
  EXPECT_EQ(U32(f, 4 + 72), 32u);   // pixel format size
  EXPECT_EQ(U32(f, 4 + 76), 4u);    // DDPF_FOURCC
  EXPECT_EQ(f.substr(4 + 80, 4), "DX10");
  EXPECT_EQ(U32(f, 4 + 104), 0x1000u);  // DDSCAPS_TEXTURE
  EXPECT_EQ(U32(f, 128), 35u);      // DXGI_FORMAT_R16G16_UNORM
  EXPECT_EQ(U32(f, 132), 3u);       // TEXTURE2D
  EXPECT_EQ(U32(f, 140), 1u);       // array size
  ASSERT_EQ(f.size(), 148u + 128 * 32 * 4);
  for (size_t i = 0; i < 128 * 32 * 2; ++i) {
    const uint16_t code = uint16_t(uint8_t(f[148 + 2 * i]) | (uint8_t(f[148 + 2 * i + 1]) << 8));
    ASSERT_EQ(code, b.image.bits16[i]) << i;
  }
  ImageLayout l = TableOf("unreal").layout;
  l.pixel = PixelType::kHalf;
  WriteImage(b.table, ArrangeTable(b.table, l), Container::kDds, dir + "/gf16.dds", "gf", "");
  EXPECT_EQ(U32(Slurp(dir + "/gf16.dds"), 128), 34u);  // DXGI_FORMAT_R16G16_FLOAT
}

// The numbers of a C array or a JS typed array, in order.
std::vector<double> ArrayNumbers(const std::string& text, const std::string& symbol) {
  const size_t at = text.find(symbol + "[");
  const size_t js = text.find(symbol + " = new ");
  const size_t start = text.find_first_of("{[", (at != std::string::npos ? at + symbol.size() + 1 : js) + 1);
  const size_t end = text.find_first_of("}]", start + 1);
  std::vector<double> out;
  std::stringstream ss(text.substr(start + 1, end - start - 1));
  std::string item;
  while (std::getline(ss, item, ',')) {
    const size_t b = item.find_first_not_of(" \n([");
    if (b == std::string::npos) continue;
    item = item.substr(b, item.find_last_not_of(" \n") - b + 1);
    if (item.rfind("0x", 0) != 0 && !item.empty() && item.back() == 'f') item.pop_back();  // 1.5f
    out.push_back(item.rfind("0x", 0) == 0 ? double(std::stoul(item, nullptr, 16)) : std::stod(item));
  }
  return out;
}

TEST(ContainerTest, HeaderAndModuleReadBack) {
  SKIP_UNLESS_BUILT("filament");
  const std::string dir = Scratch("text");
  // Filament: uint16 half bits in a header; rows flipped.
  const Baked f = BakePreset(TableOf("filament"));
  WriteImage(f.table, f.image, Container::kHeader, dir + "/dfg.h", "DFG_LUT", "filament");
  const std::string h = Slurp(dir + "/dfg.h");
  EXPECT_NE(h.find("brdfbake.preset: filament"), std::string::npos);
  EXPECT_NE(h.find("row 0 = the first roughness entry"), std::string::npos);
  EXPECT_NE(h.find("inline constexpr uint16_t DFG_LUT[49152]"), std::string::npos);
  const std::vector<double> bits = ArrayNumbers(h, "DFG_LUT");
  ASSERT_EQ(bits.size(), f.image.bits16.size());
  for (size_t i = 0; i < bits.size(); ++i) ASSERT_EQ(uint16_t(bits[i]), f.image.bits16[i]) << i;
  // Cycles: float arrays, two tables in one header.
  const Preset& cycles = FindPreset("cycles");
  const Baked e = BakePreset(cycles.tables[0]), a = BakePreset(cycles.tables[1]);
  WriteHeader({{&e.table, &e.image}, {&a.table, &a.image}}, {"table_ggx_E", "table_ggx_Eavg"},
              dir + "/ggx.h", "cycles");
  const std::string c = Slurp(dir + "/ggx.h");
  const std::vector<double> ev = ArrayNumbers(c, "table_ggx_E"), av = ArrayNumbers(c, "table_ggx_Eavg");
  ASSERT_EQ(ev.size(), 1024u);
  ASSERT_EQ(av.size(), 32u);
  for (size_t i = 0; i < ev.size(); ++i) ASSERT_EQ(float(ev[i]), float(e.image.values[i])) << i;
  for (size_t i = 0; i < av.size(); ++i) ASSERT_EQ(float(av[i]), float(a.image.values[i])) << i;
  // The header compiles (C++17), when a compiler is at hand.
  if (std::system("command -v c++ >/dev/null 2>&1") == 0) {
    WriteText(dir + "/use.cc", "#include \"ggx.h\"\n#include \"dfg.h\"\nstatic_assert(table_ggx_E_width == 32);\n"
                               "int main() { return int(table_ggx_E[0] + DFG_LUT[0]) * 0; }\n");
    EXPECT_EQ(std::system(("c++ -std=c++17 -fsyntax-only -I" + dir + " " + dir + "/use.cc").c_str()), 0);
  }
  // three.js: an ES module with a Uint16Array of halves.
  const Baked t = BakePreset(TableOf("three"));
  WriteImage(t.table, t.image, Container::kJs, dir + "/DFGLUTData.js", "DFGLUTData", "three");
  const std::string js = Slurp(dir + "/DFGLUTData.js");
  EXPECT_NE(js.find("export const width = 16;"), std::string::npos);
  EXPECT_NE(js.find("export const format = 'RG16F';"), std::string::npos);
  EXPECT_NE(js.find("export const DFGLUTData = new Uint16Array(["), std::string::npos);
  const std::vector<double> jv = ArrayNumbers(js, "DFGLUTData");
  ASSERT_EQ(jv.size(), 512u);
  for (size_t i = 0; i < jv.size(); ++i) ASSERT_EQ(uint16_t(jv[i]), t.image.bits16[i]) << i;
}

// One rounding step serves every writer: a half dfg bake stores the same
// numbers in its own EXR and in each container, and scale + bias <= 1
// holds after each container's rounding, read back from the file.
TEST(ContainerTest, OneRoundingInEveryContainer) {
  BakeSpec spec;
  spec.table = TableKind::kDfg;
  spec.half = true;
  spec.mu.size = spec.roughness.size = 64;
  spec.mu.placement = spec.roughness.placement = Placement::kCenters;
  const Table t = Bake(spec);
  const std::string dir = Scratch("rounding");
  WriteExr(t, dir + "/own.exr");
  const ExrContents own = ReadExr(dir + "/own.exr");
  const std::vector<float>& own_scale = *own.ChannelData("dfg.0_scale");
  const std::vector<float>& own_bias = *own.ChannelData("dfg.1_bias");
  const Image im = ArrangeTable(t, DefaultLayout(t));
  ASSERT_EQ(im.channel_sources, (std::vector<std::string>{"dfg.scale", "dfg.bias"}));
  size_t at_one = 0;
  for (size_t i = 0; i < own_scale.size(); ++i) {
    ASSERT_EQ(im.values[2 * i], double(own_scale[i])) << i;
    ASSERT_EQ(im.values[2 * i + 1], double(own_bias[i])) << i;
    ASSERT_LE(double(own_scale[i]) + double(own_bias[i]), 1.0) << i;
    at_one += double(own_scale[i]) + double(own_bias[i]) == 1.0;
  }
  EXPECT_GT(at_one, 0u);  // the clamp is exercised: the smooth end reaches 1
  auto check_codes = [&](const std::vector<uint16_t>& codes, const char* what) {
    ASSERT_EQ(codes.size(), im.bits16.size()) << what;
    for (size_t i = 0; i < codes.size(); i += 2) {
      ASSERT_EQ(codes[i], im.bits16[i]) << what << " " << i;
      Imath::half s, b;
      s.setBits(codes[i]);
      b.setBits(codes[i + 1]);
      ASSERT_LE(double(float(s)) + double(float(b)), 1.0) << what << " " << i;
    }
  };
  // Header and ES module: the half bits as text.
  WriteImage(t, im, Container::kHeader, dir + "/t.h", "lut", "");
  WriteImage(t, im, Container::kJs, dir + "/t.js", "lut", "");
  for (const char* f : {"/t.h", "/t.js"}) {
    std::vector<uint16_t> codes;
    for (double v : ArrayNumbers(Slurp(dir + f), "lut")) codes.push_back(uint16_t(v));
    check_codes(codes, f);
  }
  // KTX2 and DDS: the level's bytes.
  WriteImage(t, im, Container::kKtx2, dir + "/t.ktx2", "lut", "");
  WriteImage(t, im, Container::kDds, dir + "/t.dds", "lut", "");
  const Ktx2 k = ReadKtx2(Slurp(dir + "/t.ktx2"));
  const std::string dds = Slurp(dir + "/t.dds").substr(148);
  for (const std::string* bytes : {&k.data, &dds}) {
    std::vector<uint16_t> codes(bytes->size() / 2);
    for (size_t i = 0; i < codes.size(); ++i) {
      codes[i] = uint16_t(uint8_t((*bytes)[2 * i]) | (uint8_t((*bytes)[2 * i + 1]) << 8));
    }
    check_codes(codes, bytes == &dds ? "dds" : "ktx2");
  }
  // A float table arranged as halves (Bevy's) and as unorm16 codes
  // (Unreal's) keeps the bound after its own rounding too.
  for (const char* preset : {"bevy", "unreal", "three"}) {
    const Baked p = BakePreset(TableOf(preset));
    for (size_t i = 0; i < p.image.values.size(); i += 2) {
      ASSERT_LE(p.image.values[i] + p.image.values[i + 1], 1.0) << preset << " " << i;
    }
  }
}

TEST(ContainerTest, ExrReadsBackWithOpenImageIo) {
  SKIP_UNLESS_BUILT("materialx");
  const Baked b = BakePreset(TableOf("materialx"));
  const std::string dir = Scratch("exr");
  const std::string path = dir + "/albedo.exr";
  WriteImage(b.table, b.image, Container::kExr, path, "albedo", "materialx");
  const ExrContents c = ReadExr(path);  // OpenEXR
  ASSERT_EQ(c.channels.size(), 3u);
  EXPECT_EQ(c.channels[0].first, "B");  // OpenEXR sorts; image readers map R, G, B by name
  EXPECT_EQ(c.Attribute("brdfbake.preset"), "materialx");
  const std::vector<float>& r = *c.ChannelData("R");
  for (size_t i = 0; i < r.size(); ++i) ASSERT_EQ(double(r[i]), b.image.values[i * 3]) << i;
  if (std::system("command -v oiiotool >/dev/null 2>&1") != 0) GTEST_SKIP() << "no oiiotool";
  // OpenImageIO, independently: a few texels by value.
  const std::string cmd = "oiiotool --dumpdata " + path + " > " + dir + "/dump.txt 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  const std::string dump = Slurp(dir + "/dump.txt");
  for (int y : {0, 17, 63}) {
    for (int x : {0, 40, 63}) {
      const std::vector<double> v = DumpedPixel(dump, x, y, 3);
      ASSERT_EQ(v.size(), 3u) << "pixel (" << x << ", " << y << ")";
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(v[c], Value(b.image, x, y, c), 1e-6) << "pixel (" << x << ", " << y << ")";
    }
  }
}

// PNG (libpng) read back by OpenImageIO: 8- and 16-bit RGB codes texel by
// texel, and the conventions in its text chunks.
TEST(ContainerTest, PngReadsBackWithOpenImageIo) {
  if (std::system("command -v oiiotool >/dev/null 2>&1") != 0) GTEST_SKIP() << "no oiiotool";
  BakeSpec spec;
  spec.table = TableKind::kDfg;
  spec.mu.size = 12;
  spec.roughness.size = 7;
  spec.mu.placement = spec.roughness.placement = Placement::kCenters;
  const Table t = Bake(spec);
  const std::string dir = Scratch("png");
  for (PixelType pixel : {PixelType::kUnorm8, PixelType::kUnorm16}) {
    ImageLayout l;
    l.channels = {{"R", Source::kScale}, {"G", Source::kBias}, {"B", Source::kE}};
    l.pixel = pixel;
    const Image im = ArrangeTable(t, l);
    const std::string path = dir + "/dfg_" + PixelTypeName(pixel) + ".png";
    WriteImage(t, im, Container::kPng, path, "dfg", "");
    ASSERT_EQ(std::system(("oiiotool --dumpdata " + path + " > " + dir + "/dump.txt 2>&1").c_str()), 0);
    const std::string dump = Slurp(dir + "/dump.txt");
    EXPECT_NE(dump.find(pixel == PixelType::kUnorm8 ? "uint8 png" : "uint16 png"), std::string::npos) << dump.substr(0, 200);
    for (int y = 0; y < im.height; ++y) {
      for (int x = 0; x < im.width; ++x) {
        const std::vector<double> codes = DumpedPixel(dump, x, y, 3);
        ASSERT_EQ(codes.size(), 3u) << path << " pixel (" << x << ", " << y << ")";
        for (int c = 0; c < 3; ++c) {
          ASSERT_EQ(int(codes[c]), im.bits16[(size_t(y) * im.width + x) * 3 + c])
              << path << " pixel (" << x << ", " << y << ") channel " << c;
        }
        const double max = pixel == PixelType::kUnorm8 ? 255 : 65535;
        EXPECT_NEAR(im.bits16[(size_t(y) * im.width + x) * 3] / max, Value(im, x, y, 0), 1e-15);
      }
    }
    ASSERT_EQ(std::system(("iinfo -v " + path + " > " + dir + "/info.txt 2>&1").c_str()), 0);
    const std::string info = Slurp(dir + "/info.txt");
    EXPECT_NE(info.find("brdfbake.channel_order"), std::string::npos) << info.substr(0, 400);
    EXPECT_NE(info.find("brdfbake.max_abs_error"), std::string::npos);
  }
  // Other pixel types are refused in one line.
  ImageLayout l = DefaultLayout(t);
  EXPECT_THROW(WriteImage(t, ArrangeTable(t, l), Container::kPng, dir + "/f.png", "dfg", ""), std::invalid_argument);
  l.pixel = PixelType::kUnorm8;
  EXPECT_THROW(WriteImage(t, ArrangeTable(t, l), Container::kExr, dir + "/f.exr", "dfg", ""), std::invalid_argument);
  EXPECT_EQ(ContainerFromPath("x.PNG"), Container::kPng);
  EXPECT_EQ(ParseContainer("png"), Container::kPng);
}

// ------------------------------------------------- the engines' own tables

struct EngineTable {
  std::vector<std::vector<std::vector<double>>> data;  // [row][col][channel]
};

EngineTable LoadEngine(const std::string& file) {
  const nlohmann::json j = nlohmann::json::parse(Slurp(std::string(BRDFBAKE_TEST_DATA) + "/" + file));
  return {j.at("data").get<std::vector<std::vector<std::vector<double>>>>()};
}

struct Diff {
  double max = 0, rms = 0;
};

Diff Compare(const Image& im, const EngineTable& e, bool transpose_ours) {
  Diff d;
  double sum2 = 0;
  int n = 0;
  for (size_t row = 0; row < e.data.size(); ++row) {
    for (size_t col = 0; col < e.data[row].size(); ++col) {
      for (int c = 0; c < 2; ++c) {
        const int x = int(transpose_ours ? row : col), y = int(transpose_ours ? col : row);
        const double diff = Value(im, x, y, c) - e.data[row][col][c];
        d.max = std::max(d.max, std::abs(diff));
        sum2 += diff * diff;
        ++n;
      }
    }
  }
  d.rms = std::sqrt(sum2 / n);
  return d;
}

TEST(EngineTablesTest, ThreeJsAndBevyMatchTexelByTexel) {
  // three.js: rows NoV, columns roughness; our three preset has x =
  // roughness (columns), y = NoV (rows): the same arrangement.
  const Baked t = BakePreset(TableOf("three"));
  const EngineTable three = LoadEngine("threejs_dfg_16.json");
  const Diff dt = Compare(t.image, three, false);
  const Diff dt_wrong = Compare(t.image, three, true);
  // Bevy: rows roughness, columns NoV: our bevy preset.
  const Baked b = BakePreset(TableOf("bevy"));
  const EngineTable bevy = LoadEngine("bevy_dfg_64.json");
  const Diff db = Compare(b.image, bevy, false);
  const Diff db_wrong = Compare(b.image, bevy, true);
  std::printf("three.js 16x16 against ours: max %.3g, RMS %.3g (transposed: max %.3g)\n", dt.max, dt.rms,
              dt_wrong.max);
  std::printf("Bevy 64x64 against ours: max %.3g, RMS %.3g (transposed: max %.3g)\n", db.max, db.rms,
              db_wrong.max);
  // The engines integrate by sampling: about 1e-3 RMS, up to 1.4e-2 at
  // grazing NoV and small roughness. A layout error shows as tenths.
  EXPECT_LT(dt.rms, 3e-3);
  EXPECT_LT(dt.max, 2e-2);
  EXPECT_LT(db.rms, 3e-3);
  EXPECT_LT(db.max, 2e-2);
  EXPECT_GT(dt_wrong.max, 0.1);
  EXPECT_GT(db_wrong.max, 0.1);
}

// The Khronos glTF sample renderer's shipped LUTs (1024x1024 PNGs, every
// 16th texel in tests/data): file row y holds r = (y + 0.5) / 1024 (row 0
// the smooth end), column x NoV = (x + 0.5) / 1024.
//  - lut_ggx.png (8-bit): R = scale, G = bias;
//  - lut_sheen_E.png (16-bit, R = G = B): the sheen albedo of the
//    renderer's Charlie with the conty-kulla visibility, stored
//    sRGB-encoded (decoded, it is the albedo within about 0.005 where its
//    generator resolved it);
//  - lut_charlie.png (8-bit, B): the renderer's Charlie term with the
//    neubelt visibility, a sampled sum that is not the albedo at small
//    roughness.
// Each against ours at those coordinates, and with the rows flipped.
struct KhronosStats {
  double max = 0, rms = 0, flipped_max = 0;
};

KhronosStats CompareKhronos(const std::string& file, int channel,
                            const std::function<double(double nov, double r)>& ours,
                            const std::function<double(double)>& decode,
                            const std::function<bool(double nov, double r)>& region) {
  const EngineTable k = LoadEngine(file);
  KhronosStats st;
  double sum2 = 0;
  int n = 0;
  for (int j = 0; j < 64; ++j) {
    const double r = (16 * j + 8.5) / 1024, r_flipped = (16 * (63 - j) + 8.5) / 1024;
    for (int i = 0; i < 64; ++i) {
      const double nov = (16 * i + 8.5) / 1024;
      if (!region(nov, r)) continue;
      const double shipped = decode(k.data[j][i][channel]);
      const double d = shipped - ours(nov, r);
      st.max = std::max(st.max, std::abs(d));
      sum2 += d * d;
      ++n;
      if (j % 8 == 0 && region(nov, r_flipped)) {
        st.flipped_max = std::max(st.flipped_max, std::abs(shipped - ours(nov, r_flipped)));
      }
    }
  }
  st.rms = std::sqrt(sum2 / std::max(n, 1));
  return st;
}

TEST(EngineTablesTest, KhronosLutsAgainstOurs) {
  SKIP_UNLESS_BUILT("filament");  // needs charlie
  const auto identity = [](double v) { return v; };
  const auto everywhere = [](double, double) { return true; };
  const KhronosStats ggx = CompareKhronos(
      "khronos_lut_ggx_64.json", 0, [](double nov, double r) { return Exact(nov, r).scale; }, identity,
      everywhere);
  const KhronosStats ggx_bias = CompareKhronos(
      "khronos_lut_ggx_64.json", 1, [](double nov, double r) { return Exact(nov, r).bias; }, identity,
      everywhere);
  BakeSpec ck;
  ck.model.kind = ModelKind::kCharlie;
  // sRGB to linear (IEC 61966-2-1).
  const auto srgb = [](double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); };
  const auto resolved = [](double nov, double r) { return r >= 0.33 && nov >= 0.3 && nov <= 0.7; };
  const KhronosStats sheen = CompareKhronos(
      "khronos_lut_sheen_E_64.json", 0, [&](double nov, double r) { return IntegrateTexel(ck, r, nov).e; },
      srgb, resolved);
  const KhronosStats sheen_raw = CompareKhronos(
      "khronos_lut_sheen_E_64.json", 0, [&](double nov, double r) { return IntegrateTexel(ck, r, nov).e; },
      identity, resolved);
  BakeSpec ck_capped = ck;
  ck_capped.model.visibility = SheenVisibility::kContyKullaClamped;
  const KhronosStats sheen_capped = CompareKhronos(
      "khronos_lut_sheen_E_64.json", 0, [&](double nov, double r) { return IntegrateTexel(ck_capped, r, nov).e; },
      srgb, resolved);
  std::printf("Khronos lut_sheen_E.png, sRGB-decoded, against the capped-V (V_Sheen) E: max %.3g RMS %.3g\n",
              sheen_capped.max, sheen_capped.rms);
  BakeSpec neubelt = ck;
  neubelt.model.visibility = SheenVisibility::kNeubelt;
  const auto neubelt_e = [&](double nov, double r) { return std::min(1.0, IntegrateTexel(neubelt, r, nov).e); };
  const KhronosStats charlie = CompareKhronos("khronos_lut_charlie_64.json", 0, neubelt_e, identity,
                                              [](double nov, double r) { return r >= 0.5 && nov >= 0.25; });
  const KhronosStats charlie_all = CompareKhronos("khronos_lut_charlie_64.json", 0, neubelt_e, identity, everywhere);
  std::printf("Khronos lut_ggx.png: scale max %.3g RMS %.3g, bias max %.3g RMS %.3g (flipped: %.3g)\n", ggx.max,
              ggx.rms, ggx_bias.max, ggx_bias.rms, ggx.flipped_max);
  std::printf("Khronos lut_sheen_E.png, sRGB-decoded, r >= 0.33, NoV in [0.3, 0.7]: max %.3g RMS %.3g "
              "(as stored: max %.3g; flipped: %.3g)\n",
              sheen.max, sheen.rms, sheen_raw.max, sheen.flipped_max);
  std::printf("Khronos lut_charlie.png against the neubelt E: r >= 0.5, NoV >= 0.25: max %.3g RMS %.3g; "
              "everywhere: max %.3g RMS %.3g (flipped: %.3g)\n",
              charlie.max, charlie.rms, charlie_all.max, charlie_all.rms, charlie_all.flipped_max);
  // lut_ggx: 8-bit codes of a sampled table, laid out as ours.
  EXPECT_LT(ggx.rms, 5e-3);
  EXPECT_LT(ggx_bias.rms, 5e-3);
  EXPECT_GT(ggx.flipped_max, 0.1);
  // lut_sheen_E: the albedo once decoded from sRGB; as stored it is not.
  EXPECT_LT(sheen.max, 6e-3);
  EXPECT_GT(sheen_raw.max, 0.05);
  EXPECT_GT(sheen.flipped_max, 0.05);
}

// Enterprise PBR's shipped tables (res/pbrlut.hpp, decoded into
// tests/data), Monte Carlo bakes with about 1e-3 of noise, against the
// preset's: Sheen_E, Sheen_ash_E [alpha][cos_theta] 16x16, Base_E
// [f0][roughness][cos_theta] 16^3 and Base_E_avg [f0][roughness], all at
// centres. A wrong definition or layout shows as hundredths: Sheen_E with
// the conty-kulla fit, Base_E with its roughness rows reversed.
std::vector<double> Flat(const nlohmann::json& j) {
  std::vector<double> v;
  if (j.is_array()) {
    for (const auto& e : j) {
      const std::vector<double> s = Flat(e);
      v.insert(v.end(), s.begin(), s.end());
    }
  } else {
    v.push_back(j.get<double>());
  }
  return v;
}

Diff CompareFlat(const std::vector<double>& ours, const std::vector<double>& shipped) {
  Diff d;
  double sum2 = 0;
  EXPECT_EQ(ours.size(), shipped.size());
  for (size_t i = 0; i < std::min(ours.size(), shipped.size()); ++i) {
    d.max = std::max(d.max, std::abs(ours[i] - shipped[i]));
    sum2 += (ours[i] - shipped[i]) * (ours[i] - shipped[i]);
  }
  d.rms = std::sqrt(sum2 / std::max<size_t>(1, ours.size()));
  return d;
}

TEST(EngineTablesTest, EnterprisePbrShippedTables) {
  SKIP_UNLESS_BUILT("enterprise-pbr");
  const Preset& p = FindPreset("enterprise-pbr");
  const auto sheen_json = nlohmann::json::parse(Slurp(std::string(BRDFBAKE_TEST_DATA) + "/enterprise_pbr_sheen.json"));
  const auto base_json = nlohmann::json::parse(Slurp(std::string(BRDFBAKE_TEST_DATA) + "/enterprise_pbr_base.json"));
  const Diff sheen = CompareFlat(BakePreset(p.tables[4]).image.values, Flat(sheen_json["Sheen_E_HEAD_3ee9131"]["data"]));
  const Diff ash = CompareFlat(BakePreset(p.tables[5]).image.values, Flat(sheen_json["Sheen_ash_E_HEAD"]["data"]));
  const Image base = BakePreset(p.tables[2]).image;
  const Diff base_e = CompareFlat(base.values, Flat(base_json["Base_E_HEAD"]["data"]));
  const Diff base_avg = CompareFlat(BakePreset(p.tables[3]).image.values, Flat(base_json["Base_E_avg_HEAD"]["data"]));
  PresetTable ck = p.tables[4];
  ck.spec.model.visibility = SheenVisibility::kContyKulla;
  const Diff sheen_ck = CompareFlat(BakePreset(ck).image.values, Flat(sheen_json["Sheen_E_HEAD_3ee9131"]["data"]));
  std::vector<double> reversed(base.values.size());
  for (int s = 0; s < 16; ++s) {
    for (int j = 0; j < 16; ++j) {
      for (int i = 0; i < 16; ++i) reversed[(s * 16 + j) * 16 + i] = base.values[(s * 16 + 15 - j) * 16 + i];
    }
  }
  const Diff base_reversed = CompareFlat(reversed, Flat(base_json["Base_E_HEAD"]["data"]));
  std::printf("Enterprise PBR against ours: Sheen_E max %.3g RMS %.3g (conty-kulla fit: RMS %.3g), Sheen_ash_E "
              "max %.3g RMS %.3g, Base_E max %.3g RMS %.3g (rows reversed: RMS %.3g), Base_E_avg max %.3g RMS %.3g\n",
              sheen.max, sheen.rms, sheen_ck.rms, ash.max, ash.rms, base_e.max, base_e.rms, base_reversed.rms,
              base_avg.max, base_avg.rms);
  EXPECT_LT(sheen.rms, 3e-3);
  EXPECT_LT(sheen.max, 1.5e-2);
  EXPECT_LT(ash.rms, 3e-3);
  EXPECT_LT(ash.max, 1.5e-2);
  EXPECT_LT(base_e.rms, 3e-3);
  EXPECT_LT(base_e.max, 2e-2);
  EXPECT_LT(base_avg.rms, 1e-3);
  EXPECT_LT(base_avg.max, 3e-3);
  EXPECT_GT(sheen_ck.rms, 0.02);
  EXPECT_GT(base_reversed.rms, 0.02);
}

// Filament's shipped dfg.inc (64x64, a v1.19 build; tests/data): row k
// holds perceptual roughness min(1, (k + 1.5) / 64) (CubemapIBL::DFG's
// coordinate and cmgen's row order), NoV = (col + 0.5) / 64; R = bias,
// G = E, B = the cloth: DFV_Charlie_Uniform, 4096 uniform half vectors of
// the Charlie sheen with the neubelt visibility at alpha = r^2. Each
// channel against ours at those coordinates, and the cloth also against
// ours with the rows flipped (a layout error).
TEST(EngineTablesTest, FilamentClothMatchesTexelByTexel) {
  SKIP_UNLESS_BUILT("filament");
  const EngineTable f = LoadEngine("filament_dfg_64.json");
  ASSERT_EQ(f.data.size(), 64u);
  BakeSpec cloth;
  cloth.model.kind = ModelKind::kCharlie;
  cloth.model.visibility = SheenVisibility::kNeubelt;
  double max_rel[3] = {}, sum2[3] = {}, flipped = 0;
  int n = 0;
  for (int row = 0; row < 64; ++row) {
    const double r = std::min(1.0, (row + 1.5) / 64);
    for (int col = 0; col < 64; ++col) {
      const double nov = (col + 0.5) / 64;
      const TexelEstimate g = Exact(nov, r);
      const double ours[3] = {g.bias, g.scale + g.bias, IntegrateTexel(cloth, r, nov).e};
      for (int c = 0; c < 3; ++c) {
        // Relative to max(1, value): the cloth E reaches 9 at the corner.
        const double rel = (f.data[row][col][c] - ours[c]) / std::max(1.0, ours[c]);
        max_rel[c] = std::max(max_rel[c], std::abs(rel));
        sum2[c] += rel * rel;
      }
      if (row % 8 == 0) {
        const double rf = std::min(1.0, (63 - row + 1.5) / 64);
        flipped = std::max(flipped, std::abs(f.data[row][col][2] - IntegrateTexel(cloth, rf, nov).e));
      }
      ++n;
    }
  }
  for (int c = 0; c < 3; ++c) {
    std::printf("Filament dfg.inc channel %c against ours: max %.3g, RMS %.3g (of max(1, value))\n", "RGB"[c],
                max_rel[c], std::sqrt(sum2[c] / n));
  }
  std::printf("Filament cloth with the rows flipped: max %.3g\n", flipped);
  // Sampling noise and half rounding: about 1e-3 RMS; the largest
  // differences sit at grazing NoV and small roughness, where 1024 (GGX)
  // or 4096 (cloth) samples resolve a peaked integrand worst.
  for (int c = 0; c < 3; ++c) {
    EXPECT_LT(std::sqrt(sum2[c] / n), 3e-3) << "RGB"[c];
    EXPECT_LT(max_rel[c], 3e-2) << "RGB"[c];
  }
  EXPECT_GT(flipped, 0.1);
}

}  // namespace
}  // namespace brdfbake
