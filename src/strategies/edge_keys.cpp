#include "strategies/edge_keys.hpp"

#include "strategies/range_keys.hpp"

namespace fragsim {

const ParamSpec<EdgeParams>& edge_param_spec() {
  using namespace settings;
  using P = EdgeParams;
  static const ParamSpec<P> spec{
      {ranged_real(kEdgeRanges, "k", "N m s^2", "gain of the thesis force (3.4)", &P::k),
       ranged_real(kEdgeRanges, "a_max_mps2", "m/s^2", "cap on the imposed acceleration",
                   &P::a_max_mps2),
       choice("predictor", "path used to predict", &P::predictor,
              {{"thesis", Predictor::kThesis}, {"discrete", Predictor::kDiscrete}}),
       choice("reach", "the camera's reachable region", &P::reach,
              {{"thesis", Reach::kThesis}, {"growing", Reach::kGrowing}}),
       choice("horizon", "height that defines t_G", &P::horizon,
              {{"camera", Horizon::kCamera}, {"ground", Horizon::kGround}}),
       choice(
           "replan", "which non-candidates are re-examined", &P::replan,
           {{"never", Replan::kNever}, {"contact", Replan::kContact}, {"always", Replan::kAlways}}),
       ranged_real(kEdgeRanges, "horizon_cap_s", "s",
                   "t_G's fallback and cap: a path that never falls through the horizon height is "
                   "examined this far ahead (a game has no scene end)",
                   &P::horizon_cap_s)},
      {},
      // The path model and the re-examination are edge's own trade of time against error.
      {{"predictor", "predictor thesis", {{"edge.predictor", "thesis"}}},
       {"predictor", "predictor discrete", {{"edge.predictor", "discrete"}}},
       {"replan", "replan never", {{"edge.replan", "never"}}},
       {"replan", "replan contact", {{"edge.replan", "contact"}}},
       {"replan", "replan always", {{"edge.replan", "always"}}}}};
  return spec;
}

}  // namespace fragsim
