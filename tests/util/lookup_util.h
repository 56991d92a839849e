// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// A CPU model of a GPU's table lookup: texture(lut, uv) with bilinear
// filtering and clamp-to-edge addressing, and the texture coordinate of a
// physical value along a table axis, from the axis description alone
// (docs/format.md).

#ifndef BRDFBAKE_TESTS_UTIL_LOOKUP_UTIL_H_
#define BRDFBAKE_TESTS_UTIL_LOOKUP_UTIL_H_

#include <algorithm>
#include <cmath>

#include "brdfbake/bake.h"

namespace brdfbake {
namespace test {

// `at(x, y)` gives texel (x, y) of a width x height texture.
template <class At>
double TextureBilinear(const At& at, int width, int height, double u, double v) {
  auto fetch = [&](int x, int y) { return at(std::clamp(x, 0, width - 1), std::clamp(y, 0, height - 1)); };
  const double x = u * width - 0.5, y = v * height - 0.5;
  const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
  const double fx = x - x0, fy = y - y0;
  return (1 - fy) * ((1 - fx) * fetch(x0, y0) + fx * fetch(x0 + 1, y0)) +
         fy * ((1 - fx) * fetch(x0, y0 + 1) + fx * fetch(x0 + 1, y0 + 1));
}

// The texture coordinate (in [0, 1]) at which axis `a` holds the value p.
// The tail warp (gamma) is log-linear in u = (gamma - 1.5) / (gamma - 0.5);
// the fresnel-z warp (ior) linear in z = sqrt(|ior - 1| / (ior + 1)), the
// schlick-z warp (exponent) in z = 5 / (exponent + 5).
inline double TextureCoordinate(const Axis& a, double p) {
  if (a.size == 1) return 0.5;
  double t;
  if (a.warp == Warp::kFresnelZ) {
    auto z = [](double ior) { return std::isinf(ior) ? 1.0 : std::sqrt(std::abs(ior - 1) / (ior + 1)); };
    t = std::clamp((z(p) - z(a.min)) / (z(a.max) - z(a.min)), 0.0, 1.0);
  } else if (a.warp == Warp::kSchlickZ) {
    auto z = [](double e) { return std::isinf(e) ? 0.0 : 5 / (e + 5); };
    t = std::clamp((z(p) - z(a.min)) / (z(a.max) - z(a.min)), 0.0, 1.0);
  } else if (a.warp == Warp::kTail) {
    auto log_u = [](double g) { return std::isinf(g) ? 0.0 : std::log((g - 1.5) / (g - 0.5)); };
    t = std::clamp((log_u(p) - log_u(a.min)) / (log_u(a.max) - log_u(a.min)), 0.0, 1.0);
  } else {
    t = a.max > a.min ? std::clamp((p - a.min) / (a.max - a.min), 0.0, 1.0) : 0.5;
  }
  if (a.warp == Warp::kSquare) t = std::sqrt(t);
  if (a.warp == Warp::kSqrt) t = t * t;
  if (a.warp == Warp::kOneMinusSquare) t = 1 - std::sqrt(1 - t);
  return a.placement == Placement::kCenters ? t : (t * (a.size - 1) + 0.5) / a.size;
}

}  // namespace test
}  // namespace brdfbake

#endif  // BRDFBAKE_TESTS_UTIL_LOOKUP_UTIL_H_
