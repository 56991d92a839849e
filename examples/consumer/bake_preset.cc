// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Files baked in-process through brdfbake::brdfbake (outputs.h), as
// `brdfbake bake` writes them: three.js's DFGLUTData.js with a GLSL lookup
// beside it (the engine's preset), and a 16 x 16 dfg table as KTX2 (one
// table to its own file). Usage: bake_preset DIR. Exits non-zero on any
// error or a claimed error above what the files need.

#include <cstdio>
#include <exception>
#include <filesystem>
#include <optional>
#include <string>

#include "brdfbake/outputs.h"
#include "brdfbake/presets.h"

int main(int argc, char** argv) {
  using namespace brdfbake;
  if (argc != 2) {
    std::fprintf(stderr, "usage: bake_preset DIR\n");
    return 2;
  }
  const std::string dir = argv[1];
  try {
    std::filesystem::create_directories(dir);
    // An engine's files: the preset's tables, layouts and names.
    PresetRun run;
    run.dir = dir;
    run.shaders = {ShaderLanguage::kGlsl};
    const OutputSet three = PresetOutputs(FindPreset("three"), run);
    CheckOutputs(three);  // every path and the memory, before any work
    const BakedOutputs baked = BakeOutputs(three, 0, std::nullopt);
    WriteOutputs(three, baked.tables, baked.images);

    // One table to brdfbake's own file.
    TableRequest request;
    request.spec.table = TableKind::kDfg;
    request.spec.mu.size = request.spec.roughness.size = 16;
    request.output = dir + "/dfg.ktx2";
    const OutputSet own = TableOutputs(request);
    CheckOutputs(own);
    const BakedOutputs dfg = BakeOutputs(own, 0, std::nullopt);
    WriteOutputs(own, dfg.tables, dfg.images);

    int missing = 0;
    for (const OutputSet* set : {&three, &own}) {
      for (const OutputFile& f : set->files) {
        const bool there = std::filesystem::file_size(f.path) > 0;
        std::printf("%s %s (%s)\n", there ? "wrote" : "MISSING", f.path.c_str(), f.what.c_str());
        missing += there ? 0 : 1;
      }
    }
    // three.js stores half floats: its claim is the rounding, below 1e-3.
    const double claim = baked.images[0].max_abs_error;
    std::printf("DFGLUTData.js claimed max error %.3g; dfg.ktx2 %.3g\n", claim, dfg.tables[0].max_abs_error);
    return missing == 0 && claim < 1e-3 && dfg.tables[0].max_abs_error < 1e-6 ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bake_preset: %s\n", e.what());
    return 1;
  }
}
