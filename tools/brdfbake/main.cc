// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The brdfbake command-line tool: parses arguments, calls the library,
// prints. No math here.

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <functional>
#include <iostream>
#include <limits>
#include <mutex>
#include <new>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "base/text.h"
#include "brdfbake/bake.h"
#include "brdfbake/batch.h"
#include "brdfbake/containers.h"
#include "brdfbake/eval.h"
#include "brdfbake/error.h"
#include "brdfbake/exr.h"
#include "brdfbake/grid.h"
#include "brdfbake/model.h"
#include "brdfbake/output_file.h"
#include "brdfbake/outputs.h"
#include "brdfbake/presets.h"
#include "brdfbake/report.h"
#include "brdfbake/scene.h"
#include "brdfbake/shaders.h"
#include "brdfbake/table_files.h"
#include "brdfbake/stability.h"
#include "brdfbake/targets.h"
#include "brdfbake/version.h"

namespace {

using brdfbake::EvalRequest;
using brdfbake::Fresnel;
using brdfbake::Masking;

constexpr double kDegree = 3.14159265358979323846 / 180.0;

[[noreturn]] void Bad(const std::string& what) { throw std::invalid_argument(what); }

// brdfbake::ForceTarget with its message as the --target option's.
void ForceTargetOption(const std::string& target) {
  try {
    brdfbake::ForceTarget(target);
  } catch (const std::invalid_argument& e) {
    Bad(std::string("--target: ") + e.what());
  }
}

// A message on one line: control characters (a newline inside an argument,
// say), C1 controls and bidirectional overrides shown as escapes.
std::string OneLine(const std::string& s) { return brdfbake::Printable(s); }
// An error message as printed: on one line, and at most 2000 bytes (a value
// of megabytes, from a file or an argument, is shown by its start and size).
std::string ErrorLine(const std::string& s) { return brdfbake::Excerpt(OneLine(s), 2000); }

// The command line's spelling of a library parameter: --name with dashes
// (mu_o: --mu-o), and -o for the output.
std::string FlagOf(const std::string& parameter) {
  if (parameter == "output") return "-o";
  std::string flag = "--" + parameter;
  std::replace(flag.begin(), flag.end(), '_', '-');
  return flag;
}

// An error's message with the parameters it names spelled as flags.
std::string CliMessage(const std::exception& e) {
  const auto* p = dynamic_cast<const brdfbake::ParameterError*>(&e);
  return p ? p->Render(FlagOf) : std::string(e.what());
}

// One strict grammar for every number on the command line: a decimal
// number (optional sign, digits, optional fraction and exponent; no hex, no
// "nan", no empty string, nothing after it), or a decimal integer for the
// integer options. Messages quote the value as given.
bool IsDecimalNumber(const std::string& t) {
  size_t i = 0;
  if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
  size_t digits = 0;
  while (i < t.size() && std::isdigit(static_cast<unsigned char>(t[i]))) ++i, ++digits;
  if (i < t.size() && t[i] == '.') {
    ++i;
    while (i < t.size() && std::isdigit(static_cast<unsigned char>(t[i]))) ++i, ++digits;
  }
  if (digits == 0) return false;
  if (i < t.size() && (t[i] == 'e' || t[i] == 'E')) {
    ++i;
    if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
    size_t exp_digits = 0;
    while (i < t.size() && std::isdigit(static_cast<unsigned char>(t[i]))) ++i, ++exp_digits;
    if (exp_digits == 0) return false;
  }
  return i == t.size();
}

bool IsDecimalInteger(const std::string& t) {
  size_t i = (!t.empty() && (t[0] == '+' || t[0] == '-')) ? 1 : 0;
  if (i == t.size()) return false;
  for (; i < t.size(); ++i) {
    if (!std::isdigit(static_cast<unsigned char>(t[i]))) return false;
  }
  return true;
}

double ParseNumber(const std::string& opt, const std::string& text) {
  if (!IsDecimalNumber(text)) Bad(opt + ": '" + text + "' is not a decimal number");
  errno = 0;
  const double v = std::strtod(text.c_str(), nullptr);
  // Underflow gives a subnormal or 0, which the option's range then judges.
  if (std::isinf(v)) Bad(opt + ": '" + text + "' is beyond the largest double");
  return v;
}

// A number, or "inf" (the gamma of std, the end of a gamma range).
double ParseNumberOrInf(const std::string& opt, const std::string& text) {
  if (text == "inf") return std::numeric_limits<double>::infinity();
  return ParseNumber(opt, text);
}

// CLI11 checks of the numeric options, run on the text before conversion.
const CLI::Validator kNumber(
    [](std::string& t) -> std::string {
      return IsDecimalNumber(t) ? "" : "'" + t + "' is not a decimal number";
    },
    "NUMBER");
const CLI::Validator kInteger(
    [](std::string& t) -> std::string {
      return IsDecimalInteger(t) ? "" : "'" + t + "' is not a decimal integer";
    },
    "INTEGER");

uint64_t ParseSeed(const std::string& opt, const std::string& text) {
  bool digits = !text.empty();
  for (char c : text) digits &= c >= '0' && c <= '9';
  // Leading zeros do not count towards the 20 digits of 2^64 - 1.
  const size_t first = text.find_first_not_of('0');
  const std::string significant = first == std::string::npos ? "0" : text.substr(first);
  errno = 0;
  const unsigned long long v =
      digits && significant.size() <= 20 ? std::strtoull(significant.c_str(), nullptr, 10) : 0;
  if (!digits || significant.size() > 20 || errno == ERANGE) {
    Bad(opt + ": '" + text + "' is not an integer in [0, 18446744073709551615]");
  }
  return v;
}

std::array<double, 3> ParseRgb(const std::string& opt, const std::string& text) {
  std::vector<double> v;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) v.push_back(ParseNumber(opt, item));
  if (v.size() == 1) return {v[0], v[0], v[0]};
  if (v.size() != 3) Bad(opt + ": expected one value or three (r,g,b), got '" + text + "'");
  return {v[0], v[1], v[2]};
}

std::vector<std::string> SplitComma(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) out.push_back(item);
  return out;
}

// Creates the output directory (and its parents) before any work is done.
void MakeOutputDirectory(const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir)) {
    Bad("-o: cannot create directory '" + dir + "'" + (ec ? ": " + ec.message() : ""));
  }
}

// The one rule for outputs: missing directories on the way are created
// (as for -o DIR of presets, scenes and reports), before the work.
void MakeParentDirectory(const std::string& path) {
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  if (!parent.empty()) MakeOutputDirectory(parent.string());
}

bool Given(const CLI::App* app, const char* option) {
  const CLI::Option* o = app->get_option_no_throw(option);
  return o != nullptr && o->count() > 0;
}

// `flag` (given) names a parameter `model` (of `kind`) does not take:
// "--gamma: model ggx has no gamma (only std does)".
void CheckOption(const CLI::App* app, const char* flag, brdfbake::ModelKind kind, brdfbake::ModelOption option,
                 const std::string& model) {
  if (!Given(app, flag) || brdfbake::ModelTakes(kind, option)) return;
  static const char* const kWhat[] = {"gamma", "rotation", "sheen visibility", "index of refraction"};
  const std::vector<std::string> takers = brdfbake::ModelsTaking(option);
  std::string only = brdfbake::JoinList(takers, " and ") + (takers.size() == 1 ? " does" : " do");
  if (option == brdfbake::ModelOption::kIor) only += "; the Fresnel factor's is --eta";
  Bad(std::string(flag) + ": model " + model + " has no " + kWhat[static_cast<int>(option)] + " (only " + only +
      ")");
}

// Options shared by every command that names a model.
struct ModelOptions {
  std::string model = "ggx";
  std::string alpha, alpha_x, alpha_y, roughness;
  std::string gamma = "2";
  std::string visibility = "conty-kulla";
  std::string ior = "1.5";
  double theta_x_deg = 0, theta_y_deg = 0, theta_z_deg = 0;
  CLI::App* app = nullptr;

