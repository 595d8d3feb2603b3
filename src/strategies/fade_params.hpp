#pragma once
// `fade`'s parameters and their scene keys ([fade]).

#include "strategies/param_spec.hpp"

namespace fragsim {

struct FadeParams {
  // A fragment whose bounding box comes closer to the eye than start_m turns transparent in
  // proportion to the distance left, and is invisible from end_m in (end_m < start_m). Default
  // end_m clears the near rectangle's corners (0.155 m from the eye for the shipped scenes' 60
  // degree, 16:9, 10 cm frustum), so nothing that reaches the near plane is drawn. Default start_m
  // is the scenes' near-miss distance, so the fade spans about three frames of a 15 m/s fragment at
  // 60 Hz (docs/guide.md, fade).
  double start_m = 1.0;
  double end_m = 0.25;
};

const ParamSpec<FadeParams>& fade_param_spec();

}  // namespace fragsim
