// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// High-precision references kept as an unevaluated sum hi + lo (hi = the
// value rounded to double), so that got - ref is formed without a second
// rounding of the reference (tests of the double-lane kernels).

#ifndef BRDFBAKE_TESTS_REFERENCE_REF_UTIL_H_
#define BRDFBAKE_TESTS_REFERENCE_REF_UTIL_H_

#include <cmath>
#include <limits>

namespace brdfbake {
namespace test {

struct Ref {
  double hi, lo;
};

// `Big` is a Boost.Multiprecision float.
template <class Big>
Ref ToRef(const Big& v) {
  const double hi = static_cast<double>(v);
  if (!std::isfinite(hi)) return {hi, 0.0};
  return {hi, static_cast<double>(v - Big(hi))};
}

// |got - ref| (0 when both are the same infinity).
inline double AbsErr(double got, const Ref& ref) {
  if (std::isinf(ref.hi)) return got == ref.hi ? 0.0 : std::numeric_limits<double>::infinity();
  return std::abs((got - ref.hi) - ref.lo);
}

}  // namespace test
}  // namespace brdfbake

#endif  // BRDFBAKE_TESTS_REFERENCE_REF_UTIL_H_
