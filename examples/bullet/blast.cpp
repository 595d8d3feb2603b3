#include "blast.hpp"

std::vector<FragmentStart> make_blast(Vec3 eye_m, double fall_mps2, SeededDraws& draws) {
  // Wider than the largest fragment, so with fragment collisions on none starts inside another.
  constexpr double kSpacing_m = 0.13;
  // Radial speed per metre from the block's centre: the cloud grows to about 1 m across at the eye.
  constexpr double kSpread_mps_per_m = 2.5;
  constexpr double kJitter_mps = 0.3;
  const Vec3 centre_m =
      eye_m + Vec3{draws.uniform(-0.3, 0.3), draws.uniform(-0.4, -0.1), -draws.uniform(4.5, 6.5)};
  const double speed_mps = draws.uniform(9, 11);
  const Vec3 to_eye = eye_m - centre_m;
  const double flight_s = length(to_eye) / speed_mps;
  // Aimed at the eye as the camera stands at the blast: the throw's rise cancels the fall.
  const Vec3 aim_mps = to_eye * (1 / flight_s) + Vec3{0, 0.5 * fall_mps2 * flight_s, 0};
  std::vector<FragmentStart> fragments;
  const double half_block = 0.5 * (kFragmentsPerSide - 1);
  for (int i = 0; i < kFragmentsPerSide * kFragmentsPerSide * kFragmentsPerSide; ++i) {
    const Vec3 offset_m = Vec3{i % kFragmentsPerSide - half_block,
                               (i / kFragmentsPerSide) % kFragmentsPerSide - half_block,
                               i / (kFragmentsPerSide * kFragmentsPerSide) - half_block} *
                          kSpacing_m;
    FragmentStart f;
    f.position_m = centre_m + offset_m;
    f.velocity_mps =
        aim_mps + offset_m * kSpread_mps_per_m +
        Vec3{draws.uniform(-kJitter_mps, kJitter_mps), draws.uniform(-kJitter_mps, kJitter_mps),
             draws.uniform(-kJitter_mps, kJitter_mps)};
    f.spin_radps = {draws.uniform(-6, 6), draws.uniform(-6, 6), draws.uniform(-6, 6)};
    f.size_m = draws.uniform(0.06, 0.12);
    fragments.push_back(f);
  }
  return fragments;
}
