// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// STD: the Student's t-distribution of slopes ([Ribardiere17]), isotropic and
// anisotropic, with shape parameter gamma in (1.5, +inf]. gamma = 2 is GGX,
// gamma -> inf is Beckmann ([Ribardiere17] section 2).
//
// Unit-roughness ("standard", sigma = 1) slope density, [Ribardiere17] eq. 13:
//   P22(r^2) = 1 / (pi (1 + r^2 / (gamma - 1))^gamma),
// a bivariate Student's t law scaled so that the slope variance is
// (gamma - 1) / (2 (gamma - 2)) per axis for gamma > 2 (infinite below;
// -> 1/2, Beckmann's, as gamma -> inf).
// alpha_x, alpha_y are [Ribardiere17]'s sigma_x, sigma_y; anisotropy is the
// SlopeNdf stretch ([Ribardiere17] eq. 10 with f = 1 / (gamma - 1)).
//
// Smith Lambda at a = cot(theta) (unit roughness), [Ribardiere17] eq. 17 and 21.
// With nu = gamma - 1/2, m = a / sqrt(gamma - 1), x0 = 1 / (1 + m^2) and
//   K = Gamma(gamma - 1/2) / (sqrt(pi) Gamma(gamma - 1)),
// the substitution q = sqrt(gamma - 1) t in eq. 17 gives
//   Lambda = K J(m) / m,   J(m) = integral_m^inf (t - m) (1 + t^2)^(-nu) dt,
//   J = x0^(nu-1) / (2 nu - 1) [1 / (2 nu - 2) + x0 2F1(nu, 1; nu + 3/2; x0) / (2 nu + 1)]
// (from J = (1+m^2)^(1-nu) / (2 nu - 2) - m T(m), T(m) = integral_m^inf
// (1+t^2)^-nu dt = B(x0; nu - 1/2, 1/2) / 2 and B(x; p, q) = x^p (1-x)^q
// 2F1(p+q, 1; p+1; x) / p). That 2F1 is not used as such: near x0 = 1 its
// series converges slowly, and for large gamma it is so sensitive to x0
// that the rounding of x0 alone costs ~gamma ulps. Two exact rearrangements
// with positive terms are used instead (both checked against 50-digit
// mpmath quadrature):
//  (S) fraction form, after the Pfaff transformation
//      x0 2F1(nu, 1; nu + 3/2; x0) = 2F1(1, 3/2; gamma + 1; -1/m^2) / m^2:
//        Lambda = K / (2 sqrt(gamma - 1) a) (1 + m^2)^(3/2 - gamma)
//                 [1 / (2 gamma - 3) + G / (2 gamma m^2)],
//        G = 2F1(1, 3/2; gamma + 1; -1/m^2)
//      by its Gauss continued fraction, a Stieltjes fraction (positive
//      terms) whose argument -1/m^2 = -(gamma - 1)/a^2 carries no rounding
//      hazard. No subtraction at all: relative accuracy even where Lambda
//      is 1e-300. Used for a > 1.5 or m >= 1.
//  (Y) series form, [Ribardiere17] eq. 21 after the Pfaff transformation
//      2F1(1/2, nu; 3/2; -m^2) = x0^(nu - 1/2) 2F1(nu, 1; 3/2; 1 - x0):
//        Lambda = K / (sqrt(gamma - 1) a) (1 + m^2)^(3/2 - gamma)
//                 [(gamma - 1) / (2 gamma - 3) + a^2 x0 S] - 1/2,
//        S = 2F1(gamma - 1/2, 1; 3/2; 1 - x0) (positive series).
//      One subtraction, of 1/2, which costs log10(1/(2 Lambda)) digits at
//      most: <= 2.3 digits in its domain a <= 1.5 and m < 1, where the
//      series needs <= ~50 terms while the fraction would need hundreds to
//      thousands of levels (~700 at a = 0.5 for large gamma).
// (1 + m^2)^(3/2 - gamma) is exp(-(gamma - 3/2) log1p(m^2)) (exp(-a^2) in the
// limit), K / sqrt(gamma - 1) comes from Boost's tgamma_delta_ratio (no
// overflow, no lgamma cancellation) or its asymptotic series for gamma > 1e8.
// About 150 ns per call (any gamma, a log-uniform in [1e-3, 1e2]).
//
// Measured relative error of UnitLambda<double> against 50-digit mpmath
// references (hypergeometric form, cross-checked by quadrature) on 61
// log-spaced a in [1e-3, 1e3] plus 6 others, x gamma in {1.5+1e-6, 1.5001,
// 1.6, 2, 2.5, 3, 3.5, 4, 7.5, 10, 20, 100, 1e3, 1e4, 1e5, 1e6, 1e8}
// (every point with Lambda > 1e-300), and 400 random (gamma, a) with gamma in
// (1.5, 3e4]: max 6e-14 for gamma <= 1e4, 1.5e-13 up to gamma = 1e8.
// For T = float the evaluation is done in double and rounded once, so
// StudentTNdf<float>::UnitLambda is within 1 float ulp of the double value at the
// same (float) inputs. gamma > 1e8 (up to 1e300) is handled as well and
// tends to the Beckmann value smoothly.
//
// gamma is clamped below at kMinStudentTGamma = 1.5 + 1e-6: the mean slope, hence
// Lambda, diverges as 1 / (2 gamma - 3) when gamma -> 1.5. A gamma a user gives
// is checked against the same floor and refused below it (ValidateModelParams
// in model.h), so the clamp only guards internal callers. gamma = +inf
// delegates every hook to the Beckmann formulas (beckmann.h) bit for bit.
//
// Typos found in [Ribardiere17] (each checked numerically):
//  - eq. 20: the second term is (mu / sqrt(c)) 2F1(...), not (mu / 2) 2F1(...)
//    / sqrt(c) (c = (gamma - 1) sigma^2): integral_0^x (1+t^2)^-n dt =
//    x 2F1(1/2, n; 3/2; -x^2). Eq. 21 is correct as printed.
//  - Table 1, gamma = 7/2: the printed Lambda
//      (1/(3pi)) arctan(sqrt(2/5) mu/s) - 1 + 5 sqrt(5/2) (-6mu^4 + 17mu^2s^2
//      + 8s^4) / (6 pi mu s (2mu^2 + 5s^2))
//    is wrong (not even -> 0 as mu -> inf). Corrected (s = sigma):
//      Lambda = (1/pi) arctan(sqrt(2/5) mu/s) - 1/2
//               + sqrt(10) s (6mu^4 + 25mu^2 s^2 + 25 s^4)
//                 / (3 pi mu (2mu^2 + 5s^2)^2).
//    The rows gamma = 2, 5/2, 3, 4 and inf are correct (gamma = 3 simplifies
//    to ((mu^2 + s^2) / (mu sqrt(mu^2 + 2 s^2)) - 1) / 2).
//  - Section 4.1, the line before eq. 27: the integrand is
//    (q^2 / ((gamma-1) sigma^2) + 1)^-(gamma-1/2), and the substitution is
//    t = q / (sigma sqrt(gamma - 1)), not t = mu / (...).
//  - Eq. 32-33: the prefactor has no ((gamma-1) sigma^2 + q^2) factor (q is
//    the integration variable) and misses the 1/mu of eq. 17; the summary
//    eq. 29 with eq. 36-37 is right.
//  - Eq. 11 / 40: arctan(sigma_y/sigma_x tan(2 pi xi)) only covers half the
//    circle (see slope_ndf.h).
//  - Section 7.1: the conditional slope law has a = gamma - 1 + p^2, not
//    1/(gamma - 1) + p^2.
//  - Algorithm 2 line 1: 2F1(...; z = 0) = 1, not inf (it is Lambda that is
//    infinite at mu = 0).
//  - Eq. 43 (weight G / G1(v)) only holds when m is drawn from the STD's own
//    visible normals; with the GGX or Beckmann proposals of Algorithm 1 the
//    unbiased weight is f cos(theta_i) / PdfPseudoVnis, i.e. for reflection
//    F D_std G_std / (D_prop G1_prop(v)).

