// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The rule of glass_albedo.h as a template over the evaluator of its
// nodes: ScalarGlassNodes is the double reference; a lanes evaluator
// fills the same 15 values per call.

#ifndef BRDFBAKE_SRC_RULES_GLASS_GLASS_ALBEDO_RULE_H_
#define BRDFBAKE_SRC_RULES_GLASS_GLASS_ALBEDO_RULE_H_

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

#include "brdfbake/models/dielectric.h"
#include "brdfbake/models/ggx.h"
#include "quadrature/adaptive_rule.h"
#include "rules/glass/glass_albedo.h"

namespace brdfbake {

// The view and the stretched frame: wo = (so, 0, mu), v = normalize(alpha
// so, 0, mu) = (vx, 0, vz); n(theta, phi) = cos(theta) v + sin(theta)
// (cos(phi) y + sin(phi) t2), t2 = (-vz, 0, vx).
struct GlassFrame {
  double alpha, eta, mu, so, vx, vz;
  GlassFrame(double alpha_in, double eta_in, double mu_in) : alpha(alpha_in), eta(eta_in) {
    mu = std::clamp(mu_in, 1e-7, 1.0);
    so = std::sqrt((1 - mu) * (1 + mu));
    const double l = std::hypot(alpha * so, mu);
    vx = alpha * so / l;
    vz = mu / l;
  }
  // The stretched microfacet m (unnormalized) at (cos, sin) of theta along
  // the ray with (cos, sin) of phi.
  Vec3<double> M(double ct, double st, double cp, double sp) const {
    return {alpha * (ct * vx - st * sp * vz), alpha * st * cp, ct * vz + st * sp * vx};
  }
  // The lune's edge n.z = 0 along the ray phi.
  double ThetaMax(double sp) const {
    return sp >= 0 ? 0.5 * kPi<double> : std::atan2(vz, -sp * vx);
  }
};

// The kinds of roots along a ray (glass_albedo.h): the reflection's
// horizon, the refraction's horizon, the critical angle.
enum GlassCurve { kGlassReflectionHorizon = 1, kGlassRefractionHorizon = 2, kGlassCritical = 3 };

struct GlassRoot {
  double theta;
  int curve;
  int slope = 0;  // the curve's form rising (+1) or falling (-1) through it; 0 unknown
};

// The bilinear form of each curve's quadratic: the unnormalized normals m
// with form(m, m) = 0 lie on the curve (glass_albedo.h).
inline double GlassForm(const GlassFrame& f, int curve, const Vec3<double>& u, const Vec3<double>& v) {
  const Vec3<double> wo{f.so, 0, f.mu};
  const double ou = Dot(wo, u), ov = Dot(wo, v), uv = Dot(u, v);
  switch (curve) {
    case kGlassReflectionHorizon:
      return ou * v.z + ov * u.z - f.mu * uv;
    case kGlassRefractionHorizon:
      return f.mu * f.mu * uv - f.mu * (ou * v.z + ov * u.z) - (f.eta * f.eta - 1) * u.z * v.z;
    default:
      return ou * ov - (1 - f.eta * f.eta) * uv;
  }
}

// The last curve the rule cuts at: the reflection's horizon alone for eta
// >= 1, all three for eta < 1.
inline int GlassLastCurve(const GlassFrame& f) { return f.eta < 1 ? kGlassCritical : kGlassReflectionHorizon; }

// The zeros x in [0, pi) of A cos^2(x) + 2 B cos(x) sin(x) + C sin^2(x) =
// P + R cos(2 x - delta), P = (A + C) / 2, R = hypot((A - C) / 2, B); none
// unless |P| < R. Calls out(x, slope): 2 x = delta + g, g = acos(-P / R)
// in (0, pi), where the form falls through 0 (its derivative -2 R sin(g)),
// slope -1; 2 x = delta - g, where it rises, slope +1; 0 if g is 0 or pi.
template <class Out>
void HalfAngleZeros(double qa, double qb, double qc, const Out& out) {
  const double p = 0.5 * (qa + qc), q = 0.5 * (qa - qc);
  const double r = std::hypot(q, qb);
  if (!(r > 0) || !(std::abs(p) < r)) return;
  const double delta = std::atan2(qb, q), g = std::acos(-p / r);
  const int steep = g > 0 && g < kPi<double> ? 1 : 0;
  for (int side : {-1, 1}) {
    // 2 x modulo 2 pi into [0, 2 pi): x in [0, pi).
    const double two = delta - side * g;
    out(0.5 * (two - kTwoPi<double> * std::floor(two / kTwoPi<double>)), side * steep);
  }
}

// Each curve's form along the ray phi, as a quadratic in (cos(theta),
// sin(theta)): m = cos(theta) a + sin(theta) (cos(phi) b1 + sin(phi) b2)
// (GlassFrame::M), so its coefficients are qa (fixed), qb = beta1 cos(phi)
// + beta2 sin(phi) and qc = g11 cos^2(phi) + 2 g12 cos(phi) sin(phi) +
// g22 sin^2(phi), computed once per view.
struct GlassCurveForms {
  int last;
  double qa[4], beta1[4], beta2[4], g11[4], g12[4], g22[4];
  explicit GlassCurveForms(const GlassFrame& f) : last(GlassLastCurve(f)) {
    const Vec3<double> a{f.alpha * f.vx, 0, f.vz}, b1{0, f.alpha, 0}, b2{-f.alpha * f.vz, 0, f.vx};
    for (int curve = kGlassReflectionHorizon; curve <= last; ++curve) {
      qa[curve] = GlassForm(f, curve, a, a);
      beta1[curve] = GlassForm(f, curve, a, b1);
      beta2[curve] = GlassForm(f, curve, a, b2);
      g11[curve] = GlassForm(f, curve, b1, b1);
      g12[curve] = GlassForm(f, curve, b1, b2);
      g22[curve] = GlassForm(f, curve, b2, b2);
    }
  }
  double Qb(int curve, double cp, double sp) const { return beta1[curve] * cp + beta2[curve] * sp; }
  double Qc(int curve, double cp, double sp) const {
    return (g11[curve] * cp + 2 * g12[curve] * sp) * cp + g22[curve] * sp * sp;
  }
};

// The roots theta in (0, theta_max) of the three quadratic forms along the
// ray (cos(phi), sin(phi)) = (cp, sp), ascending, by their angles (the
// tests' reference for GlassTangentRoots, which the rule uses).
inline void GlassRoots(const GlassCurveForms& forms, double cp, double sp, double theta_max,
                       std::vector<GlassRoot>* roots) {
  roots->clear();
  for (int curve = kGlassReflectionHorizon; curve <= forms.last; ++curve) {
    HalfAngleZeros(forms.qa[curve], forms.Qb(curve, cp, sp), forms.Qc(curve, cp, sp), [&](double t, int slope) {
      if (t > 0 && t < theta_max) roots->push_back({t, curve, slope});
    });
  }
  std::sort(roots->begin(), roots->end(),
            [](const GlassRoot& x, const GlassRoot& y) { return x.theta < y.theta; });
}

// Whether the term a curve bounds lives at theta along the ray (cp, sp):
// the reflection above the surface (its horizon), the refraction below
// it (its horizon), the refraction at all (the critical angle: F's square
// root is on that side; beyond it F = 1). A root of the refraction's
// squared form where neither side lives is no edge at all.
inline bool GlassCurveLives(const GlassFrame& f, int curve, double theta, double cp, double sp) {
  const Vec3<double> m = f.M(std::cos(theta), std::sin(theta), cp, sp);
  const double len = std::sqrt(Dot(m, m));
  if (!(len > 0)) return true;
  const Vec3<double> h = m / len;
  const double c = f.so * h.x + f.mu * h.z;
  const double inv_eta = 1 / f.eta;
  const double ct2 = 1 - (1 - c) * (1 + c) * inv_eta * inv_eta;
  switch (curve) {
    case kGlassReflectionHorizon:
      return 2 * c * h.z - f.mu > 0;
    case kGlassRefractionHorizon:
      return ct2 > 0 && (c * inv_eta - std::sqrt(ct2)) * h.z - f.mu * inv_eta < 0;
    default:
      return ct2 > 0;
  }
}

// The rays phi in (-pi/2, pi/2) where a curve's roots along the rays
// appear or vanish, in closed form. Along the ray phi, m = cos(theta) a +
// sin(theta) (cos(phi) b1 + sin(phi) b2) with a, b1, b2 fixed
// (GlassFrame::M), so each form's coefficients in (cos(theta),
// sin(theta)) are qa (fixed), qb (linear in (cos(phi), sin(phi))) and qc
// (quadratic). Roots appear:
//  - where the ray is tangent to the curve: the discriminant qb^2 - qa qc,
//    a quadratic form in (cos(phi), sin(phi)), is 0, with the double root
//    inside (0, theta_max);
//  - where a root crosses the lune's edge: theta = pi/2 for phi >= 0 (m =
//    b, the form qc), and for phi < 0 the normal with m.z = 0, cos(phi)
//    (0, alpha vz, 0) + sin(phi) (-alpha, 0, 0) up to a positive factor.
// A scan of the rays' signatures finds changes only where it probes both
// sides: a tangency inside one of its cells (roots that appear and vanish
// again within a thousandth of a radian) was missed, by up to 1.3 times the
// claim (alpha 0.2025, eta 1/3, mu 0.15, tolerance 1e-7).
inline void GlassRayEvents(const GlassFrame& f, const GlassCurveForms& c, std::vector<double>* phis) {
  const Vec3<double> e1{0, f.alpha * f.vz, 0}, e2{-f.alpha, 0, 0};
  auto to_phi = [](double x) { return x < 0.5 * kPi<double> ? x : x - kPi<double>; };
  for (int curve = kGlassReflectionHorizon; curve <= c.last; ++curve) {
    const double qa = c.qa[curve], beta1 = c.beta1[curve], beta2 = c.beta2[curve];
    HalfAngleZeros(beta1 * beta1 - qa * c.g11[curve], beta1 * beta2 - qa * c.g12[curve],
                   beta2 * beta2 - qa * c.g22[curve], [&](double x, int) {
                     const double phi = to_phi(x), cp = std::cos(phi), sp = std::sin(phi);
                     const double qb = c.Qb(curve, cp, sp), qc = c.Qc(curve, cp, sp);
                     // The double root: P + R cos(2 theta - delta) with |P| = R
                     // is 0 at 2 theta = delta + pi for P > 0, delta for P < 0.
                     double two = std::atan2(qb, 0.5 * (qa - qc)) + (qa + qc > 0 ? kPi<double> : 0.0);
                     two -= kTwoPi<double> * std::floor(two / kTwoPi<double>);
                     const double theta = 0.5 * two;
                     if (theta > 0 && theta < f.ThetaMax(sp)) phis->push_back(phi);
                   });
    HalfAngleZeros(c.g11[curve], c.g12[curve], c.g22[curve], [&](double x, int) {
      if (to_phi(x) > 0) phis->push_back(to_phi(x));
    });
    auto form = [&](const Vec3<double>& u, const Vec3<double>& v) { return GlassForm(f, curve, u, v); };
    HalfAngleZeros(form(e1, e1), form(e1, e2), form(e2, e2), [&](double x, int) {
      if (to_phi(x) < 0) phis->push_back(to_phi(x));
    });
  }
}

// The index the rule runs at: the bsdf's (clamped to the Fresnel model's
// [0.01, 100]), or for kTransmissionSchlick, whose weight has no Fresnel
// factor, the index asked for, up to inf (t = -h there).
inline double GlassRuleEta(double bsdf_eta, double eta, DielectricPart part) {
  return part == DielectricPart::kTransmissionSchlick && eta >= 1 ? eta : bsdf_eta;
}

// What a ray's nodes depend on.
struct GlassRay {
  double cp, sp;
};

// The double reference's integrand cos(theta) sin(theta) W(h) at 15 angles
// theta along a ray, W the bracket of glass_albedo.h (or its reflection or
// refraction term alone, `part`).
struct ScalarGlassNodes {
  const RoughDielectric<double, GgxNdf<double>>* bsdf;
  const GlassFrame* frame;
  double g1o_inv;  // 1 / G1(wo) (separable) or 1 + Lambda(wo) (height-correlated)
  double lambda_o;
  DielectricPart part = DielectricPart::kBoth;
  double Weight(const Vec3<double>& h) const {
    const GlassFrame& f = *frame;
    const Vec3<double> wo{f.so, 0, f.mu};
    const double c = std::clamp(Dot(wo, h), 0.0, 1.0);
    const double fr = part == DielectricPart::kTransmissionSchlick ? 0.0 : FresnelDielectric(f.eta, c);
    auto g2_over_g1 = [&](const Vec3<double>& wi) {
      const double li = bsdf->Lambda(wi);
      if (bsdf->masking() == Masking::kSeparable) return 1 / (1 + li);
      return g1o_inv / (1 + lambda_o + li);
    };
    double w = 0;
    const Vec3<double> r = h * (2 * c) - wo;
    if (r.z > 0 && fr > 0 && !RefractionPart(part)) w += fr * g2_over_g1(r);
    // 1 / eta is 0 at eta = inf (kTransmissionSchlick), where t = -h.
    const double inv_eta = 1 / f.eta;
    const double ct2 = 1 - (1 - c) * (1 + c) * inv_eta * inv_eta;
    if (part == DielectricPart::kTransmissionSchlick) {
      // The complement of Schlick's weight, (1 - (1 - c)^5) (kSchlick).
      const double s = (1 - c) * (1 - c) * (1 - c) * (1 - c) * (1 - c);
      const Vec3<double> t = wo * -inv_eta + h * (c * inv_eta - std::sqrt(std::max(ct2, 0.0)));
      if (ct2 > 0 && t.z < 0) w += (1 - s) * g2_over_g1(t);
      return w;
    }
    if (ct2 > 0 && fr < 1 && part != DielectricPart::kReflection) {
      const Vec3<double> t = wo * -inv_eta + h * (c * inv_eta - std::sqrt(ct2));
      if (t.z < 0) w += (1 - fr) * g2_over_g1(t);
    }
    return w;
  }
  // 15 k nodes: k pieces' 15 each.
  void operator()(const GlassRay& ray, const double* theta, double* v, int k = 1) const {
    for (int i = 0; i < 15 * k; ++i) {
      const double ct = std::cos(theta[i]), st = std::sin(theta[i]);
      const Vec3<double> m = frame->M(ct, st, ray.cp, ray.sp);
      const double len = std::sqrt(Dot(m, m));
      v[i] = len > 0 && m.z >= 0 ? ct * st * Weight(m / len) : 0.0;
    }
  }
};

// The map of a segment [a, b] with singular ends: x = a + (b - a) m(t).
struct MappedSegment {
  double a, b;
  bool singular_a, singular_b;
  void Map(double t, double* x, double* jac) const {
    double m, dm;
    if (singular_a && singular_b) {
      m = t * t * (3 - 2 * t), dm = 6 * t * (1 - t);
    } else if (singular_a) {
      m = t * t, dm = 2 * t;
    } else if (singular_b) {
      m = 1 - (1 - t) * (1 - t), dm = 2 * (1 - t);
    } else {
      m = t, dm = 1;
    }
    *x = a + (b - a) * m;
    *jac = (b - a) * dm;
  }
};

// A piece of a mapped segment: [a, b] in t, with GkPiece's sums. No
// member initializers: the rule's arrays of them would be zeroed on every
// call of a psi line (a sixth of that rule's own time).
struct GlassPiece {
  double a, b, value, err, prop;
  int segment;
};

// A piece's |K15 - G7| counts three times, as in SegmentRule
// (adaptive_rule.h). Over 1200 views (roughness 1/15 to 1, eta 1/99.5 to
// 99.5, mu 1e-4 to 1, both maskings), against the rule at tolerance
// 1e-12, the largest error / claim was 0.08, 0.04 and 0.19 at tolerances
// 1e-6, 1e-7 and 1e-8; counted once, 0.14, 0.63 and 0.43, too thin a
// margin for views outside the sweep.
inline constexpr double kGlassErrorSafety = 3;

// The ratio of the geometric grading towards the roots and the lune's
// edge along a ray, and towards phi = 0 over the rays: the far end of
// each graded piece lies 16 times as far from the feature as its near
// end. The pieces' own bisection resolves what a level leaves; over 800
// views (roughness 1/15 to 1, eta 1/99.5 to 99.5, mu 1e-4 to 1,
// tolerances 1e-6 to 1e-8) it took 17 to 29% fewer nodes than ratio 4,
// with the same largest error against a 1e-11 integration.
inline constexpr double kGlassGrading = 1.0 / 16;

// The pieces' storage of GlassPiecesRule, one vector per nesting depth
// and thread (the rules nest: E's rays in phi, E_avg's psi lines in c in
// q), kept from call to call so that a line allocates nothing.
class GlassPiecesScratch {
 public:
  GlassPiecesScratch() : pieces_(depth_ < kDepths ? &pool_[depth_] : &own_) { ++depth_; }
  ~GlassPiecesScratch() { --depth_; }
  GlassPiecesScratch(const GlassPiecesScratch&) = delete;
  GlassPiecesScratch& operator=(const GlassPiecesScratch&) = delete;
  std::vector<GlassPiece>& pieces() { return *pieces_; }

