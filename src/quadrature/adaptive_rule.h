// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The adaptive Gauss-Kronrod machinery the slope-plane rules (aniso_ggx,
// ellipsoid_albedo), the sel integral and the E_avg rules share: a piece
// with its Kronrod 15 value and |K15 - G7| estimate (and the errors of
// inner integrals carried through the Kronrod weights), worst-first
// bisection, and the rule over the ray angle psi of the slope plane.

#ifndef BRDFBAKE_SRC_QUADRATURE_ADAPTIVE_RULE_H_
#define BRDFBAKE_SRC_QUADRATURE_ADAPTIVE_RULE_H_

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "brdfbake/models/vec3.h"
#include "quadrature/kronrod.h"

namespace brdfbake {

// The view of the slope-plane rules: wo at cos(theta) = mu (at least
// 1e-7) and azimuth phi, and the centre c = -wo_xy / wo.z of the horizon
// disk |s - c| < 1 / wo.z in slopes.
struct SlopeView {
  double wx, wy, wz, cx, cy;
  SlopeView(double mu, double phi) {
    wz = std::clamp(mu, 1e-7, 1.0);
    const double so = std::sqrt((1 - wz) * (1 + wz));
    wx = so * std::cos(phi);
    wy = so * std::sin(phi);
    cx = -wx / wz;
    cy = -wy / wz;
  }
};

// std::remainder(d, 2 pi): d less the nearest multiple of 2 pi, exactly.
// Angle differences within 2.5 pi take a short path that gives the same
// value (there d -+ 2 pi is exact, Sterbenz's lemma), without the C
// library's general reduction.
inline double WrapAngle(double d) {
  if (d > kPi<double>) return d < 2.5 * kPi<double> ? d - kTwoPi<double> : std::remainder(d, kTwoPi<double>);
  if (d < -kPi<double>) return d > -2.5 * kPi<double> ? d + kTwoPi<double> : std::remainder(d, kTwoPi<double>);
  return d;
}

struct GkPiece {
  double a = 0, b = 0, value = 0, err = 0, prop = 0;
};

// Gauss-Kronrod 15 on [a, b] times `scale` from the integrand v[i] at the
// 15 nodes of [a, b] (Kronrod15's x mapped to it) and the errors e[i] of
// its own (inner) evaluation there.
inline GkPiece KronrodPieceOf(double a, double b, double scale, const double* v, const double* e) {
  const KronrodRule& r = Kronrod15();
  double k = 0, g = 0, prop = 0;
  for (int i = 0; i < 15; ++i) {
    k += r.wk[i] * v[i];
    g += r.wg[i] * v[i];
    prop += r.wk[i] * e[i];
  }
  const double s = 0.5 * (b - a) * scale;
  return GkPiece{a, b, k * s, std::abs(k - g) * s, prop * s};
}

// The same of a batch integrand: f(x, v, e) fills v[i] and e[i] at the 15
// nodes x[i].
template <class F>
GkPiece KronrodPieceBatch(double a, double b, double scale, const F& f) {
  const KronrodRule& r = Kronrod15();
  const double c = 0.5 * (a + b), h = 0.5 * (b - a);
  double x[15], v[15], e[15];
  for (int i = 0; i < 15; ++i) x[i] = c + h * r.x[i];
  f(x, v, e);
  return KronrodPieceOf(a, b, scale, v, e);
}

// The same for f(x, &inner_err) returning the integrand at one point.
template <class F>
GkPiece KronrodPiece(double a, double b, double scale, const F& f) {
  return KronrodPieceBatch(a, b, scale, [&](const double* x, double* v, double* e) {
    for (int i = 0; i < 15; ++i) {
      e[i] = 0;
      v[i] = f(x[i], &e[i]);
    }
  });
}

// Replaces the piece with the largest `err` by its two halves, made by
// make(a, b).
template <class Piece, class Make>
void BisectWorst(std::vector<Piece>* pieces, const Make& make) {
  size_t worst = 0;
  for (size_t i = 1; i < pieces->size(); ++i) {
    if ((*pieces)[i].err > (*pieces)[worst].err) worst = i;
  }
  const Piece p = (*pieces)[worst];
  const double m = 0.5 * (p.a + p.b);
  (*pieces)[worst] = make(p.a, m);
  pieces->push_back(make(m, p.b));
}

// A rule's result from its final pieces: their values summed in order,
// and the error `err` plus the rounding of that sum.
template <class Piece>
RuleResult SumOfPieces(const Piece* pieces, size_t n, double err) {
  RuleResult out;
  for (size_t i = 0; i < n; ++i) out.value += pieces[i].value;
  out.error = err + 4e-16 * out.value;
  out.pieces = static_cast<int>(n);
  return out;
}
template <class Piece>
RuleResult SumOfPieces(const std::vector<Piece>& pieces, double err) {
  return SumOfPieces(pieces.data(), pieces.size(), err);
}

// One interval [a, b] of psi for SegmentRule. An end is `singular` where
// the ray there is tangent to a curve on which the ray integrand ends or
// has a kink (the horizon, G1's clamp edge): the ray integral then behaves
// like |psi - end|^(3/2), which the map psi = a + (b - a) m(t), m(t) ~ t^2
// at that end, turns into a smooth function of t. `feature` (> 0) is the
// width of a narrow smooth feature next to an end, graded towards.
struct PsiSegment {
  double a, b;
  bool singular_a = false, singular_b = false;
  double feature_a = 0, feature_b = 0;
};

// The index of the segment of `segments` (ascending, covering [lo, lo +
// 2 pi)) whose interior holds psi taken modulo 2 pi, that angle in *t; -1
// where psi falls on a segment's end.
inline int SegmentHolding(const std::vector<PsiSegment>& segments, double lo, double psi,
                          double* t) {
  *t = lo + std::remainder(psi - lo - kPi<double>, kTwoPi<double>) + kPi<double>;
  for (size_t i = 0; i < segments.size(); ++i) {
    if (segments[i].a < *t && *t < segments[i].b) return static_cast<int>(i);
  }
  return -1;
}

// Splits the segment of `segments` (ascending, covering [lo, lo + 2 pi))
// that holds psi (taken modulo 2 pi) at psi: both sides singular there (a
// ray tangent to a curve where the integrand ends or has a kink), or
// graded towards it down to half of `feature` (a narrow smooth feature).
// A feature at an end of the segment cut reaches across a cut nearer to
// it than its width: the far side is graded towards the cut as well.
// (Without that, an ellipsoid at alpha 0.05 x 0.3, theta_x 70, theta_z 20
// degrees, mu 0.21277, phi 1.60422 had a tangent ray 0.0067 from a
// feature ray of width 0.106, and the next quarter turn stayed one
// Kronrod piece, which missed by 4.6e-8 against a claim of 2.8e-8.)
inline void SplitSegment(std::vector<PsiSegment>* segments, double lo, double psi, bool singular,
                         double feature) {
  double t;
  const int i = SegmentHolding(*segments, lo, psi, &t);
  if (i < 0) return;
  PsiSegment& g = (*segments)[i];
  PsiSegment right = g;
  right.a = t;
  right.singular_a = singular;
  right.feature_a = t - g.a < g.feature_a ? std::max(feature, g.feature_a) : feature;
  g.feature_b = g.b - t < g.feature_b ? std::max(feature, g.feature_b) : feature;
  g.b = t;
  g.singular_b = singular;
  segments->insert(segments->begin() + i + 1, right);
}

// A ray psi where G2's rise at the horizon end is narrowest
// (ellipsoid_albedo_rule.h, HorizonApproaches), and the width of the
// feature it makes over psi.
struct HorizonApproach {
  double psi, width;
};

// A smooth feature of width w centred on the ray psi (singularities of the
// ray integral at psi +- i w), narrower than half the initial piece of its
// segment (at most a quarter turn): a cut there, graded towards from both
// sides down to w (`feature` 2 w), so that the singularities are no
// nearer to a piece than its width. Wider ones are left to the pieces.
inline void CutAtNarrowFeature(std::vector<PsiSegment>* segments, double lo, double psi, double w) {
  double t;
  const int i = SegmentHolding(*segments, lo, psi, &t);
  if (i < 0) return;
  const PsiSegment& g = (*segments)[i];
  if (w < 0.5 * std::min(g.b - g.a, 0.5 * kPi<double>)) {  // half of at most a quarter turn
    SplitSegment(segments, lo, psi, false, 2 * w);
  }
}

// The sum over `segments` of the integral of the ray integral / (2 pi)
// over each, rays(psi, n, value, err) giving it at n angles psi[i] at once
// (value[i], and its error err[i]): Gauss-Kronrod 15 in t in [0, 1] with
// psi = a + (b - a) m(t), where m(t) = t (no singular end), t^2 (only a),
// 1 - (1 - t)^2 (only b) or t^2 (3 - 2 t) (both); each segment starts
// with one piece per quarter turn (at least one) plus geometric grading
// (ratio 8, measured to need 17% fewer rays than a ratio of 4 for the
// same errors) towards a featured end down to half the feature (the caller
// scales `feature` to the grading its kind needs); then the worst piece
// of all is bisected until the summed |K15 - G7| (below) plus the rays'
// own errors meets `tol`, or bisection stops helping (the worst piece
// below 1/20 of the tolerance per piece), or max_pieces.
// A piece's |K15 - G7| counts three times (kSegmentErrorSafety): on a
// segment between two tangent rays (ellipsoid_albedo_rule.h) an unsplit
// piece was measured to miss by 2.15 times its |K15 - G7| (alpha 0.3 x
// 0.6, theta_x 20, theta_z 30 degrees, mu 0.18, phi 5.2033, tolerance
// 1e-7: true error 1.46e-8, |K15 - G7| 6.8e-9; one bisection brings the
// true error to 1e-14); the factor costs 4.5% more rays over that
// material's 64x64 table.
inline constexpr double kSegmentErrorSafety = 3;
template <class Rays>
RuleResult SegmentRule(const Rays& rays, const std::vector<PsiSegment>& segments, double tol,
                            int max_pieces) {
  struct Piece : GkPiece {
    int segment;
  };
  auto make = [&](int s, double t0, double t1) {
    const PsiSegment& g = segments[s];
    const double w = g.b - g.a;
    const int kind = (g.singular_a ? 1 : 0) + (g.singular_b ? 2 : 0);
    auto f = [&](const double* t, double* v, double* e) {
      double psi[15], jac[15];
      for (int i = 0; i < 15; ++i) {
        double m, dm;
        switch (kind) {
          case 0:
            m = t[i], dm = 1;
            break;
          case 1:
            m = t[i] * t[i], dm = 2 * t[i];
            break;
          case 2:
            m = 1 - (1 - t[i]) * (1 - t[i]), dm = 2 * (1 - t[i]);
            break;
          default:
            m = t[i] * t[i] * (3 - 2 * t[i]), dm = 6 * t[i] * (1 - t[i]);
            break;
        }
        jac[i] = w * dm;
        psi[i] = g.a + w * m;
      }
      rays(psi, 15, v, e);
      for (int i = 0; i < 15; ++i) {
        v[i] *= jac[i];
        e[i] *= jac[i];
      }
    };
    Piece p;
    static_cast<GkPiece&>(p) = KronrodPieceBatch(t0, t1, 1 / kTwoPi<double>, f);
    p.err *= kSegmentErrorSafety;
    p.segment = s;
    return p;
  };
  std::vector<Piece> pieces;
  for (int s = 0; s < static_cast<int>(segments.size()); ++s) {
    const PsiSegment& g = segments[s];
    const double w = g.b - g.a;
    if (!(w > 0)) continue;
    // t at which psi is `d` away from end a (b) for the map near that end.
    auto t_near = [&](double d, bool singular) { return singular ? std::sqrt(d / w) : d / w; };
    std::vector<double> cuts;
    // (A turn that rounds to a hair over a multiple of pi / 2 gets no extra piece.)
    const int n = std::clamp(static_cast<int>(std::ceil(w / (kTwoPi<double> / 4) - 1e-9)), 1, 8);
    for (int i = 0; i <= n; ++i) cuts.push_back(static_cast<double>(i) / n);
    if (g.feature_a > 0) {
      for (double d = w * 0.125; d > 0.5 * g.feature_a && cuts.size() < 40; d *= 0.125) {
        cuts.push_back(t_near(d, g.singular_a));
      }
    }
    if (g.feature_b > 0) {
      for (double d = w * 0.125; d > 0.5 * g.feature_b && cuts.size() < 80; d *= 0.125) {
        cuts.push_back(1 - t_near(d, g.singular_b));
      }
    }
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
    for (size_t i = 0; i + 1 < cuts.size(); ++i) pieces.push_back(make(s, cuts[i], cuts[i + 1]));
  }
  auto total_error = [&] {
    double e = 0;
    for (const Piece& p : pieces) e += p.err + p.prop;
    return e;
  };
  double err = total_error();
  while (err > tol && !pieces.empty() &&
         static_cast<int>(pieces.size()) < std::max(4, max_pieces)) {
    size_t worst = 0;
    for (size_t i = 1; i < pieces.size(); ++i) {
      if (pieces[i].err > pieces[worst].err) worst = i;
    }
    if (pieces[worst].err <= 0.05 * tol / pieces.size()) break;
    const Piece p = pieces[worst];
    const double m = 0.5 * (p.a + p.b);
    pieces[worst] = make(p.segment, p.a, m);
    pieces.push_back(make(p.segment, m, p.b));
    err = total_error();
  }
  return SumOfPieces(pieces, err);
}

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_QUADRATURE_ADAPTIVE_RULE_H_