#ifndef BRDFBAKE_MODELS_STD_NDF_H_
#define BRDFBAKE_MODELS_STD_NDF_H_

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

#include <boost/math/special_functions/gamma.hpp>

#include "brdfbake/models/beckmann.h"
#include "brdfbake/models/ggx.h"
#include "brdfbake/models/slope_ndf.h"
#include "brdfbake/models/vec3.h"

namespace brdfbake {

// Lower clamp of gamma ([Ribardiere17] requires gamma > 1.5 for a finite Lambda),
// and the lower end of the domain users may give (StudentTGammaAllowed).
template <typename T>
inline constexpr T kMinStudentTGamma = T(1.5) + T(1e-6);

// UnitLambda uses the series (Y) for a <= kStudentTSeriesMaxA and m < 1, the
// continued fraction (S) elsewhere (see the header comment).
inline constexpr double kStudentTSeriesMaxA = 1.5;

// Largest gamma for which StudentTHasClosedForm is true (the closed forms are
// finite sums of about gamma terms).
inline constexpr double kStudentTClosedFormMaxGamma = 10000.0;

// From this gamma on the double reference is the Beckmann limit: the
// relative difference of D is about r2^2 / (2 gamma), below 3e-15 for every
// r2 < 745 where exp(-r2) is still a double, and Lambda's is smaller
// (StudentTTest.HugeGammaIsBeckmann checks 1e16 .. the largest double). Without
// the switch, terms such as 2 gamma - 3 overflow at gamma = 2^1023.
inline constexpr double kStudentTBeckmannLimitGamma = 1e20;

// gamma clamped to [kMinStudentTGamma, +inf], +inf from kStudentTBeckmannLimitGamma
// on; NaN stays NaN (as ClampAlpha).
template <typename T>
T ClampStudentTGamma(T gamma) {
  if (gamma >= T(kStudentTBeckmannLimitGamma)) return std::numeric_limits<T>::infinity();
  return std::max(gamma, kMinStudentTGamma<T>);
}

namespace student_t_detail {

// Working precision: float is evaluated in double.
template <typename T>
using Wide = std::conditional_t<(sizeof(T) < sizeof(double)), double, T>;

// kt(gamma) = K / sqrt(gamma - 1) = Gamma(gamma - 1/2) /
// (sqrt(pi) Gamma(gamma - 1) sqrt(gamma - 1)), which tends to 1/sqrt(pi).
// Boost's tgamma_delta_ratio is accurate where Gamma(gamma) would overflow
// and an lgamma difference would cancel; beyond z = gamma - 1 = 1e8 the
// asymptotic series Gamma(z + 1/2) / (Gamma(z) sqrt(z)) = 1 - 1/(8z)
// + 1/(128z^2) + 5/(1024z^3) + O(z^-4) is exact to double precision.
// Each thread keeps the last gamma's value: the Gamma ratio in long double
// costs microseconds, and a bake constructs a model per texel at one gamma.
template <typename W>
W StudentTKt(W gamma) {
  thread_local W last_gamma = std::numeric_limits<W>::quiet_NaN(), last_kt = W(0);
  if (gamma == last_gamma) return last_kt;
  const W z = gamma - W(1);
  W kt;
  if (z > W(1e8)) {
    const W iz = W(1) / z;
    kt = (W(1) - iz * (W(1) / W(8) - iz * (W(1) / W(128) + iz * W(5) / W(1024)))) / kSqrtPi<W>;
  } else {
    kt = W(1) / (kSqrtPi<W> * std::sqrt(z) * boost::math::tgamma_delta_ratio(z, W(0.5)));
  }
  last_gamma = gamma;
  last_kt = kt;
  return kt;
}

// u = m^2 = a^2 / (gamma - 1) and expo = (gamma - 3/2) log(1 + u), so that
// (1 + m^2)^(3/2 - gamma) = exp(-expo), without overflow for huge a nor
// underflow for huge gamma (where expo -> a^2, Beckmann's exponent).
template <typename W>
void StudentTExponent(W gamma, W a, W* u, W* expo) {
  const W m = a / std::sqrt(gamma - W(1));
  if (m > W(1e100)) {
    *u = std::numeric_limits<W>::infinity();
    *expo = (gamma - W(1.5)) * W(2) * std::log(m);
    return;
  }
  *u = a * (a / (gamma - W(1)));
  if (*u < W(1e-4)) {
    const W v = *u;  // log1p(v) / v by its series, error < v^5 / 6
    const W l = W(1) - v * (W(1) / W(2) - v * (W(1) / W(3) - v * (W(1) / W(4) - v / W(5))));
    *expo = a * a * ((gamma - W(1.5)) / (gamma - W(1))) * l;
  } else {
    *expo = (gamma - W(1.5)) * std::log1p(*u);
  }
}

// G = 2F1(1, 3/2; gamma + 1; -1/m^2), v = 1/m^2 = (gamma - 1)/a^2, by the
// Gauss continued fraction of 2F1(a, b+1; c+1; z) / 2F1(a, b; c; z) with
// a = 3/2, b = 0, c = gamma (2F1(a, 0; c; z) = 1):
//   G = 1 / (1 + e1 / (1 + e2 / (1 + ...))),   e_n = k_n v,
//   k_(2j+1) = (3/2 + j)(gamma + j) / ((gamma + 2j)(gamma + 2j + 1)),
//   k_(2j)   = j (gamma - 3/2 + j) / ((gamma + 2j - 1)(gamma + 2j)).
// All e_n > 0 (a Stieltjes fraction): no cancellation. Modified Lentz
// method; levels needed (any gamma up to 1e8): ~106 at a = 1.5, 64 at
// a = 2, 36 at a = 3, 18 at a = 5, 11 at a = 10, fewer for small gamma or
// m >= 1.
template <typename W>
W StudentTHyp2F1G(W gamma, W v) {
  const W tiny = std::numeric_limits<W>::min() / std::numeric_limits<W>::epsilon();
  const W tol = std::numeric_limits<W>::epsilon();
  auto guard = [tiny](W x) { return x < tiny ? tiny : x; };  // all terms > 0
  // h = 1 + e1 / (1 + e2 / (1 + ...)); G = 1 / h.
  W h = W(1), c = W(1), d = W(0);
  for (int n = 1; n < 20000; ++n) {
    W k;
    if (n % 2 == 1) {
      const W j = W((n - 1) / 2);
      // Two factors < ~1 each: no overflow for huge gamma.
      k = ((W(1.5) + j) / (gamma + W(2) * j + W(1))) * ((gamma + j) / (gamma + W(2) * j));
    } else {
      const W j = W(n / 2);
      k = (j / (gamma + W(2) * j - W(1))) * ((gamma - W(1.5) + j) / (gamma + W(2) * j));
    }
    const W e = k * v;
    d = W(1) / guard(W(1) + e * d);
    c = guard(W(1) + e / c);
    const W delta = c * d;
    h *= delta;
    if (std::abs(delta - W(1)) <= tol) break;
  }
  return W(1) / h;
}

// Lambda by the positive continued fraction, form (S) of the header;
// kt = StudentTKt(gamma), a > 0 finite.
//   Lambda = kt / (2a) (1 + m^2)^(3/2 - gamma)
//            * [1 / (2 gamma - 3) + G (gamma - 1) / (2 gamma a^2)].
template <typename W>
W StudentTLambdaFraction(W gamma, W kt, W a) {
  W u, expo;
  StudentTExponent(gamma, a, &u, &expo);
  const W v = (gamma - W(1)) / a / a;  // 1/m^2; 0 when a^2 overflows
  const W g = StudentTHyp2F1G(gamma, v);
  return kt / (W(2) * a) * std::exp(-expo) *
         (W(1) / (W(2) * gamma - W(3)) + g * v / (W(2) * gamma));
}

// Lambda by the series form (Y) of the header (seed eq. 21 after a Pfaff
// transformation); kt = StudentTKt(gamma), a > 0, meant for m^2 < 1:
//   Lambda = kt / a (1 + m^2)^(3/2 - gamma)
//            * [(gamma - 1) / (2 gamma - 3) + a^2 S / (1 + m^2)] - 1/2,
//   S = 2F1(gamma - 1/2, 1; 3/2; y0) = sum_n (gamma - 1/2)_n / (3/2)_n y0^n,
//   y0 = m^2 / (1 + m^2), all terms positive.
template <typename W>
W StudentTLambdaSeries(W gamma, W kt, W a) {
  W u, expo;
  StudentTExponent(gamma, a, &u, &expo);
  const W w = a * a / (W(1) + u);  // (gamma - 1) y0
  const W tol = std::numeric_limits<W>::epsilon() / 2;
  W sum = W(1), term = W(1);
  for (int n = 0; n < 20000; ++n) {
    term *= (gamma - W(0.5) + W(n)) / (gamma - W(1)) * w / (W(n) + W(1.5));
    sum += term;
    if (term <= tol * sum) break;
  }
  const W lambda = kt / a * std::exp(-expo) *
                       ((gamma - W(1)) / (W(2) * gamma - W(3)) + w * sum) -
                   W(0.5);
  return std::max(W(0), lambda);
}

}  // namespace student_t_detail

// True for the gamma values with a finite closed-form Lambda ([Ribardiere17]
// section 4): integers >= 2 and half-integers >= 5/2, up to
// kStudentTClosedFormMaxGamma.
inline bool StudentTHasClosedForm(double gamma) {
  if (!(gamma >= 2.0) || gamma > kStudentTClosedFormMaxGamma) return false;
  const double twice = 2.0 * gamma;
  return twice == std::floor(twice);
}

// Closed-form unit-roughness Lambda(a), a = cot(theta) / sigma, for integer
// and half-integer gamma ([Ribardiere17] section 4, eq. 29 with eq. 30 or 36-37);
// NaN when !StudentTHasClosedForm(gamma). Evaluated in double (for float T too).
//
// Eq. 29: Lambda = (gamma-1) A1 [ sqrt(gamma-1)/a (1+m^2)^(3/2-gamma) / (2gamma-3)
//                                 - A2 ],
// m = a / sqrt(gamma-1), theta0 = arctan(m), s0 = sin(theta0) = m/sqrt(1+m^2),
// c0 = cos(theta0), A1 = Gamma(gamma-1/2) / (sqrt(pi) Gamma(gamma)) and
// A2 = integral_theta0^(pi/2) cos^(2gamma-3)(x) dx.
// The seed expands A2 (and A1 for half-integers) in alternating binomial
// sums, which lose up to ~C(gamma-2, gamma/2-1) to cancellation (useless in
// double beyond gamma ~ 30). The same finite sums are evaluated here in the
// positive form given by the reduction formula for integrals of cos^n
// (r_k = (2k-1)!!/(2k)!! = C(2k, k)/4^k):
//  integer gamma, p = gamma - 2 (cos^(2p+1)):
//    A2 = W_p (1 - s0 sum_{k=0..p} r_k c0^(2k)),  W_p = (2p)!!/(2p+1)!!,
//    and (gamma-1) A1 W_p = 1/2 (Wallis), so
//    Lambda = first - 1/2 + (s0/2) sum_{k=0..p} r_k c0^(2k);
//  half-integer gamma, p = gamma - 3/2 (cos^(2p)):
//    A2 = r_p (pi/2 - theta0 - s0 sum_{k=1..p} c0^(2k-1) / (2k r_k)),
//    and (gamma-1) A1 r_p = 1/pi (eq. 36: A1 = (2/pi) W_p), so
//    Lambda = first - (1/pi) [atan2(1, m) - s0 sum_{k=1..p} c0^(2k-1)/(2k r_k)].
// The only cancellation left is the final subtraction: measured absolute
// error <= 1.3e-15 (1 + Lambda) for gamma <= 100 (1.3e-13 at gamma = 1e4,
// rounding accumulated over the gamma terms), so the relative error grows
// like 1/Lambda for large a (closed forms of this kind cannot do better; use
// UnitLambda there).
template <typename T>
T StudentTLambdaClosedForm(T gamma, T a) {
  using W = double;
  const W g = static_cast<W>(gamma), av = static_cast<W>(a);
  if (!StudentTHasClosedForm(g)) return std::numeric_limits<T>::quiet_NaN();
  if (!(av > W(0))) return std::numeric_limits<T>::infinity();
  if (std::isinf(av)) return T(0);
  const W m = av / std::sqrt(g - W(1));
  W m2, expo;
  student_t_detail::StudentTExponent(g, av, &m2, &expo);
  const W x0 = W(1) / (W(1) + m2);                       // c0^2
  const W c0 = W(1) / std::sqrt(W(1) + m2);
  const W s0 = W(1) / std::sqrt(W(1) + W(1) / m2);       // m / sqrt(1 + m^2)
  const W power = std::exp(-expo);                       // (1 + m^2)^(3/2 - gamma)
  const bool integer = (g == std::floor(g));
  if (integer) {
    const int p = static_cast<int>(g) - 2;
    // (gamma - 1) A1 with A1 = r_(gamma-1) (eq. 30).
    W r = W(1);
    for (int k = 1; k <= p + 1; ++k) r *= W(2 * k - 1) / W(2 * k);
    const W first = (g - W(1)) * r * std::sqrt(g - W(1)) / av * power / (W(2) * g - W(3));
    W sum = W(0), term = W(1);  // term = r_k x0^k
    for (int k = 0; k <= p; ++k) {
      sum += term;
      term *= x0 * W(2 * k + 1) / W(2 * k + 2);
    }
    return static_cast<T>(first - W(0.5) + W(0.5) * s0 * sum);
  }
  const int p = static_cast<int>(g - W(1.5));
  W r = W(1);  // r_p
  for (int k = 1; k <= p; ++k) r *= W(2 * k - 1) / W(2 * k);
  const W first = W(1) / (kPi<W> * r) * std::sqrt(g - W(1)) / av * power / (W(2) * g - W(3));
  W sum = W(0), rk = W(1), cpow = c0;  // rk = r_k, cpow = c0^(2k-1)
  for (int k = 1; k <= p; ++k) {
    rk *= W(2 * k - 1) / W(2 * k);
    sum += cpow / (W(2 * k) * rk);
    cpow *= x0;
  }
  return static_cast<T>(first - kInvPi<W> * (std::atan2(W(1), m) - s0 * sum));
}

template <typename T>
class StudentTNdf : public SlopeNdf<T, StudentTNdf<T>> {
  using Base = SlopeNdf<T, StudentTNdf<T>>;
  using W = student_t_detail::Wide<T>;

