#pragma once
// The controller library's differential test (tests/control/replay.c) needs, per step, the exact
// inputs fragsim hands a strategy and the forces it applied. ControlDump records them through a
// RecordingStrategy wrapped around the real one, and writes them as one binary file, whole or not
// at all (AtomicFile). Doubles are stored as their bytes, so a replay sees the same bits.
//
// The format, native byte order (written and read on one machine), no padding between fields:
//   header  char magic[8] = "FSCDUMP2"; uint32 byte_order = 0x01020304; uint32 def_size;
//           uint32 step_count; uint32 reserved = 0;
//           the fragsim_controller_def that stands for the scene's strategy and parameters
//           (api/def_mapping.hpp, the library's own mapping), its def_size bytes as they are,
//           then zero bytes up to a multiple of 8
//   step    int32 step; int32 fragment_count; int32 force_count; int32 reserved = 0;
//           double context[32] = t, dt, end_time (+inf in the tool), eye[3], right[3], up[3],
//           forward[3], fovy_deg,
//             aspect, near, far, camera_velocity[3], V_c, max_accel, max_turn_degps,
//             body_half[3], gravity[3], ground_height;
//           fragment_count x double[8] = position[3], velocity[3], radius, mass;
//           fragment_count x uint8 touched, then zero bytes up to a multiple of 8;
//           force_count x { int32 fragment; int32 reserved = 0; double force_N[3] }
// Fragment ids are their indices (the tool's fragments never come or go).

#include <cstdint>
#include <string>
#include <string_view>

#include "io/atomic_file.hpp"
#include "sim/scene.hpp"
#include "strategies/scene_strategy.hpp"

namespace fragsim {

class ControlDump {
 public:
  // The strategies the library holds; other names throw std::invalid_argument.
  static bool supports(std::string_view strategy);
  // Throws std::runtime_error naming the path if the file cannot be created.
  ControlDump(const std::string& path, std::string_view strategy, const Scene& scene);

  void record(const StepContext& ctx, const StepOutput& out);
  // Writes the file; throws naming the path on failure.
  void commit();
  int steps() const { return steps_; }

 private:
  template <class T>
  void put(const T& v);

  AtomicFile file_;
  std::string bytes_;
  int steps_ = 0;
  std::size_t step_count_at_ = 0;  // where the header's step_count is
};

// Runs `inner` and records what it was given and what it answered.
class RecordingStrategy final : public SceneStrategy {
 public:
  RecordingStrategy(SceneStrategy& inner, ControlDump& dump) : inner_(inner), dump_(dump) {}
  std::string name() const override { return inner_.name(); }
  WorldNeeds needs() const override { return inner_.needs(); }
  void reset(int fragment_count) override { inner_.reset(fragment_count); }
  void step(const StepContext& ctx, SceneStepOutput& out) override {
    inner_.step(ctx, out);
    dump_.record(ctx, out);
  }

 private:
  SceneStrategy& inner_;
  ControlDump& dump_;
};

}  // namespace fragsim
