// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The sheen and Disney diffuse albedo rules (rules/sheen/sheen_albedo_rule.h)
// with their nodes in double SIMD lanes, through the kernels of
// kernels/sheen-inl.h that the float batch API runs too.

#include <algorithm>
#include <cfloat>
#include <cstddef>
#include <cstdint>

#include "lanes/sheen_lanes.h"
#include "rules/sheen/sheen_albedo_rule.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/lanes/sheen_lanes.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>
#include <hwy/contrib/math/math-inl.h>

#include "kernels/math_f64-inl.h"
#include "kernels/sheen-inl.h"
#include "lanes/lanes_common-inl.h"

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Lambda at the nodes of z pieces whose NoL are nol_scale = 1/2 times a
// row of the rule's z_nol: every arc with nol0 >= 0.8 takes the same rows
// at the same z (its z_hi is 1/2^power), so their Lambda is computed
// once per texel, with the same operations (the same values), and kept
// here by the row's address.
struct CharlieLambdaRows {
  static constexpr size_t kRows = 128;  // more than z_nol's 96 rows
  const double* key[kRows] = {};
  HWY_ALIGN double lambda[kRows][16];
};

// ScalarCharlieNodes with a piece's 15 nodes in lanes (the 16th at the
// piece's centre, of weight 0) and its Kronrod and Gauss sums in lanes:
// expm1 and log by Highway's (a few ulp in double), the arcs' cos(phi_h)
// and Lambda's two exponentials by CosF64ZeroToPi and ExpF64Unguarded
// (kernels/math_f64-inl.h, within 5e-16 and 3e-16 relative: the
// phi_h nodes lie in [0, pi], the exponents within +-250), Lambda(NoL) as
// CharlieLogLambda of kernels/sheen-inl.h computes it, Lambda(mu) once
// per texel.
// In z = NoL^power, z is the x^p of Lambda's L(x) = a / (1 + b x^p) + d x
// + e (CharlieLPower is the fit's p), and every NoL there is below 1/2
// (Lambda's lower branch), so L takes z itself.
// The pieces of every arc of an outer piece come in one call (Pieces),
// each with its arc's terms.
struct SimdCharlieNodes {
  using V = hn::Vec<DF64>;
  static constexpr int kCharlieBatch = 8;
  CharlieConsts<DF64> c;
  double mu;
  double lambda_mu;  // conty-kulla: Lambda(mu)
  CharlieLambdaRows* rows;  // this texel's

  // ScalarCharlieNodes::Outer in lanes: CosF64ZeroToPi (theta_h lies in
  // [0, 3 pi / 4]), Highway's Sin, Acos, Log1p, Log and Exp, D by
  // CharlieDCos2.
  void Outer(const CharlieOuterSetup& o, const double* sv, CharlieOuterNodes* out) const {
    const DF64 d;
    const size_t N = hn::Lanes(d);
    HWY_ALIGN double in[16];
    NodesTo16(sv, in);
    const V one = hn::Set(d, 1.0), minus_one = hn::Set(d, -1.0), zero = hn::Zero(d);
    const V mu = hn::Set(d, o.mu), s_mu = hn::Set(d, o.s_mu), theta_max = hn::Set(d, o.theta_max);
    const V inv_eps = hn::Set(d, 1 / o.eps);
    for (size_t i = 0; i < 16; i += N) {
      const V x = hn::Load(d, in + i);
      const V th = hn::Mul(theta_max, hn::NegMulAdd(x, x, one));
      const V cv = CosF64ZeroToPi(d, th), sv_th = hn::Sin(d, th);
      const V w = hn::Mul(hn::Mul(CharlieDCos2(d, c, hn::Mul(cv, cv)), sv_th),
                          hn::Mul(hn::Set(d, 2 * o.theta_max), x));
      const V p = hn::Mul(mu, cv), r = hn::Mul(s_mu, sv_th), two_c = hn::Add(cv, cv);
      const auto r_pos = hn::Gt(r, zero);
      const V rs = hn::IfThenElse(r_pos, r, one);
      // cos(phi) where NoL = nol: (nol + mu - 2 c p) / (2 c r), one
      // division for the three; -1 (phi = pi) where r = 0.
      const V inv = hn::Div(one, hn::Mul(two_c, rs));
      const V base = hn::NegMulAdd(two_c, p, mu);
      auto cos_at = [&](V nol) {
        const V v = hn::Mul(hn::Add(nol, base), inv);
        return hn::IfThenElse(r_pos, hn::Min(hn::Max(v, minus_one), one), minus_one);
      };
      const V cm = hn::IfThenElse(r_pos, hn::Mul(base, inv), minus_one);
      const V phi_max = hn::IfThenElse(
          hn::Lt(cm, one), hn::Acos(d, hn::Min(hn::Max(cm, minus_one), one)), zero);
      const V nol0 = hn::Sub(hn::Mul(two_c, hn::Add(p, r)), mu);
      V split = hn::Mul(hn::Set(d, 0.5), nol0);
      if (o.lambda) {
        split = hn::IfThenElse(hn::Ge(nol0, hn::Set(d, 0.8)), hn::Set(d, 0.5),
                               hn::Mul(hn::Set(d, 0.35), nol0));
      }
      hn::StoreU(cv, d, out->c + i);
      hn::StoreU(sv_th, d, out->s + i);
      hn::StoreU(w, d, out->w + i);
      hn::StoreU(phi_max, d, out->phi_max + i);
      hn::StoreU(hn::Acos(d, cos_at(split)), d, out->phi_split + i);
      // What the visibility's arcs use: phi_half and z_hi with a Lambda,
      // tau_hi without.
      if (o.lambda) {
        hn::StoreU(hn::Acos(d, cos_at(hn::Set(d, 0.5))), d, out->phi_half + i);
        const V ls = hn::Log(d, hn::IfThenElse(hn::Gt(split, zero), split, one));
        hn::StoreU(ExpF64Unguarded(d, hn::Mul(hn::Set(d, o.power), ls)), d, out->z_hi + i);
      } else {
        hn::StoreU(hn::Log1p(d, hn::Mul(split, inv_eps)), d, out->tau_hi + i);
      }
    }
  }