  void Add(CLI::App* a) {
    app = a;
    app->add_option("--model,-m", model,
                    "ggx | beckmann | std | ellipsoid | sel | charlie (sheen) | disney-diffuse, or "
                    "ggx-aniso, ggx-glass (E, E_avg only)")
        ->capture_default_str();
    app->add_option("--ior", ior,
                    "ggx-glass: relative index of refraction eta in [0.01, 100] of the medium below "
                    "the view; below 1 light leaves the denser medium (total internal reflection)")
        ->capture_default_str();
    app->add_option("--visibility", visibility,
                    "charlie: neubelt | conty-kulla | neubelt-clamped | conty-kulla-clamped | enterprise-pbr")
        ->capture_default_str();
    app->add_option("--alpha", alpha, "NDF width alpha (both axes), in (0, 1e4]; default 0.25")
        ->check(kNumber);
    app->add_option("--alpha-x", alpha_x, "alpha along the tangent")
        ->check(kNumber);
    app->add_option("--alpha-y", alpha_y, "alpha along the bitangent")
        ->check(kNumber);
    app->add_option("--roughness,-r", roughness, "perceptual roughness r, alpha = r^2 (both axes)");
    app->add_option("--gamma", gamma, "std: tail parameter in [1.500001, inf]; 'inf' is Beckmann")
        ->capture_default_str();
    app->add_option("--theta-x", theta_x_deg, "ellipsoid/sel: rotation about x, degrees")
        ->check(kNumber);
    app->add_option("--theta-y", theta_y_deg, "ellipsoid/sel: rotation about y, degrees")
        ->check(kNumber);
    app->add_option("--theta-z", theta_z_deg, "ellipsoid/sel: rotation about z, degrees")
        ->check(kNumber);
  }

  // `mirror_ok`: --roughness 0 (alpha 0, a mirror, as the tables hold it at
  // r = 0: E = 1) is accepted.
  // `ior_ok`: --ior names the dielectric shape of gen_schlick_ior_s (eval)
  // rather than a ggx-glass interface.
  brdfbake::ModelParams Get(bool mirror_ok = false, bool ior_ok = false) const {
    brdfbake::ModelParams p;
    p.kind = brdfbake::ParseModelKind(model);
    CheckOption(app, "--gamma", p.kind, brdfbake::ModelOption::kGamma, model);
    for (const char* t : {"--theta-x", "--theta-y", "--theta-z"}) {
      CheckOption(app, t, p.kind, brdfbake::ModelOption::kRotation, model);
    }
    CheckOption(app, "--visibility", p.kind, brdfbake::ModelOption::kVisibility, model);
    p.visibility = brdfbake::ParseSheenVisibility(visibility);
    if (!ior_ok) CheckOption(app, "--ior", p.kind, brdfbake::ModelOption::kIor, model);
    p.ior = ParseNumber("--ior", ior);
    if (!(p.ior >= 0.01 && p.ior <= 100)) {
      Bad("--ior must lie in [0.01, 100] (the relative index of refraction; below 1 light leaves "
          "the denser medium; got " + ior + ")");
    }
    double a = 0.25;
    if (!alpha.empty() && !roughness.empty()) Bad("--alpha and --roughness are exclusive");
    if (!alpha.empty()) a = ParseNumber("--alpha", alpha);
    bool mirror = false;
    const bool diffuse = p.kind == brdfbake::ModelKind::kDisneyDiffuse;
    if (!roughness.empty() && diffuse) {
      // r itself is the diffuse lobe's parameter: r = 0 is no mirror.
      const double r = ParseNumber("--roughness", roughness);
      if (!(r >= 0 && r <= 1)) Bad("--roughness of disney-diffuse must lie in [0, 1] (got " + roughness + ")");
      a = r * r;
    } else if (!roughness.empty()) {
      const double r = ParseNumber("--roughness", roughness);
      mirror = r == 0 && mirror_ok && p.kind != brdfbake::ModelKind::kEllipsoid;
      if (!mirror && (!(r > 0) || !(r <= 100))) {
        Bad(std::string("--roughness must lie in (0, 100] (alpha = r^2 <= 1e4)") +
            (r == 0 ? "; 0, the mirror, is taken by the table quantities E, dfg and E_avg alone" : ""));
      }
      a = mirror ? 0.0 : brdfbake::AlphaFromRoughness(r);
    }
    p.alpha_x = alpha_x.empty() ? a : ParseNumber("--alpha-x", alpha_x);
    p.alpha_y = alpha_y.empty() ? a : ParseNumber("--alpha-y", alpha_y);
    p.gamma = ParseNumberOrInf("--gamma", gamma);
    p.theta_x = theta_x_deg * kDegree;
    p.theta_y = theta_y_deg * kDegree;
    p.theta_z = theta_z_deg * kDegree;
    brdfbake::ModelParams check = p;
    if (p.kind == brdfbake::ModelKind::kGgxAniso) {
      // A table model: its widths come from --roughness and --anisotropy.
      if (!alpha_x.empty() || !alpha_y.empty()) {
        Bad("--alpha-x/--alpha-y: ggx-aniso takes --roughness and --anisotropy");
      }
      check.kind = brdfbake::ModelKind::kGgx;
    }
    if (p.kind == brdfbake::ModelKind::kGgxGlass && (!alpha_x.empty() || !alpha_y.empty())) {
      Bad("--alpha-x/--alpha-y: ggx-glass is isotropic; give --roughness or --alpha");
    }
    if (mirror) check.alpha_x = check.alpha_y = 1.0;  // the widths stand for no NDF
    brdfbake::ValidateModelParams(check);
    return p;
  }
};

struct FresnelOptions {
  std::string kind = "one";
  std::string f0 = "0.04", n = "0.2,0.92,1.1", k = "3.9,2.45,2.14";
  std::string eta = "1.5";
  CLI::App* app = nullptr;

  void Add(CLI::App* a) {
    app = a;
    app->add_option("--fresnel", kind, "one | schlick | dielectric | conductor")->capture_default_str();
    app->add_option("--f0", f0, "schlick: F0, one value or r,g,b")->capture_default_str();
    app->add_option("--eta", eta, "dielectric: relative index of refraction")->capture_default_str();
    app->add_option("--n", n, "conductor: real part of the index, r,g,b")->capture_default_str();
    app->add_option("--k", k, "conductor: imaginary part of the index, r,g,b")->capture_default_str();
  }

  Fresnel Get() const {
    const struct { const char* option; const char* kind; } owners[] = {
        {"--f0", "schlick"}, {"--eta", "dielectric"}, {"--n", "conductor"}, {"--k", "conductor"}};
    for (const auto& o : owners) {
      if (Given(app, o.option) && kind != o.kind) {
        Bad(std::string(o.option) + " applies to --fresnel " + o.kind + " only (got --fresnel " + kind + ")");
      }
    }
    if (kind == "one") return Fresnel::One();
    if (kind == "schlick") return Fresnel::Schlick(ParseRgb("--f0", f0));
    if (kind == "dielectric") return Fresnel::Dielectric(ParseNumber("--eta", eta));
    if (kind == "conductor") return Fresnel::Conductor(ParseRgb("--n", n), ParseRgb("--k", k));
    Bad("--fresnel: unknown model '" + kind + "' (expected one, schlick, dielectric or conductor)");
  }
};

Masking ParseMasking(const std::string& s) {
  if (s == "height-correlated") return Masking::kHeightCorrelated;
  if (s == "separable") return Masking::kSeparable;
  Bad("--masking: unknown variant '" + s + "' (expected height-correlated or separable)");
}

std::string VersionText() {
  std::string s = std::string("brdfbake ") + BRDFBAKE_VERSION + "\nSIMD target in use: " +
                  brdfbake::BestTarget() + "\ncompiled targets:";
  for (const std::string& t : brdfbake::CompiledTargets()) s += " " + t;
  return s;
}

std::string ModelsHelp() {
  std::string s = "Models:\n";
  for (const brdfbake::ModelInfo& m : brdfbake::ModelsDescribed()) {
    s += std::string("  ") + brdfbake::ModelName(m.kind) + ": " + m.parameters + "\n      " + m.source + "\n";
  }
  s += "Quantities (--quantity, comma-separated):\n"
       "  D, pdf      swept direction is the microfacet normal m (pdf: density of the\n"
       "              model's visible-normal sampler for the view wo, per steradian)\n"
       "  Lambda, G1  swept direction is w\n"
       "  G2, brdf    swept direction is the light wi; the view wo is fixed by --mu-o, --phi-o\n"
       "  K           swept direction is w (model sel only)\n"
       "  E, dfg      the tables' values (same integrator as bake), with their error;\n"
       "  E_avg       the swept direction is the view; --sweep roughness sweeps r with the\n"
       "              view at --mu-o; without --sweep/--from/--to/--count, one row at\n"
       "              (--mu-o, --roughness)\n";
  return s;
}

