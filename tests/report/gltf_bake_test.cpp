// The bake's writer from cases worked by hand: a piece moving at constant velocity keys exactly
// the positions it passed, a camera looking down -z has the identity rotation and one looking
// down +x a yaw of -90 degrees about +y, the same track gives the same bytes, and a recorder on a
// real run keys every step of every piece with one shared box mesh.

#include "report/gltf_bake.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstring>
#include <numbers>

#include "debris/gltf_load.hpp"
#include "experiments/evaluation.hpp"
#include "support/shipped_scene.hpp"

namespace fragsim {
namespace {

tinygltf::Model parse(const std::string& bytes) {
  return load_gltf(bytes, "bake.glb", true);
}

// The floats an accessor holds (tightly packed, as the writer lays them out).
std::vector<float> floats_of(const tinygltf::Model& m, int accessor) {
  const tinygltf::Accessor& a = m.accessors.at(static_cast<std::size_t>(accessor));
  const tinygltf::BufferView& v = m.bufferViews.at(static_cast<std::size_t>(a.bufferView));
  const std::size_t per = a.type == TINYGLTF_TYPE_SCALAR ? 1 : a.type == TINYGLTF_TYPE_VEC3 ? 3 : 4;
  std::vector<float> out(a.count * per);
  std::memcpy(out.data(), m.buffers.at(0).data.data() + v.byteOffset + a.byteOffset,
              out.size() * sizeof(float));
  return out;
}

// The sampler output of `path` animating node `node`; -1 if none.
int output_of(const tinygltf::Model& m, int node, const std::string& path) {
  for (const tinygltf::AnimationChannel& c : m.animations.at(0).channels) {
    if (c.target_node == node && c.target_path == path) {
      return m.animations[0].samplers.at(static_cast<std::size_t>(c.sampler)).output;
    }
  }
  return -1;
}

CameraPose camera_looking(const Eigen::Vector3d& forward) {
  CameraPose c;
  c.forward = forward.normalized();
  c.up = Eigen::Vector3d::UnitY();
  c.right = c.forward.cross(c.up).normalized();
  return c;
}

// One box piece from p0 at velocity v, turning about z at w rad/s, sampled at `steps` + 1 times.
BakeTrack moving_piece(const Eigen::Vector3d& p0, const Eigen::Vector3d& v, double w, int steps,
                       double dt) {
  BakeTrack t;
  t.scene_name = "hand";
  t.seed = 7;
  t.strategy = "none";
  t.dt_s = dt;
  t.ground = true;
  t.fovy_deg = 60;
  t.aspect = 1.5;
  t.near_m = 0.1;
  t.far_m = 500;
  t.meshes.push_back(bake_mesh(nullptr, Eigen::Vector3d(0.1, 0.2, 0.3)));
  t.piece_mesh = {0};
  for (int s = 0; s <= steps; ++s) {
    FragmentState f;
    f.position_m = p0 + v * (s * dt);
    f.rotation = Eigen::AngleAxisd(w * s * dt, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    CameraPose c = camera_looking({0, 0, -1});
    c.eye_m = {0, 1.6, 2.0 - s * dt};
    add_bake_sample(t, s * dt, std::span<const FragmentState>(&f, 1), c);
  }
  return t;
}

TEST(GltfBake, CameraLookingDownMinusZHasTheIdentityRotation) {
  const std::array<float, 4> q = camera_quaternion_xyzw(camera_looking({0, 0, -1}));
  EXPECT_FLOAT_EQ(q[0], 0.0f);
  EXPECT_FLOAT_EQ(q[1], 0.0f);
  EXPECT_FLOAT_EQ(q[2], 0.0f);
  EXPECT_FLOAT_EQ(q[3], 1.0f);
}

// Looking down +x: right = forward x up = +z, so the node's axes are x' = +z, y' = +y,
// z' = -forward = -x: a turn of -90 degrees about +y, q = (0, sin(-45 deg), 0, cos(-45 deg)).
TEST(GltfBake, CameraLookingDownPlusXIsAYawOfMinus90Degrees) {
  const std::array<float, 4> q = camera_quaternion_xyzw(camera_looking({1, 0, 0}));
  EXPECT_NEAR(q[0], 0.0f, 1e-7);
  EXPECT_NEAR(q[1], -0.70710678f, 1e-6);
  EXPECT_NEAR(q[2], 0.0f, 1e-7);
  EXPECT_NEAR(q[3], 0.70710678f, 1e-6);
  // And it turns the glTF camera's view direction (-z) onto +x.
  const Eigen::Quaterniond r(q[3], q[0], q[1], q[2]);
  EXPECT_NEAR((r * Eigen::Vector3d(0, 0, -1) - Eigen::Vector3d(1, 0, 0)).norm(), 0.0, 1e-6);
}

TEST(GltfBake, PieceAtConstantVelocityKeysThePositionsItPassed) {
  const Eigen::Vector3d p0(1, 2, -3), v(0.5, 4, -10);
  const double dt = 1.0 / 60.0;
  const int steps = 30;
  const tinygltf::Model m = parse(bake_glb(moving_piece(p0, v, 2.0, steps, dt)));
  // Nodes: the piece, the camera, the ground.
  ASSERT_EQ(m.nodes.size(), 3u);
  EXPECT_EQ(m.nodes[0].name, "fragment_0");
  EXPECT_EQ(m.nodes[1].camera, 0);
  EXPECT_EQ(m.nodes[2].name, "ground");
  ASSERT_EQ(m.animations.size(), 1u);
  EXPECT_EQ(m.animations[0].name, "none");
  EXPECT_EQ(m.animations[0].channels.size(), 4u);
  for (const tinygltf::AnimationSampler& s : m.animations[0].samplers) {
    EXPECT_EQ(s.interpolation, "LINEAR");
    EXPECT_EQ(s.input, m.animations[0].samplers[0].input);  // one shared time accessor
  }
  const std::vector<float> times = floats_of(m, m.animations[0].samplers[0].input);
  ASSERT_EQ(times.size(), static_cast<std::size_t>(steps + 1));
  const std::vector<float> tr = floats_of(m, output_of(m, 0, "translation"));
  const std::vector<float> rot = floats_of(m, output_of(m, 0, "rotation"));
  for (int s = 0; s <= steps; ++s) {
    EXPECT_FLOAT_EQ(times[static_cast<std::size_t>(s)], static_cast<float>(s * dt));
    const Eigen::Vector3d p = p0 + v * (s * dt);
    for (int k = 0; k < 3; ++k) EXPECT_FLOAT_EQ(tr[static_cast<std::size_t>(3 * s + k)], p[k]);
    // A turn of 2 s rad about z: (0, 0, sin(a/2), cos(a/2)).
    const double half = 0.5 * 2.0 * s * dt;
    EXPECT_NEAR(rot[static_cast<std::size_t>(4 * s + 2)], std::sin(half), 1e-6);
    EXPECT_NEAR(rot[static_cast<std::size_t>(4 * s + 3)], std::cos(half), 1e-6);
  }
  // The box's mesh about its centre: corners at +-half extents, 12 triangles.
  const tinygltf::Accessor& pos = m.accessors.at(
      static_cast<std::size_t>(m.meshes.at(0).primitives.at(0).attributes.at("POSITION")));
  EXPECT_EQ(pos.count, 8u);
  EXPECT_FLOAT_EQ(static_cast<float>(pos.maxValues[2]), 0.3f);
  EXPECT_FLOAT_EQ(static_cast<float>(pos.minValues[1]), -0.2f);
  EXPECT_EQ(m.accessors.at(static_cast<std::size_t>(m.meshes[0].primitives[0].indices)).count, 36u);
  // The camera: yfov in radians, the frustum's numbers, its eye keyed.
  ASSERT_EQ(m.cameras.size(), 1u);
  EXPECT_EQ(m.cameras[0].type, "perspective");
  EXPECT_DOUBLE_EQ(m.cameras[0].perspective.yfov, std::numbers::pi / 3.0);
  EXPECT_DOUBLE_EQ(m.cameras[0].perspective.aspectRatio, 1.5);
  EXPECT_DOUBLE_EQ(m.cameras[0].perspective.znear, 0.1);
  EXPECT_DOUBLE_EQ(m.cameras[0].perspective.zfar, 500);
  const std::vector<float> eye = floats_of(m, output_of(m, 1, "translation"));
  EXPECT_FLOAT_EQ(eye[3 * steps + 2], static_cast<float>(2.0 - steps * dt));
  // The scene's extras.
  const tinygltf::Value& x = m.scenes.at(0).extras;
  EXPECT_EQ(x.Get("scene").Get<std::string>(), "hand");
  EXPECT_EQ(x.Get("seed").Get<std::string>(), "7");
  EXPECT_EQ(x.Get("strategy").Get<std::string>(), "none");
  EXPECT_EQ(x.Get("fragsim_version").Get<std::string>(), fragsim_version());
}

// q and -q are one rotation; LINEAR interpolation between keys of opposite sign turns the long way
// round, so a piece spinning past half a turn keeps each key on the side of the one before.
TEST(GltfBake, QuaternionKeysStayOnOneSide) {
  const BakeTrack t = moving_piece({0, 0, 0}, {0, 0, 0}, 10.0, 120, 1.0 / 60.0);  // 3 turns
  for (std::size_t s = 1; s < t.sample_count(); ++s) {
    double dot = 0;
    for (int k = 0; k < 4; ++k)
      dot += t.piece_rotation[4 * s + k] * t.piece_rotation[4 * s - 4 + k];
    EXPECT_GT(dot, 0.9) << "sample " << s;
  }
}

TEST(GltfBake, SameTrackGivesTheSameBytesAndAnotherTrackOthers) {
  const BakeTrack a = moving_piece({1, 2, 3}, {0, 1, 0}, 1.0, 20, 0.01);
  EXPECT_EQ(bake_glb(a), bake_glb(a));
  const BakeTrack b = moving_piece({1, 2, 3}, {0, 1.0001, 0}, 1.0, 20, 0.01);
  EXPECT_NE(bake_glb(a), bake_glb(b));
}

TEST(GltfBake, InconsistentTrackIsRefused) {
  BakeTrack t = moving_piece({0, 0, 0}, {1, 0, 0}, 0.0, 3, 0.1);
  t.piece_mesh = {0, 0};  // two pieces, poses for one
  EXPECT_THROW(bake_glb(t), std::runtime_error);
  EXPECT_THROW(bake_glb(BakeTrack{}), std::runtime_error);
}

TEST(GltfBake, FilePathPerStrategy) {
  EXPECT_EQ(bake_file_path("out/shot.glb", "edge-min", false), "out/shot.glb");
  EXPECT_EQ(bake_file_path("out/shot.glb", "edge-min", true), "out/shot.edge-min.glb");
  EXPECT_EQ(bake_file_path("shot.glb", "none", true), "shot.none.glb");
}

TEST(GltfBake, AnimationBytesCountEverySampleOfEveryPieceAndTheCamera) {
  // 181 samples of (1728 pieces + camera) x 7 floats, plus 181 times.
  EXPECT_EQ(bake_animation_bytes(1728, 180, 1), 181u * 1729u * 28u + 181u * 4u);
  // Every 4th of 10 steps: 0, 4, 8 and the last, 10.
  EXPECT_EQ(bake_animation_bytes(1, 10, 4), 4u * 2u * 28u + 4u * 4u);
}

// A real run observed: thesis125's 125 grid cubes share one box mesh; every step of every piece is
// keyed with the run's own positions.
TEST(GltfBake, RecorderKeysEveryStepOfARun) {
  Scene scene = test::scene_named("thesis125");
  scene.sim.duration_s = 0.5;
  GltfBakeRecorder recorder;
  EvaluationOptions options;
  options.occlusion = false;
  options.extra.push_back(&recorder);
  const Evaluation run = evaluate(scene, "edge-min", options);
  ASSERT_EQ(recorder.baked().size(), 1u);
  EXPECT_EQ(recorder.baked()[0].strategy, "edge-min");
  const tinygltf::Model m = parse(recorder.baked()[0].bytes);
  EXPECT_EQ(m.meshes.size(), 2u);  // the shared box and the ground
  EXPECT_EQ(m.nodes.size(), static_cast<std::size_t>(scene.fragment_count() + 2));
  const std::vector<float> times = floats_of(m, m.animations.at(0).samplers.at(0).input);
  EXPECT_EQ(times.size(), static_cast<std::size_t>(scene.step_count() + 1));
  // The camera's last key is the run's last camera pose.
  const std::vector<float> eye = floats_of(m, output_of(m, scene.fragment_count(), "translation"));
  const Eigen::Vector3d last = run.camera.back().eye_m;
  for (int k = 0; k < 3; ++k) {
    EXPECT_FLOAT_EQ(eye[eye.size() - 3 + static_cast<std::size_t>(k)], static_cast<float>(last[k]));
  }
}

}  // namespace
}  // namespace fragsim
