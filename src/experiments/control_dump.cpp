#include "experiments/control_dump.hpp"

#include <cstring>
#include <optional>
#include <stdexcept>

#include "control/api/def_mapping.hpp"

namespace fragsim {

template <class T>
void ControlDump::put(const T& v) {
  char raw[sizeof(T)];
  std::memcpy(raw, &v, sizeof(T));
  bytes_.append(raw, sizeof(T));
}

bool ControlDump::supports(std::string_view strategy) {
  return control::strategy_named(strategy).has_value();
}

ControlDump::ControlDump(const std::string& path, std::string_view strategy, const Scene& scene)
    : file_(path) {
  const std::optional<fragsim_strategy> id = control::strategy_named(strategy);
  if (!id) {
    throw std::invalid_argument("'" + std::string(strategy) +
                                "' is not in the controller library (edge-min, edge, deflect-all)");
  }
  const fragsim_controller_def def = control::controller_def(
      *id, scene.strategies.edge_min, scene.strategies.edge, scene.strategies.deflect_all);
  bytes_.append("FSCDUMP2", 8);
  put(std::uint32_t{0x01020304});
  put(static_cast<std::uint32_t>(sizeof def));
  step_count_at_ = bytes_.size();
  put(std::uint32_t{0});
  put(std::uint32_t{0});
  put(def);
  bytes_.append((8 - sizeof def % 8) % 8, '\0');
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
  put(ctx.camera_max_turn_degps);
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
