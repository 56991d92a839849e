// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0

#include "rules/ggx_aniso/aniso_ggx.h"

#include "rules/ggx_aniso/aniso_ggx_rule.h"

namespace brdfbake {

RuleResult AnisoGgxAlbedo(double alpha_x, double alpha_y, double mu, double phi,
                               Masking masking, double tol, int max_pieces) {
  return AnisoGgxAlbedoWith(alpha_x, alpha_y, mu, phi, masking, tol, max_pieces,
                            ScalarAnisoNodes{});
}

}  // namespace brdfbake
