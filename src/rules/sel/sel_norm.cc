// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0

#include "rules/sel/sel_norm.h"

#include "rules/sel/sel_norm_rule.h"

namespace brdfbake {

SelIntegral SelLobeIntegral(double alpha_x, double alpha_y, double tol) {
  return SelLobeIntegralWith(alpha_x, alpha_y, tol, ScalarSelNodes{});
}

}  // namespace brdfbake
