// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0

#include "rules/ellipsoid/ellipsoid_albedo.h"

#include "rules/ellipsoid/ellipsoid_albedo_rule.h"

namespace brdfbake {

RuleResult EllipsoidAlbedo(double alpha_x, double alpha_y, double theta_x, double theta_y,
                                double theta_z, double mu, double phi, Masking masking,
                                double tol, int max_pieces) {
  return EllipsoidAlbedoWith(alpha_x, alpha_y, theta_x, theta_y, theta_z, mu, phi, masking, tol,
                             max_pieces, ScalarEllipsoidNodes{});
}

}  // namespace brdfbake
