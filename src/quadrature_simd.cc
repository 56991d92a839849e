// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Dynamic dispatch of the SIMD quadrature (quadrature_simd.h): the ladder,
// the lines and their horizon splits are integrate.h's templates,
// instantiated per Highway target with lines whose pieces and probes run in
// double lanes (src/simd/disk_line-inl.h, simd/math_f64-inl.h). The root
// solves on the horizon and on the layer height stay scalar
// (GgxDiskLines::Line::Z).

#include <cstring>
#include <limits>
#include <type_traits>

#include "quadrature_simd.h"

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/quadrature_simd.cc"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "simd/disk_line-inl.h"
#include "simd/math_f64-inl.h"

HWY_BEFORE_NAMESPACE();
namespace brdfbake {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using DF64 = hn::ScalableTag<double>;

// The argument a = w.z / sqrt(ax^2 w.x^2 + ay^2 w.y^2) of a slope-space
// model's unit-roughness Lambda (0 or negative below the horizon, +inf along
// the normal).
template <class V>
HWY_INLINE V SlopeArgument(V ax, V ay, V x, V y, V z) {
  const V px = hn::Mul(ax, x), py = hn::Mul(ay, y);
  return hn::Div(z, hn::Sqrt(hn::Add(hn::Mul(px, px), hn::Mul(py, py))));
}

#if BRDFBAKE_WITH_BECKMANN
// Beckmann: Lambda and D / D_ggx in lanes (simd/math_f64-inl.h,
// simd/disk_line-inl.h).
struct BeckmannLaneModel {
  hn::Vec<DF64> ax, ay;
  template <class V>
  HWY_INLINE V Lambda(DF64 d, V x, V y, V z) const {
    return BeckmannLambdaF64(d, SlopeArgument(ax, ay, x, y, z));
  }
  template <class V>
  HWY_INLINE V Ratio(DF64 d, V r2) const {
    return BeckmannOverGgx(d, r2);
  }
};
#endif

#if BRDFBAKE_WITH_STD
// The STD: D / D_ggx in lanes; Lambda (the series or continued fraction of
// StdNdf::StdLambda, whose term count depends on the argument) per lane from
// the double reference, except at gamma = inf (Beckmann).
struct StudentTLaneModel {
  const StdNdf<double>* ndf;
  hn::Vec<DF64> ax, ay, gamma, inv_gamma_minus_1;
  bool beckmann;  // gamma = inf
  template <class V>
  HWY_INLINE V Lambda(DF64 d, V x, V y, V z) const {
    const V a = SlopeArgument(ax, ay, x, y, z);
    if (beckmann) return BeckmannLambdaF64(d, a);
    HWY_ALIGN double lanes[HWY_MAX_BYTES / sizeof(double)];
    hn::Store(a, d, lanes);
    for (size_t i = 0; i < hn::Lanes(d); ++i) {
      // Below the horizon (a <= 0 or NaN) +inf, as SlopeNdf::Lambda.
      lanes[i] = lanes[i] > 0 ? ndf->StdLambda(lanes[i])
                              : std::numeric_limits<double>::infinity();
    }
    return hn::Load(d, lanes);
  }
  template <class V>
  HWY_INLINE V Ratio(DF64 d, V r2) const {
    return beckmann ? BeckmannOverGgx(d, r2) : StudentTOverGgx(d, r2, gamma, inv_gamma_minus_1);
  }
};
#endif

template <class Ndf>
auto LaneModel(DF64 d, const Ndf& ndf) {
  if constexpr (std::is_same_v<Ndf, GgxNdf<double>>) {
    return GgxDiskModel<DF64>{hn::Set(d, ndf.alpha_x()), hn::Set(d, ndf.alpha_y())};
#if BRDFBAKE_WITH_BECKMANN
  } else if constexpr (std::is_same_v<Ndf, BeckmannNdf<double>>) {
    return BeckmannLaneModel{hn::Set(d, ndf.alpha_x()), hn::Set(d, ndf.alpha_y())};
#endif
#if BRDFBAKE_WITH_STD
  } else {
    StudentTLaneModel m;
    m.ndf = &ndf;
    m.ax = hn::Set(d, ndf.alpha_x());
    m.ay = hn::Set(d, ndf.alpha_y());
    const double g = ndf.gamma();
    m.beckmann = std::isinf(g);
    m.gamma = hn::Set(d, m.beckmann ? 0.0 : g);
    m.inv_gamma_minus_1 = hn::Set(d, m.beckmann ? 0.0 : 1 / (g - 1));
    return m;
#endif
  }
}

// The lines of GgxDiskLines<Ndf> with their pieces and probes in lanes.
template <class Ndf>
class SimdDiskLines {
 public:
  using Scalar = GgxDiskLines<Ndf>;
  static constexpr bool kMirrorU2 = Scalar::kMirrorU2;

