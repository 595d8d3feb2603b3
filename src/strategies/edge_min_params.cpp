#include "strategies/edge_min_params.hpp"

namespace fragsim {

const ParamSpec<EdgeMinParams>& edge_min_param_spec() {
  using namespace settings;
  using P = EdgeMinParams;
  // The assumed camera bounds stand in for a scene that declares none: they must be numbers to
  // reason with (a camera that turns or accelerates without bound is `reachable`'s case).
  static const ParamSpec<P> spec{
      {real("margin_m", "m", "clearance kept beyond the protected rectangle's edge", &P::margin_m,
            closed(0, 100)),
       real("a_max_mps2", "m/s^2", "cap on the imposed acceleration", &P::a_max_mps2,
            closed(0, 1e9)),
       choice("camera_model",
              "what the camera is assumed to do before a fragment arrives: keep its velocity "
              "and view, change them within acceleration and turn-rate bounds, or go anywhere "
              "within V_c t",
              &P::camera_model,
              {{"constant", CameraModel::kConstant},
               {"bounded_accel", CameraModel::kBoundedAccel},
               {"reachable", CameraModel::kReachable}}),
       real("camera_accel_mps2", "m/s^2",
            "bounded_accel: the camera's acceleration bound assumed when the scene declares "
            "none (mode = path or track)",
            &P::camera_accel_mps2, closed(0, 1e6)),
       real("camera_turn_degps", "degrees/s",
            "bounded_accel and reachable: the camera's turn-rate bound assumed when the scene "
            "declares none",
            &P::camera_turn_degps, closed(0, 1e6)),
       real("horizon_cap_s", "s",
            "look-ahead cap: a path is examined until the fragment reaches the ground, at most "
            "this far ahead",
            &P::horizon_cap_s, open_closed(0, 3600)),
       integer("max_solves", "",
               "fragments solved exactly per step, the most urgent first; the rest keep their "
               "last force (0: no cap)",
               &P::max_solves, 0, 100000000)},
      {}};
  return spec;
}

}  // namespace fragsim
