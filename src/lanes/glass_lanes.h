// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The glass family's rule (glass_albedo.h) in double SIMD lanes.

#ifndef BRDFBAKE_SRC_LANES_GLASS_LANES_H_
#define BRDFBAKE_SRC_LANES_GLASS_LANES_H_

#include "brdfbake/models/brdf.h"
#include "brdfbake/models/dielectric.h"
#include "rules/glass/glass_albedo.h"

namespace brdfbake {

// GlassAlbedo (glass_albedo.h) from the parameters, each ray piece's 15
// nodes in lanes; alpha = 0 is the smooth interface (E = 1; its
// reflection F, its refraction 1 - F).
RuleResult SimdGlassAlbedo(double alpha, double eta, Masking masking, double mu, double tol, int max_pieces,
                           DielectricPart part = DielectricPart::kBoth);
// Its integrand at 15 angles theta along the ray phi (the values the
// rule's ScalarGlassNodes gives), for the tests.
void SimdGlassNodeValues(double alpha, double eta, Masking masking, double mu, double phi, const double* theta,
                         double* v, DielectricPart part = DielectricPart::kBoth);

// The K15 and G7 sums of the piece [ta, tb] of t of the segment [a, b]
// (MappedSegment) of the ray phi (MappedPieceSums of ScalarGlassNodes),
// for the tests.
void SimdGlassPieceSums(double alpha, double eta, Masking masking, double mu, double phi, double a, double b,
                        bool singular_a, bool singular_b, double ta, double tb, double* kron, double* gauss);

// GlassAlbedoAverage (glass_average.h) with each psi piece's nodes and
// Kronrod sums in lanes.
RuleResult SimdGlassAlbedoAverage(double alpha, double eta, Masking masking, double tol, int max_pieces,
                                  DielectricPart part = DielectricPart::kBoth);
// A psi line's 15 node values (ScalarAverageLines' at the coefficients
// a0, a1, b0, b1 of AverageLine), for the tests.
void SimdGlassAverageLineValues(double alpha, Masking masking, const double* coefficients, const double* w,
                                double* v);
// The K15 and G7 sums of the psi piece [a, b] of w along that line
// (ScalarAverageLines::Pieces), for the tests.
void SimdGlassAverageLineSums(double alpha, Masking masking, const double* coefficients, double a, double b,
                              double* kron, double* gauss);

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_LANES_GLASS_LANES_H_
