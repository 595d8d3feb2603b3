#include "control/api/def_mapping.hpp"

#include <cstddef>

namespace fragsim::control {

EdgeMinParams edge_min_params(const fragsim_controller_def& d) {
  EdgeMinParams p;
  p.margin_m = d.edge_min.margin_m;
  p.a_max_mps2 = d.edge_min.a_max_mps2;
  p.camera_model = static_cast<CameraModel>(raw(d.edge_min.camera_model));
  p.camera_accel_mps2 = d.edge_min.camera_accel_mps2;
  p.camera_turn_degps = d.edge_min.camera_turn_degps;
  p.horizon_cap_s = d.horizon_cap_s;
  p.max_solves = d.edge_min.max_solves;
  for (std::size_t k = 0; k < 4; ++k) p.edge_weights[k] = d.edge_min.edge_weights[k];
  p.cover_max = d.edge_min.cover_max;
  p.cover_region = d.edge_min.cover_region;
  return p;
}

EdgeParams edge_params(const fragsim_controller_def& d) {
  EdgeParams p;
  p.k = d.edge.k_Nms2;
  p.a_max_mps2 = d.edge.a_max_mps2;
  p.predictor = static_cast<Predictor>(raw(d.edge.predictor));
  p.reach = static_cast<Reach>(raw(d.edge.reach));
  p.horizon = static_cast<Horizon>(raw(d.edge.horizon));
  p.replan = static_cast<Replan>(raw(d.edge.replan));
  p.horizon_cap_s = d.horizon_cap_s;
  return p;
}

DeflectAllParams deflect_all_params(const fragsim_controller_def& d) {
  DeflectAllParams p;
  p.accel_mps2 = d.deflect_all.accel_mps2;
  p.range_m = d.deflect_all.range_m;
  return p;
}

fragsim_controller_def controller_def(fragsim_strategy strategy, const EdgeMinParams& em,
                                      const EdgeParams& e, const DeflectAllParams& da) {
  fragsim_controller_def d;
  std::memset(&d, 0, sizeof d);  // padding too, since a def's bytes are written to a file as is
  d.strategy = strategy;
  d.edge_min.margin_m = em.margin_m;
  d.edge_min.a_max_mps2 = em.a_max_mps2;
  d.edge_min.camera_model = static_cast<fragsim_camera_model>(em.camera_model);
  d.edge_min.camera_accel_mps2 = em.camera_accel_mps2;
  d.edge_min.camera_turn_degps = em.camera_turn_degps;
  d.edge_min.max_solves = em.max_solves;
  for (std::size_t k = 0; k < 4; ++k) d.edge_min.edge_weights[k] = em.edge_weights[k];
  d.edge_min.cover_max = em.cover_max;
  d.edge_min.cover_region = em.cover_region;
  d.edge.k_Nms2 = e.k;
  d.edge.a_max_mps2 = e.a_max_mps2;
  d.edge.predictor = static_cast<fragsim_edge_predictor>(e.predictor);
  d.edge.reach = static_cast<fragsim_edge_reach>(e.reach);
  d.edge.horizon = static_cast<fragsim_edge_horizon>(e.horizon);
  d.edge.replan = static_cast<fragsim_edge_replan>(e.replan);
  d.deflect_all.accel_mps2 = da.accel_mps2;
  d.deflect_all.range_m = da.range_m;
  d.horizon_cap_s = strategy == FRAGSIM_STRATEGY_EDGE ? e.horizon_cap_s : em.horizon_cap_s;
  d.worker_count = 1;  // the calling thread; no task system
  d.internal_value = kDefCookie;
  return d;
}

std::optional<fragsim_strategy> strategy_named(std::string_view name) {
  if (name == "edge-min") return FRAGSIM_STRATEGY_EDGE_MIN;
  if (name == "edge") return FRAGSIM_STRATEGY_EDGE;
  if (name == "deflect-all") return FRAGSIM_STRATEGY_DEFLECT_ALL;
  return std::nullopt;
}

}  // namespace fragsim::control
