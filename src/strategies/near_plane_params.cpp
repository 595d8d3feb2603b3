#include "strategies/near_plane_params.hpp"

namespace fragsim {

const ParamSpec<NearPlaneParams>& near_plane_param_spec() {
  using namespace settings;
  using P = NearPlaneParams;
  static const ParamSpec<P> spec{
      {real("min_near_m", "m", "the closest the near plane may come", &P::min_near_m,
            open_closed(0, 1000)),
       real("margin_m", "m", "kept between the near plane and a fragment", &P::margin_m,
            closed(0, 100)),
       integer("depth_bits", "", "bits of the depth buffer", &P::depth_bits, 8, 32),
       real("ref_distance_m", "m", "distance at which the depth step is reported",
            &P::ref_distance_m, open_closed(0, 1e7))},
      [](const P& p, const FrustumDef& camera) {
        // The strategy only ever pulls the near plane in, never pushes it out.
        if (p.min_near_m > camera.near_m) {
          throw InputError(
              bad_value_message("near-plane.min_near_m", format_double(p.min_near_m),
                                "must be <= camera.near_m = " + format_double(camera.near_m)));
        }
      }};
  return spec;
}

}  // namespace fragsim
