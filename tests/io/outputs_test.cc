// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The one orchestration of `bake --table`, presets and scenes (outputs.h):
// a request's checks name their parameter, the set bakes, arranges and
// writes what Bake, ArrangeTable and WriteOutputFile give one by one, an
// arrangement is made only where a file needs it, and a preset's stages
// are reported.

#include "brdfbake/outputs.h"

#include <gtest/gtest.h>

#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "brdfbake/error.h"
#include "brdfbake/exr.h"
#include "brdfbake/model.h"
#include "util/file_util.h"

namespace brdfbake {
namespace {

BakeSpec SmallSpec(TableKind kind) {
  BakeSpec spec;
  spec.table = kind;
  spec.mu.size = spec.roughness.size = 6;
  return spec;
}

// The marked message of the error `f` throws, or "" if none.
template <class F>
std::string ErrorOf(const F& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return ErrorText(e);
  }
  return "";
}

TEST(OutputsTest, LayoutFromTheSpecIsTheBakedTables) {
  std::vector<BakeSpec> specs = {SmallSpec(TableKind::kE), SmallSpec(TableKind::kDfg), SmallSpec(TableKind::kEavg)};
  specs[1].complement = specs[1].error_channel = true;
  specs[2].half = true;
  for (const BakeSpec& s : specs) {
    const ImageLayout a = DefaultLayout(s), b = DefaultLayout(Bake(s));
    ASSERT_EQ(a.channels.size(), b.channels.size()) << TableName(s.table);
    for (size_t c = 0; c < a.channels.size(); ++c) {
      EXPECT_EQ(a.channels[c].name, b.channels[c].name);
      EXPECT_EQ(a.channels[c].source, b.channels[c].source);
    }
    EXPECT_EQ(a.pixel, b.pixel);
  }
}

TEST(OutputsTest, TableRequestWritesWhatEachStepGivesAlone) {
  const std::string dir = test::Scratch("outputs_table");
  TableRequest r;
  r.spec = SmallSpec(TableKind::kDfg);
  r.output = dir + "/dfg.ktx2";
  r.shaders = {ShaderLanguage::kGlsl};
  const OutputSet set = TableOutputs(r);
  ASSERT_EQ(set.files.size(), 2u);
  EXPECT_EQ(set.files[0].symbol, "brdfbake_ggx_dfg");
  CheckOutputs(set);
  int stages = 0;
  const BakedOutputs baked = BakeOutputs(set, 0, std::nullopt, nullptr, [&] { ++stages; });
  EXPECT_EQ(stages, 1);  // the bake; no table of the layout's to bake
  WriteOutputs(set, baked.tables, baked.images);

  // The same files, step by step.
  const Table t = Bake(r.spec);
  const Image im = ArrangeTable(t, DefaultLayout(t));
  EXPECT_EQ(baked.tables[0].channels[0].values, t.channels[0].values);
  EXPECT_EQ(baked.images[0].values, im.values);
  for (const OutputFile& f : set.files) {
    OutputFile alone = f;
    alone.path = f.path + ".alone";
    WriteOutputFile(alone, t, im, "");
    EXPECT_EQ(test::Slurp(f.path), test::Slurp(alone.path)) << f.path;
  }
}

TEST(OutputsTest, ArrangesOnlyWhereAFileNeedsIt) {
  const std::string dir = test::Scratch("outputs_arrange");
  TableRequest r;
  r.spec = SmallSpec(TableKind::kE);
  r.output = dir + "/E.exr";
  const OutputSet own = TableOutputs(r);
  ASSERT_EQ(own.files.size(), 1u);
  EXPECT_TRUE(own.files[0].table_exr);
  BakedOutputs baked = BakeOutputs(own, 1, std::nullopt);
  EXPECT_TRUE(baked.images[0].values.empty());
  WriteOutputs(own, baked.tables, baked.images);
  EXPECT_EQ(ReadExr(r.output).channels.size(), baked.tables[0].channels.size());
  // A lookup reads the arrangement; so does rgba's EXR.
  r.shaders = {ShaderLanguage::kWgsl};
  baked = BakeOutputs(TableOutputs(r), 1, std::nullopt);
  EXPECT_EQ(baked.images[0].values.size(), 36u);
  r.shaders.clear();
  r.rgba = true;
  const OutputSet rgba = TableOutputs(r);
  EXPECT_FALSE(rgba.files[0].table_exr);
  EXPECT_EQ(rgba.preset.tables[0].layout.channels.size(), 4u);
  EXPECT_EQ(ArrangeOutputs(rgba, baked.tables)[0].values.size(), 4u * 36u);
  if (ModelBuilt(ModelKind::kSel)) {
    // sel_norm is written as its own EXR only: no layout is made (its
    // channels have none).
    TableRequest sel;
    sel.spec = SmallSpec(TableKind::kSelNorm);
    sel.spec.model.kind = ModelKind::kSel;
    sel.spec.alpha_x.size = sel.spec.alpha_y.size = 3;
    sel.output = dir + "/sel.exr";
    const OutputSet s = TableOutputs(sel);
    EXPECT_TRUE(s.preset.tables[0].layout.channels.empty());
    const BakedOutputs b = BakeOutputs(s, 1, std::nullopt);
    WriteOutputs(s, b.tables, b.images);
    EXPECT_EQ(ReadExr(sel.output).channels.size(), b.tables[0].channels.size());
  }
}

TEST(OutputsTest, RequestErrorsNameTheParameter) {
  auto error = [](TableKind kind, const std::string& output, const std::function<void(TableRequest*)>& set) {
    TableRequest r;
    r.spec = SmallSpec(kind);
    if (kind == TableKind::kSelNorm) r.spec.model.kind = ModelKind::kSel;
    r.output = output;
    set(&r);
    return ErrorOf([&] { TableOutputs(r); });
  };
  auto none = [](TableRequest*) {};
  EXPECT_EQ(error(TableKind::kE, "E.png", none),
            "{output}: png holds unorm8 or unorm16 pixels: give {pixel} unorm8 or unorm16 (got float)");
  EXPECT_EQ(error(TableKind::kE, "E.exr", [](TableRequest* r) { r->pixel = PixelType::kUnorm16; }),
            "{pixel} unorm16: only the dds and png formats hold unorm16 pixels");
  EXPECT_EQ(error(TableKind::kE, "E.dds", [](TableRequest* r) { r->pixel = PixelType::kUnorm8; }),
            "{pixel} unorm8: only the png format holds unorm8 pixels");
  EXPECT_EQ(error(TableKind::kE, "E.exr", [](TableRequest* r) { r->format = "ktx2"; }),
            "{output}: 'E.exr' does not name a ktx2 file");
  EXPECT_EQ(error(TableKind::kE, "E.h", [](TableRequest* r) { r->rgba = true; }),
            "{channels} rgba: applies to the image containers (exr, ktx2, dds), not to header");
  EXPECT_EQ(error(TableKind::kE, "E.exr",
                  [](TableRequest* r) {
                    r->rgba = true;
                    r->spec.error_channel = true;
                  }),
            "{channels} rgba: the error channel has no place among R, G, B and A; bake it with {channels} named");
  EXPECT_EQ(error(TableKind::kE, "E.exr", [](TableRequest* r) { r->symbol = "9x"; }),
            "{symbol}: '9x' is not an identifier (a letter or _, then letters, digits or _)");
  EXPECT_EQ(error(TableKind::kE, "E.exr", [](TableRequest* r) { r->symbol = "gl_E"; }),
            "{symbol}: 'gl_E' is reserved in GLSL (gl_ prefix or __)");
  if (ModelBuilt(ModelKind::kSel)) {
    EXPECT_EQ(error(TableKind::kSelNorm, "sel.h", none), "{output}: sel_norm tables are written as .exr");
    EXPECT_EQ(error(TableKind::kSelNorm, "sel.exr", [](TableRequest* r) { r->rgba = true; }),
              "{channels} rgba: sel_norm tables are written as their own EXR channels only");
  }
  EXPECT_EQ(error(TableKind::kE, "E.exr", none), "");
  EXPECT_EQ(DefaultSymbol(SmallSpec(TableKind::kEavg)), "brdfbake_ggx_E_avg");
}

TEST(OutputsTest, PresetReportsEachStageAndReplacesTheTolerance) {
  if (!PresetBuilt(FindPreset("materialx"))) GTEST_SKIP() << "materialx needs charlie";
  // materialx: a dfg table whose third channel is the Charlie E, baked
  // over its axes during the arrangement.
  Preset p = FindPreset("materialx");
  p.tables[0].spec.mu.size = p.tables[0].spec.roughness.size = 8;
  PresetRun run;
  run.dir = test::Scratch("outputs_preset");
  const OutputSet set = PresetOutputs(p, run);
  CheckOutputs(set);
  int stages = 0;
  int64_t last_total = 0;
  const BakedOutputs baked = BakeOutputs(
      set, 2, 1e-5, [&](int64_t, int64_t total) { last_total = total; }, [&] { ++stages; });
  EXPECT_EQ(stages, 2);  // the dfg, then the sheen E its layout reads
  EXPECT_EQ(last_total, 64);
  EXPECT_EQ(baked.tables[0].spec.tolerance, 1e-5);
  EXPECT_EQ(baked.tables[0].spec.threads, 2);
  ASSERT_EQ(baked.images.size(), 1u);
  EXPECT_EQ(baked.images[0].channels, 3);
  // An invalid tolerance is the spec's error, as a table's own would be.
  EXPECT_NE(ErrorOf([&] { BakeOutputs(set, 1, -1.0); }).find("{tolerance}"), std::string::npos);
}

}  // namespace
}  // namespace brdfbake
