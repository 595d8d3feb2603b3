#include "report/gltf_bake.hpp"

#include <tiny_gltf.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <tuple>

#include "debris/mesh_file.hpp"
#include "geometry/orientation.hpp"
#include "sim/scene.hpp"

#ifndef FRAGSIM_VERSION
#error "FRAGSIM_VERSION: set by CMakeLists.txt from the project's version"
#endif

namespace fragsim {
namespace {

// glTF wants one float per component; the track keeps them so.
void append_floats(std::vector<unsigned char>& data, const float* p, std::size_t n) {
  const auto* b = reinterpret_cast<const unsigned char*>(p);
  data.insert(data.end(), b, b + n * sizeof(float));
}

void pad4(std::vector<unsigned char>& data) {
  while (data.size() % 4 != 0) data.push_back(0);
}

std::array<float, 4> canonical(std::array<float, 4> q, const float* previous) {
  const double dot = previous ? double(q[0]) * previous[0] + double(q[1]) * previous[1] +
                                    double(q[2]) * previous[2] + double(q[3]) * previous[3]
                              : double(q[3]);
  if (dot < 0) {
    for (float& c : q) c = -c;
  }
  return q;
}

// A bufferView over [begin, end) of buffer 0.
int add_view(tinygltf::Model& model, std::size_t begin, std::size_t end, int target) {
  tinygltf::BufferView v;
  v.buffer = 0;
  v.byteOffset = begin;
  v.byteLength = end - begin;
  v.target = target;
  model.bufferViews.push_back(v);
  return static_cast<int>(model.bufferViews.size()) - 1;
}

int add_accessor(tinygltf::Model& model, int view, std::size_t offset, int component, int type,
                 std::size_t count) {
  tinygltf::Accessor a;
  a.bufferView = view;
  a.byteOffset = offset;
  a.componentType = component;
  a.type = type;
  a.count = count;
  model.accessors.push_back(a);
  return static_cast<int>(model.accessors.size()) - 1;
}

tinygltf::Value number(double v) {
  return tinygltf::Value(v);
}

}  // namespace

const char* fragsim_version() {
  return FRAGSIM_VERSION;
}

std::array<float, 4> quaternion_xyzw(const Eigen::Matrix3d& axes) {
  const Eigen::Quaterniond q = orientation_quaternion(axes);
  // Normalised again in float, so the stored quaternion is unit to float precision.
  Eigen::Vector4f f(static_cast<float>(q.x()), static_cast<float>(q.y()), static_cast<float>(q.z()),
                    static_cast<float>(q.w()));
  f /= f.norm();
  return {f[0], f[1], f[2], f[3]};
}

std::array<float, 4> camera_quaternion_xyzw(const CameraPose& camera) {
  return quaternion_xyzw(camera.rotation());
}

BakeMesh bake_mesh(const ConvexShape* shape, const Eigen::Vector3d& half_extents_m) {
  std::vector<Eigen::Vector3d> v;
  std::vector<std::vector<int>> faces;
  body_polyhedron(shape, half_extents_m, v, faces);
  BakeMesh m;
  for (const Eigen::Vector3d& x : v) m.vertices_m.push_back(x.cast<float>());
  for (const std::vector<int>& f : faces) {
    for (std::size_t k = 1; k + 1 < f.size(); ++k) {
      m.triangles.push_back(static_cast<std::uint32_t>(f[0]));
      m.triangles.push_back(static_cast<std::uint32_t>(f[k]));
      m.triangles.push_back(static_cast<std::uint32_t>(f[k + 1]));
    }
  }
  return m;
}

void add_bake_sample(BakeTrack& track, double t_s, std::span<const FragmentState> fragments,
                     const CameraPose& camera) {
  const std::size_t n = fragments.size();
  const bool first = track.times_s.empty();
  track.times_s.push_back(static_cast<float>(t_s));
  const std::size_t prev_rot = track.piece_rotation.size() - (first ? 0 : 4 * n);
  for (std::size_t i = 0; i < n; ++i) {
    const FragmentState& f = fragments[i];
    for (int k = 0; k < 3; ++k) {
      track.piece_translation_m.push_back(static_cast<float>(f.position_m[k]));
    }
    const float* previous = first ? nullptr : &track.piece_rotation[prev_rot + 4 * i];
    const std::array<float, 4> q = canonical(quaternion_xyzw(f.rotation), previous);
    track.piece_rotation.insert(track.piece_rotation.end(), q.begin(), q.end());
  }
  for (int k = 0; k < 3; ++k) {
    track.camera_translation_m.push_back(static_cast<float>(camera.eye_m[k]));
  }
  const float* previous =
      first ? nullptr : &track.camera_rotation[track.camera_rotation.size() - 4];
  const std::array<float, 4> q = canonical(camera_quaternion_xyzw(camera), previous);
  track.camera_rotation.insert(track.camera_rotation.end(), q.begin(), q.end());
  track.camera_near_m.push_back(camera.near_m);
}

std::string bake_glb(const BakeTrack& track) {
  const std::size_t n = track.piece_count();
  const std::size_t samples = track.sample_count();
  if (samples == 0) throw std::runtime_error("bake: no sample recorded");
  if (track.piece_translation_m.size() != 3 * n * samples ||
      track.piece_rotation.size() != 4 * n * samples ||
      track.camera_translation_m.size() != 3 * samples ||
      track.camera_rotation.size() != 4 * samples || track.camera_near_m.size() != samples) {
    throw std::runtime_error("bake: the poses do not match the pieces and samples");
  }
  for (int m : track.piece_mesh) {
    if (m < 0 || static_cast<std::size_t>(m) >= track.meshes.size()) {
      throw std::runtime_error("bake: a piece names no mesh");
    }
  }

  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = std::string("fragsim ") + FRAGSIM_VERSION;
  model.buffers.emplace_back();
  std::vector<unsigned char>& data = model.buffers.front().data;

  // The meshes (the ground's last), positions in one view, indices in another.
  std::vector<BakeMesh> meshes = track.meshes;
  int ground_mesh = -1;
  if (track.ground) {
    const auto h = static_cast<float>(track.ground_half_m);
    BakeMesh g;
    // Counter-clockwise seen from above, so the plane faces +Y.
    g.vertices_m = {{-h, 0.f, -h}, {-h, 0.f, h}, {h, 0.f, h}, {h, 0.f, -h}};
    g.triangles = {0, 1, 2, 0, 2, 3};
    ground_mesh = static_cast<int>(meshes.size());
    meshes.push_back(std::move(g));
  }
  std::vector<std::size_t> pos_offset, idx_offset;
  const std::size_t pos_begin = data.size();
  for (const BakeMesh& m : meshes) {
    pos_offset.push_back(data.size() - pos_begin);
    for (const Eigen::Vector3f& v : m.vertices_m) append_floats(data, v.data(), 3);
  }
  const int pos_view = add_view(model, pos_begin, data.size(), TINYGLTF_TARGET_ARRAY_BUFFER);
  // Vertex accessors sharing a view need its stride stated.
  model.bufferViews.back().byteStride = 3 * sizeof(float);
  const std::size_t idx_begin = data.size();
  for (const BakeMesh& m : meshes) {
    idx_offset.push_back(data.size() - idx_begin);
    const auto* b = reinterpret_cast<const unsigned char*>(m.triangles.data());
    data.insert(data.end(), b, b + m.triangles.size() * sizeof(std::uint32_t));
  }
  const int idx_view =
      add_view(model, idx_begin, data.size(), TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
  for (std::size_t i = 0; i < meshes.size(); ++i) {
    const BakeMesh& m = meshes[i];
    if (m.vertices_m.empty() || m.triangles.empty()) {
      throw std::runtime_error("bake: an empty mesh");
    }
    const int pos = add_accessor(model, pos_view, pos_offset[i], TINYGLTF_COMPONENT_TYPE_FLOAT,
                                 TINYGLTF_TYPE_VEC3, m.vertices_m.size());
    tinygltf::Accessor& pa = model.accessors[static_cast<std::size_t>(pos)];
    pa.minValues.assign(3, std::numeric_limits<double>::infinity());
    pa.maxValues.assign(3, -std::numeric_limits<double>::infinity());
    for (const Eigen::Vector3f& v : m.vertices_m) {
      for (int k = 0; k < 3; ++k) {
        pa.minValues[k] = std::min(pa.minValues[k], static_cast<double>(v[k]));
        pa.maxValues[k] = std::max(pa.maxValues[k], static_cast<double>(v[k]));
      }
    }
    const int idx =
        add_accessor(model, idx_view, idx_offset[i], TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT,
                     TINYGLTF_TYPE_SCALAR, m.triangles.size());
    tinygltf::Primitive prim;
    prim.attributes["POSITION"] = pos;
    prim.indices = idx;
    prim.mode = TINYGLTF_MODE_TRIANGLES;
    tinygltf::Mesh mesh;
    mesh.name = static_cast<int>(i) == ground_mesh ? "ground" : "shape_" + std::to_string(i);
    mesh.primitives.push_back(prim);
    model.meshes.push_back(mesh);
  }

  // The shared time accessor, then every track's keyframes, piece by piece.
  const std::size_t time_begin = data.size();
  append_floats(data, track.times_s.data(), samples);
  const int time_view = add_view(model, time_begin, data.size(), 0);
  const int time = add_accessor(model, time_view, 0, TINYGLTF_COMPONENT_TYPE_FLOAT,
                                TINYGLTF_TYPE_SCALAR, samples);
  {
    const auto [lo, hi] = std::minmax_element(track.times_s.begin(), track.times_s.end());
    model.accessors[static_cast<std::size_t>(time)].minValues = {static_cast<double>(*lo)};
    model.accessors[static_cast<std::size_t>(time)].maxValues = {static_cast<double>(*hi)};
  }
  // Translations of pieces 0..n-1 and then the camera, each contiguous over the samples.
  const std::size_t tr_begin = data.size();
  for (std::size_t i = 0; i <= n; ++i) {
    for (std::size_t s = 0; s < samples; ++s) {
      const float* p =
          i < n ? &track.piece_translation_m[3 * (s * n + i)] : &track.camera_translation_m[3 * s];
      append_floats(data, p, 3);
    }
  }
  const int tr_view = add_view(model, tr_begin, data.size(), 0);
  const std::size_t rot_begin = data.size();
  for (std::size_t i = 0; i <= n; ++i) {
    for (std::size_t s = 0; s < samples; ++s) {
      const float* q =
          i < n ? &track.piece_rotation[4 * (s * n + i)] : &track.camera_rotation[4 * s];
      append_floats(data, q, 4);
    }
  }
  const int rot_view = add_view(model, rot_begin, data.size(), 0);
  pad4(data);

  tinygltf::Animation anim;
  anim.name = track.strategy;
  tinygltf::Scene scene;
  scene.name = track.scene_name;
  auto animate = [&](int node, std::size_t i) {
    const int tr = add_accessor(model, tr_view, 3 * sizeof(float) * samples * i,
                                TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, samples);
    const int rot = add_accessor(model, rot_view, 4 * sizeof(float) * samples * i,
                                 TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC4, samples);
    for (const auto& [output, path] : {std::pair{tr, "translation"}, std::pair{rot, "rotation"}}) {
      tinygltf::AnimationSampler sampler;
      sampler.input = time;
      sampler.output = output;
      sampler.interpolation = "LINEAR";
      tinygltf::AnimationChannel channel;
      channel.sampler = static_cast<int>(anim.samplers.size());
      channel.target_node = node;
      channel.target_path = path;
      anim.samplers.push_back(sampler);
      anim.channels.push_back(channel);
    }
  };
  // The static pose of each node is its first sample's, for viewers that do not play animations.
  auto first_pose = [](tinygltf::Node& node, const float* t, const float* q) {
    node.translation = {t[0], t[1], t[2]};
    node.rotation = {q[0], q[1], q[2], q[3]};
  };
  for (std::size_t i = 0; i < n; ++i) {
    tinygltf::Node node;
    node.name = "fragment_" + std::to_string(i);
    node.mesh = track.piece_mesh[i];
    first_pose(node, &track.piece_translation_m[3 * i], &track.piece_rotation[4 * i]);
    scene.nodes.push_back(static_cast<int>(model.nodes.size()));
    model.nodes.push_back(node);
    animate(static_cast<int>(i), i);
  }

  tinygltf::Camera camera;
  camera.name = "camera";
  camera.type = "perspective";
  camera.perspective.yfov = track.fovy_deg * std::numbers::pi / 180.0;
  camera.perspective.aspectRatio = track.aspect;
  camera.perspective.znear = track.near_m;
  camera.perspective.zfar = track.far_m;
  model.cameras.push_back(camera);
  {
    tinygltf::Node node;
    node.name = "camera";
    node.camera = 0;
    first_pose(node, &track.camera_translation_m[0], &track.camera_rotation[0]);
    // Each sample's near distance in force, as `near-plane` moves it and core glTF cannot animate
    // it (the camera's znear is the first sample's).
    tinygltf::Value::Array near;
    for (double d : track.camera_near_m) near.push_back(number(d));
    tinygltf::Value::Object extras;
    extras["near_m_per_sample"] = tinygltf::Value(std::move(near));
    node.extras = tinygltf::Value(std::move(extras));
    const int index = static_cast<int>(model.nodes.size());
    scene.nodes.push_back(index);
    model.nodes.push_back(node);
    animate(index, n);
  }
  if (track.ground) {
    tinygltf::Node node;
    node.name = "ground";
    node.mesh = ground_mesh;
    node.translation = {track.ground_centre_xz_m.x(), track.ground_height_m,
                        track.ground_centre_xz_m.y()};
    scene.nodes.push_back(static_cast<int>(model.nodes.size()));
    model.nodes.push_back(node);
  }

  tinygltf::Value::Object extras;
  extras["scene"] = tinygltf::Value(track.scene_name);
  // Text, since a 64-bit seed does not fit a JSON number exactly.
  extras["seed"] = tinygltf::Value(std::to_string(track.seed));
  extras["strategy"] = tinygltf::Value(track.strategy);
  extras["fragsim_version"] = tinygltf::Value(std::string(FRAGSIM_VERSION));
  extras["dt_s"] = number(track.dt_s);
  extras["sample_every_steps"] = tinygltf::Value(track.every);
  extras["fragment_count"] = tinygltf::Value(static_cast<int>(n));
  scene.extras = tinygltf::Value(std::move(extras));
  model.animations.push_back(anim);
  model.scenes.push_back(scene);
  model.defaultScene = 0;

  std::ostringstream out;
  tinygltf::TinyGLTF writer;
  if (!writer.WriteGltfSceneToStream(&model, out, false, true)) {
    throw std::runtime_error("glTF writer failed");
  }
  return out.str();
}

std::size_t bake_animation_bytes(int piece_count, int step_count, int every) {
  const std::size_t samples = static_cast<std::size_t>(step_count / std::max(every, 1)) + 1 +
                              (step_count % std::max(every, 1) != 0 ? 1 : 0);
  return samples * (static_cast<std::size_t>(piece_count) + 1) * 7 * sizeof(float) +
         samples * sizeof(float);
}

std::string bake_file_path(const std::string& path, const std::string& strategy, bool several) {
  if (!several) return path;
  const std::filesystem::path p(path);
  return (p.parent_path() / (p.stem().string() + "." + strategy + p.extension().string())).string();
}

GltfBakeRecorder::GltfBakeRecorder(int every) : every_(std::max(every, 1)) {}

void GltfBakeRecorder::begin(const RunInfo& info, const StepSnapshot& initial) {
  track_ = BakeTrack{};
  step_count_ = info.step_count;
  track_.strategy = info.strategy;
  track_.dt_s = info.dt_s;
  track_.every = every_;
  if (info.scene) {
    const Scene& s = *info.scene;
    track_.scene_name = s.name;
    track_.seed = s.sim.seed;
    track_.ground = s.ground.enabled;
    track_.ground_height_m = s.ground.height_m;
    track_.ground_centre_xz_m = {s.object.centre_m.x(), s.object.centre_m.z()};
  }
  track_.fovy_deg = initial.camera.fovy_deg;
  track_.aspect = initial.camera.aspect;
  track_.near_m = initial.camera.near_m;
  track_.far_m = initial.camera.far_m;
  // Pieces of one shape (the grid's equal boxes, a shared hull) share one mesh, in the order met.
  std::map<std::tuple<const ConvexShape*, double, double, double>, int> seen;
  for (const FragmentState& f : initial.fragments) {
    const auto key =
        std::make_tuple(f.shape, f.shape ? 0.0 : f.half_extents_m.x(),
                        f.shape ? 0.0 : f.half_extents_m.y(), f.shape ? 0.0 : f.half_extents_m.z());
    auto [it, added] = seen.try_emplace(key, static_cast<int>(track_.meshes.size()));
    if (added) track_.meshes.push_back(bake_mesh(f.shape, f.half_extents_m));
    track_.piece_mesh.push_back(it->second);
  }
  add_bake_sample(track_, initial.t_s, initial.fragments, initial.camera);
}

void GltfBakeRecorder::observe(const StepSnapshot& snap) {
  if (snap.step % every_ == 0 || snap.step == step_count_) {
    add_bake_sample(track_, snap.t_s, snap.fragments, snap.camera);
  }
}

void GltfBakeRecorder::end() {
  baked_.push_back({track_.strategy, bake_glb(track_)});
  track_ = BakeTrack{};
}

}  // namespace fragsim