  // ScalarCharlieNodes::Pieces: m pieces [a[j], b[j]] of the arcs arc[j],
  // the first m_phi in phi and the others in `var`, at most
  // kCharlieBatch pieces at a time, their nodes in stages (Nodes).
  void Pieces(const CharlieArcTerms* t, const double* nol_scale, const int* arc, CharlieArcVar var,
              double arg, const double* a, const double* b, int m_phi, int m,
              const double* const* nol_rel, double* value, double* err) const {
    for (int j = 0; j < m; j += kCharlieBatch) {
      const int k = std::min(m - j, kCharlieBatch), k_phi = std::clamp(m_phi - j, 0, k);
      const double* const* rel = nol_rel != nullptr ? nol_rel + j : nullptr;
      if (var == CharlieArcVar::kLog) {
        Sums<CharlieArcVar::kLog>(t, nol_scale, arc + j, arg, a + j, b + j, k_phi, k, rel, value + j,
                                  err + j);
      } else {
        Sums<CharlieArcVar::kZ>(t, nol_scale, arc + j, arg, a + j, b + j, k_phi, k, rel, value + j,
                                err + j);
      }
    }
  }

  // ScalarCharlieNodes::Powers in lanes (n a multiple of 16), for the
  // rule's z_nol: x in (1e-30, 1] (normal, so Highway's log without its
  // subnormal case) and e = 1 / power, below 7, so that e log(x) lies
  // within -500 and 0 (ExpF64Unguarded's range).
  void Powers(const double* x, int n, double e, double* out) const {
    const DF64 d;
    const size_t N = hn::Lanes(d);
    const V ev = hn::Set(d, e);
    for (size_t i = 0; i < static_cast<size_t>(n); i += N) {
      const V lx = hn::impl::Log<DF64, V, false>(d, hn::LoadU(d, x + i));
      hn::StoreU(ExpF64Unguarded(d, hn::Mul(ev, lx)), d, out + i);
    }
  }