 private:
  static constexpr int kDepths = 4;
  static inline thread_local int depth_ = 0;
  static inline thread_local std::vector<GlassPiece> pool_[kDepths];
  std::vector<GlassPiece> own_;
  std::vector<GlassPiece>* pieces_;
};

// The most pieces GlassSegmentsRule evaluates in one call of its
// integrand.
inline constexpr int kGlassPieceBatch = 8;

// GlassPiecesRule's adaptive loop from the n pieces it has made:
// room(need) gives storage for `need` pieces that holds the pieces so far.
template <class Room, class Make>
RuleResult GlassBisect(size_t n, double tol, int max_pieces, const Room& room, const Make& make) {
  GlassPiece* pieces = room(n);
  auto total = [&] {
    double e = 0;
    for (size_t i = 0; i < n; ++i) e += pieces[i].err + pieces[i].prop;
    return e;
  };
  double err = total();
  while (err > tol && n > 0 && static_cast<int>(n) < max_pieces) {
    size_t worst = 0;
    for (size_t i = 1; i < n; ++i) {
      if (pieces[i].err > pieces[worst].err) worst = i;
    }
    if (pieces[worst].err <= 0.02 * tol / n) break;
    const GlassPiece p = pieces[worst];
    const double m = 0.5 * (p.a + p.b);
    GlassPiece spans[2];
    spans[0].a = p.a, spans[0].b = m, spans[0].segment = p.segment;
    spans[1].a = m, spans[1].b = p.b, spans[1].segment = p.segment;
    GlassPiece made[2];
    make(spans, 2, made);
    pieces = room(n + 1);
    pieces[worst] = made[0];
    pieces[n++] = made[1];
    err = total();
  }
  return SumOfPieces(pieces, n, err);
}

// Gauss-Kronrod 15 over the mapped segments, the worst piece bisected
// until the summed `safety` x |K15 - G7| plus the nodes' own errors meet
// `tol`, or bisection stops helping (the worst piece's part below 1/50 of
// the tolerance per piece), or `max_pieces`. make(spans, k, out) makes
// the k pieces [a, b] of t (of the segment `segment`) of `spans`, value
// and errors, k at most kGlassPieceBatch: the segments' first pieces, a
// bisected piece's halves, so that a lanes evaluator overlaps their nodes.
template <class Make>
RuleResult GlassPiecesRule(const MappedSegment* segments, int n_segments, double tol, int max_pieces,
                           const Make& make) {
  // The pieces in the scratch vector's first n entries; it grows (and
  // zeroes) only past the largest count its thread has needed.
  GlassPiecesScratch scratch;
  std::vector<GlassPiece>& store = scratch.pieces();
  size_t n = 0;
  auto room = [&](size_t need) {
    if (store.size() < need) store.resize(std::max<size_t>(need, 2 * store.size()));
    return store.data();
  };
  GlassPiece spans[kGlassPieceBatch];
  int k = 0;
  auto flush = [&] {
    make(spans, k, room(n + k) + n);
    n += k;
    k = 0;
  };
  for (int s = 0; s < n_segments; ++s) {
    if (!(segments[s].b > segments[s].a)) continue;
    spans[k].a = 0.0;
    spans[k].b = 1.0;
    spans[k].segment = s;
    if (++k == kGlassPieceBatch) flush();
  }
  if (k > 0) flush();
  return GlassBisect(n, tol, max_pieces, room, make);
}

// The 15 Kronrod nodes x of each of k pieces of the segments, mapped, and
// the maps' Jacobians.
inline void MapPieceNodes(const MappedSegment* segments, const GlassPiece* spans, int k, double* x, double* jac) {
  const KronrodRule& rule = Kronrod15();
  for (int j = 0; j < k; ++j) {
    const MappedSegment& g = segments[spans[j].segment];
    const double c = 0.5 * (spans[j].a + spans[j].b), h = 0.5 * (spans[j].b - spans[j].a);
    if (g.singular_a || g.singular_b) {
      for (int i = 0; i < 15; ++i) g.Map(c + h * rule.x[i], &x[15 * j + i], &jac[15 * j + i]);
    } else {
      // Map's identity branch, out of the loop.
      const double w = g.b - g.a;
      for (int i = 0; i < 15; ++i) {
        x[15 * j + i] = g.a + w * (c + h * rule.x[i]);
        jac[15 * j + i] = w;
      }
    }
  }
}

// GlassPiecesRule of `scale` times the integrand: f(x, v, e, k) fills the
// integrand and its errors at the 15 k points x of k pieces; the maps'
// Jacobians and the Kronrod sums are formed here.
template <class F>
RuleResult GlassSegmentsRule(const MappedSegment* segments, int n_segments, double scale, double tol,
                             int max_pieces, const F& f, double safety = kGlassErrorSafety) {
  return GlassPiecesRule(segments, n_segments, tol, max_pieces, [&](const GlassPiece* spans, int k, GlassPiece* out) {
    double x[15 * kGlassPieceBatch], jac[15 * kGlassPieceBatch];
    double v[15 * kGlassPieceBatch], e[15 * kGlassPieceBatch];
    MapPieceNodes(segments, spans, k, x, jac);
    f(x, v, e, k);
    for (int i = 0; i < 15 * k; ++i) {
      v[i] *= jac[i];
      e[i] *= jac[i];
    }
    for (int j = 0; j < k; ++j) {
      const GkPiece p = KronrodPieceOf(spans[j].a, spans[j].b, scale, v + 15 * j, e + 15 * j);
      out[j] = GlassPiece{p.a, p.b, p.value, p.err * safety, p.prop, spans[j].segment};
    }
  });
}

// A piece's K15 and G7 sums of the integrand times the map's Jacobian,
// each times the piece's half width in t.
struct GlassSums {
  double kron, gauss;
};

// The sums of the values f at a piece's 15 Kronrod nodes, of half width h.
inline GlassSums KronrodSums(const double* f, double h) {
  const KronrodRule& rule = Kronrod15();
  double ks = 0, gs = 0;
  for (int i = 0; i < 15; ++i) {
    ks += rule.wk[i] * f[i];
    gs += rule.wg[i] * f[i];
  }
  return {h * ks, h * gs};
}

// The piece `span` of `scale` times an integrand with no errors of its
// own, from its sums.
inline GlassPiece GlassPieceOfSums(const GlassPiece& span, const GlassSums& s, double scale, double safety) {
  return GlassPiece{span.a, span.b, scale * s.kron, safety * scale * std::abs(s.kron - s.gauss), 0.0, span.segment};
}

// GlassPiecesRule of `scale` times an integrand with no errors of its own
// whose evaluator forms the pieces' sums: sums(spans, k, out) fills the
// GlassSums of the k pieces `spans` of the segments.
template <class Sums>
RuleResult GlassSumsRule(const MappedSegment* segments, int n_segments, double scale, double tol, int max_pieces,
                         const Sums& sums, double safety = kGlassErrorSafety) {
  return GlassPiecesRule(segments, n_segments, tol, max_pieces, [&](const GlassPiece* spans, int k, GlassPiece* out) {
    GlassSums s[kGlassPieceBatch];
    sums(spans, k, s);
    for (int j = 0; j < k; ++j) out[j] = GlassPieceOfSums(spans[j], s[j], scale, safety);
  });
}

// The scalar sums of k pieces of the segments: node(x, v, k) fills the
// integrand at the 15 k points x of the k pieces.
template <class Node>
void MappedPieceSums(const MappedSegment* segments, const GlassPiece* spans, int k, GlassSums* out,
                     const Node& node) {
  double x[15 * kGlassPieceBatch], jac[15 * kGlassPieceBatch], v[15 * kGlassPieceBatch];
  MapPieceNodes(segments, spans, k, x, jac);
  node(x, v, k);
  for (int i = 0; i < 15 * k; ++i) v[i] *= jac[i];
  for (int j = 0; j < k; ++j) out[j] = KronrodSums(v + 15 * j, 0.5 * (spans[j].b - spans[j].a));
}

template <class F>
RuleResult GlassSegmentsRule(const std::vector<MappedSegment>& segments, double scale, double tol,
                             int max_pieces, const F& f, double safety = kGlassErrorSafety) {
  return GlassSegmentsRule(segments.data(), static_cast<int>(segments.size()), scale, tol, max_pieces, f, safety);
}

// The roots along the ray (cos(phi), sin(phi)) = (cp, sp) by their
// tangents, which need no angle: the form is cos^2(theta) (qa + 2 qb t +
// qc t^2), t = tan(theta), whose roots are t1 = q / qc and t2 = qa / q, q
// = -(qb + sign(qb) sqrt(qb^2 - qa qc)) (none unless qb^2 > qa qc, as for
// GlassRoots); those in (0, tan(theta_max)) count (theta in (0, pi) is t
// over the reals and inf, and theta_max is at most pi/2). The form's
// derivative in theta at a root has the sign of qb + qc t: the slope.
// Fills out (at most 6) ascending, t in .theta; returns their count.
inline int GlassTangentRoots(const GlassFrame& f, const GlassCurveForms& forms, double cp, double sp,
                             GlassRoot* out) {
  const double t_max = sp >= 0 ? std::numeric_limits<double>::infinity() : f.vz / (-sp * f.vx);
  int n = 0;
  for (int curve = kGlassReflectionHorizon; curve <= forms.last; ++curve) {
    const double qa = forms.qa[curve], qb = forms.Qb(curve, cp, sp), qc = forms.Qc(curve, cp, sp);
    const double disc = qb * qb - qa * qc;
    if (!(disc > 0)) continue;
    const double q = -(qb + std::copysign(std::sqrt(disc), qb));
    for (double t : {q / qc, qa / q}) {
      if (t > 0 && t < t_max) out[n++] = {t, curve, qb + qc * t > 0 ? 1 : -1};
    }
  }
  // Insertion sort of at most 6 roots by t.
  for (int i = 1; i < n; ++i) {
    for (int j = i; j > 0 && out[j].theta < out[j - 1].theta; --j) std::swap(out[j], out[j - 1]);
  }
  return n;
}

// The sequence of curves met along the ray at phi, as one number (the
// outer mesh is cut where it changes).
inline long GlassRaySignature(const GlassFrame& f, const GlassCurveForms& forms, double phi) {
  GlassRoot roots[6];
  const int n = GlassTangentRoots(f, forms, std::cos(phi), std::sin(phi), roots);
  long s = 1;
  for (int k = 0; k < n; ++k) s = 4 * s + roots[k].curve;
  return s;
}

// Whether a nodes evaluator forms its pieces' sums itself (Pieces, as
// the lanes evaluator does); otherwise MappedPieceSums forms them from its
// node values.
template <class Nodes, class = void>
struct HasPieceSums : std::false_type {};
template <class Nodes>
struct HasPieceSums<Nodes, std::void_t<decltype(&Nodes::Pieces)>> : std::true_type {};

template <class Nodes>
RuleResult GlassAlbedoWith(const GlassFrame& f, double tol, int max_pieces, const Nodes& nodes) {
  const double area = 0.5 * kPi<double> * (1 + f.vz);
  const GlassCurveForms forms(f);
  // The ray integral over theta at phi, to the absolute tolerance
  // `inner_tol`, with its error.
  std::vector<GlassRoot> roots;
  std::vector<MappedSegment> segs;
  auto ray = [&](double phi, double inner_tol, double* err) {
    const double sp = std::sin(phi), cp = std::cos(phi);
    const double theta_max = f.ThetaMax(sp);
    GlassRoot found[6];
    const int n_found = GlassTangentRoots(f, forms, cp, sp, found);
    roots.clear();
    for (int k = 0; k < n_found; ++k) roots.push_back({std::atan(found[k].theta), found[k].curve, found[k].slope});
    const size_t n_real = roots.size();
    // Near the lune's edge, where n.z falls below alpha, h turns from the
    // normal to the horizon: a layer of width about alpha in theta, which
    // the pieces are graded towards by kGlassGrading (the roots inside it
    // are cuts already).
    for (double w = 0.25 * theta_max; w > 0.25 * f.alpha && roots.size() < 64; w *= kGlassGrading) {
      roots.push_back({theta_max - w, 0});
    }
    // Inside that layer the tilt tau of h, tan(tau) = alpha |n_t| / n.z,
    // moves by alpha (over which G2 of a direction near the horizon, or F
    // near the critical angle, changes) while n.z moves by (n.z^2 +
    // alpha^2) / 2: graded by kGlassGrading towards each root down to a
    // quarter of that, from the sides where its curve's term lives
    // (GlassCurveLives); on the other side that term is 0 (or F is 1)
    // and the rest is smooth.
    for (size_t k = 0; k < n_real; ++k) {
      const double t0 = roots[k].theta;
      const double below = k > 0 ? roots[k - 1].theta : 0.0;
      const double above = k + 1 < n_real ? roots[k + 1].theta : theta_max;
      // The reflection's term lives where its form, |m|^2 (2 c h.z - mu), is
      // positive, the refraction (the critical angle) where its form,
      // |m|^2 (c^2 - (1 - eta^2)), is: on the side the form rises to. The
      // refraction's horizon is a root of a squared form: probed.
      const int slope = roots[k].curve == kGlassRefractionHorizon ? 0 : roots[k].slope;
      const bool grade_below =
          slope != 0 ? slope < 0 : GlassCurveLives(f, roots[k].curve, 0.5 * (below + t0), cp, sp);
      const bool grade_above =
          slope != 0 ? slope > 0 : GlassCurveLives(f, roots[k].curve, 0.5 * (t0 + above), cp, sp);
      const double nz = std::cos(t0) * f.vz + std::sin(t0) * sp * f.vx;
      const double finest = 0.125 * (nz * nz + f.alpha * f.alpha);
      for (double w = 0.25 * theta_max; w > finest && roots.size() < 160; w *= kGlassGrading) {
        if (grade_below && t0 - w > 0) roots.push_back({t0 - w, 0});
        if (grade_above && t0 + w < theta_max) roots.push_back({t0 + w, 0});
      }
    }
    std::sort(roots.begin(), roots.end(),
              [](const GlassRoot& x, const GlassRoot& y) { return x.theta < y.theta; });
    segs.clear();
    double a = 0;
    bool sing_a = false;
    for (const GlassRoot& r : roots) {
      const bool sing = r.curve == kGlassCritical;
      if (r.theta > a) segs.push_back({a, r.theta, sing_a, sing});
      a = r.theta;
      sing_a = sing;
    }
    segs.push_back({a, theta_max, sing_a, false});
    const GlassRay gr{cp, sp};
    const RuleResult res = GlassSumsRule(segs.data(), static_cast<int>(segs.size()), 1.0, inner_tol, 200,
                                         [&](const GlassPiece* spans, int k, GlassSums* out) {
                                           if constexpr (HasPieceSums<Nodes>::value) {
                                             nodes.Pieces(gr, segs.data(), spans, k, out);
                                           } else {
                                             MappedPieceSums(segs.data(), spans, k, out,
                                                             [&](const double* x, double* v, int n) {
                                                               nodes(gr, x, v, n);
                                                             });
                                           }
                                         });
    *err = res.error;
    return res.value;
  };
  // The outer segments over phi in [-pi/2, pi/2]: cut at 0, where a
  // curve's roots appear or vanish (GlassRayEvents), and where the scan of
  // the rays' signature sees any other change (roots of two curves
  // passing each other: bisection).
  std::vector<double> cuts = {-0.5 * kPi<double>, 0.0, 0.5 * kPi<double>};
  std::vector<double> events;
  GlassRayEvents(f, forms, &events);
  std::sort(events.begin(), events.end());
  cuts.insert(cuts.end(), events.begin(), events.end());
  // A change between probes x0 and x1 (no event between them), by
  // bisection.
  auto bisect = [&](double x0, double x1, long s0) {
    for (int it = 0; it < 60 && x1 - x0 > 1e-15; ++it) {
      const double xm = 0.5 * (x0 + x1);
      (GlassRaySignature(f, forms, xm) == s0 ? x0 : x1) = xm;
    }
    cuts.push_back(0.5 * (x0 + x1));
  };
  const int kScan = 128;
  for (int half = 0; half < 2; ++half) {
    const double lo = half == 0 ? -0.5 * kPi<double> : 0.0;
    const double step = 0.5 * kPi<double> / kScan;
    // Strictly inside the half, so that phi = 0 and +-pi/2 are not probed.
    double prev_phi = lo + 0.5 * step;
    long prev = GlassRaySignature(f, forms, prev_phi);
    for (int k = 1; k < kScan; ++k) {
      const double phi = lo + (k + 0.5) * step;
      const long s = GlassRaySignature(f, forms, phi);
      if (s != prev) {
        // The cell split at its events: each part probed a 64th inside its
        // ends at events, and bisected if its signature still changes.
        auto e = std::upper_bound(events.begin(), events.end(), prev_phi);
        double u = prev_phi;
        long su = prev;
        for (;; ++e) {
          const bool last = e == events.end() || *e >= phi;
          const double v = last ? phi : *e;
          const double inset = (v - u) / 64;
          const double pu = u == prev_phi ? u : u + inset, pv = last ? v : v - inset;
          if (u != prev_phi) su = GlassRaySignature(f, forms, pu);
          const long sv = last ? s : GlassRaySignature(f, forms, pv);
          if (sv != su) bisect(pu, pv, su);
          if (last) break;
          u = v;
        }
      }
      prev = s;
      prev_phi = phi;
    }
  }
  // For phi < 0 the lune's edge theta_max = atan(vz / (-sin(phi) vx))
  // falls from pi/2 to about vz / |phi| within |phi| ~ vz of phi = 0, and
  // for phi > 0 the normals near the edge n.z = sin(theta) sin(phi) vx +
  // cos(theta) vz change over the same width (a grazing view's narrow
  // feature, with tails in vz / |phi|): graded by kGlassGrading towards
  // phi = 0 from both sides down to vz / 4.
  for (double w = 0.125 * kPi<double>; w > 0.25 * f.vz && cuts.size() < 200; w *= kGlassGrading) {
    cuts.push_back(-w);
    cuts.push_back(w);
  }
  std::sort(cuts.begin(), cuts.end());
  std::vector<MappedSegment> outer;
  for (size_t k = 0; k + 1 < cuts.size(); ++k) {
    if (cuts[k + 1] > cuts[k]) outer.push_back({cuts[k], cuts[k + 1], true, true});
  }
  // Each ray's error is at most a tenth of the tolerance over the outer
  // weights (scale 2 / area, Jacobians of the maps at most 1.5 times the
  // segment's width, widths summing to pi).
  const double scale = 2 / area;
  const double inner_tol = 0.1 * tol / (scale * 1.5 * kPi<double>);
  return GlassSegmentsRule(outer, scale, tol, std::max(max_pieces, 8),
                           [&](const double* x, double* v, double* e, int k) {
                             for (int i = 0; i < 15 * k; ++i) v[i] = ray(x[i], inner_tol, &e[i]);
                           });
}

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_RULES_GLASS_GLASS_ALBEDO_RULE_H_
