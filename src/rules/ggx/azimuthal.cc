// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0

#include "rules/ggx/azimuthal.h"

#include <cmath>


namespace brdfbake {

const AzimuthLadder& AzimuthLadder::Get(double ratio) {
  auto make = [](double ratio, int levels) {
    const KronrodRule& k = Kronrod15();
    AzimuthLadder r;
    r.levels = levels;
    r.ring.resize(levels + 1);
    r.core.resize(levels + 1);
    r.d.resize(levels + 1);
    r.d[0] = kPi<double> / 2;
    for (int j = 1; j <= levels; ++j) r.d[j] = r.d[j - 1] / ratio;
    auto fill = [&](double a, double b, Piece* p) {
      const double mid = 0.5 * (a + b);
      p->half_width = 0.5 * (b - a);
      for (int i = 0; i < 15; ++i) {
        const double s = std::sin(0.5 * (mid + p->half_width * k.x[i]));
        p->s2[i] = s * s;
      }
      p->s2[15] = 0.5;
      const double sa = std::sin(0.5 * a);
      p->s2_start = sa * sa;
    };
    fill(kPi<double> / 2, kPi<double>, &r.outer);
    fill(0, kPi<double> / 2, &r.core[0]);
    for (int j = 1; j <= levels; ++j) {
      const double dj = kPi<double> / 2 * std::pow(double(ratio), -j);
      const double dj1 = kPi<double> / 2 * std::pow(double(ratio), 1 - j);
      fill(dj, dj1, &r.ring[j]);
      fill(0, dj, &r.core[j]);
    }
    for (int i = 0; i < 15; ++i) {
      r.wk[i] = k.wk[i];
      r.wg[i] = k.wg[i];
    }
    r.wk[15] = r.wg[15] = 0;
    return r;
  };
  static const AzimuthLadder three = make(3, 40), two_and_half = make(2.5, 48),
                             two = make(2, 62);
  return ratio == 2 ? two : ratio == 2.5 ? two_and_half : three;
}

std::vector<double> AzimuthalMesh(double theta_o, double lambda_o, double alpha,
                                  double horizon_widen, double normal_scale) {
  constexpr double kHalfPi = 1.5707963267948966;
  // Breakpoints: the peak, graded from 2 alpha outwards (ratio 3), and the horizon,
  // graded from the nearer of its singularities (see the header).
  std::vector<double> pts = {0.0, theta_o, kHalfPi};
  for (double h = 2 * alpha; h < kHalfPi; h *= 3) {
    if (theta_o - h > 0) pts.push_back(theta_o - h);
    if (theta_o + h < kHalfPi) pts.push_back(theta_o + h);
  }
  for (double e = horizon_widen * (alpha / (2 * (1 + lambda_o))); e < kHalfPi; e *= 3) {
    pts.push_back(kHalfPi - e);
  }
  std::sort(pts.begin(), pts.end());
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  if (normal_scale < kHalfPi) {
    // G2's pole at -normal_scale: no piece [a, b] wider than b = 3 a + 2 s.
    std::vector<double> graded = {pts[0]};
    for (size_t i = 1; i < pts.size(); ++i) {
      while (pts[i] > 3 * graded.back() + 2 * normal_scale) {
        graded.push_back(3 * graded.back() + 2 * normal_scale);
      }
      graded.push_back(pts[i]);
    }
    pts.swap(graded);
  }
  return pts;
}

RuleResult GgxAzimuthalAlbedo(double alpha, double mu, Masking masking, double tol,
                                   int max_pieces) {
  return GgxAzimuthalAlbedoWith(alpha, mu, masking, tol, max_pieces,
                                [](const GgxAzimuthalE& f, const double* theta, double* out) {
                                  for (int i = 0; i < 15; ++i) out[i] = f(theta[i]);
                                });
}

}  // namespace brdfbake

