// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// OpenEXR output and read-back: a table as a self-describing file
// (docs/format.md) and a plain float image with string attributes.

#ifndef BRDFBAKE_EXR_H_
#define BRDFBAKE_EXR_H_

#include <string>
#include <utility>
#include <vector>

#include "brdfbake/bake.h"

namespace brdfbake {

// Writes `table` as a self-describing OpenEXR file (docs/format.md) through
// an AtomicFile (output_file.h). Throws std::runtime_error.
void WriteExr(const Table& table, const std::string& path);

// Reads back a brdfbake EXR: every string attribute and every channel.
struct ExrContents {
  int width = 0, height = 0;
  std::vector<std::pair<std::string, std::string>> attributes;
  std::vector<std::pair<std::string, std::vector<float>>> channels;
  bool half = false;
  std::string Attribute(const std::string& name) const;
  const std::vector<float>* ChannelData(const std::string& name) const;
};
ExrContents ReadExr(const std::string& path);

// Writes a float image with string attributes, through a temporary file and
// a rename. Throws std::runtime_error.
void WriteImageExr(const std::string& path, int width, int height,
                   const std::vector<std::pair<std::string, const std::vector<float>*>>& channels,
                   const std::vector<std::pair<std::string, std::string>>& attributes);

}  // namespace brdfbake

#endif  // BRDFBAKE_EXR_H_
