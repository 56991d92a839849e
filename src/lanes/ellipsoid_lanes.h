// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The ellipsoid's slope-plane rule (ellipsoid_albedo.h) in double SIMD
// lanes: its rays set up, its kinks' brackets searched and its nodes
// evaluated a lane each.

#ifndef BRDFBAKE_SRC_LANES_ELLIPSOID_LANES_H_
#define BRDFBAKE_SRC_LANES_ELLIPSOID_LANES_H_

#include "brdfbake/models/brdf.h"
#include "quadrature/poly_roots.h"
#include "rules/ellipsoid/ellipsoid_albedo.h"

namespace brdfbake {

class EllipsoidRay;
// EllipsoidRay::SetUp for rays[0..n) (one frame), a ray per lane, as the
// ellipsoid rule sets its rays up.
void SimdSetUpEllipsoidRays(EllipsoidRay* rays, int n);
// PolyRootsInBatch (poly_roots.h) with the brackets searched in lanes, as
// the ellipsoid's kinks are: each root to its problem's tolerance.
void SimdPolyRootsInBatch(PolyRootsProblem* problems, int m);
// EllipsoidAlbedo (ellipsoid_albedo.h) with each ray piece's nodes in lanes.
RuleResult SimdEllipsoidAlbedo(double alpha_x, double alpha_y, double theta_x,
                                    double theta_y, double theta_z, double mu, double phi,
                                    Masking masking, double tol, int max_pieces);

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_LANES_ELLIPSOID_LANES_H_
