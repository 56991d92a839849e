// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Engine presets: each engine's table as its shader samples it (axes and
// which is x, placement, warps, row order, channel order and meaning,
// size, pixel type, clamps), filled with brdfbake's exact integration of
// GGX with height-correlated masking. The facts and their sources are in
// docs/engines.md.

#include <stdexcept>

#include "brdfbake/presets.h"

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

std::vector<Preset> MakePresets() {
  std::vector<Preset> p;
  {
    // Filament: DFG 128x128 RGB16F, NoV on x at centres, r on y with the
    // rows stored flipped, R = bias, G = E (multiscatter form), B = the
    // cloth (Charlie) term, shipped as uint16 half bits in a header.
    Preset f{"filament",
             "Filament's DFG: 128x128, x = NoV, y = roughness (rows flipped), R = bias, G = E, "
             "B = cloth (not baked: 0), half bits in a C++ header",
             {},
             ""};
    PresetTable t{Spec(TableKind::kDfg, 128, 128, Placement::kCenters),
                  Layout({{"R", Source::kBias}, {"G", Source::kE}, {"B", Source::kZero}}, PixelType::kHalf,
                         false, true),
                  Container::kHeader, "dfg.h", "DFG_LUT"};
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
    u.tables.push_back({Spec(TableKind::kDfg, 128, 32, Placement::kCenters),
                        Layout({{"R", Source::kScale}, {"G", Source::kBias}}, PixelType::kUnorm16),
                        Container::kDds, "PreIntegratedGF.dds", "PreIntegratedGF"});
    p.push_back(u);
  }
  {
    // Unity HDRP: FGD 64x64, x = sqrt(NoV), y = r, both with the endpoints
    // on the first and last texel centres (Remap01ToHalfTexelCoord: the
    // edges placement), x = bias, y = E, z = Disney diffuse - 0.5.
    Preset h{"hdrp",
             "HDRP's preintegrated FGD: 64x64, x = sqrt(NoV), y = roughness, endpoints on texel "
             "centres, R = bias, G = E, B = Disney diffuse (not baked: 0), half EXR",
             {},
             ""};
    BakeSpec s = Spec(TableKind::kDfg, 64, 64, Placement::kEdges);
    s.mu.warp = Warp::kSquare;  // coordinate c = sqrt(NoV): NoV = c^2
    h.tables.push_back({s,
                        Layout({{"R", Source::kBias}, {"G", Source::kE}, {"B", Source::kZero}},
                               PixelType::kHalf),
                        Container::kExr, "preintegrated_fgd.exr", "PreintegratedFGD"});
    p.push_back(h);
  }
  {
    // Godot 4: 128x128 rgba16f, NoV on x at centres, r on y at centres,
    // rows flipped, R = bias, G = E, B = cloth.
    Preset g{"godot",
             "Godot 4's DFG: 128x128, x = NoV, y = roughness (rows flipped), R = bias, G = E, "
             "B = cloth (not baked: 0), A = 1, RGBA half EXR",
             {},
             ""};
    g.tables.push_back({Spec(TableKind::kDfg, 128, 128, Placement::kCenters),
                        Layout({{"R", Source::kBias}, {"G", Source::kE}, {"B", Source::kZero}, {"A", Source::kOne}},
                               PixelType::kHalf, false, true),
                        Container::kExr, "dfg_lut.exr", "DFG_LUT"});
    p.push_back(g);
  }
  {
    // Bevy: 64x64 KTX2 R16G16_SFLOAT, NoV on x, r on y, centres, R = scale,
    // G = bias.
    Preset b{"bevy", "Bevy's dfg.ktx2: 64x64, x = NoV, y = roughness, R = scale, G = bias, R16G16_SFLOAT KTX2",
             {},
             ""};
    b.tables.push_back({Spec(TableKind::kDfg, 64, 64, Placement::kCenters),
                        Layout({{"R", Source::kScale}, {"G", Source::kBias}}, PixelType::kHalf),
                        Container::kKtx2, "dfg.ktx2", "dfg"});
    p.push_back(b);
  }
  {
    // three.js: 16x16 RG16F, roughness on x (u), NoV on y (v), centres,
    // R = scale, G = bias, a Uint16Array of half bits in an ES module.
    Preset t{"three",
             "three.js's DFGLUTData: 16x16, x = roughness, y = NoV, R = scale, G = bias, "
             "Uint16Array of halves in an ES module",
             {},
             ""};
    t.tables.push_back({Spec(TableKind::kDfg, 16, 16, Placement::kCenters),
                        Layout({{"R", Source::kScale}, {"G", Source::kBias}}, PixelType::kHalf, true),
                        Container::kJs, "DFGLUTData.js", "DFGLUTData"});
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
    c.tables.push_back({e, Layout({{"E", Source::kE}}, PixelType::kFloat, true), Container::kHeader, "",
                        "table_ggx_E"});
    BakeSpec a = Spec(TableKind::kEavg, 32, 32, Placement::kEdges);
    a.roughness.clamp_min = 1e-4;
    c.tables.push_back({a, Layout({{"E_avg", Source::kEavg}}, PixelType::kFloat), Container::kHeader, "",
                        "table_ggx_Eavg"});
    p.push_back(c);
  }
  {
    // MaterialX: the albedo table, 64x64 float RGB, NoV on x, ALPHA (not
    // r) on y, both at centres, R = scale, G = bias, B = sheen.
    Preset m{"materialx",
             "MaterialX's albedo table: 64x64, x = NoV, y = alpha at centres (r = sqrt(alpha)), "
             "R = scale, G = bias, B = sheen (not baked: 0), float EXR",
             {},
             ""};
    BakeSpec s = Spec(TableKind::kDfg, 64, 64, Placement::kCenters);
    s.roughness.warp = Warp::kSqrt;  // r = sqrt(t): alpha = t at the texel centres
    m.tables.push_back({s,
                        Layout({{"R", Source::kScale}, {"G", Source::kBias}, {"B", Source::kZero}},
                               PixelType::kFloat),
                        Container::kExr, "albedo_table.exr", "albedo_table"});
    p.push_back(m);
  }
  {
    // Enterprise PBR: GGX_E 32x32 (NoV on x, r on y) and GGX_E_avg 32, as
    // a C++ header of float arrays and as EXR. Its source does not state
    // the placement; centres suit GPU bilinear lookup.
    Preset e{"enterprise-pbr",
             "Enterprise PBR's GGX_E (32x32, x = NoV, y = roughness) and GGX_E_avg (32), centres, "
             "float: a C++ header and EXR files",
             {},
             "pbrlut.hpp"};
    e.tables.push_back({Spec(TableKind::kE, 32, 32, Placement::kCenters),
                        Layout({{"E", Source::kE}}, PixelType::kFloat), Container::kExr, "GGX_E.exr",
                        "GGX_E"});
    e.tables.push_back({Spec(TableKind::kEavg, 32, 32, Placement::kCenters),
                        Layout({{"E_avg", Source::kEavg}}, PixelType::kFloat), Container::kExr,
                        "GGX_E_avg.exr", "GGX_E_avg"});
    p.push_back(e);
  }
  return p;
}

}  // namespace

const std::vector<Preset>& Presets() {
  static const std::vector<Preset> kPresets = MakePresets();
  return kPresets;
}

const Preset& FindPreset(const std::string& name) {
  std::string names;
  for (const Preset& p : Presets()) {
    if (p.name == name) return p;
    names += (names.empty() ? "" : ", ") + p.name;
  }
  throw std::invalid_argument("--preset: unknown preset '" + name + "' (expected " + names + ")");
}

}  // namespace brdfbake
