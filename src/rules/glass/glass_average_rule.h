// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The rule of glass_average.h as a template over the evaluator of its psi
// lines' nodes: ScalarAverageLines is the double reference; a lanes
// evaluator fills the same 15 values per call.

#ifndef BRDFBAKE_SRC_RULES_GLASS_GLASS_AVERAGE_RULE_H_
#define BRDFBAKE_SRC_RULES_GLASS_GLASS_AVERAGE_RULE_H_

#include <algorithm>
#include <cmath>
#include <vector>

#include "brdfbake/models/fresnel.h"
#include "rules/glass/glass_albedo_rule.h"
#include "rules/glass/glass_average.h"

namespace brdfbake {

// What the rule reads of the model: GGX's alpha, eta (and 1 / eta), the
// masking, and the part whose weight it integrates.
struct AverageModel {
  double alpha, a2, eta, inv_eta;
  bool separable;
  DielectricPart part;

  // 1 / (1 + Lambda) of GGX at the cosine z to the normal: 2 z / (z +
  // sqrt(z^2 + alpha^2 (1 - z^2))), 0 on the horizon.
  double G1(double z) const {
    if (!(z > 0)) return 0;
    return 2 * z / (z + std::sqrt(z * z + a2 * (1 - z) * (1 + z)));
  }
  // G2 of two directions at the cosines za, zb >= 0 to the normal.
  double G2(double za, double zb) const {
    const double ga = G1(za), gb = G1(zb);
    if (separable) return ga * gb;
    // 1 / (1 + Lambda_a + Lambda_b) = 1 / (1 / ga + 1 / gb - 1).
    const double d = ga + gb - ga * gb;
    return d > 0 ? ga * gb / d : 0;
  }
  // The weights of the reflection and the refraction at c = wo.h.
  void Weights(double c, double* wr, double* wt) const {
    if (part == DielectricPart::kTransmissionSchlick) {
      const double m = 1 - c;
      *wr = 0;
      *wt = 1 - m * m * m * m * m;
      return;
    }
    const double f = FresnelDielectric(eta, c);
    *wr = RefractionPart(part) ? 0 : f;
    *wt = part == DielectricPart::kReflection ? 0 : 1 - f;
  }
};

// Each level counts its pieces' |K15 - G7| once (GlassSegmentsRule's
// `safety`), and gives the level inside it half its tolerance: over the
// stiff views of glass_average_test (alpha 1e-4 to 1, eta 1/100 to 100,
// every part, both maskings, tolerances 1e-6 and 1e-7) the claims were
// at least 150 times the error against the E rule integrated over mu,
// and at least twenty times over 263 views run by hand.
inline constexpr double kAverageSafety = 1;
inline constexpr double kInnerShare = 0.5;

// The cuts of [lo, hi] graded towards lo (ratio kGlassGrading) down to
// `finest`, and at `cut` if inside, ascending and distinct, in `cuts`
// (room for kMaxGraded + 1); returns the number of pieces [cuts[j],
// cuts[j + 1]], at most kMaxGraded.
inline constexpr int kMaxGraded = 16;
inline int GradedFromLow(double lo, double hi, double finest, double cut, double* cuts) {
  const bool inside = cut > lo && cut < hi;
  // lo + w, w descending, as many as the cuts leave room for.
  double graded[kMaxGraded];
  int ng = 0;
  for (double w = 0.25 * (hi - lo); w > finest && ng + 2 + inside < kMaxGraded; w *= kGlassGrading) {
    graded[ng++] = lo + w;
  }
  // Merged ascending, repeats dropped.
  int m = 0;
  auto add = [&](double x) {
    if (m == 0 || x > cuts[m - 1]) cuts[m++] = x;
  };
  add(lo);
  bool placed = !inside;
  for (int i = ng - 1; i >= 0; --i) {
    if (!placed && cut <= graded[i]) add(cut), placed = true;
    add(graded[i]);
  }
  if (!placed) add(cut);
  add(hi);
  return m - 1;
}

// The psi lines take w in [0, 2] for psi in [0, pi]: w = sqrt(1 - cos(psi))
// up to psi = pi/2 (w = 1), 2 - sqrt(1 + cos(psi)) beyond, so that cos(psi)
// = 1 - y^2 or y^2 - 1 with y = w or 2 - w, and dpsi = 2 dy / sqrt(2 -
// y^2), smooth at both ends (no cosine per node, and no square-root edge
// where a horizon reaches psi = 0). The second derivative jumps at w = 1:
// always a cut.
inline double WOfCos(double x) { return x >= 0 ? std::sqrt(1 - x) : 2 - std::sqrt(1 + x); }
inline void CosOfW(double w, double* x, double* jac) {
  const double y = w <= 1 ? w : 2 - w;
  *x = w <= 1 ? (1 - y) * (1 + y) : (y - 1) * (y + 1);
  *jac = 2 / std::sqrt(2 - y * y);
}

// A psi line: v = jac(w) G2(a0 + a1 x, b0 + b1 x) at nodes w, x =
// cos(psi) and jac = dpsi/dw from CosOfW; the cosines' coefficients are
// the line's.
struct AverageLine {
  double a0, a1, b0, b1;
};

// The double reference of the line's nodes.
struct ScalarAverageLines {
  const AverageModel* model;
  // 15 k nodes: k pieces' 15 each.
  void operator()(const AverageLine& l, const double* w, double* v, int k = 1) const {
    for (int i = 0; i < 15 * k; ++i) {
      double x, jac;
      CosOfW(w[i], &x, &jac);
      v[i] = jac * model->G2(l.a0 + l.a1 * x, l.b0 + l.b1 * x);
    }
  }
  // The sums of the k pieces [a[j], b[j]] of w (k at most kMaxGraded).
  void Pieces(const AverageLine& l, const double* a, const double* b, int k, GlassSums* out) const {
    const KronrodRule& r = Kronrod15();
    for (int j = 0; j < k; ++j) {
      const double c = 0.5 * (a[j] + b[j]), h = 0.5 * (b[j] - a[j]);
      double w[15], v[15];
      for (int i = 0; i < 15; ++i) w[i] = c + h * r.x[i];
      (*this)(l, w, v);
      out[j] = KronrodSums(v, h);
    }
  }
};

// `scale` times the integral over psi from acos(x_hi) to acos(x_lo), x_lo
// <= 0, of the line's G2, to `tol` (absolute), with its error. A horizon
// at x_hi < 1, where G2 turns on over (x_hi - x) ~ `width`, grades the
// pieces towards it. The evaluator forms the sums of the pieces of w
// (GlassSumsRule; a lanes evaluator forms their nodes too, in lanes).
struct PsiLine {
  double value, error;
};

inline constexpr int kMaxLinePieces = 200;

template <class Lines>
PsiLine OverPsi(double x_lo, double x_hi, double width, double scale, double tol, const AverageLine& line,
                const Lines& lines) {
  const double lo = WOfCos(std::min(x_hi, 1.0)), hi = WOfCos(x_lo);
  if (!(hi > lo)) return {0, 0};
  const double finest = x_hi < 1 ? WOfCos(std::max(x_hi - width, -1.0)) - lo : hi - lo;
  double cuts[kMaxGraded + 1];
  const int n = GradedFromLow(lo, hi, finest, 1.0, cuts);
  // GlassSumsRule on the segments [cuts[j], cuts[j + 1]], their pieces on
  // the stack and their first pieces' sums in one call.
  GlassPiece pieces[kMaxLinePieces];
  GlassSums sums[kMaxGraded];
  lines.Pieces(line, cuts, cuts + 1, n, sums);
  for (int j = 0; j < n; ++j) {
    GlassPiece whole;
    whole.a = 0.0, whole.b = 1.0, whole.segment = j;
    pieces[j] = GlassPieceOfSums(whole, sums[j], scale, kAverageSafety);
  }
  auto make = [&](const GlassPiece* spans, int k, GlassPiece* out) {
    double a[kGlassPieceBatch], b[kGlassPieceBatch];
    for (int j = 0; j < k; ++j) {
      const double lo_j = cuts[spans[j].segment], width = cuts[spans[j].segment + 1] - lo_j;
      a[j] = lo_j + width * spans[j].a;
      b[j] = lo_j + width * spans[j].b;
    }
    lines.Pieces(line, a, b, k, sums);
    for (int j = 0; j < k; ++j) out[j] = GlassPieceOfSums(spans[j], sums[j], scale, kAverageSafety);
  };
  const RuleResult res = GlassBisect(n, tol, kMaxLinePieces, [&](size_t) { return pieces; }, make);
  return {res.value, res.error};
}

// The reflection's line: wo.n = cc - k cos(psi) > 0 and r.n = cc + k
// cos(psi) > 0, |cos(psi)| < A = cc / k; 4 times the integral over psi in
// [acos(min(A, 1)), pi/2].
template <class Lines>
PsiLine ReflectionLine(const AverageModel& m, double cc, double k, double tol, const Lines& lines) {
  const double a = k > 0 ? cc / k : 2.0;
  return OverPsi(0.0, a, m.alpha / k, 4.0, tol, AverageLine{cc, -k, cc, k}, lines);
}

// The refraction's line: wo.n = cc - k cos(psi) > 0 and -t.n = ct
// cos(theta_h) - k cos(psi) / eta > 0, cos(psi) below A = cc / k and B =
// ct cos(theta_h) eta / k; twice the integral over psi in [acos(min(A, B,
// 1)), pi].
template <class Lines>
PsiLine RefractionLine(const AverageModel& m, double cc, double k, double ct, double chh, double tol,
                       const Lines& lines) {
  const double a = k > 0 ? cc / k : 2.0;
  const double b = k > 0 && m.inv_eta > 0 ? ct * chh / (m.inv_eta * k) : 2.0;
  const double slope = b < a ? m.inv_eta * k : k;
  return OverPsi(-1.0, std::min(a, b), m.alpha / slope, 2.0, tol, AverageLine{cc, -k, ct * chh, -m.inv_eta * k},
                 lines);
}

// The c integral at theta_h (sin sh, cos chh): integral_0^1 c [w_r(c)
// R(c) + w_t(c) T(c)] dc to `tol`.
template <class Lines>
RuleResult OverC(const AverageModel& m, double sh, double chh, double tol, const Lines& lines) {
  // The cuts: c = 0, sin(theta_h), and for eta < 1 the critical cosine and
  // B = 1; graded both sides towards each (down to alpha) but the critical
  // cosine, whose square-root edge the map takes.
  struct Cut {
    double c;
    bool singular, graded;
  };
  std::vector<Cut> cuts = {{0.0, false, true}, {sh, true, true}};
  if (m.eta < 1 && m.part != DielectricPart::kTransmissionSchlick) {
    const double crit = std::sqrt((1 - m.eta) * (1 + m.eta));
    cuts.push_back({crit, true, false});
    if (m.part != DielectricPart::kReflection) {
      cuts.push_back({std::sqrt((1 - m.eta * chh) * (1 + m.eta * chh)), true, true});
    }
  }
  cuts.push_back({1.0, false, false});
  std::sort(cuts.begin(), cuts.end(), [](const Cut& x, const Cut& y) { return x.c < y.c; });
  std::vector<double> grade;
  const double finest = m.alpha;
  for (size_t i = 0; i < cuts.size(); ++i) {
    if (!cuts[i].graded) continue;
    const double below = i > 0 ? cuts[i].c - cuts[i - 1].c : 0;
    const double above = i + 1 < cuts.size() ? cuts[i + 1].c - cuts[i].c : 0;
    for (double w = 0.25 * below; w > finest && grade.size() < 64; w *= kGlassGrading) grade.push_back(cuts[i].c - w);
    for (double w = 0.25 * above; w > finest && grade.size() < 64; w *= kGlassGrading) grade.push_back(cuts[i].c + w);
  }
  std::vector<MappedSegment> segs;
  {
    std::vector<Cut> all = cuts;
    for (double g : grade) all.push_back({g, false, false});
    std::sort(all.begin(), all.end(), [](const Cut& x, const Cut& y) { return x.c < y.c; });
    for (size_t i = 0; i + 1 < all.size(); ++i) {
      if (all[i + 1].c > all[i].c) segs.push_back({all[i].c, all[i + 1].c, all[i].singular, all[i + 1].singular});
    }
  }
  // Each line's error at most kInnerShare of the tolerance over the c
  // weights (c w <= 1, the maps' Jacobians at most 1.5 times a width
  // summing to 1).
  const double line_tol = kInnerShare * tol / 1.5;
  return GlassSegmentsRule(segs, 1.0, tol, 200, [&](const double* x, double* v, double* e, int k) {
    for (int i = 0; i < 15 * k; ++i) {
      const double c = std::clamp(x[i], 0.0, 1.0);
      const double s = std::sqrt((1 - c) * (1 + c));
      const double cc = c * chh, k = s * sh;
      double wr, wt;
      m.Weights(c, &wr, &wt);
      double val = 0, err = 0;
      if (wr > 0) {
        const PsiLine r = ReflectionLine(m, cc, k, line_tol / std::max(c * wr, 1e-300), lines);
        val += wr * r.value;
        err += wr * r.error;
      }
      if (wt > 0) {
        const double st = s * m.inv_eta;
        const double ct2 = (1 - st) * (1 + st);
        if (ct2 > 0) {
          const PsiLine t =
              RefractionLine(m, cc, k, std::sqrt(ct2), chh, line_tol / std::max(c * wt, 1e-300), lines);
          val += wt * t.value;
          err += wt * t.error;
        }
      }
      v[i] = c * val;
      e[i] = c * err;
    }
  }, kAverageSafety);
}

// The model of GlassAlbedoAverage's parameters (alpha at least 1e-4 but
// for 0, the smooth interface).
inline AverageModel AverageModelOf(double alpha, double eta, Masking masking, DielectricPart part) {
  AverageModel m;
  m.part = part;
  m.eta = part == DielectricPart::kTransmissionSchlick && eta >= 1 ? eta : ClampDielectricEta(eta);
  m.inv_eta = 1 / m.eta;
  m.separable = masking == Masking::kSeparable;
  m.alpha = alpha == 0 ? 0 : std::max(alpha, kMinAlpha<double>);
  m.a2 = m.alpha * m.alpha;
  return m;
}

// GlassAlbedoAverage with the lines' nodes from `lines` (ScalarAverageLines
// or a lanes evaluator filling the same values).
template <class Lines>
RuleResult GlassAlbedoAverageWith(const AverageModel& m, double tol, int max_pieces, const Lines& lines) {
  const DielectricPart part = m.part;
  if (m.alpha == 0) {
    // The smooth interface: the average of F (or 1 - F, or Schlick's
    // complement) over the hemisphere, 2 integral c w(c) dc, cut at the
    // critical cosine (eta < 1), where F reaches 1 as a square root.
    std::vector<MappedSegment> segs = {{0, 1, false, false}};
    if (m.eta < 1 && part != DielectricPart::kTransmissionSchlick) {
      const double crit = std::sqrt((1 - m.eta) * (1 + m.eta));
      segs = {{0, crit, false, true}, {crit, 1, true, false}};
    }
    return GlassSegmentsRule(segs, 2.0, tol, 64, [&](const double* x, double* v, double* e, int k) {
      for (int i = 0; i < 15 * k; ++i) {
        double wr, wt;
        m.Weights(x[i], &wr, &wt);
        v[i] = x[i] * (part == DielectricPart::kBoth ? 1.0 : wr + wt);
        e[i] = 0;
      }
    });
  }
  // theta_h from q: tan^2 = alpha^2 u / (1 - u), u = q^2 (2 - q^2), 1 - u =
  // (1 - q^2)^2; the weight 1/pi du/dq / cos(theta_h).
  auto at = [&](double q, double* sh, double* chh, double* weight) {
    const double p = (1 - q) * (1 + q);  // 1 - q^2
    const double u = q * q * (2 - q * q);
    // cos^2 = (1 - u) / (1 - u + alpha^2 u), tan = alpha sqrt(u) / p.
    const double den = std::sqrt(p * p + m.a2 * u);
    *chh = p / den;
    *sh = m.alpha * std::sqrt(u) / den;
    *weight = p > 0 ? kInvPi<double> * 4 * q * p / *chh : kInvPi<double> * 4 * m.alpha;
  };
  // q at tan(theta_h) = t: q^2 = 1 - sqrt(1 - u) = 1 - alpha / sqrt(alpha^2
  // + t^2).
  auto q_at_tan2 = [&](double t2) { return std::sqrt(1 - m.alpha / std::sqrt(m.a2 + t2)); };
  // The pieces [0, 1/2], [1/2, 1], and beyond 1/2 cut where tan(theta_h)
  // passes 16, 1, 1/16, ... (kGlassGrading) down to 4 alpha: for small
  // alpha the facets tilted far beyond alpha (their share ~ alpha^2 /
  // tan^2, their loss of order 1) lie within ~alpha / tan of q = 1, where a
  // piece [1/2, 1] has no node; at alpha 1e-4 that piece missed 2.3e-9 with
  // a claim of 8e-10 (a cut at 76 degrees alone left the same miss). Graded
  // by 4 in tan(theta_h) or by 16, the largest error / claim against the
  // rule graded by 4 at tolerance 1e-12 was 0.136 or 0.143 (alpha 1e-4 to
  // 0.5, eta 0.01 to 99.5, each part, tolerances 1e-6 to 1e-8), and by 16
  // takes 15% fewer lines. For eta < 1 also at cos(theta_h) = eta (tan^2 =
  // (1 - eta^2) / eta^2).
  std::vector<double> cuts = {0.0, 0.5, 1.0};
  for (double t = 16; t > 4 * m.alpha; t *= kGlassGrading) {
    const double q = q_at_tan2(t * t);
    if (q > 0.5) cuts.push_back(q);
  }
  if (m.eta < 1 && part != DielectricPart::kTransmissionSchlick) {
    cuts.push_back(q_at_tan2((1 - m.eta) * (1 + m.eta) / (m.eta * m.eta)));
  }
  std::sort(cuts.begin(), cuts.end());
  std::vector<MappedSegment> segs;
  for (size_t i = 0; i + 1 < cuts.size(); ++i) {
    if (cuts[i + 1] > cuts[i]) segs.push_back({cuts[i], cuts[i + 1], false, false});
  }
  return GlassSegmentsRule(
      segs, 1.0, tol, std::max(max_pieces, 8),
      [&](const double* x, double* v, double* e, int k) {
        for (int i = 0; i < 15 * k; ++i) {
          double sh, chh, w;
          at(x[i], &sh, &chh, &w);
          const RuleResult r = OverC(m, sh, chh, kInnerShare * tol / std::max(1.5 * w, 1e-300), lines);
          v[i] = w * r.value;
          e[i] = w * r.error;
        }
      },
      kAverageSafety);
}

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_RULES_GLASS_GLASS_AVERAGE_RULE_H_