 public:
  // alpha_x, alpha_y: [Ribardiere17]'s sigma_x, sigma_y (clamped as every model);
  // gamma: clamped to [kMinStudentTGamma, +inf]; +inf is Beckmann exactly.
  StudentTNdf(T alpha_x, T alpha_y, T gamma)
      : Base(alpha_x, alpha_y),
        gamma_(ClampStudentTGamma(gamma)),
        beckmann_inf_(std::isinf(gamma_)),
        kt_(beckmann_inf_ || std::isnan(gamma_)
                ? W(0)
                : student_t_detail::StudentTKt(static_cast<W>(gamma_))),
        ggx_(this->ax_, this->ay_),
        beckmann_(this->ax_, this->ay_),
        branch_(ComputeBranch()) {}

  T gamma() const { return gamma_; }

  // [Ribardiere17] eq. 13 with sigma = 1: 1 / (pi (1 + r^2/(gamma-1))^gamma),
  // written as exp(-gamma log1p(.)) (no loss for large gamma).
  T UnitP22(T r2) const {
    if (beckmann_inf_) return beckmann_.UnitP22(r2);
    return kInvPi<T> * std::exp(-gamma_ * std::log1p(r2 / (gamma_ - T(1))));
  }

  // D = exp(-gamma log1p(r^2 / (gamma - 1)) - log(ax ay z2^2)) / pi: one
  // exponential of the whole exponent (see BeckmannNdf::DFromStretched).
  T DFromStretched(T s2, T z2) const {
    if (beckmann_inf_) return beckmann_.DFromStretched(s2, z2);
    return kInvPi<T> *
           std::exp(-gamma_ * std::log1p(s2 / z2 / (gamma_ - T(1))) - this->LogAreaScale(z2));
  }