 private:
  // The nodes of m pieces go through each stage of Nodes together: a
  // stage's vectors are independent of one another, so the core overlaps
  // their long chains of cos, log, exp and divisions instead of waiting
  // on one node's chain (one piece is two vectors in AVX-512 lanes).
  // On a 64 x 64 conty-kulla table this took about 30% less time than
  // piece by piece, node by node, with the same values, and the pieces of
  // all the arcs of an outer piece in one call (rather than one arc's)
  // 7% less again.
  template <CharlieArcVar kEnd>
  void Sums(const CharlieArcTerms* t, const double* nol_scale, const int* arc, double arg,
            const double* a, const double* b, int m_phi, int m, const double* const* nol_rel,
            double* value, double* err) const {
    static const Kronrod16 rule;
    const DF64 d;
    const size_t N = hn::Lanes(d);
    HWY_ALIGN double x[16 * kCharlieBatch], g[16 * kCharlieBatch];
    for (int j = 0; j < m; ++j) {
      const double mid = 0.5 * (a[j] + b[j]), h = 0.5 * (b[j] - a[j]);
      for (size_t i = 0; i < 16; i += N) {
        hn::Store(hn::MulAdd(hn::Set(d, h), hn::Load(d, rule.x + i), hn::Set(d, mid)), d,
                  x + 16 * j + i);
      }
    }
    Terms terms[kCharlieBatch];
    for (int j = 0; j < m; ++j) terms[j] = Terms(t[arc[j]], mu, nol_scale[arc[j]]);
    Nodes<kEnd>(d, terms, arg, x, g, 16 * static_cast<size_t>(m_phi), 16 * static_cast<size_t>(m),
                nol_rel);
    for (int j = 0; j < m; ++j) {
      V ks = hn::Zero(d), gs = hn::Zero(d);
      for (size_t i = 0; i < 16; i += N) {
        const V gv = hn::Load(d, g + 16 * j + i);
        ks = hn::MulAdd(hn::Load(d, rule.wk + i), gv, ks);
        gs = hn::MulAdd(hn::Load(d, rule.wg + i), gv, gs);
      }
      const double k = hn::GetLane(hn::SumOfLanes(d, ks)), gauss = hn::GetLane(hn::SumOfLanes(d, gs));
      const double s = 2 * (0.5 * (b[j] - a[j]));
      value[j] = k * s;
      err[j] = std::abs(k - gauss) * s;
    }
  }

  // A piece's arc constants (the lanes take them one piece at a time).
  struct Terms {
    double p, r, two_c, half_over_c, nol0, nol_pi, nol_scale;
    Terms() = default;
    Terms(const CharlieArcTerms& t, double m, double scale)
        : p(t.p),
          r(t.r),
          two_c(t.two_c),
          half_over_c(1 / t.two_c),
          nol0(t.two_c * (t.p + t.r) - m),
          nol_pi(t.two_c * (t.p - t.r) - m),
          nol_scale(scale) {}
  };

