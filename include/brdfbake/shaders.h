// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Shader lookups of an arranged table.

#ifndef BRDFBAKE_SHADERS_H_
#define BRDFBAKE_SHADERS_H_

#include <string>
#include <vector>

#include "brdfbake/bake.h"
#include "brdfbake/containers.h"

namespace brdfbake {

// A shader function that samples `image` (uploaded as a 2D texture with
// bilinear filtering and clamp-to-edge) with physical inputs, one per table
// axis in the table's order: E and dfg `name(tex, NoV, roughness)`, E_avg
// `name(tex, roughness)`, a gamma axis adds `gamma`, ggx-aniso E
// `name(tex, NoV, phi_o, roughness, anisotropy)` and E_avg
// `name(tex, roughness, anisotropy)`, ellipsoid E `name(tex, NoV, phi_o)`.
// The half-texel remap, the warps, the clamps, the transpose and the row
// order are built in; a single-entry axis is a constant coordinate. Axes
// beyond the second are slices stacked vertically: the function blends the
// neighbouring slices by hand (2 samples for 3 axes, 4 for 4). dfg returns
// (scale, bias) whatever the channel layout. sel_norm tables have no
// lookup: CheckShaderTable throws std::invalid_argument for them.
enum class ShaderLanguage { kGlsl, kHlsl, kWgsl };
ShaderLanguage ParseShaderLanguage(const std::string& s);
const char* ShaderLanguageName(ShaderLanguage l);
void CheckShaderTable(const BakeSpec& spec);
std::string ShaderFunction(const Table& table, const Image& image, ShaderLanguage language,
                           const std::string& name);

}  // namespace brdfbake

#endif  // BRDFBAKE_SHADERS_H_
