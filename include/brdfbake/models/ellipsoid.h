// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The ellipsoid NDF of Walter, Dong, Marschner and Greenberg ([Walter15]): the
// normal distribution of the upper half (m.n >= 0) of an arbitrary ellipsoid
// p^T A^T A p = C_e^2 (seed eq. 7). The shape matrix is A = S R with
// S = diag(alpha_x, alpha_y, 1) and R = Rx(theta_x) Ry(theta_y) Rz(theta_z)
// (seed eq. 2-3; Mat3::RotX/RotY/RotZ are the matrices printed in eq. 3).
// theta_z turns the axes of anisotropy in the tangent plane; theta_x and
// theta_y tilt the peak of the distribution away from n (a skewed NDF).
// With R = I the model is anisotropic GGX (GTR2aniso), see [EllipsoidalGGX].
//
// Everything is expressed through the "sphere space" p_o = A p of seed
// eq. 22, where the ellipsoid is a sphere of radius C_e:
//
//   D(m)        = X+(m.n) / (pi |A| ||An|| ||A^-T m||^4)              (eq. 1)
//   A_e(u)      = pi C_e^2 ||Au|| / |A|                               (eq. 24)
//   A_l(u, v)   = pi C_e^2 (||Au|| ||Av|| + Au.Av) / (2 |A| ||Av||)   (eq. 26)
//   C_e^2       = |A| / (pi ||An||), so that A_e(n) = 1                (eq. 27)
//   G1(u)       = min(1, A_e(n) u.n / A_l(u, n))                      (eq. 29 = 6)
//   p_u(m)      = A_e(n) X+(u.m) D(m) u.m / A_l(u, n)                 (eq. 30)
//
// With the eq. 27 convention A_e(u) = ||Au|| / ||An|| and
// A_l(u, v) = ||Au|| (1 + cos theta_l) / (2 ||An||), where cos theta_l is the
// cosine between Au and Av (the normals of the two planes cutting the sphere
// into a spherical lune). We evaluate 1 + cos theta_l as ||w + k||^2 / 2 with
// w, k the unit vectors along Au, Av: it keeps full relative precision for
// thin lunes (strongly tilted ellipsoids seen at grazing angles).
//
// Typos and subtleties in [Walter15], all checked numerically (the identities
// by quadrature in tests/models/ellipsoid_test.cc, eq. 23 with mpmath):
//  - eq. 23 reads (Ma) x (Mb) = |M| M^-1 (a x b); the identity is
//    |M| M^-T (a x b) (the cofactor matrix). The text after it (and eq. 24)
//    uses the correct A^-T.
//  - eq. 6 uses |u.n|; below the horizon G1 must be 0, not the value at -u.
//  - eq. 1 needs the absolute value of the determinant if A is ever
//    multiplied on the left by an improper orthogonal matrix (the invariance
//    stated in section 1); with A = S R, |A| = alpha_x alpha_y > 0.
//  - eq. 30 is normalized by A_l(u, n), not by u.n / G1(u): the two differ
//    where the min in eq. 29 is active (tilted ellipsoids near normal view),
//    so PdfVisible and DVisible below are different functions in general.
//  - section 5: for theta_x, theta_y != 0 the half ellipsoid is cut by the
//    plane normal to A^T A n, so the mean microfacet normal is not n; D is
//    still normalized as integral of D(m) m.n dm = 1 (eq. 8), and G1 only
//    satisfies eq. 28 as an inequality.

#ifndef BRDFBAKE_MODELS_ELLIPSOID_H_
#define BRDFBAKE_MODELS_ELLIPSOID_H_

#include <algorithm>
#include <cmath>
#include <limits>

#include "brdfbake/models/slope_ndf.h"
#include "brdfbake/models/vec3.h"

