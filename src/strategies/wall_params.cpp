#include "strategies/wall_params.hpp"

namespace fragsim {

const ParamSpec<WallParams>& wall_param_spec() {
  using namespace settings;
  using P = WallParams;
  static const ParamSpec<P> spec{
      {real("distance_m", "m", "wall centre in front of the eye", &P::distance_m,
            open_closed(0, 1000)),
       real("thickness_m", "m", "depth of the wall box", &P::thickness_m, open_closed(0, 100)),
       real("margin", "", "wall size over the frustum's cross-section", &P::margin, closed(1, 100)),
       real("restitution", "", "bounce off the wall, 0 to 1", &P::restitution, closed(0, 1))},
      [](const P& p, const FrustumDef&) {
        // A thicker box would reach behind the eye and enclose the camera.
        if (p.thickness_m >= 2.0 * p.distance_m) {
          throw InputError(bad_value_message(
              "wall.thickness_m", format_double(p.thickness_m),
              "must be < 2 wall.distance_m, so the wall stays in front of the eye"));
        }
      }};
  return spec;
}

}  // namespace fragsim
