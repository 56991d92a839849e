// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Engine presets: each engine's table as its shader samples it (axes and
// which is x, placement, warps, row order, channel order and meaning,
// size, pixel type, clamps), filled with brdfbake's exact integration of
// GGX with height-correlated masking. The facts and their sources are in
// docs/engines.md.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <tuple>

#include "base/error.h"
#include "base/pixel.h"
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
             "Cycles' table_ggx_E (32x32, x = roughness, y = NoV, edges, both clamped at 1e-4), "
             "table_ggx_Eavg (32), the glass E (16x16x16 over roughness, NoV, z = F0^(1/4)) and "
             "E_avg (16x16), entering and leaving, and the generalized Schlick factors gen_schlick_ior_s "
             "and gen_schlick_s (16x16x16), float C arrays in one header",
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
    // The glass tables (shader.tables, looked up in bsdf_microfacet.h):
    // 16x16x16 E with x = r, y = NoV, slices over z = F0^(1/4) = k / 15
    // (ior = (1 + z^2) / (1 - z^2), inf at k = 15, baked at z = 0.99,
    // ior 99.5), all at edges, r and NoV clamped at 1e-4; E_avg 16x16 over
    // r and z. The inverse tables hold light leaving the medium, eta =
    // 1 / ior. They are integrated to 1e-6, the step of the six decimals
    // Cycles' own file holds (its Monte Carlo noise is some 1e-5).
    for (const bool inverse : {false, true}) {
      const std::string stem = inverse ? "table_ggx_glass_inv_" : "table_ggx_glass_";
      BakeSpec g = Spec(TableKind::kE, 16, 16, Placement::kEdges);
      g.model.kind = ModelKind::kGgxGlass;
      g.inverse = inverse;
      g.mu.clamp_min = g.roughness.clamp_min = 1e-4;
      g.ior.size = 16;
      g.ior.max = kInfinity;
      g.ior.clamp_max = 1.9801 / 0.0199;  // z = 0.99
      g.tolerance = 1e-6;
      c.tables.push_back(Entry(g, Layout({{"E", Source::kE}}, PixelType::kFloat, true), Container::kHeader, "",
                               stem + "E"));
      g.table = TableKind::kEavg;
      g.mu.clamp_min = 0;
      c.tables.push_back(Entry(g, Layout({{"E_avg", Source::kEavg}}, PixelType::kFloat), Container::kHeader, "",
                               stem + "Eavg"));
    }
    // The generalized Schlick factors (16x16x16, x = r, y = NoV, slices
    // over z): table_ggx_gen_schlick_ior_s over the same z = F0^(1/4) as
    // the glass tables, table_ggx_gen_schlick_s over z = 5 / (exponent +
    // 5) = k / 15, exponent inf to 0, baked within z in [1e-4, 0.99] (the
    // exponent axis' default).
    for (const TableKind kind : {TableKind::kGenSchlickIorS, TableKind::kGenSchlickS}) {
      BakeSpec g = Spec(kind, 16, 16, Placement::kEdges);
      g.mu.clamp_min = g.roughness.clamp_min = 1e-4;
      g.ior.size = 16;
      g.ior.max = kInfinity;
      g.ior.clamp_max = 1.9801 / 0.0199;
      g.tolerance = 1e-6;
      c.tables.push_back(Entry(g, Layout({{"s", Source::kS}}, PixelType::kFloat, true), Container::kHeader, "",
                               std::string("table_ggx_") + TableName(kind)));
    }
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
    // The Khronos glTF sample renderer ([KhronosSampleRenderer]): three
    // 1024x1024 PNGs, x = NoV, y = r (perceptual, alpha = r^2), both at
    // texel centres, row 0 (the PNG's top row) the smooth end, sampled at
    // (NoV, r) with no flip. lut_ggx.png RGB8: R = scale, G = bias (the
    // renderer reads .rg; B = E here, 0 in the shipped file).
    // lut_charlie.png RGB8: the sheen IBL term the renderer reads from .b,
    // the Charlie E with V_Ashikhmin capped at 1 (neubelt-clamped), in R =
    // G = B (the shipped R and G are 0). lut_sheen_E.png RGB16, R = G = B:
    // the albedo of the renderer's sheen BRDF, D_Charlie with V_Sheen capped
    // at 1 (conty-kulla-clamped), which it reads from .r to scale the layers
    // below the sheen. All three at most 1, as an 8- or 16-bit PNG holds.
    // Each is integrated to a tolerance well below its pixels' rounding
    // (1e-5 for 8 bits, whose step is 3.9e-3; 1e-6 for 16 bits, 1.5e-5).
    Preset k{"khronos",
             "the Khronos glTF sample renderer's lut_ggx.png (R = scale, G = bias), lut_charlie.png (B = "
             "sheen IBL term, V_Ashikhmin) and lut_sheen_E.png (sheen albedo, V_Sheen): 1024x1024, "
             "x = NoV, y = roughness (top row smooth), centres, 8-, 8- and 16-bit PNG",
             {},
             ""};
    k.tables.push_back(Entry(Spec(TableKind::kDfg, 1024, 1024, Placement::kCenters),
                        Layout({{"R", Source::kScale}, {"G", Source::kBias}, {"B", Source::kE}}, PixelType::kUnorm8),
                        Container::kPng, "lut_ggx.png", "lut_ggx"));
    k.tables.back().layout.channels[2].max = 1;
    k.tables.back().spec.tolerance = 1e-5;
    for (const auto& [file, vis, pixel] :
         {std::tuple{"lut_charlie", SheenVisibility::kNeubeltClamped, PixelType::kUnorm8},
          std::tuple{"lut_sheen_E", SheenVisibility::kContyKullaClamped, PixelType::kUnorm16}}) {
      BakeSpec s = Spec(TableKind::kE, 1024, 1024, Placement::kCenters);
      s.model.kind = ModelKind::kCharlie;
      s.model.visibility = vis;
      s.tolerance = pixel == PixelType::kUnorm8 ? 1e-5 : 1e-6;
      ImageLayout::Out e{"", Source::kE};
      e.max = 1;
      std::vector<ImageLayout::Out> rgb(3, e);
      rgb[0].name = "R";
      rgb[1].name = "G";
      rgb[2].name = "B";
      k.tables.push_back(Entry(s, Layout(rgb, pixel), Container::kPng, std::string(file) + ".png", file));
    }
    p.push_back(k);
  }
  {
    // Enterprise PBR: GGX_E[roughness][cos_theta] 32x32 and GGX_E_avg 32,
    // as res/pbrlut.hpp (extern declarations, definitions under
    // PBRLUT_IMPLEMENTATION) and as EXR. Its source does not state the
    // placement; its shipped E_avg's last entry, 0.4228, is GGX's at the
    // last texel centre (r = 0.984; 0.409 at r = 1), so centres.
    Preset e{"enterprise-pbr",
             "Enterprise PBR's pbrlut.hpp: GGX_E[roughness][cos_theta] 32x32, GGX_E_avg 32, "
             "Base_E[f0][roughness][cos_theta] 16^3 and Base_E_avg[f0][roughness] (Schlick + multiple "
             "scattering), Sheen_E and Sheen_ash_E [alpha][cos_theta] 16x16; centres, float, and EXR files",
             {},
             "pbrlut.hpp",
             EngineForm::kEnterprisePbrHeader};
    e.tables.push_back(Entry(Spec(TableKind::kE, 32, 32, Placement::kCenters),
                        Layout({{"E", Source::kE}}, PixelType::kFloat), Container::kExr, "GGX_E.exr",
                        "GGX_E"));
    e.tables.push_back(Entry(Spec(TableKind::kEavg, 32, 32, Placement::kCenters),
                        Layout({{"E_avg", Source::kEavg}}, PixelType::kFloat), Container::kExr,
                        "GGX_E_avg.exr", "GGX_E_avg"));
    // Sheen_E[alpha][cos_theta] 16x16: the Charlie E with its refined
    // Lambda fit (enterprise-pbr); Sheen_ash_E: with the neubelt ("Ashikhmin")
    // visibility, capped at 1 as the shipped table is. The rows hold alpha
    // = r^2 at the centres (the sqrt warp of r).
    // Base_E[f0][roughness][cos_theta] 16^3 and Base_E_avg[f0][roughness],
    // all at centres, at most 1 (PresetTable::Over).
    ImageLayout::Out capped{"E", Source::kE};
    capped.max = 1;
    e.tables.push_back(Entry(Spec(TableKind::kDfg, 16, 16, Placement::kCenters), Layout({capped}, PixelType::kFloat),
                             Container::kExr, "Base_E.exr", "Base_E"));
    e.tables.back().over = PresetTable::Over::kSchlickMsE;
    capped.name = "E_avg";
    capped.source = Source::kEavg;
    e.tables.push_back(Entry(Spec(TableKind::kEavg, 16, 16, Placement::kCenters), Layout({capped}, PixelType::kFloat),
                             Container::kExr, "Base_E_avg.exr", "Base_E_avg"));
    e.tables.back().over = PresetTable::Over::kSchlickMsEavg;
    for (const auto& [sym, vis, cap] : {std::tuple{"Sheen_E", SheenVisibility::kEnterprisePbr, kInfinity},
                                        std::tuple{"Sheen_ash_E", SheenVisibility::kNeubelt, 1.0}}) {
      BakeSpec s = Spec(TableKind::kE, 16, 16, Placement::kCenters);
      s.model.kind = ModelKind::kCharlie;
      s.model.visibility = vis;
      s.roughness.warp = Warp::kSqrt;
      ImageLayout::Out o{"E", Source::kE};
      o.max = cap;
      e.tables.push_back(Entry(s, Layout({o}, PixelType::kFloat), Container::kExr, std::string(sym) + ".exr", sym));
    }
    p.push_back(e);
  }
  {
    // OpenPBR (adobe/openpbr-bsdf, [OpenPbrBsdf]): impl/data/openpbr_energy_arrays.h,
    // seven unorm16 arrays [ior][alpha][cos_theta] (cos_theta fastest) of
    // 32 entries per axis, every axis at edges: cos_theta = i / 31, alpha =
    // (j / 31)^2 (the lookup's index is sqrt(alpha) 31), and ior on the
    // two-sided axis (0.4 to 1 in 1 / ior, then 1 to 2.5). Separable
    // masking G1(wi) G1(wo), as its BSDF. Stored complements 1 - E:
    //   IdealDielectric*: reflection plus refraction (ggx-glass, both);
    //   OpaqueDielectric*: the reflection alone (ggx-glass, reflection);
    //   IdealMetal*: GGX with F = 1, over alpha and cos_theta (over alpha).
    // The ReflectionRatio array is not baked: the header #includes the
    // engine's own data file for it (docs/engines.md says why).
    Preset o{"openpbr",
             "OpenPBR's openpbr_energy_arrays.h: 1 - E and 1 - E_avg of the rough dielectric (reflection plus "
             "refraction; reflection alone) over ior x alpha x cos_theta and of the F = 1 conductor, 32 per axis "
             "at edges, separable masking, unorm16 arrays; the reflection ratio kept from OpenPBR's data file",
             {},
             "openpbr_energy_arrays.h",
             EngineForm::kOpenPbrEnergyArrays};
    auto spec = [](TableKind table, ModelKind kind, DielectricPart part) {
      BakeSpec s = Spec(table, 32, 32, Placement::kEdges);
      s.model.kind = kind;
      s.masking = Masking::kSeparable;
      s.complement = true;
      s.part = part;
      s.ior = Axis{"ior", 32, 0.4, 2.5, Warp::kTwoSided, Placement::kEdges};
      s.tolerance = 1e-6;  // below the unorm16 step, 1.5e-5
      return s;
    };
    for (const auto& [sym, table, kind, part] :
         {std::tuple{"OpenPBR_IdealDielectricEnergyComplement_Array", TableKind::kE, ModelKind::kGgxGlass,
                     DielectricPart::kBoth},
          std::tuple{"OpenPBR_IdealDielectricAverageEnergyComplement_Array", TableKind::kEavg, ModelKind::kGgxGlass,
                     DielectricPart::kBoth},
          std::tuple{"OpenPBR_OpaqueDielectricEnergyComplement_Array", TableKind::kE, ModelKind::kGgxGlass,
                     DielectricPart::kReflection},
          std::tuple{"OpenPBR_OpaqueDielectricAverageEnergyComplement_Array", TableKind::kEavg, ModelKind::kGgxGlass,
                     DielectricPart::kReflection},
          std::tuple{"OpenPBR_IdealMetalEnergyComplement_Array", TableKind::kE, ModelKind::kGgx, DielectricPart::kBoth},
          std::tuple{"OpenPBR_IdealMetalAverageEnergyComplement_Array", TableKind::kEavg, ModelKind::kGgx,
                     DielectricPart::kBoth}}) {
      const Source source = table == TableKind::kE ? Source::kOneMinusE : Source::kOneMinusEavg;
      o.tables.push_back(
          Entry(spec(table, kind, part), Layout({{"1-E", source}}, PixelType::kUnorm16), Container::kHeader, "", sym));
    }
    p.push_back(o);
  }
  {
    // Blender EEVEE (4.2 and later, [Blender]): eevee_lut.cc's
    // btdf_ggx[16][64][64][1], [slice][row][column] with the column i at
    // z = F0^(1/4) = i / 63 (ior = (1 + z^2) / (1 - z^2), 1 to inf), the
    // row j at sqrt(1 - NoV) = j / 63 and the slice k at roughness k / 16,
    // where the renderer reads it (utility_tx_sample_bsdf_lut: layer 16 r
    // + 4; its generator wrote r = k / 15). The value is the refraction
    // lobe without F weighted by 1 - (1 - |wo.h|)^5, separable masking
    // (eevee_lut_comp.glsl, ggx_btdf_gt_one). Baked over mu (the
    // one-minus-square warp: mu = 1 - (1 - t)^2, the rows reversed by the
    // writer) x roughness x ior; the writer puts them in EEVEE's order.
    // The other tables of the file (the LTC fits, the split sums brdf_ggx
    // and bsdf_ggx, blue noise, the SSS profiles) are not baked: the file
    // #includes Blender's own (docs/engines.md says why).
    Preset e{"eevee",
             "Blender EEVEE's eevee_lut.cc: btdf_ggx[16][64][64][1] (the refraction weighted by 1 - (1 - wo.h)^5, "
             "separable masking; x = F0^(1/4), y = sqrt(1 - NoV), slices at roughness k / 16), float; the "
             "other tables #included from Blender's own file kept as eevee_lut_blender.cc",
             {},
             "eevee_lut.cc",
             EngineForm::kEeveeLut};
    BakeSpec s = Spec(TableKind::kE, 64, 16, Placement::kEdges);
    s.model.kind = ModelKind::kGgxGlass;
    s.part = DielectricPart::kTransmissionSchlick;
    s.masking = Masking::kSeparable;
    s.mu.warp = Warp::kOneMinusSquare;
    s.roughness.max = 15.0 / 16;
    s.ior = Axis{"ior", 64, 1.0, kInfinity, Warp::kFresnelZ, Placement::kEdges};
    s.tolerance = 1e-6;  // EEVEE stores it as half (RGBA16F), 2.4e-4 near 0.5
    e.tables.push_back(Entry(s, Layout({{"T", Source::kE}}, PixelType::kFloat), Container::kHeader, "", "btdf_ggx"));
    p.push_back(e);
  }
  // The sizes the engines' code fixes (PresetTable::size_fixed).
  for (Preset& preset : p) {
    for (PresetTable& pt : preset.tables) {
      pt.size_fixed = !preset.header_file.empty() || pt.container == Container::kHeader ||
                      pt.container == Container::kInc || pt.spec.mu.placement != Placement::kCenters ||
                      pt.spec.roughness.placement != Placement::kCenters;
    }
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
// [cos_theta]) with NAME_size = {columns, rows}, a 3D one [slices][rows]
// [columns] (Base_E[f0][roughness][cos_theta]) with NAME_size = {columns,
// rows, slices}; a 1D one NAME[n] with NAME_size = n.
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
    const bool three = im.axes.size() == 3;
    const int rows = three ? im.axes[1].size : im.height, slices = three ? im.axes[2].size : 1;
    const std::string w = std::to_string(im.width), h = std::to_string(rows), n = std::to_string(slices);
    std::string dims = "[" + h + "/*" + y + "*/][" + w + "/*" + x + "*/]";
    if (three) dims = "[" + n + "/*" + im.axes[2].name + "*/]" + dims;
    decl += "extern int " + sym + "_size[" + (three ? "3" : "2") + "];\nextern float " + sym + dims + ";\n";
    defs += "int " + sym + "_size[" + (three ? "3" : "2") + "] = { " + w + ", " + h + (three ? ", " + n : "") +
            " };\nfloat " + sym + dims + " = {\n";
    for (int s = 0; s < slices; ++s) {
      if (three) defs += "{\n";
      for (int r = 0; r < rows; ++r) {
        defs += "{";
        const size_t row = size_t(s) * rows + r;
        for (int c = 0; c < im.width; ++c) defs += (c ? "," : "") + FloatLiteral(im.values[row * im.width + c]);
        defs += "},\n";
      }
      if (three) defs += "},\n";
    }
    defs += "};\n\n";
  }
  return "// Enterprise PBR's lookup tables, baked by brdfbake " + std::string(BRDFBAKE_VERSION) +
         ". Do not edit: bake again instead.\n" + notes + "#ifndef PBRLUT_HPP\n#define PBRLUT_HPP\n" + decl +
         "#endif\n\n#ifdef PBRLUT_IMPLEMENTATION\n\n" + defs + "#endif\n";
}

