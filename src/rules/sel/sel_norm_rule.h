// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The rule of sel_norm.h as a template over the evaluator of g at an inner
// piece's 15 nodes: ScalarSelNodes is the double reference,
// lanes/sel_lanes.cc evaluates the nodes in lanes.

#ifndef BRDFBAKE_SRC_RULES_SEL_SEL_NORM_RULE_H_
#define BRDFBAKE_SRC_RULES_SEL_SEL_NORM_RULE_H_

#include <algorithm>
#include <cmath>
#include <vector>

#include "quadrature/adaptive_rule.h"
#include "rules/sel/sel_norm.h"

namespace brdfbake {

// Gauss-Kronrod 15 on pieces of [lo, hi] graded by 4 towards `toward`
// (lo or hi) down to `finest`, then the worst bisected until the summed
// |K15 - G7| is at most tol (or 200 pieces); f(x, v) fills v with the
// integrand at a piece's 15 nodes x. Returns the integral and its error
// estimate.
template <class F>
void SelAdaptive(const F& f, double lo, double hi, bool toward_lo, double finest, double tol,
                 double* value, double* error) {
  auto piece = [&](double a, double b) {
    return KronrodPieceBatch(a, b, 1.0, [&](const double* x, double* v, double* e) {
      f(x, v);
      for (int i = 0; i < 15; ++i) e[i] = 0;
    });
  };
  std::vector<GkPiece> pieces;
  double width = hi - lo;
  double edge = toward_lo ? hi : lo;  // the end of the graded part not yet covered
  while (width > 4 * finest && pieces.size() < 40) {
    const double next = 0.25 * width;
    pieces.push_back(toward_lo ? piece(lo + next, edge) : piece(edge, hi - next));
    edge = toward_lo ? lo + next : hi - next;
    width = next;
  }
  pieces.push_back(toward_lo ? piece(lo, edge) : piece(edge, hi));
  auto sum_err = [&] {
    double e = 0;
    for (const GkPiece& p : pieces) e += p.err;
    return e;
  };
  while (sum_err() > tol && pieces.size() < 200) BisectWorst(&pieces, piece);
  *value = 0;
  for (const GkPiece& p : pieces) *value += p.value;
  *error = sum_err();
}

// What g depends on at one x (SelLobeIntegralWith): g(phi) =
// 1 / sqrt(s2 (cos^2 phi ikx2 + sin^2 phi iky2) + c^2).
struct SelPhiTerms {
  double s2, c, ikx2, iky2;
};

// The double reference's g at 15 angles.
struct ScalarSelNodes {
  void operator()(const SelPhiTerms& t, const double* phi, double* g) const {
    for (int i = 0; i < 15; ++i) {
      const double cp = std::cos(phi[i]), sp = std::sin(phi[i]);
      g[i] = 1 / std::sqrt(t.s2 * (cp * cp * t.ikx2 + sp * sp * t.iky2) + t.c * t.c);
    }
  }
};

// SelLobeIntegral (sel_norm.h) with g at each inner piece's 15 nodes from
// nodes(terms, phi, g): ScalarSelNodes, or lanes/sel_lanes.cc.
template <class Nodes>
SelIntegral SelLobeIntegralWith(double alpha_x, double alpha_y, double tol, const Nodes& nodes) {
  constexpr double kHalfPi = kPi<double> / 2;
  const double ax = std::clamp(alpha_x, 1e-4, 1.0), ay = std::clamp(alpha_y, 1e-4, 1.0);
  const double a = std::max(ax, ay), a2 = a * a;
  // 1 / k^2 per axis: (alpha / a)^2.
  const double ikx2 = (ax / a) * (ax / a), iky2 = (ay / a) * (ay / a);
  // g peaks on the equator (theta' = pi/2) along the wider alpha's axis:
  // phi = 0 when alpha_x > alpha_y, over a width alpha_min / alpha_max.
  const bool peak_at_zero = ax >= ay;
  const double peak_width = std::min(ax, ay) / a;
  // The inner integral over phi at x, with its error: (2 / pi) int g dphi.
  auto over_phi = [&](double x, double* err) {
    const double d = x + a2 * (1 - x);  // (1 + t) x
    SelPhiTerms terms;
    terms.s2 = 4 * a2 * (1 - x) * x / (d * d);
    terms.c = (x - a2 * (1 - x)) / d;
    terms.ikx2 = ikx2;
    terms.iky2 = iky2;
    auto g = [&](const double* phi, double* out) { nodes(terms, phi, out); };
    double v, e;
    SelAdaptive(g, 0.0, kHalfPi, peak_at_zero, 0.25 * peak_width, 0.1 * tol, &v, &e);
    *err = e / kHalfPi;
    return v / kHalfPi;
  };
  // The x rule evaluates over_phi at its nodes; the inner errors enter with
  // the Kronrod weights.
  std::vector<GkPiece> pieces;
  auto piece = [&](double lo, double hi) { return KronrodPiece(lo, hi, 1.0, over_phi); };
  // Graded towards x = 0 down to a^2 / 4, where theta' = 2 theta_h passes
  // pi / 2 (t = 1 at x = a^2 / (1 + a^2)).
  double edge = 1.0;
  while (edge > a2 && pieces.size() < 40) {
    pieces.push_back(piece(0.25 * edge, edge));
    edge *= 0.25;
  }
  pieces.push_back(piece(0.0, edge));
  auto totals = [&](double* rule, double* inner) {
    *rule = *inner = 0;
    for (const GkPiece& p : pieces) {
      *rule += p.err;
      *inner += p.prop;
    }
  };
  double rule_err, inner_err;
  totals(&rule_err, &inner_err);
  while (rule_err > 0.5 * tol && pieces.size() < 200) {
    BisectWorst(&pieces, piece);
    totals(&rule_err, &inner_err);
  }
  SelIntegral out;
  for (const GkPiece& p : pieces) out.ratio += p.value;
  out.ratio_error = rule_err + inner_err + 4e-16 * out.ratio;
  const double scale = 4 * kPi<double> * ax * ay;
  out.n = scale * out.ratio;
  out.n_error = scale * out.ratio_error;
  return out;
}

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_RULES_SEL_SEL_NORM_RULE_H_