  // g = V NoL 4 y at NoL = 2 c y - mu, as num / den, times the Jacobian
  // jac_num / jac_den of the node's variable: y = p + r cos(phi) (kPhi);
  // NoL = z^(1/power), dphi/dz = NoL / (z power 2 c r sin(phi)) (kZ);
  // NoL = eps expm1(tau), dphi/dtau = (NoL + eps) / (2 c r sin(phi))
  // (kLog). There 2 c r sin(phi) = sqrt((nol0 - NoL) (NoL - nol_pi))
  // (ArcSine). One division per node where V is not capped. The n nodes
  // x[i] (n a multiple of 16) give g[i], stage by stage: the variable's
  // map, log(NoL) for Lambda's x^p, Lambda, and g; each stage's vectors
  // are independent of one another.
  template <CharlieArcVar kEnd>
  HWY_INLINE void Nodes(DF64 d, const Terms* terms, double arg, const double* xs, double* out,
                        size_t n_phi, size_t n, const double* const* nol_rel) const {
    const size_t N = hn::Lanes(d);
    const V one = hn::Set(d, 1.0), zero = hn::Zero(d), mu_v = hn::Set(d, mu);
    HWY_ALIGN double ys[16 * kCharlieBatch], nols[16 * kCharlieBatch], jns[16 * kCharlieBatch], jds[16 * kCharlieBatch],
        ls[16 * kCharlieBatch], ws[16 * kCharlieBatch];
    // The variable's map: the phi nodes' and the end part's vectors
    // alternate, so that the core mixes the cosines' multiply-adds with
    // the end part's square roots.
    auto phi_map = [&](size_t i) HWY_ATTR {
      const Terms& t = terms[i / 16];
      const V y = hn::MulAdd(hn::Set(d, t.r), CosF64ZeroToPi(d, hn::Load(d, xs + i)), hn::Set(d, t.p));
      hn::Store(y, d, ys + i);
      hn::Store(hn::Sub(hn::Mul(hn::Set(d, t.two_c), y), mu_v), d, nols + i);
    };
    auto end_map = [&](size_t i) HWY_ATTR {
      const Terms& t = terms[i / 16];
      const V x = hn::Load(d, xs + i);
      V nol, jac_num, jac_den;
      if constexpr (kEnd == CharlieArcVar::kZ) {
        const double* rel = nol_rel != nullptr ? nol_rel[i / 16] : nullptr;
        if (rel != nullptr) {
          nol = hn::Mul(hn::Set(d, t.nol_scale), hn::LoadU(d, rel + i % 16));
        } else {
          nol = hn::Exp(d, hn::Mul(hn::Set(d, 1 / arg), hn::Log(d, x)));
        }
      } else {
        nol = hn::Mul(hn::Set(d, arg), hn::Expm1(d, x));
      }
      const V y = hn::Mul(hn::Add(nol, mu_v), hn::Set(d, t.half_over_c));
      jac_den = hn::Sqrt(hn::Max(
          hn::Mul(hn::Sub(hn::Set(d, t.nol0), nol), hn::Sub(nol, hn::Set(d, t.nol_pi))), zero));
      if constexpr (kEnd == CharlieArcVar::kZ) {
        jac_num = nol;
        jac_den = hn::Mul(jac_den, hn::Mul(x, hn::Set(d, arg)));
      } else {
        jac_num = hn::Add(nol, hn::Set(d, arg));
      }
      hn::Store(y, d, ys + i);
      hn::Store(nol, d, nols + i);
      hn::Store(jac_num, d, jns + i);
      hn::Store(jac_den, d, jds + i);
    };
    for (size_t k = 0; k < n_phi || n_phi + k < n; k += N) {
      if (k < n_phi) phi_map(k);
      if (n_phi + k < n) end_map(n_phi + k);
    }
    // Lambda: exp of L (CharlieLogLambda: L(w) below 1/2, 2 L(1/2) - L(1 -
    // w) above, L(x) = a / (1 + b x^p) + d x + e), x^p as exp(p log x)
    // in phi, and in z, z itself (every NoL there is below 1/2).
    if (!c.neubelt) {
      const V half = hn::Set(d, 0.5);
      // w with the branch in its sign (+ below 1/2, - from 1/2 on, where
      // w = 1 - NoL may be 0), and log w: a w below DBL_MIN is taken as
      // DBL_MIN, whose x^p (p > 0.16: below 1e-51, so that 1 + b x^p
      // rounds to 1 for both) leaves L unchanged, and the log needs no
      // subnormal case (Highway's impl::Log without it; the same values
      // for normal w).
      for (size_t i = 0; i < n_phi; i += N) {
        const V nol = hn::Load(d, nols + i);
        const V nl = hn::Min(hn::IfThenElse(hn::Gt(nol, zero), nol, one), one);
        const auto low = hn::Lt(nl, half);
        const V w = hn::IfThenElse(low, nl, hn::Sub(one, nl));
        hn::Store(hn::IfThenElse(low, w, hn::Neg(w)), d, ws + i);
        hn::Store(hn::impl::Log<DF64, V, false>(d, hn::Max(w, hn::Set(d, DBL_MIN))), d, ls + i);
      }
      for (size_t i = 0; i < n_phi; i += N) {
        const V sw = hn::Load(d, ws + i);
        const auto low = hn::Gt(sw, zero);
        const V w = hn::Abs(sw);
        // (w = 0 gives x^p below 1e-51 rather than 0, the same L.)
        const V xp = ExpF64Unguarded(d, hn::Mul(c.p, hn::Load(d, ls + i)));
        const V l = hn::Add(hn::MulAdd(c.dd, w, c.e), hn::Div(c.a, hn::MulAdd(c.b, xp, one)));
        hn::Store(ExpF64Unguarded(d, hn::IfThenElse(low, l, hn::Sub(c.two_l_half, l))), d, ls + i);
      }
      for (size_t j = n_phi / 16; j < n / 16; ++j) {
        const double* rel = nol_rel != nullptr ? nol_rel[j] : nullptr;
        double* kept = nullptr;
        if (rel != nullptr && terms[j].nol_scale == 0.5) {
          const size_t slot = (reinterpret_cast<uintptr_t>(rel) / sizeof(double[16])) % rows->kRows;
          kept = rows->lambda[slot];
          if (rows->key[slot] == rel) {
            for (size_t i = 0; i < 16; i += N) hn::Store(hn::Load(d, kept + i), d, ls + 16 * j + i);
            continue;
          }
          rows->key[slot] = rel;
        }
        for (size_t i = 16 * j; i < 16 * j + 16; i += N) {
          const V nol = hn::Load(d, nols + i);
          const V nl = hn::Min(hn::IfThenElse(hn::Gt(nol, zero), nol, one), one);
          const V log_lambda = hn::Add(hn::MulAdd(c.dd, nl, c.e),
                                       hn::Div(c.a, hn::MulAdd(c.b, hn::Load(d, xs + i), one)));
          const V lambda = ExpF64Unguarded(d, log_lambda);
          hn::Store(lambda, d, ls + i);
          if (kept != nullptr) hn::Store(lambda, d, kept + i - 16 * j);
        }
      }
    }
    // g, with the Jacobian beyond the phi nodes (whose is 1).
    const V one_lambda_mu = hn::Set(d, 1 + lambda_mu);
    for (size_t i = 0; i < n; i += N) {
      const bool in_phi = i < n_phi;
      const V y = hn::Load(d, ys + i), nol = hn::Load(d, nols + i);
      const auto up = hn::Gt(nol, zero);
      const V nl = hn::Min(hn::IfThenElse(up, nol, one), one);
      V num, den;
      if (c.neubelt) {
        // V NoL 4 y = NoL y / (NoL + mu - NoL mu).
        num = hn::Mul(nol, y);
        den = hn::Add(hn::NegMulAdd(nl, mu_v, nl), mu_v);
      } else {
        // V NoL 4 y = y G2 / mu, G2 = 1 / (1 + Lambda(mu) + Lambda(NoL)).
        num = y;
        den = hn::Mul(mu_v, hn::Add(one_lambda_mu, hn::Load(d, ls + i)));
      }
      V g;
      if (c.clamp) {
        // V <= 1, so g <= 4 NoL y.
        g = hn::Min(hn::Div(num, den), hn::Mul(hn::Mul(hn::Set(d, 4.0), nl), y));
        if (!in_phi) g = hn::Div(hn::Mul(g, hn::Load(d, jns + i)), hn::Load(d, jds + i));
      } else if (in_phi) {
        g = hn::Div(num, den);
      } else {
        g = hn::Div(hn::Mul(num, hn::Load(d, jns + i)), hn::Mul(den, hn::Load(d, jds + i)));
      }
      hn::Store(hn::IfThenElseZero(up, g), d, out + i);
    }
  }
};

