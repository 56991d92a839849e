// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0

#include "brdfbake/outputs.h"

#include <cctype>
#include <string>
#include <vector>

#include "base/error.h"
#include "base/text.h"
#include "brdfbake/output_file.h"

namespace brdfbake {

namespace {

// Whether a file of the set is written from table k's arrangement: any
// file of it but its own EXR, or a file of every table.
bool ImageNeeded(const OutputSet& set, int k) {
  for (const OutputFile& f : set.files) {
    if ((f.table < 0 || f.table == k) && !f.table_exr) return true;
  }
  return false;
}

}  // namespace

std::string DefaultSymbol(const BakeSpec& spec) {
  std::string s = std::string("brdfbake_") + spec.model.name() + "_" + TableName(spec.table);
  for (char& c : s) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return s;
}

void CheckSymbol(const std::string& s) {
  bool ok = !s.empty() && s.size() <= 200 && !std::isdigit(static_cast<unsigned char>(s[0]));
  for (char c : s) {
    ok &= (std::isalnum(static_cast<unsigned char>(c)) && static_cast<unsigned char>(c) < 128) || c == '_';
  }
  if (!ok) Bad("{symbol}: '" + Printable(s) + "' is not an identifier (a letter or _, then letters, digits or _)");
  if (s.rfind("gl_", 0) == 0 || s.find("__") != std::string::npos) {
    Bad("{symbol}: '" + s + "' is reserved in GLSL (gl_ prefix or __)");
  }
}

OutputSet TableOutputs(const TableRequest& r) {
  const BakeSpec& spec = r.spec;
  const Container container = r.format.empty() ? ContainerFromPath(r.output) : ParseContainer(r.format);
  if (!r.format.empty() && ContainerFromPath(r.output) != container) {
    Bad("{output}: '" + r.output + "' does not name a " + r.format + " file");
  }
  if (r.pixel == PixelType::kUnorm16 && container != Container::kDds && container != Container::kPng) {
    Bad("{pixel} unorm16: only the dds and png formats hold unorm16 pixels");
  }
  if (r.pixel == PixelType::kUnorm8 && container != Container::kPng) {
    Bad("{pixel} unorm8: only the png format holds unorm8 pixels");
  }
  if (container == Container::kPng && r.pixel != PixelType::kUnorm8 && r.pixel != PixelType::kUnorm16) {
    Bad(std::string("{output}: png holds unorm8 or unorm16 pixels: give {pixel} unorm8 or unorm16 (got ") +
        (spec.half ? "half" : "float") + ")");
  }
  if (spec.table == TableKind::kSelNorm && container != Container::kExr) {
    Bad("{output}: sel_norm tables are written as .exr");
  }
  if (!r.shaders.empty()) CheckShaderTable(spec);
  if (r.rgba && spec.table == TableKind::kSelNorm) {
    Bad("{channels} rgba: sel_norm tables are written as their own EXR channels only");
  }
  if (r.rgba && spec.error_channel) {
    Bad("{channels} rgba: the error channel has no place among R, G, B and A; bake it with {channels} named");
  }
  if (r.rgba && (container == Container::kHeader || container == Container::kJs || container == Container::kInc)) {
    Bad("{channels} rgba: applies to the image containers (exr, ktx2, dds), not to " +
        std::string(ContainerName(container)));
  }
  const std::string symbol = r.symbol.empty() ? DefaultSymbol(spec) : r.symbol;
  CheckSymbol(symbol);
  OutputSet set;
  set.files = OwnTableFiles(r.output, container, container == Container::kExr && !r.rgba, false, r.shaders, symbol);
  PresetTable pt;
  pt.spec = spec;
  pt.container = container;
  pt.symbol = symbol;
  set.preset.tables.push_back(pt);
  // The layout of the files that arrange the table (a table's own EXR,
  // such as sel_norm's, has none).
  if (ImageNeeded(set, 0)) {
    ImageLayout& layout = set.preset.tables[0].layout;
    layout = DefaultLayout(spec);
    if (r.pixel == PixelType::kUnorm16 || r.pixel == PixelType::kUnorm8) layout.pixel = r.pixel;
    if (r.rgba) layout = RgbaLayout(layout);
  }
  return set;
}

OutputSet PresetOutputs(const Preset& preset, const PresetRun& run) { return {preset, PresetFiles(preset, run)}; }

void CheckOutputs(const OutputSet& set) {
  for (const OutputFile& f : set.files) CheckOutputPath(f.path);
  // Every table's file must fit in memory once its bake is done: checked
  // for all of them before the first bake.
  int64_t all_values = 0;
  size_t held = 0;
  for (const PresetTable& pt : set.preset.tables) {
    all_values += BakeOutputValues(pt.spec);
    held += BakeOutputBytes(pt.spec) * (1 + pt.with.size());
    // A model family the build leaves out fails here, before any work.
    for (const BakeSpec& w : pt.with) ValidateBakeSpec(w);
  }
  for (const OutputFile& f : set.files) {
    if (!f.lookup && ImageNeeded(set, f.table)) CheckContainerMemory(f.container, all_values, held, f.path);
  }
}

BakedOutputs BakeOutputs(const OutputSet& set, int threads, const std::optional<double>& tolerance,
                         const ProgressFn& progress, const std::function<void()>& stage_done) {
  BakedOutputs out;
  const std::vector<PresetTable>& tables = set.preset.tables;
  out.tables.reserve(tables.size());
  out.images.reserve(tables.size());
  for (size_t k = 0; k < tables.size(); ++k) {
    const PresetTable& pt = tables[k];
    BakeSpec spec = pt.spec;
    spec.threads = threads;
    if (tolerance) spec.tolerance = *tolerance;
    ValidateBakeSpec(spec);
    out.tables.push_back(Bake(spec, progress));
    if (stage_done) stage_done();
    out.images.push_back(ImageNeeded(set, int(k))
                             ? ArrangePresetTable(pt, out.tables.back(), threads, tolerance.value_or(0), progress)
                             : Image());
    if (!pt.with.empty() && stage_done) stage_done();
  }
  return out;
}

std::vector<Image> ArrangeOutputs(const OutputSet& set, const std::vector<Table>& tables) {
  std::vector<Image> images;
  images.reserve(tables.size());
  for (size_t k = 0; k < tables.size(); ++k) {
    images.push_back(ImageNeeded(set, int(k))
                         ? ArrangePresetTable(set.preset.tables[k], tables[k], tables[k].spec.threads)
                         : Image());
  }
  return images;
}

void WriteOutputs(const OutputSet& set, const std::vector<Table>& tables, const std::vector<Image>& images) {
  for (const OutputFile& f : set.files) WritePresetFile(set.preset, f, tables, images);
}

}  // namespace brdfbake
