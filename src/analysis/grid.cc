// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0

#include "brdfbake/grid.h"

#include <cmath>
#include <memory>
#include <stdexcept>

#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <nlohmann/json.hpp>

#include "base/error.h"
#include "brdfbake/bake.h"
#include "brdfbake/batch.h"
#include "brdfbake/targets.h"
#include "brdfbake/version.h"

namespace brdfbake {

GridKind ParseGridKind(const std::string& s) {
  if (s == "slice") return GridKind::kSlice;
  if (s == "hemisphere") return GridKind::kHemisphere;
  if (s == "g1") return GridKind::kG1;
  Bad("{grid}: unknown grid '" + s + "' (expected slice, hemisphere or g1)");
}

const char* GridKindName(GridKind k) {
  switch (k) {
    case GridKind::kSlice: return "slice";
    case GridKind::kHemisphere: return "hemisphere";
    case GridKind::kG1: return "g1";
  }
  return "slice";
}

const char* GridChannelName(GridKind k) {
  switch (k) {
    case GridKind::kSlice: return "f";
    case GridKind::kHemisphere: return "f_cos";
    case GridKind::kG1: return "G1";
  }
  return "f";
}

std::vector<std::pair<std::string, std::string>> GridAttributes(const GridRequest& req,
                                                                const Grid& grid) {
  auto axis = [](const char* name, int size, double min, double max) {
    return nlohmann::json{{"name", name}, {"size", size}, {"min", min}, {"max", max},
                          {"warp", "linear"}, {"placement", "centers"}};
  };
  nlohmann::json axes = nlohmann::json::array();
  nlohmann::json model = nlohmann::json::parse(req.model.ToJson());
  std::string value;
  switch (req.kind) {
    case GridKind::kSlice:
      axes.push_back(axis("theta_h_deg", req.width, 0, 90));
      axes.push_back(axis("theta_d_deg", req.height, 0, 90));
      value = "f(wi, wo) at the Rusinkiewicz half/difference angles, phi_h = 0, phi_d = 90 deg; "
              "a coloured Fresnel contributes its first (red) channel";
      break;
    case GridKind::kHemisphere:
      axes.push_back(axis("u", req.width, -1, 1));
      axes.push_back(axis("v", req.height, 1, -1));
      value = "f(wi, wo) cos(theta_i) for wi = (u, v, sqrt(1 - u^2 - v^2)), 0 outside the unit "
              "disk; wo at mu_o, phi_o_deg; a coloured Fresnel contributes its first (red) channel";
      model["mu_o"] = req.mu_o;
      model["phi_o_deg"] = req.phi_o * 180.0 / 3.14159265358979323846;
      break;
    case GridKind::kG1:
      axes.push_back(axis("mu", req.width, 0, 1));
      axes.push_back(axis("roughness", req.height, 0, 1));
      value = "G1(w) of the isotropic model at w.z = mu";
      model.erase("alpha_x");
      model.erase("alpha_y");
      model["alpha"] = "roughness^2 (the y axis), clamped below at 1e-4";
      break;
  }
  const char* channel = GridChannelName(req.kind);
  return {{"brdfbake.version", BRDFBAKE_VERSION},
          {"brdfbake.grid", GridKindName(req.kind)},
          {"brdfbake.model", model.dump()},
          {"brdfbake.masking", MaskingName(req.masking)},
          {"brdfbake.fresnel", req.fresnel.Name()},
          {"brdfbake.axes", axes.dump()},
          {"brdfbake.layout", kLayoutText},
          {"brdfbake.channels", nlohmann::json{{channel, channel}}.dump()},
          {"brdfbake.channel_order", nlohmann::json::array({channel}).dump()},
          {"brdfbake.channel_info",
           nlohmann::json::array({{{"index", 0}, {"name", channel}, {"meaning", channel},
                                   {"definition", value}}})
               .dump()},
          {"brdfbake.evaluated_by", grid.path}};
}

void ValidateGridRequest(const GridRequest& req) {
  ValidateModelParams(req.model);
  ValidateFresnel(req.fresnel);
  // The models without a BRDF: a lobe (sel's K) or a table model.
  if (!BatchSupports(req.model.kind, Quantity::kBrdf)) {
    Bad("{grid}: model " + std::string(req.model.name()) +
        (BatchSupports(req.model.kind, Quantity::kK) ? " is a lobe, not a BRDF"
                                                     : " has the table quantities E and E_avg only"));
  }
  if (req.width < 1 || req.height < 1 || req.width > 16384 || req.height > 16384) {
    Bad("{width}/{height} must be in [1, 16384]");
  }
  if (!(req.mu_o > 0) || req.mu_o > 1) Bad("{mu_o} must lie in (0, 1]");
  if (req.threads < 0 || req.threads > kMaxThreads) {
    Bad("{threads} must be in [0, " + std::to_string(kMaxThreads) +
                                "] (0 = all cores)");
  }
}

namespace {

// The directions of one row, as SoA.
struct RowDirs {
  std::vector<float> ix, iy, iz, ox, oy, oz;
  std::vector<char> inside;
  explicit RowDirs(int n) : ix(n), iy(n), iz(n), ox(n), oy(n), oz(n), inside(n, 1) {}
  void Set(int x, const Vec3<double>& wi, const Vec3<double>& wo) {
    ix[x] = float(wi.x); iy[x] = float(wi.y); iz[x] = float(wi.z);
    ox[x] = float(wo.x); oy[x] = float(wo.y); oz[x] = float(wo.z);
  }
};

RowDirs MakeRow(const GridRequest& req, int y) {
  const int w = req.width;
  RowDirs r(w);
  const double half_pi = 1.5707963267948966;
  if (req.kind == GridKind::kSlice) {
    const double td = (y + 0.5) / req.height * half_pi;
    // Difference vector at phi_d = 90 degrees, in the half-vector frame.
    const Vec3<double> d(0.0, std::sin(td), std::cos(td));
    for (int x = 0; x < w; ++x) {
      const double th = (x + 0.5) / w * half_pi;
      const double c = std::cos(th), s = std::sin(th);
      // Rotate about y by theta_h (phi_h = 0).
      auto rot = [&](const Vec3<double>& v) {
        return Vec3<double>(c * v.x + s * v.z, v.y, -s * v.x + c * v.z);
      };
      r.Set(x, rot(d), rot(Vec3<double>(-d.x, -d.y, d.z)));
    }
  } else if (req.kind == GridKind::kHemisphere) {
    const Vec3<double> wo = FromMuPhi(req.mu_o, req.phi_o);
    const double v = 1.0 - 2.0 * (y + 0.5) / req.height;
    for (int x = 0; x < w; ++x) {
      const double u = 2.0 * (x + 0.5) / w - 1.0;
      const double z2 = 1.0 - u * u - v * v;
      r.inside[x] = z2 > 0;
      r.Set(x, Vec3<double>(u, v, std::sqrt(std::max(0.0, z2))), wo);
    }
  } else {
    for (int x = 0; x < w; ++x) {
      r.Set(x, FromMuPhi((x + 0.5) / w, 0.0), Vec3<double>(0, 0, 1));
    }
  }
  return r;
}

}  // namespace

Grid EvalGrid(const GridRequest& req) {
  ValidateGridRequest(req);
  std::unique_ptr<tbb::global_control> limit;
  if (req.threads > 0) {
    limit = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                  req.threads);
  }
  Grid g;
  g.width = req.width;
  g.height = req.height;
  g.values.assign(size_t(req.width) * req.height, 0.0f);
  // The SIMD kernels take one channel of each Fresnel kind; a coloured
  // Fresnel (one grid, three channels) goes through the scalar reference.
  const bool simd = req.fresnel.IsGrey();
  g.path = simd ? "simd:" + BatchTarget() : "scalar";
  const std::unique_ptr<Model> model = simd ? nullptr : MakeModel(req.model);
  tbb::parallel_for(0, req.height, [&](int y) {
    const RowDirs r = MakeRow(req, y);
    float* out = g.values.data() + size_t(y) * req.width;
    if (req.kind == GridKind::kG1) {
      const double rough = (y + 0.5) / req.height;
      const float a = float(std::max(AlphaFromRoughness(rough), 1e-4));
      if (simd) {
        BatchModel p = BatchModelOf(req.model);
        p.alpha_x = p.alpha_y = a;
        EvalBatch(p, Quantity::kG1, {r.ix.data(), r.iy.data(), r.iz.data()}, out, req.width);
      } else {
        ModelParams mp = req.model;
        mp.alpha_x = mp.alpha_y = a;
        const std::unique_ptr<Model> m = MakeModel(mp);
        for (int x = 0; x < req.width; ++x) {
          out[x] = float(m->G1(Vec3<double>(r.ix[x], r.iy[x], r.iz[x])));
        }
      }
      return;
    }
    if (simd) {
      EvalBatch(BatchModelOf(req.model, req.masking, req.fresnel), Quantity::kBrdf,
                {r.ix.data(), r.iy.data(), r.iz.data()}, {r.ox.data(), r.oy.data(), r.oz.data()},
                out, req.width);
    } else {
      for (int x = 0; x < req.width; ++x) {
        out[x] = float(model->Brdf(Vec3<double>(r.ix[x], r.iy[x], r.iz[x]),
                                   Vec3<double>(r.ox[x], r.oy[x], r.oz[x]), req.fresnel,
                                   req.masking, 0));
      }
    }
    if (req.kind == GridKind::kHemisphere) {
      for (int x = 0; x < req.width; ++x) out[x] = r.inside[x] ? out[x] * r.iz[x] : 0.0f;
    }
  });
  return g;
}

}  // namespace brdfbake
