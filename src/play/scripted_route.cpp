#include "play/scripted_route.hpp"

#include <cmath>

namespace fragsim {

void ScriptedRoute::poll(long step, std::vector<PlayEvent>&, HeldControls& held) {
  const long second = static_cast<long>(std::floor(static_cast<double>(step) * dt_s_)) % 4;
  held = {};
  switch (second) {
    case 0:
      held.forward = 1.0;
      break;
    case 1:
      held.forward = 1.0;
      held.right = 1.0;
      break;
    case 2:
      held.right = -1.0;
      held.yaw = -0.5;
      break;
    default:
      held.forward = -1.0;
      held.yaw = 0.5;
      break;
  }
}

}  // namespace fragsim
