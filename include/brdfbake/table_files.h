// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The files brdfbake writes for its tables, one plan for `bake`, `--preset`
// and scenes: each file is one table's container or one table's shader
// lookup, planned first (so that every path is checked before any work),
// then written from the baked table and its arrangement.

#ifndef BRDFBAKE_TABLE_FILES_H_
#define BRDFBAKE_TABLE_FILES_H_

#include <string>
#include <vector>

#include "brdfbake/bake.h"
#include "brdfbake/containers.h"
#include "brdfbake/shaders.h"

namespace brdfbake {

struct OutputFile {
  std::string path;
  // The table it holds, an index into the tables written together; -1 is
  // a file of all of them (an engine's header), which its preset writes.
  int table = 0;
  std::string what;  // for messages: "dfg (filament)", "glsl lookup of DFG_LUT"
  Container container = Container::kExr;
  bool lookup = false;  // a shader lookup in `language` rather than a container
  ShaderLanguage language = ShaderLanguage::kGlsl;
  // The array's name (header, js) or the lookup function's name.
  std::string symbol;
  // kExr: the table's own EXR (its channels and brdfbake.* attributes)
  // rather than the arranged image.
  bool table_exr = false;
  int ktx2_zstd_level = 0;  // > 0: Zstandard supercompression (WriteImage)
};

// The one rule for a lookup's name: beside the table's file, with the
// language's extension (dfg.ktx2 -> dfg.glsl).
std::string LookupPath(const std::string& table_path, ShaderLanguage language);

// One table's own files: `path` as `container` (the table's own EXR when
// `table_exr`), a C header beside it when `header` (dfg.exr -> dfg.h), and
// a lookup beside it per language; every one names its arrays and lookup
// `symbol`.
std::vector<OutputFile> OwnTableFiles(const std::string& path, Container container, bool table_exr, bool header,
                                      const std::vector<ShaderLanguage>& shaders, const std::string& symbol,
                                      int table = 0);

// Writes file `f` of `table` (arranged as `image` for every file but the
// table's own EXR) through an AtomicFile; `engine` names the preset in the
// file's conventions ("" for none). Throws std::invalid_argument for a
// file of all tables (table -1).
void WriteOutputFile(const OutputFile& f, const Table& table, const Image& image, const std::string& engine);

}  // namespace brdfbake

#endif  // BRDFBAKE_TABLE_FILES_H_
