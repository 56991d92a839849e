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

// A shader function that samples `image` (uploaded as a texture with
// bilinear filtering and clamp-to-edge) with physical inputs: for E and dfg
// `name(tex, NoV, roughness)`, for E_avg `name(tex, roughness)`; the
// half-texel remap, the warps, the clamps, the transpose and the row order
// are built in. dfg returns (scale, bias) whatever the channel layout.
enum class ShaderLanguage { kGlsl, kHlsl, kWgsl };
ShaderLanguage ParseShaderLanguage(const std::string& s);
const char* ShaderLanguageName(ShaderLanguage l);
std::string ShaderFunction(const Table& table, const Image& image, ShaderLanguage language,
                           const std::string& name);

}  // namespace brdfbake

#endif  // BRDFBAKE_SHADERS_H_
