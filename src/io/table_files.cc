// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0

#include "brdfbake/table_files.h"

#include <filesystem>
#include <string>
#include <vector>

#include "base/error.h"
#include "brdfbake/exr.h"
#include "brdfbake/output_file.h"

namespace brdfbake {

std::string LookupPath(const std::string& table_path, ShaderLanguage language) {
  return std::filesystem::path(table_path).replace_extension(ShaderLanguageName(language)).string();
}

std::vector<OutputFile> OwnTableFiles(const std::string& path, Container container, bool table_exr, bool header,
                                      const std::vector<ShaderLanguage>& shaders, const std::string& symbol,
                                      int table) {
  std::vector<OutputFile> files;
  files.push_back({path, table, ContainerName(container), container, false, ShaderLanguage::kGlsl, symbol,
                   table_exr && container == Container::kExr});
  if (header) {
    files.push_back({std::filesystem::path(path).replace_extension(".h").string(), table, "header", Container::kHeader,
                     false, ShaderLanguage::kGlsl, symbol});
  }
  for (ShaderLanguage l : shaders) {
    files.push_back({LookupPath(path, l), table, std::string(ShaderLanguageName(l)) + " lookup " + symbol,
                     Container::kHeader, true, l, symbol});
  }
  return files;
}

void WriteOutputFile(const OutputFile& f, const Table& table, const Image& image, const std::string& engine) {
  if (f.table < 0) Bad("the file " + f.path + " holds every table: its engine's preset writes it");
  if (f.lookup) {
    WriteFileAtomically(f.path, ShaderFunction(table, image, f.language, f.symbol));
  } else if (f.table_exr) {
    WriteExr(table, f.path);
  } else {
    WriteImage(table, image, f.container, f.path, f.symbol, engine, f.ktx2_zstd_level);
  }
}

}  // namespace brdfbake
