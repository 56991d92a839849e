// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// `report`: every integrator over its budget ladder, errors against the
// converged reference, the integrators' own estimates bounding the true
// error, interpolation error, and the CSV/SVG outputs, for every table kind.

#include "brdfbake/report.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <stdexcept>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "brdfbake/model.h"

namespace brdfbake {
namespace {

std::string ReadFile(const std::string& path) {
  std::ifstream in(path);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

void CheckReport(TableKind kind) {
  ReportSpec spec;
  spec.table.table = kind;
  spec.table.mu.size = 4;
  spec.table.roughness.size = kind == TableKind::kEavg ? 2 : 4;
  spec.repeats = 1;
  spec.reference_tolerance = 1e-10;
  spec.interpolation_sizes = {3, kind == TableKind::kEavg ? 4 : 6};
  spec.interpolation_probes = kind == TableKind::kEavg ? 2 : 4;
  const Report r = RunReport(spec);
  std::set<std::string> integrators;
  for (const ReportRow& row : r.rows) {
    integrators.insert(row.integrator);
    EXPECT_GT(row.seconds_median, 0.0);
    EXPECT_TRUE(std::isfinite(row.max_abs_error));
    EXPECT_LE(row.rms_error, row.max_abs_error + 1e-15);
    // The integrator's own estimate bounds its true error.
    EXPECT_LE(row.max_abs_error, row.claimed_max_error + 2 * r.reference_claimed_error)
        << row.integrator << " " << row.budget;
  }
  EXPECT_EQ(integrators.size(), 4u);
  EXPECT_GE(r.rows.size(), 16u);
  // The deterministic quadrature at its tightest tolerance (row 5: 1e-8)
  // meets that tolerance.
  ASSERT_EQ(r.rows[5].integrator, "quadrature");
  EXPECT_EQ(r.rows[5].budget, 1e-8);
  EXPECT_LE(r.rows[5].max_abs_error, 1e-8 + 2 * r.reference_claimed_error);
  ASSERT_EQ(r.interpolation.size(), 2u);
  for (const InterpolationRow& row : r.interpolation) {
    EXPECT_GT(row.probes, 0);
    EXPECT_TRUE(std::isfinite(row.max_abs_error));
  }
  const std::string dir = ::testing::TempDir() + "/brdfbake_report_" + TableName(kind);
  std::filesystem::create_directories(dir);
  WriteReport(r, dir);
  const std::string csv = ReadFile(dir + "/report.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "integrator,budget_name,budget,seconds_median,seconds_min,max_abs_error,rms_error,"
            "claimed_max_error");
  int lines = 0;
  for (char c : csv) lines += c == '\n';
  EXPECT_EQ(lines, static_cast<int>(r.rows.size()) + 1);
  const std::string svg = ReadFile(dir + "/report.svg");
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find("polyline"), std::string::npos);
  EXPECT_NE(svg.find("quadrature"), std::string::npos);
  EXPECT_NE(svg.find("engine"), std::string::npos);
  EXPECT_NE(ReadFile(dir + "/interpolation.csv").find("size,max_abs_error"), std::string::npos);
  EXPECT_NE(ReadFile(dir + "/interpolation.svg").find("polyline"), std::string::npos);
}

TEST(ReportTest, ETable) { CheckReport(TableKind::kE); }
TEST(ReportTest, DfgTable) { CheckReport(TableKind::kDfg); }
TEST(ReportTest, EavgTable) { CheckReport(TableKind::kEavg); }

// A table the quadrature alone bakes has its ladder alone (no sampling
// rows that its spec would refuse), with the claims bounding the error;
// one over mu x roughness (f82_bias), or over ior slices too (ggx-glass),
// has its interpolation study, the slope-plane tables (sel_norm, the
// ellipsoid) none; tables with an axis of their own the probe does not
// know (gen_schlick's exponent) are refused.
TEST(ReportTest, QuadratureOnlyTablesHaveTheirLadderAlone) {
  struct Case {
    TableKind table;
    ModelKind model;
    size_t interpolation_rows;
  };
  std::vector<Case> cases = {{TableKind::kF82Bias, ModelKind::kGgx, 1}};
  if (ModelBuilt(ModelKind::kSel)) cases.push_back({TableKind::kSelNorm, ModelKind::kSel, 0});
  if (ModelBuilt(ModelKind::kGgxGlass)) {
    // Over ior slices too: the study's tables are n^3 (E_avg n^2).
    cases.push_back({TableKind::kE, ModelKind::kGgxGlass, 1});
    cases.push_back({TableKind::kEavg, ModelKind::kGgxGlass, 1});
  }
  if (ModelBuilt(ModelKind::kEllipsoid)) {
    cases.push_back({TableKind::kE, ModelKind::kEllipsoid, 0});
    cases.push_back({TableKind::kEavg, ModelKind::kEllipsoid, 0});  // one value
  }
  for (const Case& c : cases) {
    ReportSpec spec;
    spec.table.table = c.table;
    spec.table.model.kind = c.model;
    spec.table.mu.size = spec.table.roughness.size = spec.table.phi.size = 3;
    spec.table.alpha_x.size = spec.table.alpha_y.size = spec.table.ior.size = 3;
    spec.table.integrator = IntegratorKind::kQuadrature;
    spec.repeats = 1;
    spec.reference_tolerance = 1e-10;
    spec.interpolation_sizes = {3};
    spec.interpolation_probes = 2;
    const Report r = RunReport(spec);
    ASSERT_EQ(r.rows.size(), 6u) << TableName(c.table);
    for (const ReportRow& row : r.rows) {
      EXPECT_EQ(row.integrator, "quadrature");
      EXPECT_LE(row.max_abs_error, row.claimed_max_error + 2 * r.reference_claimed_error)
          << TableName(c.table) << " " << row.budget;
    }
    ASSERT_EQ(r.interpolation.size(), c.interpolation_rows) << TableName(c.table);
    for (const InterpolationRow& row : r.interpolation) {
      EXPECT_GT(row.probes, 0);
      EXPECT_TRUE(std::isfinite(row.max_abs_error));
      EXPECT_GT(row.max_abs_error, 0.0);
    }
  }
  ReportSpec gen;
  gen.table.table = TableKind::kGenSchlickS;
  gen.table.mu.size = gen.table.roughness.size = gen.table.exponent.size = 2;
  try {
    RunReport(gen);
    ADD_FAILURE() << "gen_schlick_s was reported";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("an axis over exponent the report does not interpolate"), std::string::npos)
        << e.what();
  }
}

TEST(ReportTest, SvgScalesAreLogarithmic) {
  const std::string svg = LogLogSvg("t", "x", "y", {{"a", {1e-3, 1e-1}, {1e-6, 1e-2}}}, "note");
  EXPECT_NE(svg.find(">1e-3<"), std::string::npos);
  EXPECT_NE(svg.find(">1e-1<"), std::string::npos);
  EXPECT_NE(svg.find(">1e-6<"), std::string::npos);
  EXPECT_NE(svg.find(">1e-2<"), std::string::npos);
}

}  // namespace
}  // namespace brdfbake
