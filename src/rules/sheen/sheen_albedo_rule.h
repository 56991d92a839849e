// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The rules of sheen_albedo.h as templates over the evaluator of their
// nodes: the Scalar* evaluators are the double reference,
// lanes/sheen_lanes.cc evaluates the same nodes in lanes.

#ifndef BRDFBAKE_SRC_RULES_SHEEN_SHEEN_ALBEDO_RULE_H_
#define BRDFBAKE_SRC_RULES_SHEEN_SHEEN_ALBEDO_RULE_H_

#include <algorithm>
#include <cmath>
#include <vector>

#include "brdfbake/models/disney_diffuse.h"
#include "brdfbake/models/sheen.h"
#include "quadrature/adaptive_rule.h"
#include "quadrature/gauss_legendre.h"
#include "rules/sheen/sheen_albedo.h"

namespace brdfbake {

// What the arc integrand depends on at one theta_h (CharlieAlbedoWith):
// y = wo.h = p + r cos(phi_h), NoL = 2 c y - mu.
struct CharlieArcTerms {
  double p, r, two_c, mu;
};

// g = V NoL 4 (wo.h) at one point of the arc, for wo.h = y and NoL = nol
// (nol >= 0); a V capped at 1 caps g at 4 NoL y.
inline double CharlieArcIntegrand(const CharlieSheen<double>& sheen, double mu, double y,
                                  double nol) {
  if (!(nol > 0)) return 0;
  const SheenVisibility v = sheen.visibility();
  const double g = SheenHasLambda(v) ? y * sheen.G2Cos(std::min(nol, 1.0), mu) / mu
                                     : nol * y / (nol * (1 - mu) + mu);
  return SheenClampsVisibility(v) ? std::min(g, 4 * std::min(nol, 1.0) * y) : g;
}

// The NoL below which a capped V is 1 at NoV = mu (V(NoL, mu) >= 1 there,
// and V decreases with NoL), or -1 where V < 1 for every NoL (and for the
// visibilities without a cap). neubelt: 4 (NoL + mu - NoL mu) = 1 in
// closed form; conty-kulla: 4 mu NoL (1 + Lambda(mu) + Lambda(NoL)) = 1 by
// bisection (tests/rules/sheen_albedo_test.cc checks that it is the only
// root); 1 where V >= 1 for every NoL (the cap holds throughout).
inline double CharlieClampNoL(const CharlieSheen<double>& sheen, double mu) {
  const SheenVisibility v = sheen.visibility();
  if (!SheenClampsVisibility(v)) return -1;
  if (!SheenHasLambda(v)) return mu < 0.25 ? (0.25 - mu) / (1 - mu) : -1;
  if (sheen.Visibility(1.0, mu) >= 1) return 1;
  double lo = 0, hi = 1;  // V(lo) >= 1 > V(hi)
  for (int i = 0; i < 64 && hi - lo > 1e-16; ++i) {
    const double m = 0.5 * (lo + hi);
    (sheen.Visibility(m, mu) >= 1 ? lo : hi) = m;
  }
  return 0.5 * (lo + hi);
}

// dNoL / dphi at NoL on the arc, 2 c r sin(phi_h): NoL = 2 c (p + r
// cos(phi_h)) - mu runs from nol0 (phi_h = 0) to nol_pi (phi_h = pi), and
// (2 c r sin(phi_h))^2 = (nol0 - NoL) (NoL - nol_pi), without the
// cancellation of 1 - cos(phi_h) near phi_h = 0.
inline double ArcSine(const CharlieArcTerms& t, double nol) {
  const double nol0 = t.two_c * (t.p + t.r) - t.mu, nol_pi = t.two_c * (t.p - t.r) - t.mu;
  return std::sqrt(std::max((nol0 - nol) * (nol - nol_pi), 0.0));
}

// The NoL from which an arc's end part (down to NoL = 0) takes its own
// variable, for an arc whose largest NoL is nol0 (CharlieAlbedoWith).
inline double CharlieSplitNoL(bool lambda, double nol0) {
  return lambda ? (nol0 >= 0.8 ? 0.5 : 0.35 * nol0) : 0.5 * nol0;
}

// The outer nodes of one piece in s, theta_h = theta_max (1 - s^2), as a
// node evaluator's Outer gives them: cos and sin of theta_h, the weight w
// = D(theta_h) sin(theta_h) dtheta_h/ds, and the arc's azimuths: its end
// phi_max (pi: the whole circle; 0: empty), where NoL is CharlieSplitNoL
// and (with a Lambda) 1/2, and the end part's range: z's split^power
// with a Lambda, tau's log1p(split / eps) without (the lanes fill only
// the fields the visibility uses).
struct CharlieOuterSetup {
  double theta_max, mu, s_mu, eps, power;
  bool lambda;  // the visibility has a Lambda
};
struct CharlieOuterNodes {
  double c[16], s[16], w[16], phi_max[16], phi_half[16], phi_split[16], tau_hi[16], z_hi[16];
};

// The variable of an arc piece: the azimuth phi_h; z = NoL^power towards
// the arc's end; tau = log1p(NoL / eps) there (CharlieAlbedoWith).
enum class CharlieArcVar { kPhi, kZ, kLog };

// The double reference's g at a node x of the variable `var` (arg: power
// for kZ, eps for kLog), times dphi/dx, and its Gauss-Kronrod 15 piece
// (times 2: J = 2 int g dphi); and an outer piece's nodes. A node
// evaluator gives Outer, Pieces (several pieces of one arc in one call,
// which the lanes evaluate together) and Powers.
struct ScalarCharlieNodes {
  const CharlieSheen<double>* sheen;
  double At(CharlieArcVar var, const CharlieArcTerms& t, double arg, double x) const {
    if (var == CharlieArcVar::kPhi) {
      const double y = t.p + t.r * std::cos(x);
      return CharlieArcIntegrand(*sheen, t.mu, y, t.two_c * y - t.mu);
    }
    // dphi/dz = NoL / (z power 2 c r sin(phi)), dphi/dtau = (NoL + eps) /
    // (2 c r sin(phi)).
    if (var == CharlieArcVar::kZ) return AtZ(t, arg, x, std::pow(x, 1 / arg));
    const double nol = arg * std::expm1(x);
    return CharlieArcIntegrand(*sheen, t.mu, (nol + t.mu) / t.two_c, nol) * (nol + arg) / ArcSine(t, nol);
  }
  // The same in z at a node x whose NoL = x^(1/power) is given.
  double AtZ(const CharlieArcTerms& t, double power, double x, double nol) const {
    const double jac = nol / (x * power * ArcSine(t, nol));
    return CharlieArcIntegrand(*sheen, t.mu, (nol + t.mu) / t.two_c, nol) * jac;
  }
  // out[i] = x[i]^e, i < n.
  void Powers(const double* x, int n, double e, double* out) const {
    for (int i = 0; i < n; ++i) out[i] = std::pow(x[i], e);
  }
  void Outer(const CharlieOuterSetup& o, const double* sv, CharlieOuterNodes* out) const {
    for (int i = 0; i < 15; ++i) {
      const double th = o.theta_max * (1 - sv[i] * sv[i]);
      const double c = std::cos(th), s = std::sin(th);
      out->c[i] = c;
      out->s[i] = s;
      out->w[i] = sheen->DCos2(c * c) * s * 2 * o.theta_max * sv[i];
      const CharlieArcTerms t{o.mu * c, o.s_mu * s, 2 * c, o.mu};
      // NoL = 0 at cos(phi) = (mu / (2 c) - mu c) / (s_mu s).
      const double cm = t.r > 0 ? (o.mu / t.two_c - t.p) / t.r : -1.0;
      out->phi_max[i] = !(cm < 1) ? 0.0 : cm <= -1 ? kPi<double> : std::acos(cm);
      const double split = CharlieSplitNoL(o.lambda, t.two_c * (t.p + t.r) - o.mu);
      auto phi_at = [&](double nol) {
        return std::acos(std::clamp(((nol + o.mu) / t.two_c - t.p) / t.r, -1.0, 1.0));
      };
      out->phi_half[i] = phi_at(0.5);
      out->phi_split[i] = phi_at(split);
      out->tau_hi[i] = std::log1p(split / o.eps);
      out->z_hi[i] = o.lambda ? std::pow(split, o.power) : 0.0;
    }
  }
  GkPiece Piece(CharlieArcVar var, const CharlieArcTerms& t, double arg, double a, double b) const {
    return KronrodPieceBatch(a, b, 2.0, [&](const double* x, double* v, double* e) {
      for (int i = 0; i < 15; ++i) {
        v[i] = At(var, t, arg, x[i]);
        e[i] = 0;
      }
    });
  }
  // The pieces [a[j], b[j]], j < m, each of the arc arc[j] (whose terms
  // are t[arc[j]]; the pieces of several arcs in one call), the first
  // m_phi in phi and the others in `var` (kZ or kLog, with its arg):
  // their values and |K15 - G7|. Where nol_rel (if given) has nol_rel[j],
  // piece j is in z and its nodes' NoL are nol_scale[arc[j]] nol_rel[j][i]
  // (CharlieAlbedoWith's end part).
  void Pieces(const CharlieArcTerms* t, const double* nol_scale, const int* arc, CharlieArcVar var,
              double arg, const double* a, const double* b, int m_phi, int m,
              const double* const* nol_rel, double* value, double* err) const {
    for (int j = 0; j < m; ++j) {
      GkPiece p;
      const CharlieArcTerms& u = t[arc[j]];
      if (nol_rel != nullptr && nol_rel[j] != nullptr) {
        const double* rel = nol_rel[j];
        const double scale = nol_scale[arc[j]];
        p = KronrodPieceBatch(a[j], b[j], 2.0, [&](const double* x, double* v, double* e) {
          for (int i = 0; i < 15; ++i) {
            v[i] = AtZ(u, arg, x[i], scale * rel[i]);
            e[i] = 0;
          }
        });
      } else {
        p = Piece(j < m_phi ? CharlieArcVar::kPhi : var, u, arg, a[j], b[j]);
      }
      value[j] = p.value;
      err[j] = p.err;
    }
  }
};

template <class Nodes>
RuleResult CharlieAlbedoWith(const CharlieSheen<double>& sheen, double mu_in, double tol,
                             int max_pieces, const Nodes& nodes) {
  const double mu = std::clamp(mu_in, 1e-7, 1.0);
  const double s_mu = std::sqrt((1 - mu) * (1 + mu));
  const double q = 0.5 / sheen.alpha();
  const bool ck = SheenHasLambda(sheen.visibility());
  const double power = CharlieLPower(sheen.alpha(), sheen.visibility());
  // A capped V kinks the integrand at NoL = nol_cap.
  const double nol_cap = CharlieClampNoL(sheen, mu);
  // J <= 2 pi max g, with g = V NoL 4 y (y <= 1): neubelt's NoL y / (NoL +
  // mu (1 - NoL)) <= y; the Lambda visibilities' y G2 / mu <= 1 / (mu (1 +
  // Lambda(mu))); a capped V's 4 NoL y <= 4.
  double g_max = ck ? 1 / (mu * (1 + sheen.LambdaCos(mu))) : 1.0;
  if (SheenClampsVisibility(sheen.visibility())) g_max = std::min(g_max, 4.0);
  const double j_bound = 2 * kPi<double> * g_max;
  // NoL is largest at phi_h = 0, cos(2 theta_h - theta_o): positive below
  // theta_max = pi/4 + theta_o/2.
  const double theta_max = 0.25 * kPi<double> + 0.5 * std::acos(mu);
  // J(theta_h) = 2 int_0^phi_max g dphi with its error, to an absolute
  // tolerance `inner_tol`.
  // The neubelt tau's scale (below).
  const double eps = ck ? 1.0 : std::min(mu / (1 - mu), 1e6);
  const CharlieOuterSetup setup{theta_max, mu, s_mu, eps, power, ck};
  // z at the NoL levels of the end part below (levels[k] / levels[0])^power,
  // the first a factor 4 down and the others 16, once per texel rather
  // than a pow per level of every arc.
  double z_ratio[24];
  z_ratio[0] = 1;
  if (ck) {
    const double first = std::pow(0.25, power), then = std::pow(0.0625, power);
    for (int k = 1; k < 24; ++k) z_ratio[k] = z_ratio[k - 1] * (k == 1 ? first : then);
  }
  // The NoL at the nodes of those initial z pieces over nol_split, the
  // same for every arc: NoL = z^(1/power) and z = z_hi (x at the piece's
  // node in units of z_hi), so NoL = nol_split x^(1/power). Once per
  // texel instead of a log and an exp at every node: rows 2k for the
  // piece between levels k + 1 and k, 2k + 1 from 0 to level k, for the
  // levels of nol_split = 1/2, the most an arc has (its nodes in the
  // order of Kronrod15, the 16th at the centre). Rows 48 + 2k and 48 +
  // 2k + 1 are the lower and upper halves of row 2k + 1 (the bottom
  // piece, which nearly every bisection in z splits), filled when a
  // bottom piece of level k is first bisected.
  double z_nol[96][16];
  bool z_halves[24] = {};
  if (ck) {
    int k_max = 1;
    for (double l = 0.5; l > 0.25 * mu && k_max < 24; ++k_max) l *= k_max == 1 ? 0.25 : 0.0625;
    const KronrodRule& rule = Kronrod15();
    double x[48][16];
    for (int k = 0; k < k_max; ++k) {
      for (int bottom = 0; bottom < 2; ++bottom) {
        const double lo = bottom ? 0.0 : (k + 1 < 24 ? z_ratio[k + 1] : 0.0), hi = z_ratio[k];
        const double mid = 0.5 * (lo + hi), h = 0.5 * (hi - lo);
        for (int i = 0; i < 16; ++i) x[2 * k + bottom][i] = mid + h * (i < 15 ? rule.x[i] : 0.0);
      }
    }
    nodes.Powers(&x[0][0], 32 * k_max, 1 / power, &z_nol[0][0]);
  }
  // The two halves' rows of level k's bottom piece (z from 0 to level k).
  auto z_halves_of = [&](int k) {
    if (!z_halves[k]) {
      const KronrodRule& rule = Kronrod15();
      double x[2][16];
      const double q = 0.25 * z_ratio[k];
      for (int half = 0; half < 2; ++half) {
        for (int i = 0; i < 16; ++i) x[half][i] = (1 + 2 * half) * q + q * (i < 15 ? rule.x[i] : 0.0);
      }
      nodes.Powers(&x[0][0], 32, 1 / power, z_nol[48 + 2 * k]);
      z_halves[k] = true;
    }
    return z_nol[48 + 2 * k];
  };
  using Var = CharlieArcVar;
  // An arc's pieces, in slots left uninitialised (an array of GkPiece,
  // whose members start at 0, was zeroed whole at every node). rel: the
  // piece's row of z_nol (or nullptr), bottom: the level whose bottom
  // piece it is (or -1).
  struct Slot {
    double a, b, value, err;
    Var var;
    const double* rel;
    int bottom;
  };
  constexpr int kMaxArcPieces = 96;
  // The arcs of one outer piece's nodes: their terms and NoL splits (the
  // node evaluator's arrays) and pieces.
  struct Arcs {
    CharlieArcTerms t[15];
    double nol_split[15];
    int n[15];
    Slot pieces[15][kMaxArcPieces];
  };
  // Pieces on their way to the node evaluator: piece j is slot[j] of arc
  // arc[j].
  constexpr int kMaxBatch = 15 * 32;
  struct Batch {
    double a[kMaxBatch], b[kMaxBatch];
    const double* rel[kMaxBatch];
    int arc[kMaxBatch], slot[kMaxBatch];
    int m = 0;
  };
  // The end part's variable and its argument.
  const Var end_var = ck ? Var::kZ : Var::kLog;
  const double end_arg = ck ? power : eps;
  // The pieces [a[j], b[j]], j < m (the first m_phi in phi, the others
  // in end_var), slot[j] of arc arc[j], their rows of z_nol rel[j], into
  // their slots, in one call of the node evaluator: the lanes evaluate
  // their nodes together.
  auto put = [&](Arcs* arcs, const double* a, const double* b, const double* const* rel,
                 const int* arc, const int* slot, int m_phi, int m) {
    double value[kMaxBatch], err[kMaxBatch];
    nodes.Pieces(arcs->t, arcs->nol_split, arc, end_var, end_arg, a, b, m_phi, m, rel, value, err);
    for (int j = 0; j < m; ++j) {
      Slot& p = arcs->pieces[arc[j]][slot[j]];
      p.value = value[j];
      p.err = err[j];
    }
  };
  // Arc k of outer node i: its cuts and initial pieces, whose slots get
  // everything but their values; the pieces go to the batches (in phi and
  // in end_var apart: the node evaluator takes those in phi first).
  auto start_arc = [&](const CharlieOuterNodes& o, int i, int k, Arcs* arcs, Batch* in_phi,
                       Batch* in_end) {
    const double c = o.c[i], s = o.s[i];
    CharlieArcTerms& t = arcs->t[k];
    t = CharlieArcTerms{mu * c, s_mu * s, 2 * c, mu};
    const double phi_max = o.phi_max[i];
    const bool arc_end = phi_max < kPi<double>;
    const double nol0 = t.two_c * (t.p + t.r) - mu;  // NoL at phi_h = 0, its largest
    auto phi_at = [&](double nol) {
      return std::acos(std::clamp(((nol + mu) / t.two_c - t.p) / t.r, -1.0, 1.0));
    };
    // The pieces: in phi, and where the arc ends inside (0, pi), its last
    // part (NoL below nol_split, about nol0 / 2) in a variable in which
    // the visibility's change over NoL ~ mu near the end is smooth.
    //  - neubelt: tau = log1p(NoL / eps), eps = mu / (1 - mu). V NoL is
    //    NoL / (4 (1 - mu) (NoL + eps)), whose pole at NoL = -eps, just
    //    past the arc's end for a small mu, is gone in tau: NoL + eps =
    //    eps e^tau and dNoL = (NoL + eps) dtau. Pieces of at most 2 in tau
    //    (the singularities left are those of dphi/dNoL, past the range's
    //    ends). This replaced cuts in phi at NoL = nol0 / 2 4^-k down to
    //    mu / 4, with 25% fewer nodes over a 64 x 64 table.
    //  - the Lambda visibilities: z = NoL^power, in which their Lambda (a
    //    function of NoL^power, power about 0.2, near NoL = 0) is smooth,
    //    from nol_split = 0.35 nol0, cut at NoL = nol_split / 4 and then
    //    every factor 16 down to mu / 4, where G2 ~ 1 / (Lambda(mu) +
    //    Lambda(NoL)) changes; their plain part is cut at NoL = 1/2, where
    //    Lambda changes branch (its second derivative jumps). Where nol0
    //    is near 1 the end part starts at NoL = 1/2 rather than leave a
    //    sliver of phi next to 1/2. Of the z pieces, the one next to
    //    nol_split, nearest the square root of dphi/dNoL at nol0, holds
    //    nearly all of the error: the split at 0.35 nol0 and the finer
    //    first step are for it (chosen by counting the nodes of a 64 x 64
    //    table: 8% fewer than with cuts at NoL = nol0 / 2 4^-k).
    // Fixed arrays: no allocation per node.
    double phi_cuts[6], z_cuts[28], log_cuts[16];
    int n_phi = 0, n_z = 0, n_log = 0, z_levels = 0;
    phi_cuts[n_phi++] = 0.0;
    const double nol_split = CharlieSplitNoL(ck, nol0);
    arcs->nol_split[k] = nol_split;
    if (ck && 0.5 < nol0 && (!arc_end || 0.5 > nol_split)) phi_cuts[n_phi++] = o.phi_half[i];
    if (arc_end) {
      phi_cuts[n_phi++] = o.phi_split[i];
      if (ck) {
        double levels[24];
        int n_levels = 0;
        levels[n_levels++] = nol_split;
        while (levels[n_levels - 1] > 0.25 * mu && n_levels < 24) {
          levels[n_levels] = (n_levels == 1 ? 0.25 : 0.0625) * levels[n_levels - 1];
          ++n_levels;
        }
        z_cuts[n_z++] = 0.0;
        for (int k = n_levels - 1; k >= 0; --k) z_cuts[n_z++] = o.z_hi[i] * z_ratio[k];
        z_levels = n_levels;
      } else {
        const double hi = o.tau_hi[i];
        const int n = std::clamp(static_cast<int>(std::ceil(0.5 * hi)), 1, 12);
        for (int k = 0; k < n; ++k) log_cuts[n_log++] = hi * k / n;
        log_cuts[n_log++] = hi;
      }
    } else {
      phi_cuts[n_phi++] = phi_max;
    }
    // The cap's kink, where the arc's NoL range (from nol0 down to 0 at
    // the arc's end, or to its value at phi_h = pi) holds nol_cap.
    const double nol_low = arc_end ? 0.0 : t.two_c * (t.p - t.r) - mu;
    if (nol_cap > nol_low && nol_cap < nol0) {
      if (arc_end && nol_cap < nol_split) {
        if (ck) {
          z_cuts[n_z++] = std::pow(nol_cap, power);
        } else {
          log_cuts[n_log++] = std::log1p(nol_cap / eps);
        }
      } else {
        phi_cuts[n_phi++] = phi_at(nol_cap);
      }
      std::sort(phi_cuts, phi_cuts + n_phi);
      std::sort(z_cuts, z_cuts + n_z);
      std::sort(log_cuts, log_cuts + n_log);
    }
    // The initial pieces between the cuts.
    Slot* pieces = arcs->pieces[k];
    int n = 0;
    // (Each cut read once, into a register: the compiler's paired load of
    // cuts[j] and cuts[j + 1], just stored one by one, stalled on store
    // forwarding.)
    auto add = [&](const double* cuts, int m, Var var, Batch* q) {
      double lo = cuts[0];
      for (int j = 0; j + 1 < m; ++j) {
        const double hi = cuts[j + 1];
        if (hi > lo) {
          pieces[n] = Slot{lo, hi, 0.0, 0.0, var, nullptr, -1};
          q->a[q->m] = lo;
          q->b[q->m] = hi;
          q->arc[q->m] = k;
          q->slot[q->m] = n;
          q->rel[q->m] = nullptr;
          ++q->m;
          ++n;
        }
        lo = hi;
      }
    };
    add(phi_cuts, n_phi, Var::kPhi, in_phi);
    const int m_phi = n, first_end = in_end->m;
    add(z_cuts, n_z, end_var, in_end);
    add(log_cuts, n_log, end_var, in_end);
    // The z pieces between the levels alone (no cap cut among them):
    // their nodes' NoL from z_nol, the lowest first.
    if (z_levels > 0 && n_z == z_levels + 1 && n - m_phi == z_levels) {
      for (int q = 0; q < z_levels; ++q) {
        Slot& p = pieces[m_phi + q];
        p.rel = q == 0 ? z_nol[2 * (z_levels - 1) + 1] : z_nol[2 * (z_levels - 1 - q)];
        p.bottom = q == 0 ? z_levels - 1 : -1;
        in_end->rel[first_end + q] = p.rel;
      }
    }
    arcs->n[k] = n;
  };
  // J of arc k (its initial pieces evaluated) with its error: the worst
  // piece bisected until the tolerance, or until |K15 - G7| is down to
  // the rounding of the sum (a large weight D sin(theta_h) can ask for
  // more).
  auto finish_arc = [&](int k, Arcs* arcs, double inner_tol, double* err) {
    Slot* pieces = arcs->pieces[k];
    int& n = arcs->n[k];
    double v, e;
    auto sums = [&] {
      v = e = 0;
      for (int j = 0; j < n; ++j) {
        v += pieces[j].value;
        e += pieces[j].err;
      }
    };
    for (sums(); e > std::max(inner_tol, 1e-13 * v) && n < kMaxArcPieces; sums()) {
      int w = 0;
      for (int j = 1; j < n; ++j) {
        if (pieces[j].err > pieces[w].err) w = j;
      }
      const Slot p = pieces[w];
      const double m = 0.5 * (p.a + p.b);
      // A bottom piece's halves take their rows of z_nol (once per
      // texel and level, rather than a log and an exp at every node).
      const double* h = p.bottom >= 0 ? z_halves_of(p.bottom) : nullptr;
      const double* rel[2] = {h, h != nullptr ? h + 16 : nullptr};
      pieces[w] = Slot{p.a, m, 0.0, 0.0, p.var, rel[0], -1};
      pieces[n] = Slot{m, p.b, 0.0, 0.0, p.var, rel[1], -1};
      const double a[2] = {p.a, m}, b[2] = {m, p.b};
      const int arc[2] = {k, k}, slot[2] = {w, n++};
      put(arcs, a, b, rel, arc, slot, p.var == Var::kPhi ? 2 : 0, 2);
    }
    *err = e;
    return v;
  };
  // The outer integrand D(theta_h) sin(theta_h) J(theta_h) in s, theta_h =
  // theta_max (1 - s^2): J vanishes as (theta_max - theta_h)^(3/2) at
  // theta_max, smooth in s, and a narrow lobe's peak there, over the width
  // tan(theta_max) / (2 q) in theta_h, is wider in s. The inner tolerance
  // keeps the arcs' errors carried through the Kronrod weights at most
  // half of `tol` (the weights of a piece sum to its width, the widths to
  // 1; half rather than a tenth: 6% fewer nodes over a 64 x 64
  // conty-kulla table).
  auto piece = [&](double a, double b) {
    return KronrodPieceBatch(a, b, 1.0, [&](const double* sv, double* v, double* e) {
      CharlieOuterNodes o;
      nodes.Outer(setup, sv, &o);
      // The arcs' initial pieces of all 15 nodes go through the node
      // evaluator in one call (long stages of independent vectors in the
      // lanes), then each arc is refined on its own.
      Arcs arcs;
      Batch in_phi, in_end;
      int node_of[15], n_arcs = 0;
      for (int i = 0; i < 15; ++i) {
        const double w = o.w[i];
        v[i] = e[i] = 0;
        if (!(w > 0)) continue;
        // A node whose whole contribution w J is below 1e-3 tol by the
        // bound j_bound counts as 0 with that bound as its error (12% to
        // 16% of the nodes of a 64 x 64 table, far out on a narrow lobe's
        // flank).
        if (w * j_bound < 1e-3 * tol) {
          e[i] = w * j_bound;
          continue;
        }
        // An empty arc: J = 0.
        if (!(o.phi_max[i] > 0)) continue;
        start_arc(o, i, n_arcs, &arcs, &in_phi, &in_end);
        node_of[n_arcs++] = i;
      }
      const int m_phi = in_phi.m;
      for (int j = 0; j < in_end.m; ++j) {
        in_phi.a[m_phi + j] = in_end.a[j];
        in_phi.b[m_phi + j] = in_end.b[j];
        in_phi.rel[m_phi + j] = in_end.rel[j];
        in_phi.arc[m_phi + j] = in_end.arc[j];
        in_phi.slot[m_phi + j] = in_end.slot[j];
      }
      put(&arcs, in_phi.a, in_phi.b, in_phi.rel, in_phi.arc, in_phi.slot, m_phi, m_phi + in_end.m);
      for (int k = 0; k < n_arcs; ++k) {
        const int i = node_of[k];
        double err;
        const double j = finish_arc(k, &arcs, 0.5 * tol / o.w[i], &err);
        e[i] = o.w[i] * err;
        v[i] = o.w[i] * j;
      }
    });
  };
  // Graded by 4 towards s = 0 down to the peak's width, and for a grazing
  // view to sqrt(mu / theta_max): within about mu of theta_max the arc's
  // end moves at the rate 1 / cos(theta_h) (its cos(phi_max) holds mu /
  // (2 cos(theta_h))).
  // The mesh is also cut where the arc stops being the whole circle: NoL
  // at phi_h = pi is cos(2 theta_h + theta_o), zero at theta_full = pi/4 -
  // theta_o/2, and J changes form there (its arc's ends appear).
  const double finest = std::min(std::sqrt(std::min(0.25, std::tan(theta_max) / (2 * q * theta_max))),
                                 std::sqrt(mu / theta_max));
  // The cut at s = 1/2 starts the grading; with a Lambda, whose cuts
  // below (at least three inside (0, 1)) split s already, only where the
  // grading goes on below it (18% fewer nodes over a 64 x 64 conty-kulla
  // table; neubelt, with one cut of its own, needs it).
  std::vector<double> cuts = {1.0};
  if (!ck || 0.5 > 4 * finest) cuts.push_back(0.5);
  for (double edge = 0.5; edge > 4 * finest && cuts.size() < 24;) {
    edge *= 0.25;
    cuts.push_back(edge);
  }
  cuts.push_back(0.0);
  const double theta_o = std::acos(mu);
  std::vector<double> theta_cuts = {0.25 * kPi<double> - 0.5 * theta_o};
  if (ck) {
    // And where the arc's NoL range first reaches 1 (theta_h = theta_o /
    // 2: wi at the normal, where Lambda holds (1 - NoL)^p) or passes 1/2
    // (Lambda's change of branch): NoL spans cos(2 theta_h + theta_o) to
    // cos(2 theta_h - theta_o).
    const double third = kPi<double> / 3;
    for (double t : {0.5 * theta_o, 0.5 * (theta_o + third), 0.5 * (theta_o - third), 0.5 * (third - theta_o)}) {
      theta_cuts.push_back(t);
    }
  }
  if (nol_cap > 0 && nol_cap < 1) {
    // And where the arc's NoL range first reaches the cap's NoL, passes it
    // at its far end, or leaves it.
    const double a = std::acos(nol_cap);
    for (double t : {0.5 * (theta_o - a), 0.5 * (theta_o + a), 0.5 * (a - theta_o)}) theta_cuts.push_back(t);
  }
  for (double t : theta_cuts) {
    if (t > 0 && t < theta_max) cuts.push_back(std::sqrt(1 - t / theta_max));
  }
  std::sort(cuts.begin(), cuts.end());
  std::vector<GkPiece> pieces;
  for (size_t k = 0; k + 1 < cuts.size(); ++k) {
    if (cuts[k + 1] > cuts[k]) pieces.push_back(piece(cuts[k], cuts[k + 1]));
  }
  auto totals = [&](double* rule, double* inner) {
    *rule = *inner = 0;
    for (const GkPiece& p : pieces) {
      *rule += p.err;
      *inner += p.prop;
    }
  };
  double rule_err, inner_err;
  totals(&rule_err, &inner_err);
  while (rule_err + inner_err > tol && rule_err > 0.1 * tol &&
         int(pieces.size()) < std::max(max_pieces, 8)) {
    BisectWorst(&pieces, piece);
    totals(&rule_err, &inner_err);
  }
  return SumOfPieces(pieces, rule_err + inner_err);
}

// The double reference's azimuthal mean of pi f at n cosines x.
struct ScalarDisneyNodes {
  double r;
  void operator()(const double* x, double mu, int n, double* m) const {
    const DisneyDiffuse<double> f(r);
    for (int i = 0; i < n; ++i) m[i] = f.AzimuthMean(x[i], mu);
  }
};

// 2 integral_0^1 x M(x, mu) dx by the n-point rule `gl`.
template <class Nodes>
double DisneyRule(const GaussLegendre& gl, double mu, const Nodes& nodes) {
  const int n = static_cast<int>(gl.x.size());
  double m[16];
  nodes(gl.x.data(), mu, n, m);
  double s = 0;
  for (int i = 0; i < n; ++i) s += gl.w[i] * gl.x[i] * m[i];
  return 2 * s;
}

template <class Nodes>
RuleResult DisneyAlbedoWith(double mu, const Nodes& nodes) {
  static const GaussLegendre fine(8), coarse(6);
  const double e = DisneyRule(fine, mu, nodes);
  RuleResult out;
  out.value = e;
  out.error = std::abs(e - DisneyRule(coarse, mu, nodes)) + 1e-15 * std::abs(e);
  out.pieces = 1;
  return out;
}

template <class Nodes>
RuleResult DisneyEavgWith(const Nodes& nodes) {
  static const GaussLegendre fine(8), coarse(6);
  auto rule = [&](const GaussLegendre& gl) {
    double s = 0;
    for (size_t k = 0; k < gl.x.size(); ++k) s += gl.w[k] * gl.x[k] * DisneyRule(gl, gl.x[k], nodes);
    return 2 * s;
  };
  const double e = rule(fine);
  RuleResult out;
  out.value = e;
  out.error = std::abs(e - rule(coarse)) + 1e-15 * std::abs(e);
  out.pieces = 1;
  return out;
}

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_RULES_SHEEN_SHEEN_ALBEDO_RULE_H_
