// The explosion, before any engine sees it: a block of small boxes a few metres in front of the
// camera, thrown at the camera's eye (fragsim's front.ini, closer and smaller).
#pragma once

#include <vector>

#include "seeded_draws.hpp"
#include "vec3.hpp"

struct FragmentStart {
  Vec3 position_m;
  Vec3 velocity_mps;
  Vec3 spin_radps;
  double size_m = 0;  // edge of the cube
};

constexpr int kFragmentsPerSide = 6;            // 216 fragments
constexpr double kFragmentDensity_kgpm3 = 600;  // front.ini's

// Fragments in a kFragmentsPerSide^3 block 4.5-6.5 m ahead of eye_m, aimed at it at 9-11 m/s
// (lifted so the block's centre would fall onto the eye), with a radial spread and jitter.
std::vector<FragmentStart> make_blast(Vec3 eye_m, double fall_mps2, SeededDraws& draws);
