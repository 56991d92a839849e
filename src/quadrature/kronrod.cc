// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0

#include "quadrature/kronrod.h"

#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>

namespace brdfbake {

const KronrodRule& Kronrod15() {
  static const KronrodRule rule = [] {
    // Boost stores the non-negative half: Kronrod nodes 0, x1, ..., x7 with
    // the Gauss nodes at the even indices (0, x2, x4, x6).
    const auto& kx = boost::math::quadrature::gauss_kronrod<double, 15>::abscissa();
    const auto& kw = boost::math::quadrature::gauss_kronrod<double, 15>::weights();
    const auto& gw = boost::math::quadrature::gauss<double, 7>::weights();
    KronrodRule r{};
    int j = 0;
    for (int i = 7; i >= 1; --i, ++j) {  // negative nodes, ascending
      r.x[j] = -kx[i];
      r.wk[j] = kw[i];
      r.wg[j] = i % 2 == 0 ? gw[i / 2] : 0.0;
    }
    r.x[7] = 0;
    r.wk[7] = kw[0];
    r.wg[7] = gw[0];
    for (int i = 1; i <= 7; ++i) {
      r.x[7 + i] = kx[i];
      r.wk[7 + i] = kw[i];
      r.wg[7 + i] = i % 2 == 0 ? gw[i / 2] : 0.0;
    }
    return r;
  }();
  return rule;
}

}  // namespace brdfbake
