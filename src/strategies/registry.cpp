#include "strategies/registry.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "strategies/deflect_all_strategy.hpp"
#include "strategies/edge_min_strategy.hpp"
#include "strategies/edge_strategy.hpp"
#include "strategies/near_plane_strategy.hpp"
#include "strategies/none_strategy.hpp"
#include "strategies/wall_strategy.hpp"

namespace fragsim {
namespace {

void require(bool ok, const char* key, double value, const char* rule) {
  if (ok) return;
  std::ostringstream msg;
  msg << key << " = " << value << ": " << rule;
  throw std::invalid_argument(msg.str());
}

void validate(const WallParams& p) {
  require(std::isfinite(p.distance_m) && p.distance_m > 0, "wall.distance_m", p.distance_m,
          "must be > 0");
  require(std::isfinite(p.thickness_m) && p.thickness_m > 0 && p.thickness_m < 2 * p.distance_m,
          "wall.thickness_m", p.thickness_m, "must be > 0 and < 2 wall.distance_m");
  require(std::isfinite(p.margin) && p.margin >= 1, "wall.margin", p.margin, "must be >= 1");
  require(p.restitution >= 0 && p.restitution <= 1, "wall.restitution", p.restitution,
          "must be in [0, 1]");
}

void validate(const DeflectAllParams& p) {
  require(std::isfinite(p.accel_mps2) && p.accel_mps2 >= 0, "deflect-all.accel_mps2", p.accel_mps2,
          "must be >= 0");
  require(std::isfinite(p.range_m) && p.range_m >= 0, "deflect-all.range_m", p.range_m,
          "must be >= 0");
}

void validate(const NearPlaneParams& p, double camera_near_m) {
  require(std::isfinite(p.min_near_m) && p.min_near_m > 0 && p.min_near_m <= camera_near_m,
          "near-plane.min_near_m", p.min_near_m, "must be > 0 and <= camera.near_m");
  require(std::isfinite(p.margin_m) && p.margin_m >= 0, "near-plane.margin_m", p.margin_m,
          "must be >= 0");
  require(p.depth_bits >= 8 && p.depth_bits <= 32, "near-plane.depth_bits", p.depth_bits,
          "must be in [8, 32]");
  require(std::isfinite(p.ref_distance_m) && p.ref_distance_m > 0, "near-plane.ref_distance_m",
          p.ref_distance_m, "must be > 0");
}

void validate(const EdgeParams& p) {
  require(std::isfinite(p.k) && p.k >= 0, "edge.k", p.k, "must be >= 0");
  require(std::isfinite(p.a_max_mps2) && p.a_max_mps2 >= 0, "edge.a_max_mps2", p.a_max_mps2,
          "must be >= 0");
}

void validate(const EdgeMinParams& p) {
  require(std::isfinite(p.margin_m) && p.margin_m >= 0, "edge-min.margin_m", p.margin_m,
          "must be >= 0");
  require(std::isfinite(p.a_max_mps2) && p.a_max_mps2 >= 0, "edge-min.a_max_mps2", p.a_max_mps2,
          "must be >= 0");
  // The assumed bounds stand in for a scene that declares none: they must be numbers to reason
  // with (a camera that turns or accelerates without bound is `reachable`'s case, not infinity).
  require(std::isfinite(p.camera_accel_mps2) && p.camera_accel_mps2 >= 0,
          "edge-min.camera_accel_mps2", p.camera_accel_mps2, "must be finite and >= 0");
  require(std::isfinite(p.camera_turn_degps) && p.camera_turn_degps >= 0,
          "edge-min.camera_turn_degps", p.camera_turn_degps, "must be finite and >= 0");
}

}  // namespace

const std::vector<std::string>& strategy_names() {
  static const std::vector<std::string> names{"none",       "wall", "deflect-all",
                                              "near-plane", "edge", "edge-min"};
  return names;
}

std::unique_ptr<Strategy> make_strategy(std::string_view name, const StrategySettings& scene) {
  if (name == "none") return std::make_unique<NoneStrategy>();
  if (name == "wall") {
    validate(scene.wall);
    return std::make_unique<WallStrategy>(scene.wall, scene.camera_fovy_deg, scene.camera_aspect);
  }
  if (name == "deflect-all") {
    validate(scene.deflect_all);
    return std::make_unique<DeflectAllStrategy>(scene.deflect_all);
  }
  if (name == "near-plane") {
    validate(scene.near_plane, scene.camera_near_m);
    return std::make_unique<NearPlaneStrategy>(scene.near_plane);
  }
  if (name == "edge") {
    validate(scene.edge);
    return std::make_unique<EdgeStrategy>(scene.edge);
  }
  if (name == "edge-min") {
    validate(scene.edge_min);
    return std::make_unique<EdgeMinStrategy>(scene.edge_min);
  }
  std::string known;
  for (const std::string& n : strategy_names()) known += (known.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown strategy '" + std::string(name) + "' (known: " + known +
                              ")");
}

}  // namespace fragsim
