#include "strategies/deflect_all_keys.hpp"

#include "strategies/range_keys.hpp"

namespace fragsim {

const ParamSpec<DeflectAllParams>& deflect_all_param_spec() {
  using P = DeflectAllParams;
  static const ParamSpec<P> spec{
      {ranged_real(kDeflectAllRanges, "accel_mps2", "m/s^2", "push away from the view axis",
                   &P::accel_mps2),
       ranged_real(kDeflectAllRanges, "range_m", "m",
                   "only fragments this close to the eye are pushed", &P::range_m)},
      {}};
  return spec;
}

}  // namespace fragsim