  // Smith Lambda at a = cot(theta), unit roughness ([Ribardiere17] eq. 17 / 21);
  // see the header comment for the method and its measured accuracy.
  T UnitLambda(T a) const {
    if (beckmann_inf_) return beckmann_.UnitLambda(a);
    if (!(a > T(0))) return std::numeric_limits<T>::infinity();
    if (std::isinf(a)) return T(0);
    const W g = static_cast<W>(gamma_), av = static_cast<W>(a);
    if (av <= W(kStudentTSeriesMaxA) && av * av < g - W(1)) {
      return static_cast<T>(student_t_detail::StudentTLambdaSeries(g, kt_, av));
    }
    return static_cast<T>(student_t_detail::StudentTLambdaFraction(g, kt_, av));
  }

  // Inverse of the radial CDF 1 - (1 + r^2/(gamma-1))^(1-gamma) ([Ribardiere17]
  // eq. 42 with sigma = 1): r^2 = (gamma-1) expm1(-log1p(-u) / (gamma-1)),
  // accurate for small u and for large gamma.
  T UnitSampleR2(T u) const {
    if (beckmann_inf_) return beckmann_.UnitSampleR2(u);
    const T uc = std::min(u, T(1) - std::numeric_limits<T>::epsilon() / 2);
    const T e = -std::log1p(-uc);
    return (gamma_ - T(1)) * std::expm1(e / (gamma_ - T(1)));
  }

