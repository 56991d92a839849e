// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Shader functions that sample an arranged table with its exact texel
// mapping (GLSL, HLSL, WGSL).

#include "brdfbake/shaders.h"

#include <string>

#include "base/error.h"
#include "base/text.h"

namespace brdfbake {
namespace {

std::string Lit(double v) {
  std::string s = NumG9(v);
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return s;
}

// One axis' texture coordinate from a physical value, as shader source.
// HLSL spells clamp(x, 0, 1) saturate(x).
std::string AxisCoordinate(const Axis& a, const std::string& value, bool hlsl) {
  const std::string x = "(" + value + " - " + Lit(a.min) + ") / " + Lit(a.max - a.min);
  std::string t = hlsl ? "saturate(" + x + ")" : "clamp(" + x + ", 0.0, 1.0)";
  if (a.warp == Warp::kSquare) t = "sqrt(" + t + ")";
  if (a.warp == Warp::kSqrt) t = "(" + t + ") * (" + t + ")";
  if (a.placement == Placement::kEdges) {
    return "(" + t + " * " + Lit(a.size - 1) + " + 0.5) / " + Lit(a.size);
  }
  return t;
}

}  // namespace

ShaderLanguage ParseShaderLanguage(const std::string& s) {
  if (s == "glsl") return ShaderLanguage::kGlsl;
  if (s == "hlsl") return ShaderLanguage::kHlsl;
  if (s == "wgsl") return ShaderLanguage::kWgsl;
  Bad("--shader: unknown language '" + s + "' (expected glsl, hlsl or wgsl)");
}

const char* ShaderLanguageName(ShaderLanguage l) {
  switch (l) {
    case ShaderLanguage::kGlsl: return "glsl";
    case ShaderLanguage::kHlsl: return "hlsl";
    case ShaderLanguage::kWgsl: return "wgsl";
  }
  return "glsl";
}

std::string ShaderFunction(const Table& t, const Image& im, ShaderLanguage lang,
                           const std::string& name) {
  const bool glsl = lang == ShaderLanguage::kGlsl, hlsl = lang == ShaderLanguage::kHlsl;
  const std::string f1 = hlsl || glsl ? "float" : "f32";
  const std::string f2 = glsl ? "vec2" : hlsl ? "float2" : "vec2<f32>";
  const bool one_d = t.spec.table == TableKind::kEavg;
  // Texture coordinates.
  auto coord = [&](const Axis& a) { return AxisCoordinate(a, a.name == "mu" ? "NoV" : "roughness", hlsl); };
  std::string u = coord(im.axes[0]);
  std::string v = one_d ? "0.5" : coord(im.axes[1]);
  if (im.flip_rows) v = "1.0 - (" + v + ")";
  // Which component holds what.
  auto comp = [&](const char* source) -> int {
    for (size_t c = 0; c < im.channel_sources.size(); ++c) {
      if (im.channel_sources[c] == source) return int(c);
    }
    return -1;
  };
  const char* xyzw[] = {"x", "y", "z", "w"};
  auto get = [&](const char* source) {
    const int c = comp(source);
    return c < 0 ? std::string() : std::string("s.") + xyzw[c];
  };
  std::string result, type;
  if (t.spec.table == TableKind::kDfg) {
    type = f2;
    std::string scale = get("dfg.scale"), bias = get("dfg.bias"), e = get("E");
    if (scale.empty()) scale = "(" + e + " - " + bias + ")";
    if (bias.empty()) bias = "(" + e + " - " + scale + ")";
    result = f2 + "(" + scale + ", " + bias + ")";
  } else {
    type = f1;
    const std::string direct = get(one_d ? "E_avg" : "E");
    const std::string comp_ = get(one_d ? "1-E_avg" : "1-E");
    result = !direct.empty() ? direct : "1.0 - " + comp_;
  }
  std::ostringstream os;
  os << "// " << name << ": the brdfbake " << TableName(t.spec.table) << " table ("
     << im.width << "x" << im.height << ", " << MaskingName(t.spec.masking)
     << ") sampled with its exact texel mapping; bilinear filtering, clamp-to-edge.\n";
  os << "// x = " << im.axes[0].name << (one_d ? "" : ", y = " + im.axes[1].name)
     << (im.flip_rows ? ", rows flipped" : "") << "; channels:";
  for (size_t c = 0; c < im.channel_sources.size(); ++c) os << " " << xyzw[c] << " = " << im.channel_sources[c];
  os << (t.spec.table == TableKind::kDfg ? "; returns (scale, bias): F = F0 scale + F90 bias\n" : "\n");
  const std::string pre_u = "  " + std::string(glsl || hlsl ? f1 + " u = " : "let u: f32 = ") + u + ";\n";
  const std::string pre_v = "  " + std::string(glsl || hlsl ? f1 + " v = " : "let v: f32 = ") + v + ";\n";
  if (glsl) {
    os << type << " " << name << "(sampler2D lut, " << (one_d ? "" : "float NoV, ") << "float roughness) {\n"
       << pre_u << pre_v << "  vec4 s = texture(lut, vec2(u, v));\n  return " << result << ";\n}\n";
  } else if (hlsl) {
    os << type << " " << name << "(Texture2D<float4> lut, SamplerState lut_sampler, "
       << (one_d ? "" : "float NoV, ") << "float roughness) {\n"
       << pre_u << pre_v << "  float4 s = lut.SampleLevel(lut_sampler, float2(u, v), 0.0);\n  return "
       << result << ";\n}\n";
  } else {
    os << "fn " << name << "(lut: texture_2d<f32>, lut_sampler: sampler, "
       << (one_d ? "" : "NoV: f32, ") << "roughness: f32) -> " << type << " {\n"
       << pre_u << pre_v << "  let s: vec4<f32> = textureSampleLevel(lut, lut_sampler, vec2<f32>(u, v), 0.0);\n"
       << "  return " << result << ";\n}\n";
  }
  return os.str();
}

}  // namespace brdfbake