// "WxH" (or "N" for a one-axis table) as integers in [1, 8192].
std::vector<int> ParseSize(const std::string& text, size_t axes, const char* form) {
  std::vector<int> out;
  std::string item;
  std::stringstream ss(text);
  bool ok = !text.empty() && text.back() != 'x';
  while (ok && std::getline(ss, item, 'x')) {
    bool digits = !item.empty() && item.size() <= 5;
    for (char c : item) digits &= c >= '0' && c <= '9';
    const int v = digits ? std::atoi(item.c_str()) : 0;
    ok = digits && v >= 1 && v <= 8192;
    out.push_back(v);
  }
  if (!ok || out.size() != axes) {
    Bad(std::string("--size: expected ") + form + " with each entry an integer in [1, 8192] (got '" +
        text + "')");
  }
  return out;
}

// The options with which the command line overrides a scene's settings
// (plan and bake SCENE). `full`: all of them (plan); otherwise the two that
// bake has no other use for.
void AddSceneOverrides(CLI::App* app, std::string* preset, std::string* format, std::string* pixel,
                       std::string* shader, std::string* max_size, std::string* error_target, bool full) {
  if (full) {
    app->add_option("--preset", *preset, "bake the scene's tables in this engine's layouts and containers");
    app->add_option("--format", *format, "the container of every table (exr | header | inc | js | ktx2 | dds), or "
                                         "another container the --preset engine loads");
    app->add_option("--pixel", *pixel, "float | half | unorm16 (dds only), instead of the scene's");
    app->add_option("--shader", *shader, "lookup functions beside each table: glsl, hlsl, wgsl, comma-separated");
  }
  app->add_option("--max-size", *max_size, "scenes: entries per axis at most, instead of the scene's max_lut_size")
      ->check(kInteger);
  app->add_option("--error-target", *error_target,
                  "scenes: max abs error of a bilinear lookup, instead of the scene's error_target")
      ->check(kNumber);
}

// The overrides given, in a fixed order, for ApplySceneOverrides.
brdfbake::SceneOverrides SceneOverridesGiven(const CLI::App* app, const std::string& preset, const std::string& format,
                                             const std::string& pixel, const std::string& shader,
                                             const std::string& max_size, const std::string& error_target) {
  brdfbake::SceneOverrides o;
  const std::pair<const char*, const std::string*> all[] = {{"--preset", &preset}, {"--format", &format},
                                                            {"--pixel", &pixel},   {"--shader", &shader},
                                                            {"--max-size", &max_size}, {"--error-target", &error_target}};
  for (const auto& [option, value] : all) {
    if (Given(app, option)) o.push_back({option, *value});
  }
  return o;
}

struct BakeOptions {
  std::string table, model = "ggx", gamma = "2", visibility = "conty-kulla", size = "32x32",
      warp = "linear", range;
  std::string placement = "edges", masking = "height-correlated", integrator = "quadrature";
  std::string pixel = "float", output, seed = "1", preset, format, shader, scene, symbol;
  std::string channels = "named";
  std::string target = "best";
  std::string max_size, error_target;  // scene bakes only
  std::string alpha_x = "0.25", alpha_y = "0.25";  // ellipsoid
  double theta_x_deg = 0, theta_y_deg = 0, theta_z_deg = 0;
  int samples = 0, threads = 0;
  double tolerance = brdfbake::BakeSpec().tolerance;
  bool complement = false, error_channel = false, inverse = false;
  std::string part = "both";  // ggx-glass
  bool for_report = false;
  CLI::App* app = nullptr;

  void Add(CLI::App* a, bool report) {
    app = a;
    for_report = report;
    app->add_option("--table,-t", table, brdfbake::SpellParameters(brdfbake::TableKindsHelp(), FlagOf));
    app->add_option("--model,-m", model,
                    "ggx | beckmann | std | ggx-aniso (anisotropic GGX, KHR_materials_anisotropy) | "
                    "ellipsoid (one material: --alpha-x/-y, --theta-x/-y/-z) | sel (--table sel_norm) | "
                    "charlie (sheen, --visibility) | disney-diffuse (E, E_avg) | ggx-glass (rough "
                    "dielectric, E and E_avg over an ior axis)")
        ->capture_default_str();
    app->add_option("--visibility", visibility,
                    "charlie: neubelt (1 / (4 (NoL + NoV - NoL NoV))) | conty-kulla (the fitted Lambda) | "
                    "neubelt-clamped, conty-kulla-clamped (V capped at 1) | enterprise-pbr (the refined fit)")
        ->capture_default_str();
    app->add_option("--gamma", gamma,
                    "std: tail parameter in [1.500001, inf]; without it, a third --size entry bakes "
                    "over a gamma axis")
        ->capture_default_str();
    app->add_option("--size", size,
                    "mu x roughness entries, default " + size + " (E_avg: N roughness entries, default " +
                        (report ? "16" : "32") + "); std without --gamma: WxHxD (E_avg: NxD) adds D "
                        "gamma slices over [1.501, inf]; ggx-aniso: mu x phi_o x roughness x anisotropy "
                        "(E_avg: roughness x anisotropy); ellipsoid: mu x phi_o; sel_norm: alpha_x x alpha_y; "
                        "ggx-glass: mu x roughness x ior, default 32x32x32 (E_avg: roughness x ior); gen_schlick_s, "
                        "gen_schlick_ior_s: mu x roughness x exponent or ior, default 16x16x16");
    app->add_option("--warp", warp,
                    "linear | square | sqrt, or per axis: mu=linear,roughness=square "
                    "(the gamma axis: gamma=tail, its only warp; the ior axis: ior=fresnel-z, the "
                    "default, ior=linear, or ior=two-sided for both sides of the interface on one axis; "
                    "the exponent axis: exponent=schlick-z, the default, or exponent=linear)")
        ->capture_default_str();
    app->add_option("--range", range,
                    "axis ranges within [0, 1], e.g. mu=1e-4:1,roughness=0.05:1; "
                    "gamma=min:max within [1.500001, inf], default 1.501:inf; phi_o in radians within "
                    "[0, pi/2] (ggx-aniso) or [0, 2 pi] (ellipsoid); ior=min:max within [1, 100], "
                    "default 1:3 (ggx-glass); exponent=min:max, either way, default inf:0 (Cycles': z = 5 / "
                    "(exponent + 5) = k / 15, baked within [0.0505, 49995])");
    app->add_option("--placement", placement, "edges | centers (texel centres for GPU bilinear)")
        ->capture_default_str();
    app->add_option("--masking", masking, "height-correlated | separable")->capture_default_str();
    app->add_option("--threads", threads, "worker threads, at most 1024; 0 = all cores")
        ->capture_default_str()
        ->check(kInteger);
    app->add_option("--seed", seed, "seed of the randomized integrators, in [0, 2^64 - 1]")
        ->capture_default_str();
    if (for_report) {
      app->add_option("-o,--output", output, "output directory (created if missing)")->required();
      return;
    }
    app->add_option("--alpha-x", alpha_x, "ellipsoid: width along x")->capture_default_str()
        ->check(kNumber);
    app->add_option("--alpha-y", alpha_y, "ellipsoid: width along y")->capture_default_str()
        ->check(kNumber);
    app->add_option("--theta-x", theta_x_deg, "ellipsoid: rotation about x, degrees")
        ->check(kNumber);
    app->add_option("--theta-y", theta_y_deg, "ellipsoid: rotation about y, degrees")
        ->check(kNumber);
    app->add_option("--theta-z", theta_z_deg, "ellipsoid: rotation about z, degrees")
        ->check(kNumber);
    app->add_option("--integrator", integrator, "quadrature | qmc | mc | engine")->capture_default_str();
    app->add_option("--samples", samples, "max nodes per dimension (quadrature) or samples per texel; 0 = default")
        ->check(kInteger);
    app->add_option("--target", target,
                    "the SIMD target of the integrand (AVX3, AVX2, SSE4, SSSE3, SCALAR, best), "
                    "or scalar for the double scalar reference")
        ->capture_default_str();
    app->add_option("--tolerance", tolerance, "quadrature: refine until two rules agree to this")
        ->capture_default_str()
        ->check(kNumber);
    app->add_option("--pixel", pixel, "float | half | unorm16 (dds, png) | unorm8 (png)")->capture_default_str();
    app->add_flag("--complement", complement,
                  "E: store 1-E; E_avg: store 1-E_avg; dfg: add a 1-E channel");
    app->add_flag("--error-channel", error_channel, "add a per-texel 'error' channel");
    app->add_flag("--inverse", inverse,
                  "ggx-glass: light leaving the medium (the view inside it): each ior slice is baked at "
                  "eta = 1/ior, with total internal reflection (Cycles' inverse tables)");
    app->add_option("--part", part,
                    "ggx-glass: both (reflection plus refraction) | reflection (the energy the interface "
                    "reflects, weighted by F) | transmission (the refraction alone, weighted by 1 - F) | "
                    "transmission-schlick (the refraction without F, weighted by 1 - (1 - wo.h)^5: EEVEE's "
                    "btdf_ggx; the ior axis may reach inf)")
        ->capture_default_str();
    app->add_option("-o,--output", output,
                    "output file: .exr, .h/.hpp/.inc, .js/.mjs, .ktx2 or .dds (with --preset: a "
                    "directory, default .)");
    app->add_option("scene", scene, "a scene (.toml, .gltf, .glb): bake exactly the tables it needs into -o DIR");
    app->add_option("--preset", preset, "an engine's tables as its shader samples them: " + PresetNames());
    app->add_option("--format", format,
                    "exr | header | inc | js | ktx2 | dds (default: from the extension; with --preset: a "
                    "container the engine also loads)");
    app->add_option("--shader", shader,
                    "also write lookup functions beside each table: glsl, hlsl, wgsl, or several "
                    "comma-separated");
    app->add_option("--symbol", symbol,
                    "the array's name in .h/.js files and the lookup's name (default "
                    "brdfbake_<model>_<table>, e.g. brdfbake_ggx_E)");
    AddSceneOverrides(app, &preset, &format, &pixel, &shader, &max_size, &error_target, false);
    app->add_option("--channels", channels,
                    "named (E, dfg.scale, ...) | rgba: channels named R, G, B, A and padded to four "
                    "(B = 0, A = 1) for loaders that know only those; the meanings stay in the header")
        ->capture_default_str();
  }

