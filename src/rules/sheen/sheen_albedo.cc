// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0

#include "rules/sheen/sheen_albedo.h"

#include "rules/sheen/sheen_albedo_rule.h"

namespace brdfbake {

RuleResult CharlieAlbedo(const CharlieSheen<double>& sheen, double mu, double tol, int max_pieces) {
  return CharlieAlbedoWith(sheen, mu, tol, max_pieces, ScalarCharlieNodes{&sheen});
}

RuleResult DisneyAlbedo(double r, double mu) { return DisneyAlbedoWith(mu, ScalarDisneyNodes{r}); }

RuleResult DisneyEavg(double r) { return DisneyEavgWith(ScalarDisneyNodes{r}); }

}  // namespace brdfbake