RuleResult CharlieTexel(double alpha, SheenVisibility visibility, double mu, double tol,
                        int max_pieces) {
  const CharlieSheen<double> sheen(alpha, visibility);
  const double m = std::clamp(mu, 1e-7, 1.0);
  CharlieLambdaRows rows;
  const SimdCharlieNodes nodes{CharlieConsts<DF64>(DF64(), alpha, visibility), m,
                               SheenHasLambda(visibility) ? sheen.LambdaCos(m) : 0.0, &rows};
  return CharlieAlbedoWith(sheen, mu, tol, max_pieces, nodes);
}

// ScalarDisneyNodes with the n <= 16 cosines in lanes.
struct SimdDisneyNodes {
  double r;
  void operator()(const double* x, double mu, int n, double* m) const {
    using V = hn::Vec<DF64>;
    const DF64 d;
    const size_t N = hn::Lanes(d);
    HWY_ALIGN double in[16] = {}, out[16];
    for (int i = 0; i < n; ++i) in[i] = x[i];
    const DisneyConsts<DF64> c(d, r);
    const V muv = hn::Set(d, mu);
    for (size_t i = 0; i < size_t(n); i += N) {
      hn::Store(DisneyAzimuthMean(d, c, hn::Load(d, in + i), muv), d, out + i);
    }
    for (int i = 0; i < n; ++i) m[i] = out[i];
  }
};

RuleResult DisneyTexel(double r, double mu) { return DisneyAlbedoWith(mu, SimdDisneyNodes{r}); }
RuleResult DisneyEavgTexel(double r) { return DisneyEavgWith(SimdDisneyNodes{r}); }

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace brdfbake {

HWY_EXPORT(CharlieTexel);
RuleResult SimdCharlieAlbedo(double alpha, SheenVisibility visibility, double mu, double tol,
                             int max_pieces) {
  return HWY_DYNAMIC_DISPATCH(CharlieTexel)(alpha, visibility, mu, tol, max_pieces);
}

HWY_EXPORT(DisneyTexel);
RuleResult SimdDisneyAlbedo(double r, double mu) { return HWY_DYNAMIC_DISPATCH(DisneyTexel)(r, mu); }

HWY_EXPORT(DisneyEavgTexel);
RuleResult SimdDisneyEavg(double r) { return HWY_DYNAMIC_DISPATCH(DisneyEavgTexel)(r); }

}  // namespace brdfbake
#endif  // HWY_ONCE
