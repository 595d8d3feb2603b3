#include "strategies/fade_params.hpp"

namespace fragsim {

const ParamSpec<FadeParams>& fade_param_spec() {
  using namespace settings;
  using P = FadeParams;
  static const ParamSpec<P> spec{
      {real("start_m", "m", "a fragment closer to the eye than this begins to fade", &P::start_m,
            open_closed(0, 1e6)),
       real("end_m", "m", "a fragment this close to the eye or closer is invisible", &P::end_m,
            closed(0, 1e6))},
      [](const P& p, const FrustumDef&) {
        // The fade runs from opaque at start_m down to invisible at end_m, nearer the eye.
        if (!(p.end_m < p.start_m)) {
          throw InputError(
              bad_value_message("fade.end_m", format_double(p.end_m),
                                "must be < fade.start_m = " + format_double(p.start_m)));
        }
      }};
  return spec;
}

}  // namespace fragsim
