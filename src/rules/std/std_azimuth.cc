// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0

#include "rules/std/std_azimuth.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <boost/math/quadrature/gauss.hpp>
#include <cstring>
#include <map>
#include <memory>
#include <mutex>

namespace brdfbake {

void StdAzimuthMoments::Direct(double gamma, double y, double* n) {
  constexpr double kHalfPi = 1.5707963267948966;
  if (!(y > 0)) {
    n[0] = 2 * kHalfPi;
    n[1] = kHalfPi;
    n[2] = 0.75 * kHalfPi;
    return;
  }
  const double z = gamma * y;
  // Breakpoints in th: the peak's width graded by 4 up to pi/2, and where
  // gamma log1p(y sin^2 th) = L for L = 1/2, 1, ..., 64 (the decay of a
  // large gamma's Gaussian-like peak).
  std::vector<double> pts = {0.0, kHalfPi};
  for (double l = 0.5; l <= 64; l *= 2) {
    const double s2 = std::expm1(l / gamma) / y;
    if (!(s2 < 1)) break;
    pts.push_back(std::asin(std::sqrt(s2)));
  }
  for (double th = 1 / std::sqrt(z); th < kHalfPi; th *= 4) pts.push_back(th);
  std::sort(pts.begin(), pts.end());
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  // Gauss-Legendre 20 (Boost stores the non-negative half).
  const auto& x = boost::math::quadrature::gauss<double, 20>::abscissa();
  const auto& wt = boost::math::quadrature::gauss<double, 20>::weights();
  double s[3] = {0, 0, 0};
  for (size_t i = 0; i + 1 < pts.size(); ++i) {
    // From where the integrand's factor (1 + y sin^2)^-gamma is below e^-745
    // (0 in double; it decreases, and sin^2k <= 1) nothing is left.
    const double s0 = std::sin(pts[i]);
    if (gamma * std::log1p(y * s0 * s0) > 745) break;
    const double c = 0.5 * (pts[i] + pts[i + 1]), h = 0.5 * (pts[i + 1] - pts[i]);
    double p[3] = {0, 0, 0};
    for (size_t j = 0; j < x.size(); ++j) {
      for (int sign = -1; sign <= 1; sign += 2) {
        if (x[j] == 0 && sign > 0) continue;
        const double sn = std::sin(c + sign * h * x[j]), s2 = sn * sn;
        const double f = wt[j] * std::exp(-gamma * std::log1p(y * s2));
        p[0] += f;
        p[1] += f * s2;
        p[2] += f * s2 * s2;
      }
    }
    for (int k = 0; k < 3; ++k) s[k] += 2 * h * p[k];
  }
  for (int k = 0; k < 3; ++k) n[k] = s[k];
}

StdAzimuthMoments::StdAzimuthMoments(double gamma)
    : gamma_(gamma),
      horizon_widen_(HorizonWiden(
          [ndf = StudentTNdf<double>(1.0, 1.0, gamma)](double a) { return ndf.UnitLambda(a); })),
      degree_(gamma <= 5 ? 20 : 30) {
  const int nodes = degree_ + 1;
  coef_.assign(size_t(kPieces) * nodes * 3, 0.0);
  for (int k = 0; k < 3; ++k) p_[k] = std::min(k + 0.5, gamma);
  std::vector<double> cosines(size_t(nodes) * nodes);  // [m][i]: cos(m pi (i + 1/2) / nodes)
  for (int m = 0; m < nodes; ++m) {
    for (int i = 0; i < nodes; ++i) cosines[m * nodes + i] = std::cos(m * kPi<double> * (i + 0.5) / nodes);
  }
  // The pieces in parallel (each independent of the others: the same
  // table at any thread count), isolated: a thread waiting here must not
  // pick up an outer task that would ask StdAzimuthMomentsFor for this
  // table under the lock it holds.
  tbb::this_task_arena::isolate([&] {
    tbb::parallel_for(0, kPieces, [&](int piece) {
      std::vector<double> g(size_t(3) * nodes);  // [k][i]
      for (int i = 0; i < nodes; ++i) {
        const double t = (piece + 0.5 * (cosines[nodes + i] + 1)) * kWidth;
        double n[3];
        Direct(gamma, std::expm1(t) / gamma, n);
        for (int k = 0; k < 3; ++k) g[k * nodes + i] = n[k] * std::exp(p_[k] * t);
      }
      for (int k = 0; k < 3; ++k) {
        for (int m = 0; m < nodes; ++m) {
          double sum = 0;
          for (int i = 0; i < nodes; ++i) sum += g[k * nodes + i] * cosines[m * nodes + i];
          coef_[(size_t(piece) * nodes + m) * 3 + k] = (m == 0 ? 1.0 : 2.0) * sum / nodes;
        }
      }
    });
  });
}

namespace {
std::mutex& CacheMutex() {
  static std::mutex m;
  return m;
}
std::map<double, std::unique_ptr<StdAzimuthMoments>>& Cache() {
  static std::map<double, std::unique_ptr<StdAzimuthMoments>> c;
  return c;
}
}  // namespace

const StdAzimuthMoments& StdAzimuthMomentsFor(double gamma) {
  std::lock_guard<std::mutex> lock(CacheMutex());
  auto& cache = Cache();
  auto it = cache.find(gamma);
  if (it == cache.end()) {
    it = cache.emplace(gamma, std::make_unique<StdAzimuthMoments>(gamma)).first;
  }
  return *it->second;
}

void ClearStdAzimuthMoments() {
  std::lock_guard<std::mutex> lock(CacheMutex());
  Cache().clear();
}

}  // namespace brdfbake