  explicit SimdDiskLines(const Integrand<Ndf>& f) : scalar_(f) {}

  class Line {
   public:
    explicit Line(const typename Scalar::Line& line) : line_(line) {}

    double Z(double t) const { return line_.Z(t); }

    // As Scalar::Line::IntegratePiece; the tail of the rule is padded with
    // zero-weight nodes at t = (a + b) / 2.
    void IntegratePiece(double a, double b, const GaussLegendre& rule, double* acc,
                        double* acc_fc) const {
      const DF64 d;
      const Scalar& fam = *line_.fam;
      if (fam.separable) {
        Piece(d, std::true_type(), a, b, rule, acc, acc_fc);
      } else {
        Piece(d, std::false_type(), a, b, rule, acc, acc_fc);
      }
    }

    void Probe(int probes, double* z) const {
      const DF64 d;
      const size_t N = hn::Lanes(d);
      const DiskLineConsts<DF64> k(d, *line_.fam, line_.c, line_.s);
      HWY_ALIGN double t[HWY_MAX_BYTES / sizeof(double)];
      HWY_ALIGN double out[HWY_MAX_BYTES / sizeof(double)];
      for (int k0 = 0; k0 <= probes; k0 += static_cast<int>(N)) {
        for (size_t i = 0; i < N; ++i) {
          const int kk = std::min(k0 + static_cast<int>(i), probes);
          t[i] = static_cast<double>(kk) / probes;
        }
        hn::Store(DiskZ(d, k, hn::Load(d, t)), d, out);
        for (size_t i = 0; i < N && k0 + static_cast<int>(i) <= probes; ++i) z[k0 + i] = out[i];
      }
    }

   private:
    template <class Separable>
    void Piece(DF64 d, Separable separable, double a, double b, const GaussLegendre& rule,
               double* acc, double* acc_fc) const {
      using V = hn::Vec<DF64>;
      const size_t N = hn::Lanes(d);
      const Scalar& fam = *line_.fam;
      const DiskLineConsts<DF64> k(d, fam, line_.c, line_.s);
      const auto model = LaneModel(d, *fam.ndf);
      const V va = hn::Set(d, a), vba = hn::Set(d, b - a);
      const V half_pi = hn::Set(d, 1.5707963267948966), pi = hn::Set(d, 3.141592653589793);
      V sum = hn::Zero(d), sum_fc = hn::Zero(d);
      auto node = [&](V x, V wt) {
        const V t = hn::MulAdd(vba, x, va);
        V w, w_fc;
        DiskEval<Scalar::kIsGgx>(d, k, model, separable, t, &w, &w_fc);
        const V jac = hn::Mul(hn::Mul(wt, vba), hn::Mul(half_pi, hn::Sin(d, hn::Mul(pi, t))));
        sum = hn::MulAdd(jac, w, sum);
        sum_fc = hn::MulAdd(jac, w_fc, sum_fc);
      };
      const size_t n = rule.x.size();
      size_t i = 0;
      for (; i + N <= n; i += N) {
        node(hn::LoadU(d, rule.x.data() + i), hn::LoadU(d, rule.w.data() + i));
      }
      if (i < n) {
        HWY_ALIGN double x[HWY_MAX_BYTES / sizeof(double)];
        HWY_ALIGN double wt[HWY_MAX_BYTES / sizeof(double)];
        for (size_t j = 0; j < N; ++j) {
          x[j] = i + j < n ? rule.x[i + j] : 0.5;
          wt[j] = i + j < n ? rule.w[i + j] : 0.0;
        }
        node(hn::Load(d, x), hn::Load(d, wt));
      }
      *acc += hn::GetLane(hn::SumOfLanes(d, sum));
      *acc_fc += hn::GetLane(hn::SumOfLanes(d, sum_fc));
    }

    typename Scalar::Line line_;
  };

  Line At(double u2) const { return Line(scalar_.At(u2)); }

