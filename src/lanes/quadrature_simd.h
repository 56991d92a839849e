// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The baker's one-dimensional rules (azimuthal.h for GGX, azimuthal_slope.h
// for Beckmann and STD) in double SIMD lanes: each theta_i piece's 15 nodes
// together (angles, Lambda, G2, the azimuth's parameters or closed form),
// then node by node the nodes of the numerical azimuthal integrals;
// dispatched once per texel to the best Highway target (or the one
// ForceTarget chose). The same pieces and nodes as the scalar references
// GgxAzimuthalAlbedo, GgxAzimuthalDfg and SlopeAzimuthalDfg.

#ifndef BRDFBAKE_SRC_LANES_QUADRATURE_SIMD_H_
#define BRDFBAKE_SRC_LANES_QUADRATURE_SIMD_H_

#include "brdfbake/models/beckmann.h"
#include "brdfbake/models/brdf.h"
#include "brdfbake/models/dielectric.h"
#include "brdfbake/models/ggx.h"
#include "brdfbake/models/std_ndf.h"
#include "brdfbake/targets.h"
#include "quadrature/poly_roots.h"
#include "rules/beckmann/beckmann_azimuth.h"
#include "rules/ggx/azimuthal.h"
#include "rules/sel/sel_norm.h"
#include "rules/sheen/sheen_albedo.h"
#include "rules/slope/azimuthal_slope.h"
#include "rules/std/std_azimuth.h"

namespace brdfbake {

// AnisoGgxAlbedo (aniso_ggx.h) with each ray piece's nodes in lanes.
RuleResult SimdAnisoGgxAlbedo(double alpha_x, double alpha_y, double mu, double phi,
                                   Masking masking, double tol, int max_pieces);

// CharlieAlbedo, DisneyAlbedo and DisneyEavg (sheen_albedo.h) with their
// nodes in lanes.
RuleResult SimdCharlieAlbedo(double alpha, SheenVisibility visibility, double mu, double tol,
                             int max_pieces);
RuleResult SimdDisneyAlbedo(double r, double mu);
RuleResult SimdDisneyEavg(double r);

// GlassAlbedo (glass_albedo.h) from the parameters, each ray piece's 15
// nodes in lanes; alpha = 0 is the smooth interface (E = 1; its
// reflection F, its refraction 1 - F).
RuleResult SimdGlassAlbedo(double alpha, double eta, Masking masking, double mu, double tol, int max_pieces,
                           DielectricPart part = DielectricPart::kBoth);
// Its integrand at 15 angles theta along the ray phi (the values the
// rule's ScalarGlassNodes gives), for the tests.
void SimdGlassNodeValues(double alpha, double eta, Masking masking, double mu, double phi, const double* theta,
                         double* v, DielectricPart part = DielectricPart::kBoth);

// SelLobeIntegral (sel_norm.h) with the inner rule's nodes in lanes.
SelIntegral SimdSelLobeIntegral(double alpha_x, double alpha_y, double tol);
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

// GgxAzimuthalAlbedo with each theta_i piece's 15 nodes in lanes.
RuleResult SimdGgxAzimuthalAlbedo(double alpha, double mu, Masking masking, double tol,
                                       int max_pieces);

// BeckmannAzimuthalAlbedo with each theta_i piece's 15 nodes in lanes
// (angles, Lambda, G2, the closed-form azimuthal moments).
RuleResult SimdBeckmannAzimuthalAlbedo(double alpha, double mu, Masking masking, double tol,
                                            int max_pieces);

#if BRDFBAKE_WITH_STD
// StdAzimuthalAlbedo (finite gamma) with each theta_i piece's 15 nodes in
// lanes (angles, Lambda, G2, the tabulated azimuthal moments).
RuleResult SimdStdAzimuthalAlbedo(const StudentTNdf<double>& ndf, double mu, Masking masking,
                                       double tol, int max_pieces);
#endif

// GgxAzimuthalDfg with each theta_i piece's 15 nodes in lanes (angles, Phi,
// G2, the closed-form moments) and then, node by node, the azimuthal
// remainder's nodes in lanes.
AzimuthalDfgResult SimdGgxAzimuthalDfg(double alpha, double mu, Masking masking, double tol,
                                       int max_pieces);

// SlopeAzimuthalDfg with each theta_i piece's 15 nodes in lanes, then the
// azimuthal integrals' nodes in lanes.
#if BRDFBAKE_WITH_BECKMANN
AzimuthalDfgResult SimdSlopeAzimuthalDfg(const BeckmannNdf<double>& ndf, double mu,
                                         Masking masking, bool with_bias, double tol,
                                         int max_pieces);
#endif
#if BRDFBAKE_WITH_STD
AzimuthalDfgResult SimdSlopeAzimuthalDfg(const StudentTNdf<double>& ndf, double mu, Masking masking,
                                         bool with_bias, double tol, int max_pieces);
#endif

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_LANES_QUADRATURE_SIMD_H_