namespace brdfbake {

template <typename T>
class EllipsoidNdf {
 public:
  // A = S R, S = diag(alpha_x, alpha_y, 1), R = Rx(theta_x) Ry(theta_y)
  // Rz(theta_z), angles in radians; alphas are clamped to kMinAlpha.
  EllipsoidNdf(T alpha_x, T alpha_y, T theta_x, T theta_y, T theta_z)
      : EllipsoidNdf(ClampAlpha(alpha_x), ClampAlpha(alpha_y),
                     Mat3<T>::RotX(theta_x) * Mat3<T>::RotY(theta_y) *
                         Mat3<T>::RotZ(theta_z)) {}

  // A general non-singular shape matrix (seed eq. 1 only depends on A up to
  // a positive scale and a left orthogonal factor). alpha_x() and alpha_y()
  // then report ||row 0|| / ||row 2|| and ||row 1|| / ||row 2|| of A, which
  // are the alphas whenever A = c S R; no clamping is applied.
  static EllipsoidNdf FromShapeMatrix(const Mat3<T>& a) {
    return EllipsoidNdf(a, InverseTransposed(a));
  }

  T alpha_x() const { return ax_; }
  T alpha_y() const { return ay_; }
  const Mat3<T>& shape_matrix() const { return a_; }
  const Mat3<T>& inverse_transposed() const { return a_inv_t_; }  // A^-T

  // The pieces of Lambda below, for evaluators that take Lambda apart (the
  // baker's double lanes): Lambda(u) = N(u) / ||h|| scale / u.z with
  // N / ||h|| as computed there, h_dir = h / ||h||, rho = ||An|| / ||h||.
  const Vec3<T>& lambda_h_dir() const { return h_dir_; }
  T lambda_rho() const { return rho_; }
  T lambda_scale() const { return lambda_scale_; }
  // rho ||Au|| - Au . h_dir: Lambda(u) is 0 (G1's clamp is active) exactly
  // where this is <= 0; smooth in u, so the clamp's edge is its root.
  T ClampMargin(const Vec3<T>& u) const {
    const Vec3<T> a = a_ * u;
    return rho_ * Length(a) - Dot(a, h_dir_);
  }

  // Seed eq. 1, per steradian; zero for m.z <= 0.
  T D(const Vec3<T>& m) const {
    if (!(m.z > T(0))) return T(0);
    const Vec3<T> q = a_inv_t_ * m;
    const T q2 = Dot(q, q);
    return d_scale_ / (q2 * q2);
  }

  // Projected area of the whole ellipsoid along the unit direction u
  // (seed eq. 24) with C_e from eq. 27, i.e. ProjectedArea(n) = 1.
  T ProjectedArea(const Vec3<T>& u) const { return Length(a_ * u) * inv_an_len_; }

  // Projected area along u of the ellipsoidal lune {m.u >= 0, m.v >= 0}
  // (seed eq. 25-26) with the eq. 27 convention. LuneProjectedArea(u, n) is
  // the projected area of the visible part of the microsurface,
  // = integral of max(0, u.m) D(m) dm.
  T LuneProjectedArea(const Vec3<T>& u, const Vec3<T>& v) const {
    const Vec3<T> au = a_ * u;
    const T au_len = Length(au);
    const Vec3<T> half = au / au_len + Normalize(a_ * v);
    return T(0.25) * au_len * Dot(half, half) * inv_an_len_;
  }

  // Smith-like Lambda, defined here as 1 / G1(u) - 1 so that the generic
  // height-correlated G2 = 1 / (1 + Lambda(wi) + Lambda(wo)) (docs/format.md,
  // conventions) can be used with this model. This is brdfbake's extension:
  // [Walter15] only defines the separable G = G1 G1 (eq. 5). +inf for
  // u.z <= 0, 0 where the min in eq. 6 is active.
  //
  // From eq. 6, Lambda = N / (2 ||An||^2 u.n) with
  //   N = ||Au|| ||An|| + Au.An - 2 ||An||^2 u.n = ||An|| ||a|| - a.h,
  // a = Au, h = 2 ||An||^2 A^-T n - An (using u.n = Au . A^-T n). N is
  // evaluated as ||h|| (rho ||a|| - a.h^) with rho = ||An|| / ||h|| <= 1,
  // rationalized when a.h^ > 0; for R = I (h^ = n, rho = 1) this is the
  // cancellation-free GGX form |(ax ux, ay uy)|^2 / (||Au|| + u.z).
  T Lambda(const Vec3<T>& u) const {
    if (!(u.z > T(0))) return std::numeric_limits<T>::infinity();
    const Vec3<T> a = a_ * u;
    const T a_len = Length(a);
    const T ah = Dot(a, h_dir_);
    T n_over_h;
    if (ah > T(0)) {
      const Vec3<T> a_perp = a - h_dir_ * ah;
      const T num = rho2_ * Dot(a_perp, a_perp) - one_minus_rho2_ * ah * ah;
      n_over_h = num / (rho_ * a_len + ah);
    } else {
      n_over_h = rho_ * a_len - ah;
    }
    if (!(n_over_h > T(0))) return T(0);
    return n_over_h * lambda_scale_ / u.z;
  }

