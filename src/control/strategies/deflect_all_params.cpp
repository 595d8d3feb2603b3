#include "strategies/deflect_all_params.hpp"

namespace fragsim {

const ParamSpec<DeflectAllParams>& deflect_all_param_spec() {
  using namespace settings;
  using P = DeflectAllParams;
  static const ParamSpec<P> spec{
      {real("accel_mps2", "m/s^2", "push away from the view axis", &P::accel_mps2, closed(0, 1e6)),
       real("range_m", "m", "only fragments this close to the eye are pushed", &P::range_m,
            closed(0, 1e6))},
      {}};
  return spec;
}

}  // namespace fragsim
