// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The file plan `bake`, presets and scenes share (table_files.h): the
// names of a table's files, the symbols they carry, and that each file is
// what its plan says once written.

#include "brdfbake/table_files.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "brdfbake/exr.h"
#include "brdfbake/presets.h"
#include "util/file_util.h"

namespace brdfbake {
namespace {

TEST(TableFilesTest, OwnFilesSitBesideTheTable) {
  const std::vector<OutputFile> files = OwnTableFiles(
      "out/dfg.ktx2", Container::kKtx2, true, true, {ShaderLanguage::kGlsl, ShaderLanguage::kWgsl}, "brdfbake_dfg", 3);
  ASSERT_EQ(files.size(), 4u);
  EXPECT_EQ(files[0].path, "out/dfg.ktx2");
  EXPECT_EQ(files[0].container, Container::kKtx2);
  EXPECT_FALSE(files[0].table_exr);  // only an EXR can be the table's own
  EXPECT_EQ(files[1].path, "out/dfg.h");
  EXPECT_EQ(files[1].container, Container::kHeader);
  EXPECT_EQ(files[2].path, "out/dfg.glsl");
  EXPECT_TRUE(files[2].lookup);
  EXPECT_EQ(files[3].path, "out/dfg.wgsl");
  EXPECT_EQ(files[3].language, ShaderLanguage::kWgsl);
  for (const OutputFile& f : files) {
    EXPECT_EQ(f.table, 3);
    EXPECT_EQ(f.symbol, "brdfbake_dfg");
  }
  EXPECT_EQ(LookupPath("a.b/E.exr", ShaderLanguage::kHlsl), "a.b/E.hlsl");
  EXPECT_TRUE(OwnTableFiles("E.exr", Container::kExr, true, false, {}, "s")[0].table_exr);
}

TEST(TableFilesTest, WritesWhatThePlanSays) {
  BakeSpec spec;
  spec.mu.size = spec.roughness.size = 4;
  const Table t = Bake(spec);
  const Image im = ArrangeTable(t, DefaultLayout(t));
  const std::string dir = test::Scratch("table_files");
  for (const OutputFile& f :
       OwnTableFiles(dir + "/E.exr", Container::kExr, true, true, {ShaderLanguage::kGlsl}, "brdfbake_E")) {
    WriteOutputFile(f, t, im, "");
  }
  const ExrContents back = ReadExr(dir + "/E.exr");
  EXPECT_EQ(back.channels.size(), t.channels.size());
  EXPECT_NE(test::Slurp(dir + "/E.h").find("brdfbake_E["), std::string::npos);
  EXPECT_NE(test::Slurp(dir + "/E.glsl").find("brdfbake_E("), std::string::npos);
  // A file of every table is its preset's to write.
  OutputFile all;
  all.path = dir + "/all.h";
  all.table = -1;
  EXPECT_THROW(WriteOutputFile(all, t, im, ""), std::invalid_argument);
  EXPECT_FALSE(std::filesystem::exists(dir + "/all.h"));
}

// A preset's lookups are named by their symbols and carry brdfbake_
// before it; its tables' files carry the engine's symbol.
TEST(TableFilesTest, PresetFilesNameTheirSymbols) {
  PresetRun run;
  run.dir = "d";
  run.shaders = {ShaderLanguage::kGlsl};
  const std::vector<PresetFile> files = PresetFiles(FindPreset("filament"), run);
  ASSERT_EQ(files.size(), 2u);
  EXPECT_EQ(files[0].path, "d/dfg.inc");
  EXPECT_EQ(files[0].symbol, "DFG_LUT");
  EXPECT_EQ(files[1].path, "d/DFG_LUT.glsl");
  EXPECT_EQ(files[1].symbol, "brdfbake_DFG_LUT");
}

}  // namespace
}  // namespace brdfbake
