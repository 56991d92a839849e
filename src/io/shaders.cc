// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Shader functions that sample an arranged table with its exact texel
// mapping (GLSL, HLSL, WGSL).

#include "brdfbake/shaders.h"

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "bake/warp_coordinates.h"
#include "base/error.h"
#include "base/text.h"

namespace brdfbake {
namespace {

// A float literal every language reads; negative ones in parentheses.
std::string Lit(double v) {
  std::string s = NumG9(v);
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
  return v < 0 ? "(" + s + ")" : s;
}

// The shader's parameter for a table axis.
std::string ParameterName(const Axis& a) {
  if (a.name == "mu") return "NoV";
  return a.name;  // roughness, phi_o, anisotropy, gamma, ior, exponent
}

// One axis' texture coordinate in [0, 1] from its physical value, as
// shader source: the warp inverted, the clamp, and for edges placement the
// half-texel remap. A single-entry axis is the constant 0.5 (its one
// texel's centre), with no division. HLSL spells clamp(x, 0, 1) saturate(x).
std::string AxisCoordinate(const Axis& a, bool hlsl) {
  if (a.size == 1) return "0.5";
  const std::string value = ParameterName(a);
  std::string x;
  if (a.warp == Warp::kTail) {
    // u = (gamma - 1.5) / (gamma - 0.5) = 1 - 1 / (gamma - 0.5) (1 at
    // gamma = inf), ln u linear in t between the axis' ends.
    auto log_u = [](double g) { return std::isinf(g) ? 0.0 : std::log((g - 1.5) / (g - 0.5)); };
    const double lo = log_u(a.min), hi = log_u(a.max);
    x = "(log(1.0 - 1.0 / (" + value + " - 0.5)) - " + Lit(lo) + ") / " + Lit(hi - lo);
  } else if (a.warp == Warp::kFresnelZ) {
    // z = sqrt(|ior - 1| / (ior + 1)) (= F0^(1/4)) linear in t between the
    // axis' ends (bake.h).
    const double lo = FresnelZOfIor(a.min), hi = FresnelZOfIor(a.max);
    x = "(sqrt(abs(" + value + " - 1.0) / (" + value + " + 1.0)) - " + Lit(lo) + ") / " + Lit(hi - lo);
  } else if (a.warp == Warp::kSchlickZ) {
    // z = 5 / (exponent + 5) linear in t between the axis' ends (bake.h;
    // z = 0 at exponent = inf).
    const double lo = SchlickZOfExponent(a.min), hi = SchlickZOfExponent(a.max);
    x = "(5.0 / (" + value + " + 5.0) - " + Lit(lo) + ") / " + Lit(hi - lo);
  } else if (a.warp == Warp::kTwoSided) {
    // The fractional index (bake.h): below 1, H - 1 - (1 / ior - 1) (H -
    // 1) / (1 / min - 1); from 1 up, H + (ior - 1) (H - 1) / (max - 1);
    // picked by step(), which the three languages share.
    const double h = a.size / 2;
    const std::string below =
        "(" + Lit(h - 1) + " - (1.0 / " + value + " - 1.0) * " + Lit((h - 1) / (1 / a.min - 1)) + ")";
    const std::string above = "(" + Lit(h) + " + (" + value + " - 1.0) * " + Lit((h - 1) / (a.max - 1)) + ")";
    const std::string s = "step(1.0, " + value + ")";
    x = "mix(" + below + ", " + above + ", " + s + ") / " + Lit(a.size - 1);
    if (hlsl) x = "lerp(" + below + ", " + above + ", " + s + ") / " + Lit(a.size - 1);
  } else {
    x = "(" + value + " - " + Lit(a.min) + ") / " + Lit(a.max - a.min);
  }
  std::string t = hlsl ? "saturate(" + x + ")" : "clamp(" + x + ", 0.0, 1.0)";
  if (a.warp == Warp::kSquare) t = "sqrt(" + t + ")";
  if (a.warp == Warp::kSqrt) t = "(" + t + ") * (" + t + ")";
  if (a.warp == Warp::kOneMinusSquare) t = "(1.0 - sqrt(1.0 - " + t + "))";
  if (a.placement == Placement::kEdges) {
    return "(" + t + " * " + Lit(a.size - 1) + " + 0.5) / " + Lit(a.size);
  }
  return t;
}

// The syntax of the three languages.
struct Syntax {
  ShaderLanguage lang;
  bool glsl() const { return lang == ShaderLanguage::kGlsl; }
  bool hlsl() const { return lang == ShaderLanguage::kHlsl; }
  std::string f1() const { return glsl() || hlsl() ? "float" : "f32"; }
  std::string f2() const { return glsl() ? "vec2" : hlsl() ? "float2" : "vec2<f32>"; }
  std::string f4() const { return glsl() ? "vec4" : hlsl() ? "float4" : "vec4<f32>"; }
  std::string Let(const std::string& type, const std::string& name, const std::string& value) const {
    if (glsl() || hlsl()) return "  " + type + " " + name + " = " + value + ";\n";
    return "  let " + name + ": " + type + " = " + value + ";\n";
  }
  std::string Mix(const std::string& a, const std::string& b, const std::string& w) const {
    return std::string(hlsl() ? "lerp(" : "mix(") + a + ", " + b + ", " + w + ")";
  }
  std::string Sample(const std::string& u, const std::string& v) const {
    if (glsl()) return "texture(lut, vec2(" + u + ", " + v + "))";
    if (hlsl()) return "lut.SampleLevel(lut_sampler, float2(" + u + ", " + v + "), 0.0)";
    return "textureSampleLevel(lut, lut_sampler, vec2<f32>(" + u + ", " + v + "), 0.0)";
  }
};

}  // namespace

ShaderLanguage ParseShaderLanguage(const std::string& given) {
  const std::string s = Lowercase(given);
  if (s == "glsl") return ShaderLanguage::kGlsl;
  if (s == "hlsl") return ShaderLanguage::kHlsl;
  if (s == "wgsl") return ShaderLanguage::kWgsl;
  Bad("{shader}: unknown language '" + given + "' (expected glsl, hlsl or wgsl)" +
      DidYouMean(given, {"glsl", "hlsl", "wgsl"}, {{"webgpu", "wgsl"}, {"opengl", "glsl"}, {"webgl", "glsl"},
                                                   {"d3d", "hlsl"}, {"directx", "hlsl"}}));
}

const char* ShaderLanguageName(ShaderLanguage l) {
  switch (l) {
    case ShaderLanguage::kGlsl: return "glsl";
    case ShaderLanguage::kHlsl: return "hlsl";
    case ShaderLanguage::kWgsl: return "wgsl";
  }
  return "glsl";
}

void CheckShaderTable(const BakeSpec& spec) {
  if (spec.table == TableKind::kSelNorm) {
    Bad("{shader}: no lookup function is written for sel_norm tables (alpha_x x alpha_y); "
        "read the EXR with the axes of its header");
  }
}

std::string ShaderFunction(const Table& t, const Image& im, ShaderLanguage lang,
                           const std::string& name) {
  CheckShaderTable(t.spec);
  const Syntax syn{lang};
  const bool glsl = syn.glsl(), hlsl = syn.hlsl();
  const std::vector<Axis>& axes = im.axes;
  const int n_axes = int(axes.size());
  // x = axes[0] and the rows of a slice = axes[1] are filtered by the
  // texture unit; each further axis picks slices of axes[1].size rows
  // (stacked vertically, the third axis fastest), blended by hand.
  const int rows = n_axes >= 2 ? axes[1].size : 1;
  std::string body;
  body += syn.Let(syn.f1(), "u", n_axes >= 1 ? AxisCoordinate(axes[0], hlsl) : "0.5");
  const std::string cy = n_axes >= 2 ? AxisCoordinate(axes[1], hlsl) : "0.5";
  const bool slices = n_axes > 2;
  // v in texel rows of one slice, clamped to its first and last centre so
  // that the filter never reaches into the next slice.
  if (slices) {
    body += syn.Let(syn.f1(), "y", "clamp(" + cy + " * " + Lit(rows) + ", 0.5, " + Lit(rows - 0.5) + ")");
  }
  // Per slice axis k: the fractional index f, its two neighbours and weight.
  int stride = 1;
  std::vector<int> strides;
  for (int k = 2; k < n_axes; ++k) {
    const Axis& a = axes[k];
    const std::string ks = std::to_string(k);
    strides.push_back(stride);
    stride *= a.size;
    if (a.size == 1) {
      body += syn.Let(syn.f1(), "i" + ks, "0.0") + syn.Let(syn.f1(), "j" + ks, "0.0") +
              syn.Let(syn.f1(), "w" + ks, "0.0");
      continue;
    }
    body += syn.Let(syn.f1(), "f" + ks,
                    "clamp(" + AxisCoordinate(a, hlsl) + " * " + Lit(a.size) + " - 0.5, 0.0, " +
                        Lit(a.size - 1) + ")");
    body += syn.Let(syn.f1(), "i" + ks, "floor(f" + ks + ")");
    body += syn.Let(syn.f1(), "j" + ks, "min(i" + ks + " + 1.0, " + Lit(a.size - 1) + ")");
    body += syn.Let(syn.f1(), "w" + ks, "f" + ks + " - i" + ks);
  }
  // The texture's v of slice index `slice` (an expression).
  auto v_of = [&](const std::string& slice) {
    std::string v = slices ? "((" + slice + ") * " + Lit(rows) + " + y) / " + Lit(im.height) : cy;
    if (im.flip_rows) v = "1.0 - (" + v + ")";
    return v;
  };
  if (!slices) {
    body += syn.Let(syn.f1(), "v", v_of(""));
    body += syn.Let(syn.f4(), "s", syn.Sample("u", "v"));
  } else {
    // Every corner of the slice axes: 2^(n - 2) samples, blended axis by axis.
    const int corners = 1 << (n_axes - 2);
    for (int c = 0; c < corners; ++c) {
      std::string slice;
      for (int k = 2; k < n_axes; ++k) {
        const std::string idx = (((c >> (k - 2)) & 1) ? "j" : "i") + std::to_string(k);
        slice += (slice.empty() ? "" : " + ") +
                 (strides[k - 2] == 1 ? idx : Lit(strides[k - 2]) + " * " + idx);
      }
      body += syn.Let(syn.f4(), "s" + std::to_string(c), syn.Sample("u", v_of(slice)));
    }
    std::vector<std::string> level;
    for (int c = 0; c < corners; ++c) level.push_back("s" + std::to_string(c));
    for (int k = 2; k < n_axes; ++k) {
      std::vector<std::string> next;
      for (size_t c = 0; c + 1 < level.size(); c += 2) {
        next.push_back(syn.Mix(level[c], level[c + 1], "w" + std::to_string(k)));
      }
      level = next;
    }
    body += syn.Let(syn.f4(), "s", level[0]);
  }
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
  const bool eavg = t.spec.table == TableKind::kEavg;
  // An image formed from the table (Image::table_name: Base_E over F0) has
  // one channel, over the image's own axes.
  const bool formed = !im.table_name.empty();
  const bool dfg = t.spec.table == TableKind::kDfg && !formed;
  // A table of one quantity of its own (gen_schlick's s, f82_bias): its
  // first channel's meaning, which is neither E nor E_avg.
  const Meaning first = t.channels.empty() ? Meaning::kE : t.channels[0].meaning;
  const bool own_quantity = !dfg && first != Meaning::kE && first != Meaning::kOneMinusE &&
                            first != Meaning::kEavg && first != Meaning::kOneMinusEavg;
  std::string result, type;
  if (formed) {
    type = syn.f1();
    result = "s.x";
  } else if (own_quantity) {
    type = syn.f1();
    result = get(MeaningName(first));
  } else if (dfg) {
    type = syn.f2();
    std::string scale = get("dfg.scale"), bias = get("dfg.bias"), e = get("E");
    if (scale.empty()) scale = "(" + e + " - " + bias + ")";
    if (bias.empty()) bias = "(" + e + " - " + scale + ")";
    result = syn.f2() + "(" + scale + ", " + bias + ")";
  } else {
    type = syn.f1();
    const std::string direct = get(eavg ? "E_avg" : "E");
    const std::string complement = get(eavg ? "1-E_avg" : "1-E");
    result = !direct.empty() ? direct : "1.0 - " + complement;
  }
  // The parameters, in the table's own axis order.
  std::string params;
  for (const Axis& a : formed ? im.axes : t.axes) {
    const std::string p = ParameterName(a);
    params += ", " + (glsl || hlsl ? "float " + p : p + ": f32");
  }
  std::ostringstream os;
  os << "// " << name << ": the brdfbake " << (formed ? im.table_name : std::string(TableName(t.spec.table)))
     << " table of " << t.spec.model.name()
     << " (" << im.width << "x" << im.height << ", " << MaskingName(t.spec.masking)
     << ") sampled with its exact texel mapping; bilinear filtering, clamp-to-edge.\n";
  os << "// x = " << (n_axes >= 1 ? axes[0].name : "-");
  if (n_axes >= 2) os << ", y = " << axes[1].name << (slices ? " (within a slice)" : "");
  for (int k = 2; k < n_axes; ++k) os << ", slices over " << axes[k].name;
  os << (im.flip_rows ? ", rows flipped" : "") << "; channels:";
  for (size_t c = 0; c < im.channel_sources.size(); ++c) os << " " << xyzw[c] << " = " << im.channel_sources[c];
  os << (dfg ? "; returns (scale, bias): F = F0 scale + F90 bias\n" : "\n");
  if (glsl) {
    os << type << " " << name << "(sampler2D lut" << params << ") {\n";
  } else if (hlsl) {
    os << type << " " << name << "(Texture2D<float4> lut, SamplerState lut_sampler" << params << ") {\n";
  } else {
    os << "fn " << name << "(lut: texture_2d<f32>, lut_sampler: sampler" << params << ") -> " << type << " {\n";
  }
  os << body << "  return " << result << ";\n}\n";
  return os.str();
}

}  // namespace brdfbake
