// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// One orchestration for every bake that writes files: `bake --table` (one
// table to brdfbake's own files, TableOutputs), `bake --preset` (an
// engine's files, PresetOutputs) and scenes (the plan's tables, in their
// engine's files or their own). Each is an OutputSet: its tables as a
// Preset (spec, layout, the tables the layout's channels read) and every
// file they go to. The set is planned before any work, so that every path
// and the memory are checked first (CheckOutputs); then each table is baked
// and arranged in its layout (BakeOutputs, or ArrangeOutputs for tables a
// scene's plan has baked) and every file written (WriteOutputs).

#ifndef BRDFBAKE_OUTPUTS_H_
#define BRDFBAKE_OUTPUTS_H_

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "brdfbake/presets.h"

namespace brdfbake {

struct OutputSet {
  // An engine's preset, or brdfbake's own files (name "", the tables'
  // layouts and nothing else).
  Preset preset;
  std::vector<OutputFile> files;
};

// `bake --table`: one table to brdfbake's own files.
struct TableRequest {
  BakeSpec spec;
  std::string output;  // the table's file
  std::string format;  // a container name; empty: the one the output's extension names
  // kUnorm16 or kUnorm8: the image containers' pixels; kFloat: the table's
  // own (half when spec.half).
  PixelType pixel = PixelType::kFloat;
  bool rgba = false;  // channels R, G, B, A rather than the table's names (exr, ktx2, dds)
  std::vector<ShaderLanguage> shaders;
  std::string symbol;  // arrays and lookups; empty: brdfbake_<model>_<table>
};

// The default symbol of spec's table: brdfbake_<model>_<table>
// (brdfbake_ggx_E, brdfbake_ggx_aniso_E_avg), so that two tables' headers
// can be included together.
std::string DefaultSymbol(const BakeSpec& spec);

// Throws a ParameterError naming {symbol} unless `symbol` is an
// identifier in C, C++, JavaScript and the shading languages.
void CheckSymbol(const std::string& symbol);

// The set of a request: its container, pixel type and channels checked
// against the table (ParameterError naming the parameter).
OutputSet TableOutputs(const TableRequest& request);

// The set of an engine's preset (PresetFiles).
OutputSet PresetOutputs(const Preset& preset, const PresetRun& run);

// Before any work: every path (CheckOutputPath), the models of the tables
// the layouts read, and the memory that arranging and writing each file
// will take beside the bakes (CheckContainerMemory).
void CheckOutputs(const OutputSet& set);

struct BakedOutputs {
  std::vector<Table> tables;
  std::vector<Image> images;  // empty where no file needs the arrangement
};

// Bakes each table (with `threads`; `tolerance`, when given, replaces the
// tables'), then arranges it, baking the tables its layout reads.
// `progress` follows each of those bakes, and `stage_done` is called after
// each.
BakedOutputs BakeOutputs(const OutputSet& set, int threads, const std::optional<double>& tolerance,
                         const ProgressFn& progress = nullptr, const std::function<void()>& stage_done = nullptr);

// The arrangements of tables already baked (a scene's), each with its own
// spec's threads.
std::vector<Image> ArrangeOutputs(const OutputSet& set, const std::vector<Table>& tables);

// Writes every file of the set (each through an AtomicFile).
void WriteOutputs(const OutputSet& set, const std::vector<Table>& tables, const std::vector<Image>& images);

}  // namespace brdfbake

#endif  // BRDFBAKE_OUTPUTS_H_