  // Seed eq. 6 / 29 without the back-facing indicator; 0 for u.z <= 0.
  T G1(const Vec3<T>& u) const {
    if (!(u.z > T(0))) return T(0);
    return T(1) / (T(1) + Lambda(u));
  }

  // Seed eq. 6 with the indicator X+(u.m).
  T G1(const Vec3<T>& u, const Vec3<T>& m) const {
    return Dot(u, m) > T(0) ? G1(u) : T(0);
  }

  // Heitz's distribution of visible normals G1(u) max(0, u.m) D(m) / u.z
  // ([Heitz18] eq. 3). It integrates to min(1, A_l(u, n) / u.z) <= 1: exactly
  // 1 for R = I, less where the min in eq. 6 is active.
  T DVisible(const Vec3<T>& u, const Vec3<T>& m) const {
    const T um = Dot(u, m);
    if (!(um > T(0)) || !(u.z > T(0))) return T(0);
    return G1(u) * um * D(m) / u.z;
  }

  // Visible-normal sampling without rejection, [Walter15] section 4,
  // "Version 3". In sphere space (eq. 22) the ellipsoid is the unit sphere,
  // the view direction is w = normalize(Au) and the cut plane of the
  // half-ellipsoid m.n >= 0 has normal k = normalize(An) (eq. 21). The valid
  // lune {p.w >= 0, p.k >= 0} projects along w onto a crescent of area
  // pi (1 + w.k) / 2: a uniform disk point is compressed by
  // s = (1 + w.k) / 2 along t2 and sheared onto the crescent ([Heitz18]
  // Listing 1 is the case k = z), lifted onto the sphere along w, and mapped
  // to the ellipsoid normal at A^-1 p, m = normalize(A^T p). Uniform points
  // on the projected lune give m with density PdfVisible(u, m) (eq. 30).
  // Requires u.z > 0. With R = I this is GgxNdf::SampleVisible step by step.
  Vec3<T> SampleVisible(const Vec3<T>& u, T u1, T u2) const {
    const Vec3<T> w = Normalize(a_ * u);
    const Vec3<T> k = an_dir_;
    // Basis (t1, t2, w) with k in the (t2, w) half-plane of positive t2.
    const Vec3<T> kw = Cross(k, w);
    const T kw2 = Dot(kw, kw);
    Vec3<T> t1;
    if (kw2 > T(0)) {
      t1 = kw / std::sqrt(kw2);
    } else {
      // w = k: the lune is the whole hemisphere, any basis will do.
      t1 = std::abs(w.y) < T(0.9) ? Normalize(Cross(Vec3<T>(T(0), T(1), T(0)), w))
                                  : Normalize(Cross(w, Vec3<T>(T(1), T(0), T(0))));
    }
    const Vec3<T> t2 = Cross(w, t1);
    // Uniform point on the unit disk, compressed and sheared onto the
    // crescent p2 in [-(w.k) sqrt(1 - p1^2), sqrt(1 - p1^2)].
    const T r = std::sqrt(u1);
    const T phi = T(2) * kPi<T> * u2;
    const T p1 = r * std::cos(phi);
    T p2 = r * std::sin(phi);
    const Vec3<T> wk = w + k;
    const T s = T(0.25) * Dot(wk, wk);  // (1 + w.k) / 2
    p2 = (T(1) - s) * std::sqrt(std::max(T(0), T(1) - p1 * p1)) + s * p2;
    // Lift along w onto the sphere, then to the ellipsoid normal.
    const Vec3<T> p =
        t1 * p1 + t2 * p2 + w * std::sqrt(std::max(T(0), T(1) - p1 * p1 - p2 * p2));
    Vec3<T> q = a_t_ * p;
    q.z = std::max(T(0), q.z);  // q.z = p.An >= 0 up to rounding
    return Normalize(q);
  }

