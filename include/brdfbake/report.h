// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// `brdfbake report`: error against run time for every integrator over a
// ladder of budgets, measured against a converged reference the report
// computes itself, and the interpolation error of bilinear lookup over a
// ladder of table sizes.

#ifndef BRDFBAKE_REPORT_H_
#define BRDFBAKE_REPORT_H_

#include <functional>
#include <string>
#include <vector>

#include "brdfbake/bake.h"

namespace brdfbake {

struct ReportSpec {
  BakeSpec table;          // table kind, model, masking, size, placement, warp
  int repeats = 3;         // timing: median of this many bakes
  double reference_tolerance = 1e-11;
  std::vector<int> interpolation_sizes = {4, 8, 16, 32, 64};
  int interpolation_probes = 16;  // per axis, cell midpoints checked (at most)
};

struct ReportRow {
  std::string integrator;
  std::string budget_name;  // "tolerance", "samples"
  double budget = 0;
  double seconds_median = 0, seconds_min = 0;
  double max_abs_error = 0, rms_error = 0;
  double claimed_max_error = 0;  // the integrator's own estimate
};

struct InterpolationRow {
  int size = 0;  // entries per axis
  double max_abs_error = 0, rms_error = 0;
  double max_abs_error_inner = 0;  // without the cells touching mu = mu_min
  int probes = 0;
  double bake_seconds = 0;
};

// ggx-aniso: what collapsing an anisotropic material to one isotropic GGX
// width costs, for one anisotropy strength and one collapse: the largest
// and RMS difference of the isotropic E (the exact value, not a table
// lookup) at the collapsed width from the true anisotropic E, over the
// spec's mu, phi_o and roughness axes.
struct CollapseRow {
  double anisotropy = 0;
  std::string collapse;  // geometric-mean, arithmetic-mean, view-projected
  double max_abs_error = 0, rms_error = 0;
  double worst_roughness = 0, worst_mu = 0, worst_phi = 0;  // where the max is
};

struct Report {
  ReportSpec spec;
  double reference_seconds = 0;
  double reference_claimed_error = 0;
  std::vector<ReportRow> rows;
  std::vector<InterpolationRow> interpolation;
  std::vector<CollapseRow> collapse;  // ggx-aniso only (instead of the above)
};

using ReportLog = std::function<void(const std::string&)>;

Report RunReport(const ReportSpec& spec, const ReportLog& log = nullptr);
// The checks RunReport makes first (throws std::invalid_argument, one
// line), for a caller to make before it creates any output.
void ValidateReportSpec(const ReportSpec& spec);

// The isotropic GGX width a collapse gives for alpha_t, alpha_b and the
// view's azimuth phi_o from the tangent: "geometric-mean" sqrt(alpha_t
// alpha_b) (Cycles, MaterialX, Enterprise PBR), "arithmetic-mean", or
// "view-projected" sqrt(alpha_t^2 cos^2 phi_o + alpha_b^2 sin^2 phi_o).
double CollapsedAlpha(const std::string& collapse, double alpha_t, double alpha_b, double phi_o);

// The collapse study (report --model ggx-aniso): for each entry of the
// spec's anisotropy axis and each collapse, the largest and RMS difference
// of the isotropic value at the collapsed width (exact, no table lookup)
// from the anisotropic one, over the spec's mu, phi_o and roughness axes
// (E), or over roughness (E_avg, whose collapses take no view).
std::vector<CollapseRow> CollapseStudy(const BakeSpec& spec, const std::vector<std::string>& collapses,
                                       const ReportLog& say = nullptr);

// Writes DIR/report.csv, DIR/report.svg, DIR/interpolation.csv and
// DIR/interpolation.svg (each through a temporary file and a rename); for
// ggx-aniso, DIR/collapse.csv and DIR/collapse.svg.
void WriteReport(const Report& report, const std::string& dir);

// The SVG plots alone (exposed for tests).
struct Series {
  std::string name;
  std::vector<double> x, y;
};
std::string LogLogSvg(const std::string& title, const std::string& x_label,
                      const std::string& y_label, const std::vector<Series>& series,
                      const std::string& footnote);

}  // namespace brdfbake

#endif  // BRDFBAKE_REPORT_H_