  brdfbake::BakeSpec Get() const {
    brdfbake::BakeSpec spec;
    if (!for_report) spec.inverse = inverse;
    if (part == "reflection") {
      spec.part = brdfbake::DielectricPart::kReflection;
    } else if (part == "transmission") {
      spec.part = brdfbake::DielectricPart::kTransmission;
    } else if (part == "transmission-schlick") {
      spec.part = brdfbake::DielectricPart::kTransmissionSchlick;
    } else if (part != "both") {
      Bad("--part: unknown part '" + part +
          "' (expected both, reflection, transmission or transmission-schlick)");
    }
    if (table.empty()) Bad("--table: required (E, E_avg or dfg), unless --preset names the tables");
    spec.table = brdfbake::ParseTable(table);
    spec.model.kind = brdfbake::ParseModelKind(model);
    CheckOption(app, "--gamma", spec.model.kind, brdfbake::ModelOption::kGamma, model);
    spec.model.gamma = ParseNumberOrInf("--gamma", gamma);
    CheckOption(app, "--visibility", spec.model.kind, brdfbake::ModelOption::kVisibility, model);
    spec.model.visibility = brdfbake::ParseSheenVisibility(visibility);
    if (Given(app, "--masking") && !brdfbake::ModelTakesMasking(spec.model.kind)) {
      const bool visibility = brdfbake::ModelTakes(spec.model.kind, brdfbake::ModelOption::kVisibility);
      Bad("--masking: model " + model + " has no Smith masking" +
          (visibility ? " (its visibility is --visibility)" : ""));
    }
    spec.masking = ParseMasking(masking);
    spec.integrator = brdfbake::ParseIntegrator(integrator);
    if (Given(app, "--tolerance") && spec.integrator != brdfbake::IntegratorKind::kQuadrature) {
      Bad("--tolerance applies to the quadrature integrator only (got --integrator " + integrator + ")");
    }
    if (target == "scalar") {
      spec.simd = false;
    } else {
      try {
        brdfbake::ForceTarget(target);
      } catch (const std::invalid_argument& e) {
        // The bake also takes scalar, the double scalar reference.
        std::string what = std::string("--target: ") + e.what();
        const std::string best = ", or best)";
        const size_t at = what.rfind(best);
        if (at != std::string::npos && at + best.size() == what.size()) {
          what = what.substr(0, at) + ", best, or scalar for the double scalar reference)";
        }
        Bad(what);
      }
    }
    spec.samples = samples;
    spec.tolerance = tolerance;
    spec.seed = ParseSeed("--seed", seed);
    if (Given(app, "--seed") && spec.integrator == brdfbake::IntegratorKind::kQuadrature) {
      Bad("--seed applies to the qmc, mc and engine integrators (got --integrator " + integrator + ")");
    }
    spec.complement = complement;
    spec.error_channel = error_channel;
    spec.threads = threads;
    if (pixel != "float" && pixel != "half" && ((pixel != "unorm16" && pixel != "unorm8") || for_report)) {
      Bad("--pixel: expected float, half" + std::string(for_report ? "" : ", unorm16 or unorm8") + ", got '" +
          pixel + "'");
    }
    spec.half = pixel == "half";
    const bool eavg = spec.table == brdfbake::TableKind::kEavg;
    // A model taking gamma (std) without --gamma takes one more --size
    // entry: the gamma axis.
    const bool gamma_ok =
        brdfbake::ModelTakes(spec.model.kind, brdfbake::ModelOption::kGamma) && !Given(app, "--gamma");
    const bool given = Given(app, "--size");
    const size_t entries = !given || size.empty() ? 0 : size_t(std::count(size.begin(), size.end(), 'x')) + 1;
    const bool gen_schlick = spec.GenSchlick();
    const bool aniso = spec.model.kind == brdfbake::ModelKind::kGgxAniso;
    const bool glass = spec.model.kind == brdfbake::ModelKind::kGgxGlass;
    const bool sel = spec.table == brdfbake::TableKind::kSelNorm;
    const bool ellipsoid = spec.model.kind == brdfbake::ModelKind::kEllipsoid;
    // E, dfg or E_avg over mu and roughness, with an optional gamma axis.
    const bool plain_table = !aniso && !glass && !gen_schlick && !sel && !ellipsoid;
    if (ellipsoid && eavg && given) Bad("--size: the ellipsoid's E_avg is one value (no axes)");
    if (entries == (eavg ? 2u : 3u) && !gamma_ok && !aniso && !glass && !gen_schlick) {
      Bad("--size: expected " + brdfbake::SizeForm(spec) + " (got '" + size +
          "'); the gamma axis, one more entry, exists only for std without --gamma");
    }
    const bool gamma_axis = gamma_ok && entries == (eavg ? 2u : 3u);
    if (gamma_axis) spec.gamma.size = 1;  // an axis of the table now; its size comes from --size
    if (!for_report) {
      for (const char* o : {"--alpha-x", "--alpha-y", "--theta-x", "--theta-y", "--theta-z"}) {
        if (Given(app, o) && !ellipsoid) {
          Bad(std::string(o) + ": only ellipsoid tables take a material's widths and angles");
        }
      }
    }
    if (ellipsoid) {
      spec.model.alpha_x = ParseNumber("--alpha-x", alpha_x);
      spec.model.alpha_y = ParseNumber("--alpha-y", alpha_y);
      spec.model.theta_x = theta_x_deg * kDegree;
      spec.model.theta_y = theta_y_deg * kDegree;
      spec.model.theta_z = theta_z_deg * kDegree;
      spec.phi.max = 2 * brdfbake::kPi<double>;  // no azimuthal symmetry
    }
    if (plain_table && eavg && given && size.find('x') != std::string::npos && !gamma_axis) {
      Bad("--size: E_avg has one axis (roughness): expected N, e.g. --size 32 (got '" + size + "')");
    }
    // The table's axes in --size order (brdfbake::TableAxes), and their sizes.
    const std::vector<brdfbake::Axis*> named = brdfbake::TableAxes(&spec);
    std::vector<int> n;
    if (given) {
      std::string form = brdfbake::SizeForm(spec);
      if (plain_table && gamma_ok && !gamma_axis && !eavg) form += " or WxHxD (x gamma)";
      n = ParseSize(size, named.size(), form.c_str());
    } else {
      n = brdfbake::DefaultSizes(spec);
      // report's own defaults: a smaller probe of the same table.
      if (for_report && plain_table) n.assign(n.size(), 16);
      if (for_report && aniso && !eavg) n = {12, 7, 10, 8};
    }
    for (size_t i = 0; i < named.size(); ++i) named[i]->size = n[i];
    const brdfbake::Placement pl = brdfbake::ParsePlacement(placement);
    for (brdfbake::Axis* a : {&spec.mu, &spec.roughness, &spec.gamma, &spec.ior, &spec.exponent, &spec.phi,
                              &spec.anisotropy, &spec.alpha_x, &spec.alpha_y}) {
      a->placement = pl;
    }
    // Per-axis settings: "value" for every view and lobe axis of the table
    // (not gamma, ior or exponent), or "axis=value"; each axis at most once.
    std::vector<brdfbake::Axis*> axes;
    for (brdfbake::Axis* a : named) {
      if (!brdfbake::ParameterAxis(*a)) axes.push_back(a);
    }
    auto per_axis = [&](const char* opt, const std::string& text, bool plain_ok,
                        const std::function<void(brdfbake::Axis*, const std::string&)>& set) {
      std::vector<std::string> seen;
      for (const std::string& item : SplitComma(text)) {
        const size_t eq = item.find('=');
        std::vector<brdfbake::Axis*> targets;
        std::string value = item;
        if (eq == std::string::npos) {
          if (!plain_ok) Bad(std::string(opt) + ": expected axis=min:max, got '" + item + "'");
          targets = axes;
        } else {
          const std::string name = item.substr(0, eq);
          value = item.substr(eq + 1);
          for (brdfbake::Axis* a : named) {
            if (a->name == name) targets.push_back(a);
          }
          if (targets.empty()) {
            std::string expected;
            for (size_t k = 0; k < named.size(); ++k) {
              expected += (k == 0 ? "" : k + 1 == named.size() ? " or " : ", ") + named[k]->name;
            }
            if (named.empty()) expected = "none (E_avg is one value)";
            Bad(std::string(opt) + ": " +
                (eavg && name == "mu" ? std::string("E_avg has no mu axis (its one axis is roughness)")
                 : name == "gamma"
                     ? std::string("no gamma axis (std without --gamma and a third --size entry has one)")
                 : name == "ior" ? std::string("no ior axis (only ggx-glass and gen_schlick_ior_s have one)")
                 : name == "exponent" ? std::string("no exponent axis (only gen_schlick_s has one)")
                                 : "unknown axis '" + name + "' (expected " + expected + ")"));
          }
        }
        for (brdfbake::Axis* a : targets) {
          for (const std::string& s : seen) {
            if (s == a->name) Bad(std::string(opt) + ": the " + a->name + " axis is given twice");
          }
          seen.push_back(a->name);
          set(a, value);
        }
      }
    };
    per_axis("--warp", warp, true,
             [](brdfbake::Axis* a, const std::string& v) { a->warp = brdfbake::ParseWarp(v); });
    if (!range.empty()) {
      per_axis("--range", range, false, [](brdfbake::Axis* a, const std::string& v) {
        const size_t colon = v.find(':');
        if (colon == std::string::npos) Bad("--range: expected " + a->name + "=min:max, got '" + v + "'");
        a->min = ParseNumberOrInf("--range", v.substr(0, colon));
        a->max = ParseNumberOrInf("--range", v.substr(colon + 1));
      });
    }
    if (output.empty()) Bad("-o: an output file is required");
    brdfbake::ValidateBakeSpec(spec);
    return spec;
  }