  // Pseudo visible-normal importance sampling, [Ribardiere17] section 7.2,
  // Algorithm 1. sigma = sqrt(alpha_x alpha_y) (the geometric mean, exact for
  // isotropic alphas) is used in the algorithm's thresholds:
  //   sigma <= 0.01                      -> NDF sampling (branch 0)
  //   gamma > 10                         -> Beckmann VNDF (branch 2)
  //   gamma < min(5, 2 + sigma/0.1)      -> GGX VNDF (branch 1)
  //   gamma > max(5, 10 - 5 max(0, sigma - 0.2)/0.1) -> Beckmann VNDF (2)
  //   otherwise                          -> NDF sampling (0).
  // The GGX and Beckmann proposals use the same alpha_x, alpha_y (GGX is STD
  // at gamma = 2 and Beckmann the gamma -> inf limit for the same sigma).
  int PseudoVnisBranch() const { return branch_; }

  // Draws a microfacet normal m for the view w (w.z > 0) by the branch above.
  Vec3<T> SamplePseudoVnis(const Vec3<T>& w, T u1, T u2) const {
    switch (branch_) {
      case 1:
        return ggx_.SampleVisible(w, u1, u2);
      case 2:
        return beckmann_.SampleVisible(w, u1, u2);
      default:
        return this->SampleNdf(u1, u2);
    }
  }

