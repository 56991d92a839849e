// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// The error of a GPU's lookup of a baked table: linear interpolation along
// every axis between the stored texels (bilinear within a 2D slice, the
// slices beyond the second axis blended by hand, as the shader lookups of
// shaders.h do), clamp-to-edge at the ends, against the exact values at
// probe points. `report` measures how this error falls with table size;
// the scene planner states it, as a bound, for every planned table.

#ifndef BRDFBAKE_PROBE_H_
#define BRDFBAKE_PROBE_H_

#include <cstdint>
#include <vector>

#include "brdfbake/bake.h"

namespace brdfbake {

// Where along one axis a probe looks, in fractional texel index.
//   kNodes: on texels (no interpolation along this axis), up to `probes`.
//   kMidpoints: the midpoint of up to `probes` cells, spread over the axis.
//   kBound: the midpoints and every place where the table is not smooth
//     or a lookup leaves the texels: with texel centres, both ends of the
//     axis (a GPU's clamp-to-edge holds the last texel there); along mu,
//     the grazing boundary layer (E -> 1 as mu -> 0, narrower than a cell)
//     down to NoV = 1e-4, the smallest engines clamp to; along roughness,
//     both sides of the mirror cut (alpha = 1e-4, where E jumps to 1).
enum class ProbePoints { kNodes, kMidpoints, kBound };

struct ProbeOptions {
  // Per axis of the table (Table::axes order); empty: kBound on every axis.
  std::vector<ProbePoints> points;
  int probes = 12;       // cells (or nodes) probed per axis at most
  int minor_probes = 12;  // the same for the axes other than mu and roughness (phi_o, anisotropy, gamma)
  bool stored = true;    // the stored values (rounded to the pixel type), or the baked doubles
  // Only lookups at roughness in [roughness_min, roughness_max] (the
  // materials' range within a wider engine axis): the cells that overlap
  // it, and its ends.
  double roughness_min = -kInfinity, roughness_max = kInfinity;
  // The same along the ior axis (ggx-glass).
  double ior_min = -kInfinity, ior_max = kInfinity;
};

struct ProbeResult {
  double max_abs_error = 0, rms_error = 0;
  double max_abs_error_inner = 0;  // without the probes in the first mu cell
  int64_t probes = 0;              // probe points times value channels
  std::vector<double> worst_at;    // the axes' values (Table::axes order) at the largest error
};

// Whether LookupError can probe tables of `spec` (it knows their exact
// values): E, E_avg, dfg and tables of one quantity over (mu,) roughness,
// over gamma or ior slices too, and ggx-aniso E and E_avg; not sel_norm,
// the ellipsoid or gen_schlick.
bool ProbeSupports(const BakeSpec& spec);

// The probe positions `options` gives along each of the table's axes.
std::vector<std::vector<double>> ProbePositions(const Table& table, const ProbeOptions& options = {});

// Interpolated against exact at every point of the product of the
// positions, over every value channel (all but "error"). The exact values are the table's own integrator at each point,
// moved into the stored range as the bake stores them; they are computed in
// parallel and reduced serially, so the result does not depend on the
// thread count. Throws std::invalid_argument for the tables ProbeSupports
// refuses.
ProbeResult LookupError(const Table& table, const ProbeOptions& options = {});

// The exact values of the table's channels (as LookupError compares them)
// at one point, the axes' values in Table::axes order.
std::vector<double> ExactTableValues(const Table& table, const std::vector<double>& at);

}  // namespace brdfbake

#endif  // BRDFBAKE_PROBE_H_