  static std::string PresetNames() {
    std::string names;
    for (const brdfbake::Preset& p : brdfbake::Presets()) names += (names.empty() ? "" : ", ") + p.name;
    return names;
  }
};

// A progress bar on stderr when it is a terminal and the work has taken
// more than a second: percent, elapsed and remaining time.
class Progress {
 public:
  Progress() : tty_(::isatty(2) != 0), start_(std::chrono::steady_clock::now()) {}
  void operator()(int64_t done, int64_t total) {
    if (!tty_) return;
    const auto now = std::chrono::steady_clock::now();
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    if (elapsed < 1.0) return;
    std::lock_guard<std::mutex> lock(mu_);
    if (done < total && std::chrono::duration<double>(now - last_).count() < 0.1) return;
    last_ = now;
    const int width = 40;
    total = std::max<int64_t>(1, total);
    const int filled = static_cast<int>(width * done / total);
    const double remaining = done > 0 ? elapsed * double(total - done) / double(done) : 0.0;
    std::fprintf(stderr, "\r[%.*s%*s] %3d%% %.1fs elapsed, %.1fs left ", filled,
                 "========================================", width - filled, "",
                 static_cast<int>(100 * done / total), elapsed, remaining);
    shown_ = true;
  }
  void Finish() {
    if (shown_) std::fprintf(stderr, "\n");
  }
  // Finish, then start over for the next stage.
  void Restart() {
    Finish();
    shown_ = false;
    start_ = std::chrono::steady_clock::now();
  }

 private:
  bool tty_;
  bool shown_ = false;
  std::chrono::steady_clock::time_point start_, last_;
  std::mutex mu_;
};

// A scene plan's progress on stderr when it is a terminal and the plan has
// taken more than a second: the candidate just measured and the time so
// far, on one line rewritten in place.
class PlanProgress {
 public:
  PlanProgress() : tty_(::isatty(2) != 0), start_(std::chrono::steady_clock::now()) {}
  void operator()(const std::string& line) {
    if (!tty_) return;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    if (elapsed < 1.0) return;
    std::fprintf(stderr, "\r\x1b[Kplanning, %.0fs: %s", elapsed, OneLine(line).substr(0, 100).c_str());
    shown_ = true;
  }
  void Finish() {
    if (shown_) std::fprintf(stderr, "\r\x1b[K");
  }

 private:
  bool tty_;
  bool shown_ = false;
  std::chrono::steady_clock::time_point start_;
};

// `image`: the arrangement written when it is not the table's own EXR (its
// pixel type, hence its claimed error, may differ).
void PrintWrote(const std::string& path, const brdfbake::Table& table, const std::string& what,
                const brdfbake::Image* image = nullptr) {
  const double claim = image ? image->max_abs_error : table.max_abs_error;
  const int w = image ? image->width : table.width, h = image ? image->height : table.height;
  std::string dims = std::to_string(w) + "x" + std::to_string(h);
  if (table.spec.HasGammaAxis()) {
    dims += " (" + std::to_string(table.spec.gamma.size) + " gamma slices of " +
            std::to_string(h / table.spec.gamma.size) + " rows)";
  }
  if (table.spec.Glass() && table.spec.table == brdfbake::TableKind::kE) {
    dims += " (" + std::to_string(table.spec.ior.size) + " ior slices of " +
            std::to_string(h / table.spec.ior.size) + " rows" + (table.spec.inverse ? ", inverse" : "") + ")";
  }
  if (table.spec.GenSchlick()) {
    const brdfbake::Axis& a = table.axes.back();
    dims += " (" + std::to_string(a.size) + " " + a.name + " slices of " + std::to_string(h / a.size) + " rows)";
  }
  std::printf("wrote %s: %s %s %s, %s integrator, baked in %.3f s, max abs error %.2e\n",
              OneLine(path).c_str(), what.c_str(), table.spec.model.name(), dims.c_str(),
              brdfbake::IntegratorName(table.spec.integrator), table.seconds, claim);
}