  // Density per steradian of the m returned by SamplePseudoVnis: the GGX or
  // Beckmann visible-normal density, or D(m) m.z of the STD itself. The
  // Monte Carlo weight of a sample is f cos(theta_i) / pdf with the STD's own
  // D and G (not the G / G1(v) of seed eq. 43, which assumes the STD's own
  // visible normals).
  T PdfPseudoVnis(const Vec3<T>& w, const Vec3<T>& m) const {
    switch (branch_) {
      case 1:
        return ggx_.PdfVisible(w, m);
      case 2:
        return beckmann_.PdfVisible(w, m);
      default:
        return this->PdfNdf(m);
    }
  }

 private:
  int ComputeBranch() const {
    const T sigma = std::sqrt(this->ax_ * this->ay_);
    if (sigma <= T(0.01)) return 0;
    if (gamma_ > T(10)) return 2;
    const T ggx_upper = std::min(T(5), T(2) + sigma / T(0.1));
    const T beckmann_lower =
        std::max(T(5), T(10) - T(5) * std::max(T(0), sigma - T(0.2)) / T(0.1));
    if (gamma_ < ggx_upper) return 1;
    if (gamma_ > beckmann_lower) return 2;
    return 0;
  }

  T gamma_;
  bool beckmann_inf_;
  W kt_;  // Gamma(gamma - 1/2) / (sqrt(pi) Gamma(gamma - 1) sqrt(gamma - 1))
  GgxNdf<T> ggx_;
  BeckmannNdf<T> beckmann_;
  int branch_;  // PseudoVnisBranch()
};

}  // namespace brdfbake

#endif  // BRDFBAKE_MODELS_STD_NDF_H_