// OpenPBR's impl/data/openpbr_energy_arrays.h: under the same guard and
// settings as the engine's file (array mode only, OPENPBR_USE_TEXTURE_LUTS
// = 0), OpenPBR_EnergyTableElement from the interop layer's 16- or 32-bit
// unsigned type, and each table as OPENPBR_CONSTEXPR_GLOBAL
// OpenPBR_EnergyTableElement NAME[OpenPBR_EnergyTableSize^rank], the
// unorm16 codes (value = code / 65535) in the order [ior][alpha][cos_theta],
// cos_theta fastest. The reflection ratio, which brdfbake does not bake,
// #includes the engine's own data file, after the ideal dielectric's
// average, in the engine's order.
std::string OpenPbrEnergyArrays(const Preset& preset, const std::vector<Table>& tables,
                                const std::vector<Image>& images) {
  std::string notes, arrays;
  for (size_t k = 0; k < preset.tables.size(); ++k) {
    const Image& im = images[k];
    const std::string& sym = preset.tables[k].symbol;
    if (im.pixel != PixelType::kUnorm16 || im.channels != 1) Bad("openpbr_energy_arrays.h holds unorm16 codes");
    notes += ConventionComment(tables[k], im, preset.name, ("// " + sym + ": ").c_str());
    const size_t n = im.bits16.size();
    int rank = 1;
    for (size_t m = 32; m < n; m *= 32) ++rank;
    std::string dims = "OpenPBR_EnergyTableSize";
    for (int r = 1; r < rank; ++r) dims += " * OpenPBR_EnergyTableSize";
    arrays += "OPENPBR_CONSTEXPR_GLOBAL OpenPBR_EnergyTableElement " + sym + "[" + dims + "] = {\n";
    for (size_t i = 0; i < n; ++i) {
      arrays += (i % 32 == 0 ? "    " : " ") + std::to_string(im.bits16[i]) + (i + 1 < n ? "," : "");
      if (i % 32 == 31 || i + 1 == n) arrays += "\n";
    }
    arrays += "};\n\n";
    if (sym == "OpenPBR_IdealDielectricAverageEnergyComplement_Array") {
      arrays +=
          "// Not baked by brdfbake: OpenPBR's own reflection ratio (its generator's rule for the split is not "
          "published).\n"
          "OPENPBR_CONSTEXPR_GLOBAL OpenPBR_EnergyTableElement OpenPBR_IdealDielectricReflectionRatio_Array"
          "[OpenPBR_EnergyTableSize * OpenPBR_EnergyTableSize] = {\n"
          "#include \"openpbr_ideal_dielectric_reflection_ratio_data.h\"\n};\n\n";
    }
  }
  return "// OpenPBR's energy compensation tables (impl/data/openpbr_energy_arrays.h), baked by brdfbake " +
         std::string(BRDFBAKE_VERSION) +
         ". Do not edit: bake again instead.\n"
         "// Every value is code / 65535; each array is [ior][alpha][cos_theta] with cos_theta fastest.\n" +
         notes +
         "\n#ifndef OPENPBR_ENERGY_ARRAYS_H\n#define OPENPBR_ENERGY_ARRAYS_H\n\n"
         "#include \"../../openpbr_settings.h\"\n\n"
         "#if !OPENPBR_USE_TEXTURE_LUTS\n\n"
         "#include \"../../openpbr_data_constants.h\"\n\n"
         "#ifndef OPENPBR_ENERGY_TABLES_USE_UINT16\n"
         "#error \"openpbr_energy_arrays.h needs OPENPBR_ENERGY_TABLES_USE_UINT16 from an OpenPBR interop header\"\n"
         "#endif\n"
         "#if OPENPBR_ENERGY_TABLES_USE_UINT16\n"
         "#ifndef OPENPBR_UINT16\n#error \"openpbr_energy_arrays.h needs OPENPBR_UINT16 from the interop layer\"\n"
         "#endif\n#define OpenPBR_EnergyTableElement OPENPBR_UINT16\n"
         "#else\n"
         "#ifndef OPENPBR_UINT32\n#error \"openpbr_energy_arrays.h needs OPENPBR_UINT32 from the interop layer\"\n"
         "#endif\n#define OpenPBR_EnergyTableElement OPENPBR_UINT32\n"
         "#endif\n\n" +
         arrays + "#endif  // !OPENPBR_USE_TEXTURE_LUTS\n\n#endif  // OPENPBR_ENERGY_ARRAYS_H\n";
}