// The languages of --shader ("glsl,hlsl"), each once.
std::vector<brdfbake::ShaderLanguage> ShaderLanguages(const std::string& list) {
  std::vector<brdfbake::ShaderLanguage> langs;
  if (list.empty()) return langs;
  std::stringstream ss(list);
  for (std::string item; std::getline(ss, item, ',');) {
    const brdfbake::ShaderLanguage l = brdfbake::ParseShaderLanguage(item);
    if (std::find(langs.begin(), langs.end(), l) != langs.end()) Bad("--shader: '" + item + "' is given twice");
    langs.push_back(l);
  }
  if (list.back() == ',') Bad("--shader: an empty language after the last comma");
  return langs;
}

int RunPreset(const BakeOptions& opts) {
  const brdfbake::Preset& preset = brdfbake::FindPreset(opts.preset);
  // A preset fixes the tables; only how they are computed and where they go
  // may be chosen.
  for (const char* o : {"--table", "--model", "--gamma", "--visibility", "--size", "--warp", "--range",
                        "--placement", "--masking", "--pixel", "--complement", "--error-channel", "--integrator",
                        "--samples", "--seed", "--symbol", "--channels", "--inverse", "--part"}) {
    if (Given(opts.app, o)) Bad(std::string(o) + ": fixed by --preset " + preset.name);
  }
  const std::string dir = opts.output.empty() ? "." : opts.output;
  std::error_code ec;
  const std::string ext = std::filesystem::path(dir).extension().string();
  if (!ext.empty() && !std::filesystem::is_directory(dir, ec)) {
    Bad("-o: with --preset, -o names a directory (got '" + dir + "'); the preset names its files");
  }
  brdfbake::PresetRun run;
  run.dir = dir;
  run.format = opts.format;
  run.shaders = ShaderLanguages(opts.shader);
  const brdfbake::OutputSet set = brdfbake::PresetOutputs(preset, run);
  MakeOutputDirectory(dir);
  brdfbake::CheckOutputs(set);
  Progress progress;
  const brdfbake::BakedOutputs baked = brdfbake::BakeOutputs(
      set, opts.threads, Given(opts.app, "--tolerance") ? std::optional<double>(opts.tolerance) : std::nullopt,
      [&](int64_t d, int64_t n) { progress(d, n); }, [&] { progress.Restart(); });
  brdfbake::WriteOutputs(set, baked.tables, baked.images);
  for (const brdfbake::OutputFile& f : set.files) {
    if (f.table >= 0 && !f.lookup) {
      PrintWrote(f.path, baked.tables[f.table], f.what, &baked.images[f.table]);
    } else {
      std::printf("wrote %s: %s\n", OneLine(f.path).c_str(), f.what.c_str());
    }
  }
  return 0;
}

int RunSceneBake(const BakeOptions& opts) {
  for (const char* o : {"--table", "--model", "--gamma", "--visibility", "--size", "--warp", "--range", "--placement", "--masking",
                        "--complement", "--error-channel", "--integrator", "--samples", "--seed", "--tolerance",
                        "--symbol", "--channels", "--inverse", "--part"}) {
    if (Given(opts.app, o)) {
      Bad(std::string(o) + ": a scene bake takes its settings from the scene file (the command line may override "
                           "--preset, --format, --pixel, --shader, --max-size and --error-target)");
    }
  }
  if (opts.output.empty()) Bad("-o: a scene bake writes into a directory: name it with -o DIR");
  std::error_code ec;
  if (!std::filesystem::exists(opts.scene, ec)) {
    // `bake dfg` meant a table, not a scene file.
    const std::string table = brdfbake::NearestChoice(opts.scene, {"E", "E_avg", "dfg", "sel_norm"});
    Bad(OneLine(opts.scene) + ": no such scene file" +
        (table.empty() ? "" : "; did you mean --table " + table + "?"));
  }
  brdfbake::Scene scene = brdfbake::LoadScene(opts.scene);
  brdfbake::ApplySceneOverrides(&scene, SceneOverridesGiven(opts.app, opts.preset, opts.format, opts.pixel, opts.shader,
                                                            opts.max_size, opts.error_target));
  // Every file name is known (and a --format the engine does not load
  // refused) before the directory is made.
  const std::vector<std::string> outputs = brdfbake::SceneOutputFiles(scene, opts.output);
  MakeOutputDirectory(opts.output);
  // Every output is checked before the plan's work (a directory in the
  // place of a table failed only after the planning).
  for (const std::string& f : outputs) brdfbake::CheckOutputPath(f);
  PlanProgress progress;
  const brdfbake::ScenePlan plan = brdfbake::PlanScene(scene, [&](const std::string& l) { progress(l); });
  progress.Finish();
  const std::vector<std::string> files = brdfbake::WriteScenePlan(scene, plan, opts.output);
  std::printf("%s", brdfbake::PlanText(scene, plan).c_str());
  for (const std::string& f : files) std::printf("wrote %s\n", OneLine(f).c_str());
  return 0;
}

int RunBake(const BakeOptions& opts) {
  if (!opts.scene.empty()) return RunSceneBake(opts);
  for (const char* o : {"--max-size", "--error-target"}) {
    if (Given(opts.app, o)) Bad(std::string(o) + ": applies to scene bakes (bake SCENE -o DIR) and plan");
  }
  if (!opts.preset.empty()) return RunPreset(opts);
  brdfbake::TableRequest request;
  request.spec = opts.Get();
  request.output = opts.output;
  request.format = opts.format;
  if (opts.pixel == "unorm16") request.pixel = brdfbake::PixelType::kUnorm16;
  if (opts.pixel == "unorm8") request.pixel = brdfbake::PixelType::kUnorm8;
  request.shaders = ShaderLanguages(opts.shader);
  if (opts.channels != "named" && opts.channels != "rgba") {
    Bad("--channels: unknown value '" + opts.channels + "' (expected named or rgba)");
  }
  request.rgba = opts.channels == "rgba";
  request.symbol = opts.symbol;
  const brdfbake::BakeSpec& spec = request.spec;
  const brdfbake::OutputSet set = brdfbake::TableOutputs(request);
  MakeParentDirectory(opts.output);
  brdfbake::CheckOutputs(set);
  Progress progress;
  const brdfbake::BakedOutputs baked =
      brdfbake::BakeOutputs(set, spec.threads, std::nullopt, [&](int64_t d, int64_t t) { progress(d, t); });
  progress.Finish();
  brdfbake::WriteOutputs(set, baked.tables, baked.images);
  for (const brdfbake::OutputFile& f : set.files) {
    if (f.lookup) {
      std::printf("wrote %s: %s lookup %s\n", OneLine(f.path).c_str(), brdfbake::ShaderLanguageName(f.language),
                  f.symbol.c_str());
    } else {
      PrintWrote(f.path, baked.tables[0], brdfbake::TableName(spec.table), f.table_exr ? nullptr : &baked.images[0]);
    }
  }
  if (spec.roughness.placement == brdfbake::Placement::kEdges) {
    std::fprintf(stderr,
                 "note: edges placement puts texel i at t = i / (N - 1); a GPU's bilinear lookup "
                 "needs t' = (t (N - 1) + 0.5) / N, or bake with --placement centers\n");
  }
  return 0;
}

int RunReportCommand(const BakeOptions& opts, int repeats, double reference_tolerance) {
  brdfbake::ReportSpec rs;
  rs.table = opts.Get();
  rs.repeats = repeats;
  if (!(reference_tolerance > 0) || !std::isfinite(reference_tolerance)) {
    Bad("--reference-tolerance must be a finite number > 0");
  }
  rs.reference_tolerance = reference_tolerance;
  if (rs.repeats < 1 || rs.repeats > 100) Bad("--repeats must be in [1, 100]");
  // The request is checked, then the directory made, before the work.
  brdfbake::ValidateReportSpec(rs);
  MakeOutputDirectory(opts.output);
  const bool aniso = rs.table.Anisotropic();
  const std::vector<const char*> files =
      aniso ? std::vector<const char*>{"collapse.csv", "collapse.svg"}
            : std::vector<const char*>{"report.csv", "report.svg", "interpolation.csv",
                                       "interpolation.svg"};
  for (const char* f : files) brdfbake::CheckOutputPath(opts.output + "/" + f);
  const brdfbake::Report r = brdfbake::RunReport(
      rs, [](const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); });
  brdfbake::WriteReport(r, opts.output);
  std::printf("wrote %s/%s\n", OneLine(opts.output).c_str(),
              aniso ? "collapse.csv, collapse.svg"
                    : "report.csv, report.svg, interpolation.csv, interpolation.svg");
  return 0;
}

