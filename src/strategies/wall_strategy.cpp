#include "strategies/wall_strategy.hpp"

#include <cmath>

#include "control/geometry/frustum.hpp"

namespace fragsim {

WallStrategy::WallStrategy(const WallParams& params, double fovy_deg, double aspect) {
  // Sized to the frustum's cross-section at the wall's far face, so no fragment reaches the near
  // plane around its rim. The near and far planes do not enter the cross-section.
  const Frustum frustum(fovy_deg, aspect, 0.0, 0.0);
  const double far_face_m = params.distance_m + 0.5 * params.thickness_m;
  spec_.distance_m = params.distance_m;
  spec_.thickness_m = params.thickness_m;
  spec_.width_m = 2.0 * params.margin * frustum.half_width_at(far_face_m);
  spec_.height_m = 2.0 * params.margin * frustum.half_height_at(far_face_m);
  spec_.restitution = params.restitution;
}

WorldNeeds WallStrategy::needs() const {
  return WorldNeeds{spec_};
}

}  // namespace fragsim
