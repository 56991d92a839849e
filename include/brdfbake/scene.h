// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Scenes: the materials a renderer uses and the engine's preferences, read
// from a TOML scene file or a glTF 2.0 file, turned into the minimal set of
// tables (`plan`) at the resolution that meets the error target under
// bilinear lookup, and baked (`bake SCENE -o DIR`) with a manifest.

#ifndef BRDFBAKE_SCENE_H_
#define BRDFBAKE_SCENE_H_

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "brdfbake/bake.h"
#include "brdfbake/containers.h"
#include "brdfbake/presets.h"
#include "brdfbake/shaders.h"

namespace brdfbake {

struct SceneMaterial {
  std::string name;
  ModelKind model = ModelKind::kGgx;  // ggx, beckmann, std or ggx-aniso
  double roughness_min = 0.5, roughness_max = 0.5;
  double gamma = 2;  // std
  double anisotropy = 0;  // ggx-aniso strength (glTF KHR_materials_anisotropy)
  // The least strength: an anisotropyTexture modulates it over [0, strength].
  double anisotropy_min = 0;
  Masking masking = Masking::kHeightCorrelated;
  // glTF KHR_materials_clearcoat: a GGX layer (IOR 1.5) over the base at
  // its own roughness; clearcoat = 0 is no layer.
  double clearcoat = 0;
  double clearcoat_roughness_min = 0, clearcoat_roughness_max = 0;
  // A sheen layer (glTF KHR_materials_sheen with a sheen colour above 0,
  // TOML sheen_roughness): the Charlie NDF with the conty-kulla visibility
  // at its own roughness (alpha = r^2), which scales the base layer by
  // 1 - max(sheenColor) E(NoV, r). A sheenRoughnessTexture modulates the
  // factor over [0, factor].
  bool sheen = false;
  double sheen_roughness_min = 0, sheen_roughness_max = 0;
  // The index of refraction (glTF KHR_materials_ior, 1.5 by default; TOML
  // ior, a number or a range [min, max] in [1, 100]). On an opaque
  // material it sets F0 = ((ior - 1) / (ior + 1))^2 alone.
  double ior_min = 1.5, ior_max = 1.5;
  bool ior_given = false;
  // A transmissive material (glTF KHR_materials_transmission with a factor
  // above 0, TOML transmission = true): the rough dielectric over GGX
  // (ggx-glass) at its roughness and ior, reflection plus refraction.
  // `volume` (KHR_materials_volume with a thickness above 0, TOML volume =
  // true): the surface bounds a medium, so light also leaves it (eta = 1 /
  // ior); without it the material is thin-walled.
  bool transmission = false;
  bool volume = false;
  std::string source;  // "toml" or "glTF material 3"
  // Features brdfbake recognises but does not bake tables for (glTF
  // extensions), each with what it would need and why it is not baked
  // ("needs ..., which brdfbake does not bake yet").
  std::vector<std::pair<std::string, std::string>> unsupported;
};

struct SceneEngine {
  int max_lut_size = 64;  // entries per axis at most
  PixelType pixel = PixelType::kHalf;
  Placement placement = Placement::kCenters;
  double error_target = 2e-3;  // max abs error of a bilinear lookup
  bool complement = false;     // E and E_avg stored as 1 - E
  std::vector<TableKind> tables = {TableKind::kDfg, TableKind::kE, TableKind::kEavg};
  bool header = false;                  // a C++ header beside each EXR
  std::vector<ShaderLanguage> shaders;  // lookup functions beside each EXR
  // An engine preset (presets.h): the tables are baked in its layouts and
  // containers. Empty: brdfbake's own EXR files.
  std::string preset;
  // The container of each table without a preset (exr, header, js, ktx2,
  // dds, inc), or another container the preset's engine loads; empty: EXR
  // (or the engine's own).
  std::string format;
  bool unorm16 = false;  // --pixel unorm16: 16-bit fixed point (dds)
};

// Command-line settings that override the scene's, recorded in the
// manifest, as (option, value) in the order given: --preset, --format,
// --pixel, --shader, --max-size, --error-target.
using SceneOverrides = std::vector<std::pair<std::string, std::string>>;

struct Scene {
  std::string path;
  SceneEngine engine;
  std::vector<SceneMaterial> materials;
  SceneOverrides overrides;  // those applied (ApplySceneOverrides)
};

// Reads a TOML scene (.toml) or a glTF 2.0 file (.gltf, .glb). Throws
// std::invalid_argument with one line naming the file, the material and the
// field.
Scene LoadScene(const std::string& path);

// Applies command-line overrides to a loaded scene and records them. Throws
// std::invalid_argument naming the option for a value out of its domain or
// one the scene's engine fixes.
void ApplySceneOverrides(Scene* scene, const SceneOverrides& overrides);

struct PlannedTable {
  BakeSpec spec;
  std::string group;                   // the material group: ggx, std_g3, ggx-aniso, ...
  std::string file;                    // the table's file in the output directory
  std::vector<std::string> materials;  // who needs it
  std::string why;
  // The lookup error (LookupError, probe.h: every place the table is not
  // smooth), and the bound the plan states: it plus the stored values'
  // claim (and the rounding of the engine's pixel type).
  double interpolation_error = 0;
  double total_error = 0;
  // The largest error of a material that looks this table up at a
  // collapsed roughness (anisotropic GGX as isotropic), measured by the
  // collapse study; 0 if none does. The target is met when total_error +
  // collapse_error is within it.
  double collapse_error = 0;
  bool meets_target = false;
  bool size_fixed = false;  // the engine's layout fixes the size
  std::string hint;         // when the target is not met: the size and warp that would meet it
  Table table;              // as baked while choosing the resolution
  ImageLayout layout;       // how it is written (the engine's layout, or brdfbake's own)
};

struct ScenePlan {
  std::vector<PlannedTable> tables;
  // How anisotropic, clearcoat, sheen and transmissive materials are
  // served, and why.
  std::vector<std::string> decisions;
  std::vector<std::string> notes;  // materials or features not baked, and why
};

// The minimal set of tables, each at the smallest size (and mu warp) whose
// bilinear lookup meets the error target. Anisotropic GGX groups get the
// smaller of the 4D ggx-aniso tables over their (r, s) box and the
// isotropic tables looked up at the collapsed roughness that meets the
// target; clearcoat layers the isotropic GGX tables; sheen layers the
// charlie (conty-kulla) E and E_avg over their sheen roughness, or the
// engine's own sheen channel; transmissive materials the ggx-glass E and
// E_avg over their roughness and ior range (and the inverse tables, eta =
// 1 / ior, for a volume). `progress` gets one line per candidate tried.
ScenePlan PlanScene(const Scene& scene, const std::function<void(const std::string&)>& progress = nullptr);

// The files a bake of `scene` may write into `dir` (each table's file, its
// header and shader files, the manifest; for an anisotropic group, those
// of both choices): known before the plan, so that they can be checked
// (CheckOutputPath) before its work.
std::vector<std::string> SceneOutputFiles(const Scene& scene, const std::string& dir);

// What `plan` prints.
std::string PlanText(const Scene& scene, const ScenePlan& plan);

// Writes every planned table into `dir` (EXR, and the header and shader
// functions the engine asked for, or the engine preset's files) and
// dir/manifest.json; returns the paths.
std::vector<std::string> WriteScenePlan(const Scene& scene, const ScenePlan& plan, const std::string& dir);

}  // namespace brdfbake

#endif  // BRDFBAKE_SCENE_H_