int RunStabilityCommand(int samples, const std::string& seed_text) {
  if (samples < 1 || samples > 100000000) Bad("--samples must be in [1, 100000000]");
  const uint64_t seed = ParseSeed("--seed", seed_text);
  std::ostringstream out;
  const std::vector<brdfbake::StabilityRow> rows = brdfbake::RunStability(samples, seed);
  brdfbake::WriteStabilityCsv(rows, out);
  std::cout << out.str();
  int64_t outside = 0, non_finite = 0;
  for (const brdfbake::StabilityRow& r : rows) {
    outside += r.Within() ? 0 : 1;
    non_finite += r.non_finite;
  }
  std::cerr << rows.size() << " rows: " << non_finite << " non-finite outputs, " << outside
            << " rows outside their stated bound\n";
  return outside > 0 ? 1 : 0;
}

struct EvalOptions {
  ModelOptions model;
  FresnelOptions fresnel;
  std::string quantity = "D", masking = "height-correlated", sweep = "mu", exponent = "5";
  EvalRequest req;
  double phi_deg = 0, phi_o_deg = 0;
  std::string grid_kind, grid_out, target = "best";
  int grid_w = 256, grid_h = 256, grid_threads = 0;
  CLI::App* app = nullptr;

  void Add(CLI::App* eval) {
    app = eval;
    eval->footer(ModelsHelp());
    model.Add(eval);
    fresnel.Add(eval);
    eval->add_option("--quantity,-q", quantity,
                     "D, Lambda, G1, G2, brdf, pdf, K, E, dfg, E_avg, gen_schlick_s (at --exponent), "
                     "gen_schlick_ior_s (at --ior), f82_bias (comma-separated)")
        ->capture_default_str();
    eval->add_option("--exponent", exponent,
                     "gen_schlick_s: the Schlick exponent, s_h = (1 - wo.h)^exponent, in [0, inf] (baked "
                     "within [0.0505, 49995], as the tables clamp it)")
        ->capture_default_str();
    eval->add_option("--masking", masking, "height-correlated | separable")->capture_default_str();
    eval->add_option("--sweep", sweep, "mu (cos theta), theta (degrees), roughness or none")
        ->capture_default_str();
    eval->add_option("--from", req.from, "first value of the sweep")->capture_default_str()
        ->check(kNumber);
    eval->add_option("--to", req.to, "last value of the sweep")->capture_default_str()
        ->check(kNumber);
    eval->add_option("--count,-n", req.count, "number of samples")->capture_default_str()
        ->check(kInteger);
    eval->add_option("--phi", phi_deg, "azimuth of the swept direction, degrees")->capture_default_str()
        ->check(kNumber);
    eval->add_option("--mu-o", req.mu_o, "cos(theta) of the view wo (G2, brdf, pdf, E, dfg)")
        ->capture_default_str()
        ->check(kNumber);
    eval->add_option("--phi-o", phi_o_deg, "azimuth of the view wo, degrees")->capture_default_str()
        ->check(kNumber);
    eval->add_option("--anisotropy", req.anisotropy,
                     "ggx-aniso: KHR_materials_anisotropy strength s in [0, 1] (alpha_t = "
                     "mix(r^2, 1, s^2), alpha_b = r^2)")
        ->capture_default_str()
        ->check(kNumber);
    eval->add_option("--grid", grid_kind,
                     "evaluate a grid to EXR instead of a sweep: slice (theta_h x theta_d BRDF), "
                     "hemisphere (f cos over wi for the view --mu-o/--phi-o), g1 (mu x roughness)");
    eval->add_option("--width", grid_w, "grid width")->capture_default_str()
        ->check(kInteger);
    eval->add_option("--height", grid_h, "grid height")->capture_default_str()
        ->check(kInteger);
    eval->add_option("--threads", grid_threads, "grid: worker threads, at most 1024; 0 = all cores")
        ->capture_default_str()
        ->check(kInteger);
    eval->add_option("-o,--output", grid_out, "grid: output .exr file");
    eval->add_option("--target", target, "force a SIMD target (AVX3, AVX2, SSE4, SSSE3, SCALAR, or best)")
        ->capture_default_str();
  }
};

int RunGrid(const EvalOptions& o) {
  ForceTargetOption(o.target);
  brdfbake::GridRequest gr;
  gr.model = o.model.Get();
  gr.fresnel = o.fresnel.Get();
  gr.masking = ParseMasking(o.masking);
  gr.kind = brdfbake::ParseGridKind(o.grid_kind);
  gr.width = o.grid_w;
  gr.height = o.grid_h;
  gr.threads = o.grid_threads;
  gr.mu_o = o.req.mu_o;
  gr.phi_o = o.phi_o_deg * kDegree;
  if (o.grid_out.empty()) Bad("-o: --grid writes an EXR file; name it with -o");
  brdfbake::ValidateGridRequest(gr);
  brdfbake::CheckOutputExtension(o.grid_out, ".exr", "eval --grid");
  MakeParentDirectory(o.grid_out);
  brdfbake::CheckOutputPath(o.grid_out);
  const auto start = std::chrono::steady_clock::now();
  const brdfbake::Grid g = brdfbake::EvalGrid(gr);
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  brdfbake::WriteImageExr(o.grid_out, g.width, g.height,
                          {{brdfbake::GridChannelName(gr.kind), &g.values}},
                          brdfbake::GridAttributes(gr, g));
  std::printf("wrote %s: %s grid %dx%d of %s in %.3f s (%s)\n", OneLine(o.grid_out).c_str(),
              brdfbake::GridKindName(gr.kind), g.width, g.height, gr.model.name(), secs,
              g.path.c_str());
  return 0;
}

int RunEval(const EvalOptions& o) {
  if (!o.grid_kind.empty()) return RunGrid(o);
  // The CSV goes to standard output: the grid's options do not apply.
  for (const char* grid_only : {"--output", "--width", "--height", "--threads"}) {
    if (Given(o.app, grid_only)) {
      Bad(std::string(grid_only == std::string("--output") ? "-o" : grid_only) +
          " applies to --grid only (eval prints its CSV to standard output)");
    }
  }
  if (o.target != "best") ForceTargetOption(o.target);
  EvalRequest req = o.req;
  req.quantities = SplitComma(o.quantity);
  bool tables_only = true, eavg_only = true;
  for (const std::string& q : req.quantities) {
    tables_only &= brdfbake::IsTableQuantity(q);
    eavg_only &= q == "E_avg";
  }
  // Options that do not apply to the quantities asked for.
  if (eavg_only) {
    for (const char* view : {"--mu-o", "--phi-o"}) {
      if (Given(o.app, view)) Bad(std::string(view) + ": E_avg does not depend on the view (it averages E over mu)");
    }
  }
  if (tables_only && Given(o.app, "--phi")) {
    Bad("--phi: the table quantities E, dfg and E_avg have no swept direction (the view is --mu-o, --phi-o)");
  }
  const bool ior_s = std::find(req.quantities.begin(), req.quantities.end(), "gen_schlick_ior_s") !=
                     req.quantities.end();
  if (Given(o.app, "--exponent")) {
    if (std::find(req.quantities.begin(), req.quantities.end(), "gen_schlick_s") == req.quantities.end()) {
      Bad("--exponent: applies to the quantity gen_schlick_s only");
    }
  }
  req.exponent = ParseNumberOrInf("--exponent", o.exponent);
  req.model = o.model.Get(tables_only, ior_s);
  req.fresnel = o.fresnel.Get();
  req.masking = ParseMasking(o.masking);
  req.sweep = o.sweep;
  // Table quantities alone and no sweep asked for: one value at
  // (--mu-o, --roughness).
  if (tables_only && !Given(o.app, "--sweep") && !Given(o.app, "--from") && !Given(o.app, "--to") &&
      !Given(o.app, "--count")) {
    req.sweep = "none";
  }
  req.phi = o.phi_deg * kDegree;
  req.phi_o = o.phi_o_deg * kDegree;
  // Nothing is printed unless the whole sweep succeeds. (Read and write:
  // the buffer is copied to standard output from its get area.)
  std::stringstream out;
  brdfbake::EvalCsv(req, out);
  if (!out) {
    // The stream sets badbit where memory runs out, and drops the rest.
    Bad("eval: the CSV could not be held in memory; ask for fewer values (--count)");
  }
  std::cout << out.rdbuf();
  return 0;
}