 private:
  Scalar scalar_;
};

// The remainder of the Schlick-weighted azimuthal integral (azimuthal.h,
// ScalarRemainderNodes) with each piece's 16 nodes (15 and one of weight 0)
// in lanes.
struct SimdRemainderNodes {
  void operator()(const OddRemainder& rem, const RemainderRule::Piece* const* pieces, int n,
                  double* k, double* g) const {
    using V = hn::Vec<DF64>;
    const DF64 d;
    const size_t N = hn::Lanes(d);
    const RemainderRule& rule = RemainderRule::Get();
    V t[8];
    for (int m = 0; m < 8; ++m) t[m] = hn::Set(d, rem.t[m]);
    const V a = hn::Set(d, rem.a), vmin = hn::Set(d, rem.vmin), two_b = hn::Set(d, rem.two_b);
    for (int p = 0; p < n; ++p) {
      V ks = hn::Zero(d), gs = hn::Zero(d);
      for (size_t i = 0; i < 16; i += N) {
        const V b = hn::Sqrt(hn::MulAdd(two_b, hn::LoadU(d, pieces[p]->s2 + i), vmin));
        V acc = t[7];
        for (int m = 6; m >= 0; --m) acc = hn::MulAdd(acc, b, t[m]);
        const V ab = hn::Add(a, b);
        const V f = hn::Div(acc, hn::Mul(ab, ab));
        ks = hn::MulAdd(hn::LoadU(d, rule.wk + i), f, ks);
        gs = hn::MulAdd(hn::LoadU(d, rule.wg + i), f, gs);
      }
      k[p] = hn::GetLane(hn::SumOfLanes(d, ks));
      g[p] = hn::GetLane(hn::SumOfLanes(d, gs));
    }
  }
};

AzimuthalDfgResult GgxDfgTexel(double alpha, double mu, Masking masking, double tol,
                               int max_pieces) {
  return GgxAzimuthalDfgWith(alpha, mu, masking, tol, max_pieces, SimdRemainderNodes());
}

TexelValue GgxTexel(const GgxNdf<double>& ndf, double mu, Masking masking, int max_nodes,
                    double tol) {
  return QuadratureTexelWith<SimdDiskLines<GgxNdf<double>>>(ndf, mu, masking, max_nodes, tol);
}
#if BRDFBAKE_WITH_BECKMANN
TexelValue BeckmannTexel(const BeckmannNdf<double>& ndf, double mu, Masking masking,
                         int max_nodes, double tol) {
  return QuadratureTexelWith<SimdDiskLines<BeckmannNdf<double>>>(ndf, mu, masking, max_nodes,
                                                                 tol);
}
#endif
#if BRDFBAKE_WITH_STD
TexelValue StudentTTexel(const StdNdf<double>& ndf, double mu, Masking masking, int max_nodes,
                         double tol) {
  return QuadratureTexelWith<SimdDiskLines<StdNdf<double>>>(ndf, mu, masking, max_nodes, tol);
}
#endif

}  // namespace HWY_NAMESPACE
}  // namespace brdfbake
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace brdfbake {

HWY_EXPORT(GgxDfgTexel);
AzimuthalDfgResult SimdGgxAzimuthalDfg(double alpha, double mu, Masking masking, double tol,
                                       int max_pieces) {
  return HWY_DYNAMIC_DISPATCH(GgxDfgTexel)(alpha, mu, masking, tol, max_pieces);
}

HWY_EXPORT(GgxTexel);
TexelValue SimdQuadratureTexel(const GgxNdf<double>& ndf, double mu, Masking masking,
                               int max_nodes, double tol) {
  return HWY_DYNAMIC_DISPATCH(GgxTexel)(ndf, mu, masking, max_nodes, tol);
}
#if BRDFBAKE_WITH_BECKMANN
HWY_EXPORT(BeckmannTexel);
TexelValue SimdQuadratureTexel(const BeckmannNdf<double>& ndf, double mu, Masking masking,
                               int max_nodes, double tol) {
  return HWY_DYNAMIC_DISPATCH(BeckmannTexel)(ndf, mu, masking, max_nodes, tol);
}
#endif
#if BRDFBAKE_WITH_STD
HWY_EXPORT(StudentTTexel);
TexelValue SimdQuadratureTexel(const StdNdf<double>& ndf, double mu, Masking masking,
                               int max_nodes, double tol) {
  return HWY_DYNAMIC_DISPATCH(StudentTTexel)(ndf, mu, masking, max_nodes, tol);
}
#endif

}  // namespace brdfbake
#endif  // HWY_ONCE