// Blender EEVEE's eevee_lut.cc (source/blender/draw/engines/eevee_next/,
// [Blender]): its btdf_ggx[16][64][64][1] in namespace blender::eevee::lut,
// [k][j][i][0] = slice k (roughness), row j (sqrt(1 - NoV) = j / 63: the
// baked mu entry 63 - j), column i (ior entry i). Every other table of the
// file is Blender's own: the shipped eevee_lut.cc, kept beside this one as
// eevee_lut_blender.cc, is #included with its btdf_ggx renamed away, so
// this file defines the same symbols as the one it replaces.
std::string EeveeLut(const Preset& preset, const std::vector<Table>& tables, const std::vector<Image>& images) {
  if (preset.tables.size() != 1 || images[0].pixel != PixelType::kFloat || images[0].channels != 1 ||
      images[0].axes.size() != 3) {
    Bad("eevee_lut.cc holds one float table over mu, roughness and ior");
  }
  const Image& im = images[0];
  const int n_mu = im.axes[0].size, n_r = im.axes[1].size, n_ior = im.axes[2].size;
  const std::string sym = preset.tables[0].symbol;
  const std::string dims = "[" + std::to_string(n_r) + "][" + std::to_string(n_mu) + "][" +
                           std::to_string(n_ior) + "][1]";
  std::string s = "/* EEVEE's lookup tables (source/blender/draw/engines/eevee_next/eevee_lut.cc) with " + sym +
                  " baked by brdfbake " + std::string(BRDFBAKE_VERSION) + ". Do not edit: bake again instead.\n";
  s += ConventionComment(tables[0], im, preset.name, " * ");
  s += " * The array is in EEVEE's order, not the axes' order above: " + sym +
       "[k][j][i][0] holds roughness entry k, mu entry " + std::to_string(n_mu - 1) +
       " - j (sqrt(1 - NoV) = j / " + std::to_string(n_mu - 1) + "), ior entry i (F0^(1/4) = i / " +
       std::to_string(n_ior - 1) + ").\n */\n\n";
  s += "/* Not baked by brdfbake: ltc_mat_ggx, ltc_mag_ggx, ltc_disk_integral, brdf_ggx, bsdf_ggx, blue_noise,\n"
       " * burley_sss_profile, random_walk_sss_profile. They are Blender's own: keep the shipped eevee_lut.cc\n"
       " * beside this file as eevee_lut_blender.cc (it is compiled only through this #include); its " +
       sym + "\n * is renamed away and unused. */\n";
  s += "#define " + sym + " " + sym + "_blender\n#include \"eevee_lut_blender.cc\"\n#undef " + sym + "\n\n";
  s += "namespace blender::eevee::lut {\n\n";
  s += "/* The declaration of eevee_lut.hh, which the renaming above hid. */\nextern const float " + sym + dims +
       ";\n\n";
  s += "const float " + sym + dims + " = {\n";
  for (int k = 0; k < n_r; ++k) {
    s += "    {\n";
    for (int j = 0; j < n_mu; ++j) {
      const int i_mu = n_mu - 1 - j;
      s += "        {";
      for (int i = 0; i < n_ior; ++i) {
        const double v = im.values[(size_t(i) * n_r + k) * n_mu + i_mu];
        s += (i ? (i % 8 == 0 ? ",\n         " : ", ") : "") + std::string("{") + FloatLiteral(v) + "}";
      }
      s += "},\n";
    }
    s += "    },\n";
  }
  s += "};\n\n}  // namespace blender::eevee::lut\n";
  return s;
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
  Bad("{format} " + format + ": " + preset.name + " loads its " + TableName(pt.spec.table) + " table as " +
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
  if (preset.header_form == EngineForm::kEeveeLut && !run.shaders.empty()) {
    Bad("{shader}: " + preset.name + " samples " + preset.header_file +
        "'s tables with its own shader (utility_tx_sample_bsdf_lut); no lookup is written");
  }
  std::vector<PresetFile> files;
  for (size_t k = 0; k < preset.tables.size(); ++k) {
    const PresetTable& pt = preset.tables[k];
    if (!pt.file.empty()) {
      const Container c = ContainerFor(preset, pt, run.format);
      files.push_back({TablePath(preset, pt, run), int(k),
                       std::string(TableName(pt.spec.table)) + " (" + preset.name + ")", c, false,
                       ShaderLanguage::kGlsl, pt.symbol, false, c == Container::kKtx2 ? pt.ktx2_zstd_level : 0});
    }
    for (ShaderLanguage l : run.shaders) {
      files.push_back({ShaderFile(run, pt, l), int(k),
                       std::string(ShaderLanguageName(l)) + " lookup of " + pt.symbol, Container::kHeader, true,
                       l, "brdfbake_" + pt.symbol});
    }
  }
  bool any_file = false;
  for (const PresetTable& pt : preset.tables) any_file |= !pt.file.empty();
  if (!run.format.empty() && !any_file) {
    Bad("{format} " + run.format + ": " + preset.name + " loads its tables from " + preset.header_file +
        " only");
  }
  if (!preset.header_file.empty()) {
    OutputFile header;
    header.path = run.dir + "/" + preset.header_file;
    header.table = -1;
    header.what = std::to_string(preset.tables.size()) + " tables (" + preset.name + ")";
    header.container = Container::kHeader;
    files.push_back(header);
  }
  return files;
}

namespace {

// PresetTable::Over: Base_E (x = mu, y = roughness, slices over F0) from the
// dfg table, or Base_E_avg (x = roughness, y = F0) from the E_avg table,
// with E_avg (and bias_avg) integrated per roughness at the table's
// tolerance. The claim: the errors of scale, bias and E_avg carried
// through the formula (F_ms's slope in E_avg is F_avg^2 (1 - F_avg) / (1 -
// F_avg (1 - E_avg))^2), plus the rounding to float.
Image ArrangeOverF0(const PresetTable& pt, const Table& table) {
  const bool eavg = pt.over == PresetTable::Over::kSchlickMsEavg;
  const Axis& r_axis = table.axes[eavg ? 0 : 1];
  const int n_r = r_axis.size, n_mu = eavg ? 1 : table.axes[0].size, n_f0 = pt.f0.size;
  BakeSpec e_spec = table.spec;
  e_spec.table = TableKind::kE;
  std::vector<EavgEstimate> e_avg(n_r), bias_avg(n_r);
  for (int j = 0; j < n_r; ++j) {
    const double r = std::max(r_axis.Value(j), r_axis.clamp_min);
    e_avg[j] = IntegrateEavg(e_spec, r);
    if (eavg) bias_avg[j] = IntegrateBiasAvg(e_spec, r);
  }
  const ImageLayout::Out& out = pt.layout.channels.at(0);
  Image im;
  im.width = eavg ? n_r : n_mu;
  im.height = eavg ? n_f0 : n_r * n_f0;
  im.channels = 1;
  im.pixel = pt.layout.pixel;
  im.axes = eavg ? std::vector<Axis>{r_axis, pt.f0} : std::vector<Axis>{table.axes[0], r_axis, pt.f0};
  im.channel_names = {out.name};
  im.table_name = eavg ? "Base_E_avg" : "Base_E";
  im.fresnel = "schlick over the f0 axis (F90 = 1), with the multiple-scattering lobe of [KullaConty17] "
               "weighted by F_ms = F_avg^2 E_avg / (1 - F_avg (1 - E_avg)), F_avg = (20 f0 + 1) / 21";
  im.channel_sources = {std::string(eavg ? "f0 E_avg + (1 - f0) bias_avg + F_ms (1 - E_avg)"
                                         : "f0 dfg.scale + dfg.bias + F_ms (1 - E)") +
                        (std::isfinite(out.max) ? ", at most " + NumG9(out.max) : "")};
  im.values.resize(size_t(im.width) * im.height);
  if (im.pixel != PixelType::kFloat) im.bits16.resize(im.values.size());
  double claim = 0, rounding = 0;
  for (int k = 0; k < n_f0; ++k) {
    const double f0 = pt.f0.Value(k);
    const double f_avg = (20 * f0 + 1) / 21;
    for (int j = 0; j < n_r; ++j) {
      const double ea = e_avg[j].value, den = 1 - f_avg * (1 - ea);
      const double f_ms = f_avg * f_avg * ea / den;
      const double slope = f_avg * f_avg * (1 - f_avg) / (den * den);
      for (int i = 0; i < n_mu; ++i) {
        double v, err;
        if (eavg) {
          v = f0 * ea + (1 - f0) * bias_avg[j].value + f_ms * (1 - ea);
          err = (f0 + f_ms + slope * (1 - ea)) * e_avg[j].error + (1 - f0) * bias_avg[j].error;
        } else {
          const double a = table.channels[0].values[size_t(j) * table.width + i];
          const double b = table.channels[1].values[size_t(j) * table.width + i];
          v = f0 * a + b + f_ms * (1 - a - b);
          err = (f0 + 1 + 2 * f_ms) * table.integration_error + slope * (1 - a - b) * e_avg[j].error;
        }
        const double stored = std::min(v, out.max);
        const size_t dst = eavg ? size_t(k) * n_r + j : (size_t(k) * n_r + j) * n_mu + i;
        im.values[dst] = RoundToPixel(stored, im.pixel);
        if (im.pixel != PixelType::kFloat) im.bits16[dst] = PixelCode(im.values[dst], im.pixel);
        claim = std::max(claim, err);
        rounding = std::max(rounding, std::abs(im.values[dst] - stored));
      }
    }
  }
  im.max_abs_error = claim + rounding;
  return im;
}

}  // namespace

Image ArrangePresetTable(const PresetTable& pt, const Table& table, int threads, double tolerance,
                         const ProgressFn& progress) {
  if (pt.over != PresetTable::Over::kNone) return ArrangeOverF0(pt, table);
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

void WritePresetFile(const Preset& preset, const PresetFile& f, const std::vector<Table>& tables,
                     const std::vector<Image>& images) {
  if (f.table < 0) {
    if (preset.header_form == EngineForm::kEnterprisePbrHeader) {
      WriteFileAtomically(f.path, EnterprisePbrHeader(preset, tables, images));
      return;
    }
    if (preset.header_form == EngineForm::kOpenPbrEnergyArrays) {
      WriteFileAtomically(f.path, OpenPbrEnergyArrays(preset, tables, images));
      return;
    }
    if (preset.header_form == EngineForm::kEeveeLut) {
      WriteFileAtomically(f.path, EeveeLut(preset, tables, images));
      return;
    }
    std::vector<std::pair<const Table*, const Image*>> arrays;
    std::vector<std::string> symbols;
    for (size_t k = 0; k < preset.tables.size(); ++k) {
      arrays.push_back({&tables[k], &images[k]});
      symbols.push_back(preset.tables[k].symbol);
    }
    WriteHeader(arrays, symbols, f.path, preset.name);
    return;
  }
  const PresetTable& pt = preset.tables[f.table];
  const Table& t = tables[f.table];
  const Image& im = images[f.table];
  if (!f.lookup && f.container == pt.container && pt.form == EngineForm::kThreeDfgModule) {
    WriteFileAtomically(f.path, ThreeDfgModule(t, im, preset.name));
    return;
  }
  WriteOutputFile(f, t, im, preset.name);
}

void WritePresetFiles(const Preset& preset, const PresetRun& run, const std::vector<Table>& tables,
                      const std::vector<Image>& images) {
  for (const PresetFile& f : PresetFiles(preset, run)) WritePresetFile(preset, f, tables, images);
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
  Bad("{preset}: unknown preset '" + name + "' (expected " + names + ")" +
      DidYouMean(name, all,
                 {{"ue4", "unreal"}, {"ue5", "unreal"}, {"unreal-engine", "unreal"}, {"unity", "hdrp"},
                  {"three.js", "three"}, {"threejs", "three"}, {"blender", "cycles"}, {"eevee-next", "eevee"},
                  {"enterprise", "enterprise-pbr"}, {"dassault", "enterprise-pbr"}}));
}

}  // namespace brdfbake
