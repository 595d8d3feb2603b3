#include "experiments/control_dump.hpp"

#include <array>
#include <cstring>
#include <stdexcept>

namespace fragsim {

template <class T>
void ControlDump::put(const T& v) {
  char raw[sizeof(T)];
  std::memcpy(raw, &v, sizeof(T));
  bytes_.append(raw, sizeof(T));
}

bool ControlDump::supports(std::string_view strategy) {
  return strategy == "edge-min" || strategy == "edge" || strategy == "deflect-all";
}

ControlDump::ControlDump(const std::string& path, std::string_view strategy, const Scene& scene)
    : file_(path) {
  if (!supports(strategy)) {
    throw std::invalid_argument("'" + std::string(strategy) +
                                "' is not in the controller library (edge-min, edge, deflect-all)");
  }
  std::array<double, 8> param{};
  std::array<std::int32_t, 8> iparam{};
  std::uint32_t id = 0;
  if (strategy == "edge-min") {
    const EdgeMinParams& p = scene.strategies.edge_min;
    param = {p.margin_m, p.a_max_mps2, p.camera_accel_mps2, p.camera_turn_degps, p.horizon_cap_s};
    iparam[0] = static_cast<std::int32_t>(p.camera_model);
    iparam[1] = p.max_solves;
  } else if (strategy == "edge") {
    id = 1;
    const EdgeParams& p = scene.strategies.edge;
    param = {p.k, p.a_max_mps2, p.horizon_cap_s};
    iparam = {static_cast<std::int32_t>(p.predictor), static_cast<std::int32_t>(p.reach),
              static_cast<std::int32_t>(p.horizon), static_cast<std::int32_t>(p.replan)};
  } else {
    id = 2;
    param = {scene.strategies.deflect_all.accel_mps2, scene.strategies.deflect_all.range_m};
  }
  bytes_.append("FSCDUMP1", 8);
  put(std::uint32_t{0x01020304});
  put(id);
  step_count_at_ = bytes_.size();
  put(std::uint32_t{0});
  put(std::uint32_t{0});
  for (double v : param) put(v);
  for (std::int32_t v : iparam) put(v);
}

void ControlDump::record(const StepContext& ctx, const StepOutput& out) {
  const auto n = static_cast<std::int32_t>(ctx.fragments.size());
  put(std::int32_t{ctx.step});
  put(n);
  put(static_cast<std::int32_t>(out.forces.size()));
  put(std::int32_t{0});
  const CameraPose& c = ctx.camera;
  auto put3 = [this](const Eigen::Vector3d& v) {
    put(v.x());
    put(v.y());
    put(v.z());
  };
  put(ctx.t_s);
  put(ctx.dt_s);
  put(ctx.end_time_s);
  put3(c.eye_m);
  put3(c.right);
  put3(c.up);
  put3(c.forward);
  put(c.fovy_deg);
  put(c.aspect);
  put(c.near_m);
  put(c.far_m);
  put3(ctx.camera_velocity_mps);
  put(ctx.camera_max_speed_mps);
  put(ctx.camera_max_accel_mps2);
  put(ctx.camera_max_turn_radps);
  put3(ctx.camera_body_half_m);
  put3(ctx.gravity_mps2);
  put(ctx.ground_height_m);
  for (const FragmentState& f : ctx.fragments) {
    put3(f.position_m);
    put3(f.velocity_mps);
    put(f.radius_m);
    put(f.mass_kg);
  }
  for (const FragmentState& f : ctx.fragments) bytes_.push_back(f.touched ? 1 : 0);
  bytes_.append((8 - ctx.fragments.size() % 8) % 8, '\0');
  for (const AppliedForce& a : out.forces) {
    put(std::int32_t{a.fragment});
    put(std::int32_t{0});
    put3(a.force_N);
  }
  ++steps_;
}

void ControlDump::commit() {
  const auto steps = static_cast<std::uint32_t>(steps_);
  std::memcpy(bytes_.data() + step_count_at_, &steps, sizeof steps);
  file_.out().write(bytes_.data(), static_cast<std::streamsize>(bytes_.size()));
  file_.commit();
}

}  // namespace fragsim
