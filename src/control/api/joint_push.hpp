#pragma once
// Several cameras' pushes on the same fragments, joined into one force per fragment.
//
// Each camera's strategy has answered as if it were the only camera. A fragment none of them pushes
// is clear of every camera. For one that some push, edge-min's answers are joined in rounds,
// starting from the largest push (its camera is clear by construction); then each camera not known
// to be clear is asked, through a probe (edge-min with the controller's parameters, without the
// budget or the occlusion bound, so it keeps no state between calls), for its least extra push on
// the path the push so far makes; a camera that asks for nothing is clear, one that asks for more
// gets it added, and every other camera must be asked again. All clear within FRAGSIM_CAMERA_ROUNDS
// rounds, the joint push keeps the fragment off every camera as edge-min's one-camera push keeps it
// off one. Otherwise the fragment is a conflict, reported; its force is the last round's, capped at
// a_max like any edge-min force.
//
// A probe sees the pushed path exactly as edge-min planned it, since a constant push a from this
// step on moves a fragment by a (t^2 + t dt) / 2 under semi-implicit Euler (the displacement
// edge-min's least push is solved with), which is the path of gravity g + a from velocity
// v + a dt / 2. So the probe, with no new predictor, runs on that one fragment with those two
// changed.
//
// edge and deflect-all, whose forces are not least pushes, add the cameras' forces.

#include <Eigen/Core>
#include <cstdint>
#include <span>
#include <vector>

#include "control/memory/memory_resource.hpp"
#include "control/strategies/edge_min_params.hpp"
#include "control/strategies/strategy.hpp"

namespace fragsim {
class EdgeMinStrategy;
}

namespace fragsim::control {

class JointPush {
 public:
  explicit JointPush(MemoryResource* mem);
  ~JointPush();
  JointPush(const JointPush&) = delete;
  JointPush& operator=(const JointPush&) = delete;

  // edge-min's rounds need the probe, made once (may throw std::bad_alloc, changing nothing).
  void make_probe(const EdgeMinParams& params);
  bool has_probe() const { return probe_ != nullptr; }
  // Room for steps of up to n fragments. May throw std::bad_alloc.
  void reserve(std::size_t n);

  struct Conflicts {
    int count = 0;
    int first = -1;  // the lowest fragment index among them (-1 if none)
  };
  // Joins the cameras' answers (outs[j] for contexts[j], over `fragments`) into `out`, which
  // arrives cleared: forces, candidates and capped (each fragment once), guarded and deferred
  // summed, rejected_cheaply the least over the cameras. Rounds only with the probe (edge-min).
  // Allocates nothing within the room made.
  Conflicts join(std::span<const StepContext> contexts, std::span<const StepOutput* const> outs,
                 std::span<const FragmentState> fragments, StepOutput& out);

 private:
  // The extra acceleration the camera of `ctx` asks for on fragment f's path pushed by accel (zero
  // if clear), and whether the probe had to cap it.
  Eigen::Vector3d extra_push(const StepContext& ctx, const FragmentState& f,
                             const Eigen::Vector3d& accel_mps2, bool* capped);
  // edge-min's rounds for one fragment from the largest push; true when every camera is clear.
  bool settle(std::span<const StepContext> contexts, const FragmentState& f, int owner,
              Eigen::Vector3d& accel_mps2);
  void touch(int k);

  MemoryResource* mem_;
  EdgeMinStrategy* probe_ = nullptr;  // from mem_
  double a_max_mps2_ = 0.0;
  StepOutput probe_out_;
  // Per fragment, reset after each join (only the entries in touched_), the force so far, the
  // camera of the largest push (-1 if none), and marks (bit j for camera j's candidate, kCapped).
  ResourceVector<Eigen::Vector3d> force_N_;
  ResourceVector<std::int8_t> owner_;
  ResourceVector<std::uint16_t> marks_;
  ResourceVector<std::int32_t> touched_;
};

}  // namespace fragsim::control
