// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// Quadrature rules and low-discrepancy points for the integrators.

#ifndef BRDFBAKE_SRC_QUADRATURE_GAUSS_LEGENDRE_H_
#define BRDFBAKE_SRC_QUADRATURE_GAUSS_LEGENDRE_H_

#include <cmath>
#include <cstdint>
#include <vector>

namespace brdfbake {

// n-point Gauss-Legendre rule on [0, 1], nodes ascending. Nodes are the
// roots of P_n found by Newton's method from Chebyshev-like initial guesses;
// accurate to a few ulps for n up to several thousand.
struct GaussLegendre {
  std::vector<double> x, w;
  explicit GaussLegendre(int n) : x(n), w(n) {
    for (int i = 0; i < (n + 1) / 2; ++i) {
      double z = std::cos(3.14159265358979323846 * (i + 0.75) / (n + 0.5));
      double dp = 1;
      for (int it = 0; it < 100; ++it) {
        double p0 = 1, p1 = z;
        for (int k = 2; k <= n; ++k) {
          const double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
          p0 = p1;
          p1 = p2;
        }
        if (n == 1) p0 = 1, p1 = z;
        dp = n * (z * p1 - p0) / (z * z - 1);
        const double dz = p1 / dp;
        z -= dz;
        if (std::abs(dz) < 1e-16) break;
      }
      // Recompute the derivative at the converged root.
      double p0 = 1, p1 = z;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (z * p1 - p0) / (z * z - 1);
      const double weight = 1.0 / ((1 - z * z) * dp * dp);  // on [-1, 1]: 2 / (...)
      x[i] = 0.5 * (1 - z);
      x[n - 1 - i] = 0.5 * (1 + z);
      w[i] = w[n - 1 - i] = weight;
    }
  }
};

// Van der Corput radical inverse in base 2.
inline double RadicalInverse2(uint32_t i) {
  uint32_t b = i;
  b = (b << 16) | (b >> 16);
  b = ((b & 0x00ff00ffu) << 8) | ((b & 0xff00ff00u) >> 8);
  b = ((b & 0x0f0f0f0fu) << 4) | ((b & 0xf0f0f0f0u) >> 4);
  b = ((b & 0x33333333u) << 2) | ((b & 0xccccccccu) >> 2);
  b = ((b & 0x55555555u) << 1) | ((b & 0xaaaaaaaau) >> 1);
  return b * 2.3283064365386963e-10;  // 2^-32
}

// SplitMix64: a bijective 64-bit mixer, used to derive independent
// per-texel streams from (seed, texel) so results do not depend on the
// order texels are computed in.
inline uint64_t Mix64(uint64_t z) {
  z += 0x9e3779b97f4a7c15ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

// A small counter-based generator of uniforms in [0, 1).
class Rng {
 public:
  explicit Rng(uint64_t seed) : state_(Mix64(seed)) {}
  double Uniform() {
    state_ = Mix64(state_);
    return (state_ >> 11) * 1.1102230246251565e-16;  // 2^-53
  }

 private:
  uint64_t state_;
};

}  // namespace brdfbake

#endif  // BRDFBAKE_SRC_QUADRATURE_GAUSS_LEGENDRE_H_
