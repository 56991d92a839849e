// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The stability report: no float kernel produces a non-finite value in any
// region of the documented domain, and the SIMD kernels stay within their
// documented bound there. (The float instantiations of the scalar reference
// are reported, not bounded: see README "Stability".)

#include "brdfbake/stability.h"

#include <cstdio>
#include <sstream>

#include <gtest/gtest.h>

namespace brdfbake {
namespace {

TEST(StabilityTest, NoNonFiniteOutputAndSimdWithinBound) {
  const std::vector<StabilityRow> rows = RunStability(5000, 3);
  ASSERT_GT(rows.size(), 50u);
  int simd_rows = 0;
  for (const StabilityRow& r : rows) {
    EXPECT_EQ(r.non_finite, 0) << r.region << " " << r.model << " " << r.quantity << " "
                               << r.kernel;
    EXPECT_EQ(r.samples, 5000);
    if (r.kernel.rfind("simd:", 0) == 0) {
      ++simd_rows;
      EXPECT_LE(r.max_rel_error, 2e-6) << r.region << " " << r.quantity;
    }
  }
  EXPECT_GT(simd_rows, 0);
  std::ostringstream csv;
  WriteStabilityCsv(rows, csv);
  std::printf("%s", csv.str().c_str());
}

}  // namespace
}  // namespace brdfbake
