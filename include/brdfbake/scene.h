// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Scenes: the materials a renderer uses and the engine's preferences, read
// from a TOML scene file or a glTF 2.0 file, turned into the minimal set of
// tables (`plan`) at the resolution that meets the error target under
// bilinear lookup, and baked (`bake SCENE -o DIR`) with a manifest.

#ifndef BRDFBAKE_SCENE_H_
#define BRDFBAKE_SCENE_H_

#include <string>
#include <vector>

#include "brdfbake/bake.h"
#include "brdfbake/presets.h"
#include "brdfbake/shaders.h"

namespace brdfbake {

struct SceneMaterial {
  std::string name;
  ModelKind model = ModelKind::kGgx;  // ggx, beckmann, std or ggx-aniso
  double roughness_min = 0.5, roughness_max = 0.5;
  double gamma = 2;  // std
  double anisotropy = 0;  // ggx-aniso strength (glTF KHR_materials_anisotropy)
  Masking masking = Masking::kHeightCorrelated;
  std::string source;  // "toml" or "glTF material 3"
  // Features brdfbake recognises but does not bake tables for (glTF
  // extensions), each with the table it would need.
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
};

struct Scene {
  std::string path;
  SceneEngine engine;
  std::vector<SceneMaterial> materials;
};

// Reads a TOML scene (.toml) or a glTF 2.0 file (.gltf, .glb). Throws
// std::invalid_argument with one line naming the file, the material and the
// field.
Scene LoadScene(const std::string& path);

struct PlannedTable {
  BakeSpec spec;
  std::string file;                    // file name in the output directory
  std::vector<std::string> materials;  // who needs it
  std::string why;
  double interpolation_error = 0;  // measured at cell midpoints
  double total_error = 0;          // interpolation + the stored values' claim
  bool meets_target = false;
  Table table;  // as baked while choosing the resolution
};

struct ScenePlan {
  std::vector<PlannedTable> tables;
  std::vector<std::string> notes;  // materials or features not baked, and why
};

// The minimal set of tables, each at the smallest size (and mu warp) whose
// bilinear lookup meets the error target; `progress` gets one line per
// candidate tried.
ScenePlan PlanScene(const Scene& scene, const std::function<void(const std::string&)>& progress = nullptr);

// The files a bake of `scene` writes into `dir` (each table's EXR, its
// header and shader files, the manifest): known before the plan, so that
// they can be checked (CheckOutputPath) before its work.
std::vector<std::string> SceneOutputFiles(const Scene& scene, const std::string& dir);

// What `plan` prints.
std::string PlanText(const Scene& scene, const ScenePlan& plan);

// Writes every planned table into `dir` (EXR, and the header and shader
// functions the engine asked for) and dir/manifest.json; returns the paths.
std::vector<std::string> WriteScenePlan(const Scene& scene, const ScenePlan& plan, const std::string& dir);

// The largest error of a bilinear lookup of `t` at the midpoints of its
// cells (up to `probes` cells per axis), against the exact values.
double InterpolationError(const Table& t, int probes = 12);

}  // namespace brdfbake

#endif  // BRDFBAKE_SCENE_H_
