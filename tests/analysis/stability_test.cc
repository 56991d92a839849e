// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The stability report: no float kernel (the SIMD kernels of every model
// family and the float instantiation of the scalar reference) produces a
// non-finite value in any region of the documented domain, and every sample
// stays within its stated bound (include/brdfbake/models/kernel_bounds.h).

#include "brdfbake/stability.h"

#include <cstdio>
#include <set>
#include <sstream>

#include <gtest/gtest.h>

namespace brdfbake {
namespace {

TEST(StabilityTest, NoNonFiniteOutputAndEveryRegionWithinItsBound) {
  const std::vector<StabilityRow> rows = RunStability(5000, 3);
  ASSERT_GT(rows.size(), 100u);
  int simd_rows = 0;
  std::set<std::string> simd_models;
  for (const StabilityRow& r : rows) {
    const std::string what = r.region + " " + r.model + " " + r.quantity + " " + r.kernel;
    EXPECT_EQ(r.non_finite, 0) << what;
    EXPECT_EQ(r.samples, 5000) << what;
    // Each sample's error within that sample's stated bound.
    EXPECT_LE(r.max_error_over_bound, 1.0) << what << " max rel error " << r.max_rel_error;
    EXPECT_TRUE(r.Within()) << what;
    if (r.kernel.rfind("simd:", 0) == 0) {
      ++simd_rows;
      simd_models.insert(r.model);
    }
  }
  // Every model family's SIMD kernels are in the report.
  EXPECT_EQ(simd_models, (std::set<std::string>{"beckmann", "ellipsoid", "ggx", "std"}));
  EXPECT_GT(simd_rows, 40);
  std::ostringstream csv;
  WriteStabilityCsv(rows, csv);
  std::printf("%s", csv.str().c_str());
}

}  // namespace
}  // namespace brdfbake
