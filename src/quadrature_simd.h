// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The baker's two-dimensional quadrature (integrate.h, QuadratureTexel) with
// its integrand evaluated in double-precision SIMD lanes: the same nodes,
// horizon splits, ladder and error estimate as the scalar reference, the
// quadrature nodes of each piece and the horizon probes of each line
// several per vector. Dispatched once per texel to the best Highway target
// (or the one ForceTarget chose).

#ifndef BRDFBAKE_SRC_QUADRATURE_SIMD_H_
#define BRDFBAKE_SRC_QUADRATURE_SIMD_H_

#include "brdfbake/beckmann.h"
#include "brdfbake/brdf.h"
#include "brdfbake/ggx.h"
#include "brdfbake/std_ndf.h"
#include "azimuthal.h"
#include "integrate.h"

namespace brdfbake {

// GgxAzimuthalDfg with the azimuthal remainder's nodes in lanes.
AzimuthalDfgResult SimdGgxAzimuthalDfg(double alpha, double mu, Masking masking, double tol,
                                       int max_pieces);

TexelValue SimdQuadratureTexel(const GgxNdf<double>& ndf, double mu, Masking masking,
                               int max_nodes, double tol);
#if BRDFBAKE_WITH_BECKMANN
TexelValue SimdQuadratureTexel(const BeckmannNdf<double>& ndf, double mu, Masking masking,
                               int max_nodes, double tol);
#endif
#if BRDFBAKE_WITH_STD
TexelValue SimdQuadratureTexel(const StdNdf<double>& ndf, double mu, Masking masking,
                               int max_nodes, double tol);
#endif

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_QUADRATURE_SIMD_H_