// CLI11 lists unexpected arguments in reverse; this names them in order,
// as they stand on the command line (`argv`). A value that followed an
// unknown option and was taken as bake's SCENE is put back in its place.
std::string ExtrasMessage(const CLI::App& app, int argc, char** argv, const std::string& scene) {
  for (const CLI::App* sub : app.get_subcommands()) {
    std::vector<std::string> pending = sub->remaining();
    if (pending.empty()) continue;
    std::vector<std::string> extras;
    for (int i = 1; i < argc; ++i) {
      const std::string a = argv[i];
      const auto it = std::find(pending.begin(), pending.end(), a);
      if (it != pending.end()) {
        extras.push_back(a);
        pending.erase(it);
      } else if (!scene.empty() && a == scene && !extras.empty() && extras.back()[0] == '-') {
        extras.push_back(a);
      }
    }
    extras.insert(extras.end(), pending.begin(), pending.end());
    std::string list;
    for (const std::string& e : extras) list += (list.empty() ? "" : " ") + e;
    const std::string& first = extras.front();
    std::string msg = sub->get_name() + ": ";
    if (first.size() > 1 && first[0] == '-' && !std::isdigit(static_cast<unsigned char>(first[1])) &&
        first[1] != '.') {
      std::vector<std::string> names;
      for (const CLI::Option* o : sub->get_options()) {
        for (const std::string& l : o->get_lnames()) names.push_back("--" + l);
      }
      msg += "unknown option '" + first + "'" + brdfbake::DidYouMean(first.substr(0, first.find('=')), names);
    } else {
      msg += "unexpected argument '" + first + "'";
    }
    if (extras.size() > 1) msg += " (unexpected, in order: " + list + ")";
    return msg + "; see brdfbake " + sub->get_name() + " --help";
  }
  const std::vector<std::string> extras = app.remaining();
  std::string list;
  for (const std::string& e : extras) list += (list.empty() ? "" : " ") + e;
  return "unexpected arguments: " + list + " (see brdfbake --help)";
}

// Every byte of standard output reached its destination (a full disk or a
// closed pipe is an error, not a silent success).
bool FlushStdout() {
  std::cout.flush();
  return std::cout && std::fflush(stdout) == 0 && !std::ferror(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  brdfbake::InstallTemporaryCleanup();
  CLI::App app{"brdfbake: microfacet BRDF models and the lookup tables real-time engines sample."};
  app.set_version_flag("--version", VersionText());
  app.require_subcommand(1);
  app.allow_extras();

  CLI::App* eval = app.add_subcommand(
      "eval", "Evaluate a model's D, Lambda, G1, G2, BRDF, pdf, or a table's E, dfg, E_avg, "
              "along a sweep, as CSV on stdout.");
  eval->allow_extras();
  EvalOptions eval_opts;
  eval_opts.Add(eval);

  CLI::App* bake = app.add_subcommand(
      "bake", "Bake a lookup table (E, E_avg, dfg or sel_norm) to a self-describing file, an engine's tables "
              "(--preset), or exactly the tables a scene needs (bake SCENE -o DIR).");
  bake->allow_extras();
  BakeOptions bake_opts;
  bake_opts.Add(bake, false);

  CLI::App* report = app.add_subcommand(
      "report", "Error against run time of every integrator over a ladder of budgets, and the "
                "interpolation error against table size: CSV and SVG plots in a directory.");
  report->allow_extras();
  BakeOptions report_opts;
  report_opts.size = "16x16";
  report_opts.Add(report, true);
  int repeats = 3;
  double reference_tolerance = 1e-11;
  report->add_option("--repeats", repeats, "timing: median of this many bakes")->capture_default_str()
        ->check(kInteger);
  report->add_option("--reference-tolerance", reference_tolerance,
                     "tolerance of the converged quadrature used as the reference")
      ->capture_default_str()
        ->check(kNumber);

  CLI::App* plan = app.add_subcommand(
      "plan", "What `bake SCENE -o DIR` would write: the minimal set of tables for a scene's materials, "
              "each at the resolution that meets the scene's error target.");
  plan->allow_extras();
  std::string plan_scene, plan_preset, plan_format, plan_pixel, plan_shader, plan_max_size, plan_error_target;
  plan->add_option("scene", plan_scene, "a scene: .toml (see examples/README.md), .gltf or .glb")->required();
  AddSceneOverrides(plan, &plan_preset, &plan_format, &plan_pixel, &plan_shader, &plan_max_size, &plan_error_target,
                    true);

  CLI::App* stability = app.add_subcommand(
      "stability", "Float kernels against the double reference, region by region over the "
                   "documented domain: max relative error and non-finite count, as CSV.");
  stability->allow_extras();
  int stability_samples = 20000;
  std::string stability_seed = "1";
  stability->add_option("--samples", stability_samples, "samples per region and model")
      ->capture_default_str()
        ->check(kInteger);
  stability->add_option("--seed", stability_seed, "seed, in [0, 2^64 - 1]")->capture_default_str();

  // Help and the version go to standard output, which must take them.
  const auto exit_printed = [&](const CLI::Error& e) {
    const int status = app.exit(e);
    if (!FlushStdout()) {
      std::fprintf(stderr, "brdfbake: error: cannot write to standard output: %s\n",
                   std::strerror(errno ? errno : EIO));
      return 1;
    }
    return status;
  };
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return exit_printed(e);
  } catch (const CLI::CallForAllHelp& e) {
    return exit_printed(e);
  } catch (const CLI::CallForVersion& e) {
    return exit_printed(e);
  } catch (const CLI::ParseError& e) {
    // A first word that is no command: name the commands, and the near one.
    std::vector<std::string> commands;
    for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) {
      commands.push_back(sub->get_name());
    }
    if (argc > 1 && argv[1][0] != '-' &&
        std::find(commands.begin(), commands.end(), argv[1]) == commands.end()) {
      std::string list;
      for (const std::string& c : commands) list += (list.empty() ? "" : ", ") + c;
      std::fprintf(stderr, "brdfbake: error: unknown command '%s' (expected %s)%s\n", ErrorLine(argv[1]).c_str(),
                   list.c_str(), brdfbake::DidYouMean(argv[1], commands).c_str());
      return 2;
    }
    std::fprintf(stderr, "brdfbake: error: %s (see brdfbake --help)\n", ErrorLine(e.what()).c_str());
    return 2;
  }
  bool extras = !app.remaining().empty();
  for (const CLI::App* sub : app.get_subcommands()) extras |= !sub->remaining().empty();
  if (extras) {
    std::fprintf(stderr, "brdfbake: error: %s\n", ErrorLine(ExtrasMessage(app, argc, argv, bake_opts.scene)).c_str());
    return 2;
  }

  int status = 0;
  try {
    if (*bake) status = RunBake(bake_opts);
    if (*plan) {
      brdfbake::Scene scene = brdfbake::LoadScene(plan_scene);
      brdfbake::ApplySceneOverrides(&scene, SceneOverridesGiven(plan, plan_preset, plan_format, plan_pixel, plan_shader,
                                                                plan_max_size, plan_error_target));
      brdfbake::SceneOutputFiles(scene, ".");  // a --format the engine does not load is refused here too
      PlanProgress progress;
      const brdfbake::ScenePlan scene_plan = brdfbake::PlanScene(scene, [&](const std::string& l) { progress(l); });
      progress.Finish();
      std::printf("%s", brdfbake::PlanText(scene, scene_plan).c_str());
    }
    if (*report) status = RunReportCommand(report_opts, repeats, reference_tolerance);
    if (*stability) status = RunStabilityCommand(stability_samples, stability_seed);
    if (*eval) status = RunEval(eval_opts);
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "brdfbake: error: out of memory\n");
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "brdfbake: error: %s\n", ErrorLine(CliMessage(e)).c_str());
    return 1;
  }
  if (!FlushStdout()) {
    std::fprintf(stderr, "brdfbake: error: cannot write to standard output: %s\n",
                 std::strerror(errno ? errno : EIO));
    return 1;
  }
  return status;
}