  // Seed eq. 30 with A_e(n) = 1: D(m) max(0, u.m) / A_l(u, n), the density
  // per steradian of SampleVisible's m. Zero for u.z <= 0.
  T PdfVisible(const Vec3<T>& u, const Vec3<T>& m) const {
    const T um = Dot(u, m);
    if (!(um > T(0)) || !(u.z > T(0))) return T(0);
    return D(m) * um / LuneProjectedArea(u, Vec3<T>(T(0), T(0), T(1)));
  }

 private:
  EllipsoidNdf(T ax, T ay, const Mat3<T>& r)
      : EllipsoidNdf(Mat3<T>::Diagonal(ax, ay, T(1)) * r,
                     // (S R)^-T = S^-1 R: exact, no general inverse needed.
                     Mat3<T>::Diagonal(T(1) / ax, T(1) / ay, T(1)) * r) {}

  EllipsoidNdf(const Mat3<T>& a, const Mat3<T>& a_inv_t) : a_(a), a_inv_t_(a_inv_t) {
    a_t_ = a_.Transposed();
    const T det = std::abs(a_.Determinant());
    const Vec3<T> an(a_.m[0][2], a_.m[1][2], a_.m[2][2]);  // A n, n = z
    const T an_len = Length(an);
    an_dir_ = an / an_len;
    inv_an_len_ = T(1) / an_len;
    d_scale_ = kInvPi<T> / (det * an_len);
    // Lambda: h = 2 ||An||^2 A^-T n - An.
    const T an2 = an_len * an_len;
    const Vec3<T> g(a_inv_t_.m[0][2], a_inv_t_.m[1][2], a_inv_t_.m[2][2]);
    const Vec3<T> h = g * (T(2) * an2) - an;
    const T h_len = Length(h);
    h_dir_ = h / h_len;
    rho_ = std::min(T(1), an_len / h_len);
    rho2_ = rho_ * rho_;
    one_minus_rho2_ = (T(1) - rho_) * (T(1) + rho_);
    lambda_scale_ = h_len / (T(2) * an2);
    const auto row_len = [&](int i) {
      return std::sqrt(a_.m[i][0] * a_.m[i][0] + a_.m[i][1] * a_.m[i][1] +
                       a_.m[i][2] * a_.m[i][2]);
    };
    ax_ = row_len(0) / row_len(2);
    ay_ = row_len(1) / row_len(2);
  }

  // A^-T = cof(A) / det(A).
  static Mat3<T> InverseTransposed(const Mat3<T>& a) {
    Mat3<T> c;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        const int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
        const int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
        c.m[i][j] = a.m[i1][j1] * a.m[i2][j2] - a.m[i1][j2] * a.m[i2][j1];
      }
    }
    const T inv_det = T(1) / a.Determinant();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) c.m[i][j] *= inv_det;
    return c;
  }

  Mat3<T> a_;        // A = S R
  Mat3<T> a_inv_t_;  // A^-T
  Mat3<T> a_t_;      // A^T
  Vec3<T> an_dir_;   // An / ||An||
  T inv_an_len_;     // 1 / ||An||
  T d_scale_;        // 1 / (pi |A| ||An||)
  Vec3<T> h_dir_;    // Lambda: h / ||h||
  T rho_, rho2_, one_minus_rho2_, lambda_scale_;
  T ax_, ay_;
};

}  // namespace brdfbake

#endif  // BRDFBAKE_MODELS_ELLIPSOID_H_
