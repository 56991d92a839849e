// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Rounding to a pixel type, the one step every writer (the tables' EXR,
// headers, ES modules, KTX2, DDS) stores its values through, so that one
// bake holds the same numbers in every container.

#ifndef BRDFBAKE_SRC_BASE_PIXEL_H_
#define BRDFBAKE_SRC_BASE_PIXEL_H_

#include <Imath/half.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "brdfbake/pixel_type.h"

namespace brdfbake {

// The 16-bit code of v: IEEE half bits, or round(v 65535) for unorm16,
// round(v 255) for unorm8 (v clamped to [0, 1]). Float pixels have no code
// (0).
inline uint16_t PixelCode(double v, PixelType p) {
  if (p == PixelType::kHalf) return Imath::half(float(v)).bits();
  if (p == PixelType::kUnorm16) return uint16_t(std::lround(std::clamp(v, 0.0, 1.0) * 65535.0));
  if (p == PixelType::kUnorm8) return uint16_t(std::lround(std::clamp(v, 0.0, 1.0) * 255.0));
  return 0;
}

// The value a code stands for.
inline double PixelCodeValue(uint16_t code, PixelType p) {
  if (p == PixelType::kUnorm16) return code / 65535.0;
  if (p == PixelType::kUnorm8) return code / 255.0;
  Imath::half h;
  h.setBits(code);
  return double(float(h));
}

// The pixel type's value nearest to v. The float is held in a volatile:
// GCC 12 at -O3 dropped the plain round trip double(float(v)) once this was
// inlined into the bake's rounding loop, leaving double values where float
// ones were claimed (RangeTest.StoredValuesStayInTheUnitInterval).
inline double RoundToPixel(double v, PixelType p) {
  if (p == PixelType::kFloat) {
    const volatile float f = float(v);
    return double(f);
  }
  return PixelCodeValue(PixelCode(v, p), p);
}

// The pixel type's next value towards zero from a stored, non-negative value.
inline double PixelTowardsZero(double stored, PixelType p) {
  if (stored <= 0) return 0;
  if (p == PixelType::kFloat) {
    // The float below: one less in the bits of a positive float.
    const float f = float(stored);
    uint32_t bits;
    std::memcpy(&bits, &f, sizeof(bits));
    --bits;
    float below;
    std::memcpy(&below, &bits, sizeof(below));
    return double(below);
  }
  return PixelCodeValue(static_cast<uint16_t>(PixelCode(stored, p) - 1), p);
}

// Rounds dfg's (scale, bias) so that the stored pair keeps scale + bias <= 1
// (the split-sum's F0 = F90 = 1 reflects no more than it receives): the
// larger is moved down a step at a time. The move is at most a few steps of
// the pixel type, within the rounding the claimed error adds.
inline void RoundScaleBias(double scale, double bias, PixelType p, double* stored_scale,
                           double* stored_bias) {
  double s = RoundToPixel(scale, p), b = RoundToPixel(bias, p);
  while (s + b > 1.0) {
    if (s >= b) {
      s = PixelTowardsZero(s, p);
    } else {
      b = PixelTowardsZero(b, p);
    }
  }
  *stored_scale = s;
  *stored_bias = b;
}

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_BASE_PIXEL_H_
