// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Engine presets: each engine's table as its shader samples it (axes and
// which is x, placement, warps, row order, channel order and meaning,
// size, pixel type, clamps), filled with brdfbake's exact integration of
// GGX with height-correlated masking. The facts and their sources are in
// docs/engines.md.

#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "base/error.h"
#include "base/text.h"
#include "brdfbake/output_file.h"
#include "brdfbake/presets.h"
#include "brdfbake/version.h"

namespace brdfbake {
namespace {

BakeSpec Spec(TableKind table, int n_mu, int n_r, Placement placement) {
  BakeSpec s;
  s.table = table;
  s.mu.size = n_mu;
  s.roughness.size = n_r;
  s.mu.placement = s.roughness.placement = placement;
  return s;
}

// E of another model over a preset table's axes (ArrangePresetTable gives
// it the table's axes).
BakeSpec LobeE(ModelKind kind, SheenVisibility visibility = SheenVisibility::kContyKulla) {
  BakeSpec s;
  s.table = TableKind::kE;
  s.model.kind = kind;
  s.model.visibility = visibility;
  return s;
}

// Channel `name` from table 1 (the preset table's first `with`).
ImageLayout::Out With(const char* name, Source source, double scale = 1, double offset = 0,
                      double max = kInfinity) {
  ImageLayout::Out o{name, source};
  o.table = 1;
  o.scale = scale;
  o.offset = offset;
  o.max = max;
  return o;
}

ImageLayout Layout(std::vector<ImageLayout::Out> channels, PixelType pixel, bool roughness_on_x = false,
                   bool flip_rows = false) {
  ImageLayout l;
  l.channels = std::move(channels);
  l.pixel = pixel;
  l.roughness_on_x = roughness_on_x;
  l.flip_rows = flip_rows;
  l.header_half_bits = pixel == PixelType::kHalf;
  return l;
}

PresetTable Entry(const BakeSpec& spec, const ImageLayout& layout, Container container,
                  const std::string& file, const std::string& symbol) {
  PresetTable t;
  t.spec = spec;
  t.layout = layout;
  t.container = container;
  t.file = file;
  t.symbol = symbol;
  return t;
}

std::vector<Preset> MakePresets() {
  std::vector<Preset> p;
  {
    // Filament: DFG 128x128 RGB16F, NoV on x at centres, r on y with row 0
    // the smooth end (cmgen writes the image's rows bottom-up), R = bias,
    // G = E (multiscatter form), B = the cloth term, the Charlie sheen's E
    // with the neubelt visibility at alpha = r^2 (CubemapIBL's
    // DFV_Charlie_Uniform), shipped as uint16 half bits #included inside
    // DFG.cpp's array initializer.
    Preset f{"filament",
             "Filament's DFG: 128x128, x = NoV, y = roughness (row 0 smooth), R = bias, G = E, "
             "B = cloth (Charlie sheen E, neubelt), half bits as dfg.inc, #included into DFG_LUT[]",
             {},
             ""};
    PresetTable t = Entry(Spec(TableKind::kDfg, 128, 128, Placement::kCenters),
                  Layout({{"R", Source::kBias}, {"G", Source::kE}, With("B", Source::kE)}, PixelType::kHalf),
                  Container::kInc, "dfg.inc", "DFG_LUT");
    t.with = {LobeE(ModelKind::kCharlie, SheenVisibility::kNeubelt)};
    f.tables.push_back(t);
    p.push_back(f);
  }
  {
    // Unreal Engine 4: PreIntegratedGF 128 x 32, G16R16 unorm, R = scale,
    // G = bias, NoV and r at centres.
    Preset u{"unreal",
             "Unreal's PreIntegratedGF: 128 (NoV) x 32 (roughness), R = scale, G = bias, unorm16, DDS",
             {},
             ""};
    u.tables.push_back(Entry(Spec(TableKind::kDfg, 128, 32, Placement::kCenters),
                        Layout({{"R", Source::kScale}, {"G", Source::kBias}}, PixelType::kUnorm16),
                        Container::kDds, "PreIntegratedGF.dds", "PreIntegratedGF"));
    p.push_back(u);
  }
  {
    // Unity HDRP: FGD 64x64, x = sqrt(NoV), y = r, both with the endpoints
    // on the first and last texel centres (Remap01ToHalfTexelCoord: the
    // edges placement), x = bias, y = E, z = the Disney diffuse E at the
    // perceptual roughness, divided by 1.03571 (DisneyDiffuseNoPI's
    // normalisation), less 0.5 (GetPreIntegratedFGDGGXAndDisneyDiffuse
    // adds it back).
    Preset h{"hdrp",
             "HDRP's preintegrated FGD: 64x64, x = sqrt(NoV), y = roughness, endpoints on texel "
             "centres, R = bias, G = E, B = Disney diffuse E / 1.03571 - 0.5, half EXR",
             {},
             ""};
    BakeSpec s = Spec(TableKind::kDfg, 64, 64, Placement::kEdges);
    s.mu.warp = Warp::kSquare;  // coordinate c = sqrt(NoV): NoV = c^2
    h.tables.push_back(Entry(s,
                        Layout({{"R", Source::kBias}, {"G", Source::kE},
                                With("B", Source::kE, 1 / 1.03571, -0.5)},
                               PixelType::kHalf),
                        Container::kExr, "preintegrated_fgd.exr", "PreintegratedFGD"));
    h.tables.back().with = {LobeE(ModelKind::kDisneyDiffuse)};
    p.push_back(h);
  }
  {
    // Godot 4: 128x128 rgba16f, NoV on x at centres, r on y at centres,
    // rows flipped, R = bias, G = E, B = cloth (the Charlie sheen's E with
    // the neubelt visibility at alpha = r^2, as integrate_dfg.glsl).
    Preset g{"godot",
             "Godot 4's DFG: 128x128, x = NoV, y = roughness (rows flipped), R = bias, G = E, "
             "B = cloth (Charlie sheen E, neubelt), A = 1, RGBA half EXR",
             {},
             ""};
    g.tables.push_back(Entry(Spec(TableKind::kDfg, 128, 128, Placement::kCenters),
                        Layout({{"R", Source::kBias}, {"G", Source::kE}, With("B", Source::kE), {"A", Source::kOne}},
                               PixelType::kHalf, false, true),
                        Container::kExr, "dfg_lut.exr", "DFG_LUT"));
    g.tables.back().with = {LobeE(ModelKind::kCharlie, SheenVisibility::kNeubelt)};
    p.push_back(g);
  }
  {
    // Bevy: 64x64 KTX2 R16G16_SFLOAT, zstd-supercompressed, NoV on x, r on
    // y, centres, R = scale, G = bias; Bevy's image loader also reads DDS
    // and EXR.
    Preset b{"bevy",
             "Bevy's dfg.ktx2: 64x64, x = NoV, y = roughness, R = scale, G = bias, R16G16_SFLOAT KTX2, "
             "zstd-supercompressed",
             {},
             ""};
    b.tables.push_back(Entry(Spec(TableKind::kDfg, 64, 64, Placement::kCenters),
                        Layout({{"R", Source::kScale}, {"G", Source::kBias}}, PixelType::kHalf),
                        Container::kKtx2, "dfg.ktx2", "dfg"));
    b.tables.back().ktx2_zstd_level = 19;
    b.tables.back().also = {Container::kDds, Container::kExr};
    p.push_back(b);
  }
  {
    // three.js: 16x16 RG16F, roughness on x (u), NoV on y (v), centres,
    // R = scale, G = bias: src/renderers/shaders/DFGLUTData.js, whose
    // getDFGLUT() the renderer imports.
    Preset t{"three",
             "three.js's DFGLUTData.js: 16x16, x = roughness, y = NoV, R = scale, G = bias, "
             "half bits in the module three.js imports (getDFGLUT)",
             {},
             ""};
    t.tables.push_back(Entry(Spec(TableKind::kDfg, 16, 16, Placement::kCenters),
                        Layout({{"R", Source::kScale}, {"G", Source::kBias}}, PixelType::kHalf, true),
                        Container::kJs, "DFGLUTData.js", "DFGLUTData"));
    t.tables.back().form = EngineForm::kThreeDfgModule;
    t.tables.back().also = {Container::kExr, Container::kKtx2};
    p.push_back(t);
  }
  {
    // Blender Cycles: ggx_E 32x32 with r on x and NoV on y, both at edges
    // and clamped at 1e-4; ggx_Eavg over r; float C arrays.
    Preset c{"cycles",
             "Cycles' table_ggx_E (32x32, x = roughness, y = NoV, edges, both clamped at 1e-4) and "
             "table_ggx_Eavg (32), float C arrays in one header",
             {},
             "ggx_tables.h"};
    BakeSpec e = Spec(TableKind::kE, 32, 32, Placement::kEdges);
    e.mu.clamp_min = e.roughness.clamp_min = 1e-4;
    c.tables.push_back(Entry(e, Layout({{"E", Source::kE}}, PixelType::kFloat, true), Container::kHeader, "",
                        "table_ggx_E"));
    BakeSpec a = Spec(TableKind::kEavg, 32, 32, Placement::kEdges);
    a.roughness.clamp_min = 1e-4;
    c.tables.push_back(Entry(a, Layout({{"E_avg", Source::kEavg}}, PixelType::kFloat), Container::kHeader, "",
                        "table_ggx_Eavg"));
    p.push_back(c);
  }
  {
    // MaterialX: the albedo table, 64x64 float RGB, NoV on x, ALPHA (not
    // r) on y, both at centres, R = scale, G = bias, B = sheen: the
    // Charlie E with the neubelt visibility (mx_imageworks_sheen_brdf) at
    // the NDF width y itself (= r^2 here), clamped to 1 as the generator
    // clamps it.
    Preset m{"materialx",
             "MaterialX's albedo table: 64x64, x = NoV, y = alpha at centres (r = sqrt(alpha)), "
             "R = scale, G = bias, B = sheen (Charlie E, neubelt, at most 1), float EXR",
             {},
             ""};
    BakeSpec s = Spec(TableKind::kDfg, 64, 64, Placement::kCenters);
    s.roughness.warp = Warp::kSqrt;  // r = sqrt(t): alpha = t at the texel centres
    m.tables.push_back(Entry(s,
                        Layout({{"R", Source::kScale}, {"G", Source::kBias}, With("B", Source::kE, 1, 0, 1)},
                               PixelType::kFloat),
                        Container::kExr, "albedo_table.exr", "albedo_table"));
    m.tables.back().with = {LobeE(ModelKind::kCharlie, SheenVisibility::kNeubelt)};
    p.push_back(m);
  }
  {
    // Enterprise PBR: GGX_E[roughness][cos_theta] 32x32 and GGX_E_avg 32,
    // as res/pbrlut.hpp (extern declarations, definitions under
    // PBRLUT_IMPLEMENTATION) and as EXR. Its source does not state the
    // placement; its shipped E_avg's last entry, 0.4228, is GGX's at the
    // last texel centre (r = 0.984; 0.409 at r = 1), so centres.
    Preset e{"enterprise-pbr",
             "Enterprise PBR's pbrlut.hpp (GGX_E[roughness][cos_theta] 32x32, GGX_E_avg 32; not "
             "Base_E or Sheen_E), centres, float, and EXR files",
             {},
             "pbrlut.hpp",
             EngineForm::kEnterprisePbrHeader};
    e.tables.push_back(Entry(Spec(TableKind::kE, 32, 32, Placement::kCenters),
                        Layout({{"E", Source::kE}}, PixelType::kFloat), Container::kExr, "GGX_E.exr",
                        "GGX_E"));
    e.tables.push_back(Entry(Spec(TableKind::kEavg, 32, 32, Placement::kCenters),
                        Layout({{"E_avg", Source::kEavg}}, PixelType::kFloat), Container::kExr,
                        "GGX_E_avg.exr", "GGX_E_avg"));
    p.push_back(e);
  }
  return p;
}

// The extension of a container's files.
const char* Extension(Container c) {
  switch (c) {
    case Container::kExr: return ".exr";
    case Container::kHeader: return ".h";
    case Container::kJs: return ".js";
    case Container::kKtx2: return ".ktx2";
    case Container::kDds: return ".dds";
    case Container::kInc: return ".inc";
    case Container::kPng: return ".png";
  }
  return ".exr";
}

// The conventions of a table as comment lines after `prefix`.
std::string ConventionComment(const Table& t, const Image& im, const std::string& preset,
                              const char* prefix) {
  std::string s;
  for (const auto& kv : ImageConventions(t, im, preset)) s += prefix + kv.first + ": " + kv.second + "\n";
  return s;
}

// A float as a C literal ("0.5f", "1.0f").
std::string FloatLiteral(double v) {
  std::string s = NumG9(v);
  if (s.find_first_of(".e") == std::string::npos) s += ".0";
  return s + "f";
}

// three.js's src/renderers/shaders/DFGLUTData.js: the half bits in a
// module-private Uint16Array, and getDFGLUT() returning one DataTexture
// (RG, half float, linear filtering, clamp to edge, no mipmaps) made on
// the first call, as WebGLRenderer imports it. The imports are relative to
// the module's place in three's source tree.
std::string ThreeDfgModule(const Table& t, const Image& im, const std::string& preset) {
  if (im.pixel != PixelType::kHalf || im.channels != 2) {
    Bad("the three.js module holds two half channels (got " + std::to_string(im.channels) + " " +
        PixelTypeName(im.pixel) + ")");
  }
  std::string s = "/*\n * The DFG table of three.js's physically based shading, baked by brdfbake " +
                  std::string(BRDFBAKE_VERSION) + ".\n" + ConventionComment(t, im, preset, " * ") + " */\n\n";
  s += "import { DataTexture } from '../../textures/DataTexture.js';\n";
  s += "import { RGFormat, HalfFloatType, LinearFilter, ClampToEdgeWrapping } from '../../constants.js';\n\n";
  s += "const DATA = new Uint16Array( [\n";
  for (size_t i = 0; i < im.bits16.size(); ++i) {
    char buf[16];
    std::snprintf(buf, sizeof(buf), "0x%04x", im.bits16[i]);
    s += (i % 16 == 0 ? "\t" : " ") + std::string(buf) + (i + 1 < im.bits16.size() ? "," : "");
    if (i % 16 == 15 || i + 1 == im.bits16.size()) s += "\n";
  }
  s += "] );\n\nlet lut = null;\n\n";
  s += "export function getDFGLUT() {\n\n\tif ( lut === null ) {\n\n";
  s += "\t\tlut = new DataTexture( DATA, " + std::to_string(im.width) + ", " + std::to_string(im.height) +
       ", RGFormat, HalfFloatType );\n";
  s += "\t\tlut.name = 'DFG_LUT';\n";
  s += "\t\tlut.minFilter = LinearFilter;\n\t\tlut.magFilter = LinearFilter;\n";
  s += "\t\tlut.wrapS = ClampToEdgeWrapping;\n\t\tlut.wrapT = ClampToEdgeWrapping;\n";
  s += "\t\tlut.generateMipmaps = false;\n\t\tlut.needsUpdate = true;\n\n\t}\n\n\treturn lut;\n\n}\n";
  return s;
}

// Enterprise PBR's res/pbrlut.hpp: `extern` declarations of each table and
// its size, and their definitions when PBRLUT_IMPLEMENTATION is defined (in
// one translation unit). A 2D table is [rows][columns] (GGX_E[roughness]
// [cos_theta]) with NAME_size = {columns, rows}; a 1D one NAME[n] with
// NAME_size = n.
std::string EnterprisePbrHeader(const Preset& preset, const std::vector<Table>& tables,
                                const std::vector<Image>& images) {
  std::string decl, defs, notes;
  for (size_t k = 0; k < preset.tables.size(); ++k) {
    const Image& im = images[k];
    const std::string& sym = preset.tables[k].symbol;
    if (im.pixel != PixelType::kFloat || im.channels != 1) Bad("pbrlut.hpp holds one float channel per table");
    const std::string x = im.axes[0].name == "mu" ? "cos_theta" : im.axes[0].name;
    notes += ConventionComment(tables[k], im, preset.name, ("// " + sym + ": ").c_str());
    if (im.height == 1) {
      const std::string n = std::to_string(im.width);
      decl += "extern int " + sym + "_size;\nextern float " + sym + "[" + n + "/*" + x + "*/];\n";
      defs += "int " + sym + "_size = " + n + ";\nfloat " + sym + "[" + n + "/*" + x + "*/] = {";
      for (int i = 0; i < im.width; ++i) defs += (i ? "," : "") + FloatLiteral(im.values[i]);
      defs += "};\n\n";
      continue;
    }
    const std::string y = im.axes[1].name;
    const std::string w = std::to_string(im.width), h = std::to_string(im.height);
    const std::string dims = "[" + h + "/*" + y + "*/][" + w + "/*" + x + "*/]";
    decl += "extern int " + sym + "_size[2];\nextern float " + sym + dims + ";\n";
    defs += "int " + sym + "_size[2] = { " + w + ", " + h + " };\nfloat " + sym + dims + " = {\n";
    for (int r = 0; r < im.height; ++r) {
      defs += "{";
      for (int c = 0; c < im.width; ++c) defs += (c ? "," : "") + FloatLiteral(im.values[size_t(r) * im.width + c]);
      defs += "},\n";
    }
    defs += "};\n\n";
  }
  return "// Enterprise PBR's lookup tables, baked by brdfbake " + std::string(BRDFBAKE_VERSION) +
         ". Do not edit: bake again instead.\n" + notes + "#ifndef PBRLUT_HPP\n#define PBRLUT_HPP\n" + decl +
         "#endif\n\n#ifdef PBRLUT_IMPLEMENTATION\n\n" + defs + "#endif\n";
}

// The container a run writes table `pt` as: the preset's own, or --format
// where the engine loads that container.
Container ContainerFor(const Preset& preset, const PresetTable& pt, const std::string& format) {
  if (format.empty()) return pt.container;
  const Container c = ParseContainer(format);
  if (c == pt.container) return c;
  for (Container a : pt.also) {
    if (a == c) return c;
  }
  std::string loads = ContainerName(pt.container);
  for (Container a : pt.also) loads += std::string(", ") + ContainerName(a);
  Bad("--format " + format + ": " + preset.name + " loads its " + TableName(pt.spec.table) + " table as " +
      loads);
}

std::string TablePath(const Preset& preset, const PresetTable& pt, const PresetRun& run) {
  const Container c = ContainerFor(preset, pt, run.format);
  std::filesystem::path file(pt.file);
  if (c != pt.container) file.replace_extension(Extension(c));
  return run.dir + "/" + file.string();
}

std::string ShaderFile(const PresetRun& run, const PresetTable& pt, ShaderLanguage l) {
  return run.dir + "/" + pt.symbol + "." + ShaderLanguageName(l);
}

}  // namespace

std::vector<PresetFile> PresetFiles(const Preset& preset, const PresetRun& run) {
  std::vector<PresetFile> files;
  for (size_t k = 0; k < preset.tables.size(); ++k) {
    const PresetTable& pt = preset.tables[k];
    if (!pt.file.empty()) {
      files.push_back({TablePath(preset, pt, run), int(k),
                       std::string(TableName(pt.spec.table)) + " (" + preset.name + ")",
                       ContainerFor(preset, pt, run.format)});
    }
    for (ShaderLanguage l : run.shaders) {
      files.push_back({ShaderFile(run, pt, l), int(k),
                       std::string(ShaderLanguageName(l)) + " lookup of " + pt.symbol, Container::kHeader, true,
                       l});
    }
  }
  bool any_file = false;
  for (const PresetTable& pt : preset.tables) any_file |= !pt.file.empty();
  if (!run.format.empty() && !any_file) {
    Bad("--format " + run.format + ": " + preset.name + " loads its tables from " + preset.header_file +
        " only");
  }
  if (!preset.header_file.empty()) {
    files.push_back({run.dir + "/" + preset.header_file, -1,
                     std::to_string(preset.tables.size()) + " tables (" + preset.name + ")", Container::kHeader});
  }
  return files;
}

Image ArrangePresetTable(const PresetTable& pt, const Table& table, int threads, double tolerance,
                         const ProgressFn& progress) {
  std::vector<Table> with;
  with.reserve(pt.with.size());
  for (BakeSpec s : pt.with) {
    s.mu = table.spec.mu;
    s.roughness = table.spec.roughness;
    s.half = table.spec.half;
    s.threads = threads;
    if (tolerance > 0) s.tolerance = tolerance;
    ValidateBakeSpec(s);
    with.push_back(Bake(s, progress));
  }
  std::vector<const Table*> others;
  for (const Table& w : with) others.push_back(&w);
  return ArrangeTables(table, others, pt.layout);
}

void WritePresetFiles(const Preset& preset, const PresetRun& run, const std::vector<Table>& tables,
                      const std::vector<Image>& images) {
  for (const PresetFile& f : PresetFiles(preset, run)) {
    if (f.table < 0) {
      if (preset.header_form == EngineForm::kEnterprisePbrHeader) {
        WriteFileAtomically(f.path, EnterprisePbrHeader(preset, tables, images));
        continue;
      }
      std::vector<std::pair<const Table*, const Image*>> arrays;
      std::vector<std::string> symbols;
      for (size_t k = 0; k < preset.tables.size(); ++k) {
        arrays.push_back({&tables[k], &images[k]});
        symbols.push_back(preset.tables[k].symbol);
      }
      WriteHeader(arrays, symbols, f.path, preset.name);
      continue;
    }
    const PresetTable& pt = preset.tables[f.table];
    const Table& t = tables[f.table];
    const Image& im = images[f.table];
    if (f.lookup) {
      WriteFileAtomically(f.path, ShaderFunction(t, im, f.language, "brdfbake_" + pt.symbol));
      continue;
    }
    const Container c = f.container;
    if (c == pt.container && pt.form == EngineForm::kThreeDfgModule) {
      WriteFileAtomically(f.path, ThreeDfgModule(t, im, preset.name));
      continue;
    }
    WriteImage(t, im, c, f.path, pt.symbol, preset.name, c == Container::kKtx2 ? pt.ktx2_zstd_level : 0);
  }
}

const std::vector<Preset>& Presets() {
  static const std::vector<Preset> kPresets = MakePresets();
  return kPresets;
}

bool PresetBuilt(const Preset& preset) {
  for (const PresetTable& pt : preset.tables) {
    if (!ModelBuilt(pt.spec.model.kind)) return false;
    for (const BakeSpec& w : pt.with) {
      if (!ModelBuilt(w.model.kind)) return false;
    }
  }
  return true;
}

const Preset& FindPreset(const std::string& name) {
  std::string names;
  std::vector<std::string> all;
  for (const Preset& p : Presets()) {
    if (p.name == name) return p;
    names += (names.empty() ? "" : ", ") + p.name;
    all.push_back(p.name);
  }
  Bad("--preset: unknown preset '" + name + "' (expected " + names + ")" +
      DidYouMean(name, all,
                 {{"ue4", "unreal"}, {"ue5", "unreal"}, {"unreal-engine", "unreal"}, {"unity", "hdrp"},
                  {"three.js", "three"}, {"threejs", "three"}, {"blender", "cycles"},
                  {"enterprise", "enterprise-pbr"}, {"dassault", "enterprise-pbr"}}));
}

}  // namespace brdfbake
