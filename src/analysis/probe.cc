// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The lookup-error probe (probe.h), shared by `report` and the scene
// planner.

#include "brdfbake/probe.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <tbb/parallel_for.h>

#include "bake/warp_coordinates.h"
#include "base/error.h"
#include "brdfbake/models/slope_ndf.h"
#include "rules/ggx_aniso/aniso_ggx.h"

namespace brdfbake {
namespace {

bool MajorAxis(const Axis& a) { return a.name == "mu" || a.name == "roughness"; }

// The fractional texel index of value v on axis a (Axis::ValueAt inverted)
// for the linear, square and sqrt warps: where a table is not smooth.
double IndexOf(const Axis& a, double v) {
  double t = a.max > a.min ? std::clamp((v - a.min) / (a.max - a.min), 0.0, 1.0) : 0.5;
  if (a.warp == Warp::kFresnelZ) {
    // z = sqrt(|ior - 1| / (ior + 1)) linear in t (bake.h), 1 at ior = inf.
    const double lo = FresnelZOfIor(a.min), hi = FresnelZOfIor(a.max);
    t = hi > lo ? std::clamp((FresnelZOfIor(v) - lo) / (hi - lo), 0.0, 1.0) : 0.5;
  }
  if (a.warp == Warp::kSquare) t = std::sqrt(t);
  if (a.warp == Warp::kSqrt) t = t * t;
  if (a.warp == Warp::kOneMinusSquare) t = 1 - std::sqrt(1 - t);
  return a.placement == Placement::kCenters ? t * a.size - 0.5 : t * (a.size - 1);
}

std::vector<double> Positions(const Axis& a, ProbePoints points, int probes) {
  const int n = a.size;
  if (n == 1) return {0.0};
  std::vector<double> f;
  if (points == ProbePoints::kNodes) {
    const int k = std::min(n, probes);
    for (int i = 0; i < k; ++i) f.push_back(double(i * n / k));
    return f;
  }
  const int cells = n - 1, k = std::min(cells, probes);
  for (int i = 0; i < k; ++i) f.push_back(i * cells / k + 0.5);
  if (points == ProbePoints::kMidpoints) return f;
  if (a.placement == Placement::kCenters) {
    f.push_back(-0.5);
    f.push_back(n - 0.5);
  }
  if (a.name == "mu") {
    // E's grazing boundary layer: more points in the first two cells and,
    // with centres, below texel 0; then NoV down to 1e-4.
    for (double x : {0.05, 0.1, 0.2, 0.3, 0.7, 0.9}) f.push_back(x);
    if (cells > 1) {
      for (double x : {1.1, 1.25, 1.75, 1.9}) f.push_back(x);
    }
    if (a.placement == Placement::kCenters) {
      for (double x : {-0.45, -0.4, -0.3, -0.2, -0.1}) f.push_back(x);
    }
    if (a.warp != Warp::kTail) {
      for (double mu : {1e-4, 1e-3, 1e-2}) {
        if (mu > a.min && mu < a.max) f.push_back(IndexOf(a, mu));
      }
    }
  }
  return f;
}

// Both sides of the mirror cut along roughness: alpha = kMinAlpha for the
// isotropic models, alpha_t = r^2 + (1 - r^2) s^2 = kMinAlpha for
// ggx-aniso at each anisotropy s probed below sqrt(kMinAlpha).
void AddMirrorCut(const Axis& ar, const std::vector<double>& strengths, std::vector<double>* f) {
  if (ar.size < 2 || ar.warp == Warp::kTail) return;
  const double a_min = kMinAlpha<double>;
  for (double s : strengths) {
    if (!(s * s < a_min)) continue;
    const double cut = std::sqrt((a_min - s * s) / (1 - s * s));
    if (!(cut > ar.min && cut < ar.max)) continue;
    for (double r : {cut * (1 - 1e-9), cut, cut * (1 + 1e-6), cut * 1.01}) f->push_back(IndexOf(ar, r));
  }
}

double ValueAtIndex(const Axis& a, double f) { return a.size > 1 ? a.ValueAt(f) : a.Value(0); }

int AxisIndex(const Table& t, const char* name) {
  for (size_t k = 0; k < t.axes.size(); ++k) {
    if (t.axes[k].name == name) return int(k);
  }
  return -1;
}

}  // namespace

bool ProbeSupports(const BakeSpec& s) {
  // ExactTableValues knows E, E_avg, dfg and the tables of one quantity
  // over the roughness (f82_bias), over gamma, ior or anisotropy slices
  // too; not the tables without a roughness axis (a material's own table,
  // a lobe's norm over its widths), nor gen_schlick's slices.
  return TableHasAxis(s, "roughness") && !s.GenSchlick();
}

std::vector<std::vector<double>> ProbePositions(const Table& t, const ProbeOptions& o) {
  const BakeSpec& s = t.spec;
  if (!ProbeSupports(s)) {
    Bad(std::string("lookup error: no probe for ") + TableName(s.table) + " tables of " + s.model.name());
  }
  if (!o.points.empty() && o.points.size() != t.axes.size()) Bad("lookup error: one probe kind per table axis");
  std::vector<std::vector<double>> pos(t.axes.size());
  for (size_t k = 0; k < t.axes.size(); ++k) {
    const Axis& a = t.axes[k];
    const ProbePoints p = o.points.empty() ? ProbePoints::kBound : o.points[k];
    pos[k] = Positions(a, p, MajorAxis(a) ? o.probes : o.minor_probes);
  }
  const int kr = AxisIndex(t, "roughness");
  const bool bound_r = kr >= 0 && (o.points.empty() || o.points[size_t(kr)] == ProbePoints::kBound);
  if (bound_r) {
    std::vector<double> strengths = {0.0};
    if (s.Anisotropic()) {
      strengths.clear();
      const int ks = AxisIndex(t, "anisotropy");
      if (ks >= 0) {
        for (double f : pos[size_t(ks)]) strengths.push_back(ValueAtIndex(t.axes[size_t(ks)], f));
      }
    }
    AddMirrorCut(t.axes[size_t(kr)], strengths, &pos[size_t(kr)]);
  }
  // Only the lookups within [vmin, vmax] along the axis `name`.
  auto restrict = [&](const char* name, double vmin, double vmax, int probes) {
    const int ka = AxisIndex(t, name);
    if (ka < 0 || t.axes[size_t(ka)].size <= 1 || !(vmin > -kInfinity || vmax < kInfinity)) return;
    const Axis& ar = t.axes[size_t(ka)];
    const int n = ar.size;
    const double lo = IndexOf(ar, std::max(vmin, ar.min)), hi = IndexOf(ar, std::min(vmax, ar.max));
    std::vector<double> within;
    for (double f : pos[size_t(ka)]) {
      if (f >= lo && f <= hi) within.push_back(f);
    }
    // The midpoints of (up to `probes` of) the cells that overlap the range.
    const int c0 = std::clamp(int(std::floor(lo)), 0, n - 2), c1 = std::clamp(int(std::floor(hi)), 0, n - 2);
    const int cells = c1 - c0 + 1, k = std::min(cells, probes);
    for (int i = 0; i < k; ++i) {
      const double f = c0 + i * cells / k + 0.5;
      if (f >= lo && f <= hi) within.push_back(f);
    }
    within.push_back(lo);
    within.push_back(hi);
    pos[size_t(ka)] = within;
  };
  restrict("roughness", o.roughness_min, o.roughness_max, o.probes);
  restrict("ior", o.ior_min, o.ior_max, o.minor_probes);
  return pos;
}

std::vector<double> ExactTableValues(const Table& t, const std::vector<double>& at) {
  const BakeSpec& s = t.spec;
  auto value = [&](const char* name, double fallback) {
    const int k = AxisIndex(t, name);
    return k >= 0 ? at[size_t(k)] : fallback;
  };
  const double r = std::max(value("roughness", s.roughness.min), s.roughness.clamp_min);
  std::vector<double> out;
  if (s.Anisotropic()) {
    const double an = value("anisotropy", s.anisotropy.min);
    double e;
    if (s.table == TableKind::kEavg) {
      e = IntegrateAnisoEavg(s, r, an).value;
    } else {
      const double mu = std::max(value("mu", s.mu.min), s.mu.clamp_min);
      e = IntegrateAnisoTexel(s, r, an, mu, value("phi_o", s.phi.min)).e;
    }
    e = std::clamp(e, 0.0, 1.0);
    out.push_back(s.complement ? 1 - e : e);
    return out;
  }
  BakeSpec one = s;
  if (s.HasGammaAxis()) {
    one.gamma.size = 0;
    one.model.gamma = value("gamma", s.model.gamma);
  }
  if (s.Glass()) {
    // The slice's eta, as Bake sets it: ior, or 1 / ior inside the medium.
    const double ior = std::min(value("ior", s.ior.min), s.ior.clamp_max);
    one.model.ior = s.inverse ? 1 / ior : ior;
  }
  // The stored range: [0, 1], or unbounded above for the lobes that do
  // not conserve energy (charlie, disney-diffuse: StoredEMax), as the bake
  // stores them.
  const double e_max = StoredEMax(s);
  if (s.table == TableKind::kEavg) {
    one.table = TableKind::kE;
    const double v = std::clamp(IntegrateEavg(one, r).value, 0.0, e_max);
    out.push_back(s.complement ? 1 - v : v);
    return out;
  }
  const double mu = std::max(value("mu", s.mu.min), s.mu.clamp_min);
  const TexelEstimate v = ClampToRange(IntegrateTexel(one, r, mu), e_max);
  if (s.table != TableKind::kDfg) {
    // E, or a table of one quantity of its own (f82_bias), in v.e.
    out.push_back(s.complement ? 1 - v.e : v.e);
  } else {
    out.push_back(v.scale);
    out.push_back(v.bias);
    if (s.complement) out.push_back(1 - v.e);
  }
  return out;
}

ProbeResult LookupError(const Table& t, const ProbeOptions& o) {
  const std::vector<std::vector<double>> pos = ProbePositions(t, o);
  const size_t naxes = pos.size();
  int64_t points = 1;
  for (const auto& p : pos) points *= int64_t(p.size());
  const int kmu = AxisIndex(t, "mu");
  // The value channels, in order (the error channel, if any, is last).
  size_t nvalue = 0;
  for (const Channel& c : t.channels) nvalue += c.meaning == Meaning::kError ? 0 : 1;
  std::vector<double> diff(size_t(points) * nvalue, 0.0);
  tbb::parallel_for(int64_t(0), points, [&](int64_t k) {
    // Point k: the first axis fastest.
    std::vector<double> f(naxes), at(naxes);
    int64_t rest = k;
    for (size_t a = 0; a < naxes; ++a) {
      f[a] = pos[a][size_t(rest % int64_t(pos[a].size()))];
      rest /= int64_t(pos[a].size());
      at[a] = ValueAtIndex(t.axes[a], f[a]);
    }
    const std::vector<double> exact = ExactTableValues(t, at);
    // Linear weights along each axis, clamped to the ends (clamp-to-edge).
    std::vector<int64_t> i0(naxes), i1(naxes), stride(naxes);
    std::vector<double> w(naxes);
    int64_t st = 1;
    for (size_t a = 0; a < naxes; ++a) {
      const int n = t.axes[a].size;
      const double c = std::clamp(f[a], 0.0, double(n - 1));
      i0[a] = std::min(int64_t(std::floor(c)), int64_t(std::max(0, n - 2)));
      i1[a] = std::min(i0[a] + 1, int64_t(n - 1));
      w[a] = c - double(i0[a]);
      stride[a] = st;
      st *= n;
    }
    for (size_t c = 0; c < nvalue && c < exact.size(); ++c) {
      const Channel& ch = t.channels[c];
      double interp = 0;
      for (int64_t corner = 0; corner < (int64_t(1) << naxes); ++corner) {
        double weight = 1;
        int64_t index = 0;
        for (size_t a = 0; a < naxes; ++a) {
          const bool hi = (corner >> a) & 1;
          weight *= hi ? w[a] : 1 - w[a];
          index += (hi ? i1[a] : i0[a]) * stride[a];
        }
        if (weight == 0) continue;
        interp += weight * (o.stored ? double(ch.stored[size_t(index)]) : ch.values[size_t(index)]);
      }
      diff[size_t(k) * nvalue + c] = std::abs(interp - exact[c]);
    }
  });
  ProbeResult r;
  double sum2 = 0;
  int64_t worst = -1;
  // The stride of the mu positions in the point index, for "inner".
  int64_t mu_stride = 1;
  for (int a = 0; a < kmu; ++a) mu_stride *= int64_t(pos[size_t(a)].size());
  for (int64_t k = 0; k < points; ++k) {
    const bool inner = kmu < 0 || t.axes[size_t(kmu)].size == 1 ||
                       pos[size_t(kmu)][size_t((k / mu_stride) % int64_t(pos[size_t(kmu)].size()))] >= 1;
    for (size_t c = 0; c < nvalue; ++c) {
      const double d = diff[size_t(k) * nvalue + c];
      if (d > r.max_abs_error) {
        r.max_abs_error = d;
        worst = k;
      }
      if (inner) r.max_abs_error_inner = std::max(r.max_abs_error_inner, d);
      sum2 += d * d;
    }
  }
  r.probes = points * int64_t(nvalue);
  r.rms_error = r.probes ? std::sqrt(sum2 / double(r.probes)) : 0;
  if (worst >= 0) {
    int64_t rest = worst;
    for (size_t a = 0; a < naxes; ++a) {
      r.worst_at.push_back(ValueAtIndex(t.axes[a], pos[a][size_t(rest % int64_t(pos[a].size()))]));
      rest /= int64_t(pos[a].size());
    }
  }
  return r;
}

}  // namespace brdfbake
