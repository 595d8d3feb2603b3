#pragma once
// One controller of the C API, with the strategy it runs (the same compiled classes fragsim runs),
// the fragments it keeps by id between calls, and the work space of its steps.
//
// A step runs in two phases. The first checks the input and makes room (every allocation that
// depends on the fragment count happens here); it changes no state, so a refusal or a failed
// allocation leaves the controller as it was. The second runs the strategy in that room, which
// allocates nothing; should it still run out of memory (the occlusion bound, edge-min's
// cover_max < 1, allocates as it steps), the re-indexing by id is undone, or, where the strategy
// had already changed its state, every fragment is forgotten and the message says so.
//
// Everything it allocates, itself included, comes from its HookResource (the def's allocator hook,
// or operator new and delete). The strategies run in the frame of the step's ground normal
// (GroundFrame); the state they keep per fragment lives in that frame, so a step with another
// normal than the last successful one forgets every fragment first.
//
// Each camera has its own strategy and state, run as for one camera. With several cameras their
// pushes on a fragment are then joined (JointPush in joint_push.hpp), edge-min's by rounds of
// probes that ask each camera for its least extra push on the pushed path. A step with another
// camera count than the last successful one forgets every fragment first, like a new normal, as the
// strategies of the cameras added have no state for them.
//
// With the def's task system (TaskSystem) the strategies run their per-fragment work in ranges on
// the game's workers; the answer is the same for any worker count.

#include <cstdint>
#include <memory>
#include <vector>

#include "control/api/hook_resource.hpp"
#include "control/api/id_table.hpp"
#include "control/api/input_checks.hpp"
#include "control/api/joint_push.hpp"
#include "control/api/task_system.hpp"
#include "control/geometry/fragment_state.hpp"
#include "control/memory/memory_resource.hpp"
#include "control/strategies/strategy.hpp"
#include "fragsim/control.h"

namespace fragsim {
class EdgeStrategy;
class EdgeMinStrategy;
}  // namespace fragsim

namespace fragsim::control {

class GroundFrame;

// Destroys a strategy allocated from a controller's resource.
struct StrategyDelete {
  MemoryResource* mem = nullptr;
  std::size_t size = 0;
  std::size_t align = 0;
  void operator()(Strategy* s) const noexcept;
};
using StrategyPtr = std::unique_ptr<Strategy, StrategyDelete>;

// One camera's strategy, its answer of the step, and its constants when set on the controller.
struct CameraSlot {
  explicit CameraSlot(MemoryResource* mem) : out(mem) {}
  StrategyPtr strategy;
  EdgeStrategy* edge = nullptr;         // the same object, when it keeps per-fragment state
  EdgeMinStrategy* edge_min = nullptr;  // likewise (its budget's last forces)
  StepOutput out;
  fragsim_camera_def def{};
};

class Controller {
 public:
  // A controller in memory from a valid def's allocator; throws std::bad_alloc, having freed what
  // it took, when that fails.
  static Controller* create(const fragsim_controller_def& def);
  // Destroys it and gives its memory back to the allocator it came from.
  static void destroy(Controller* c) noexcept;

  // Forgets every fragment; keeps the room made.
  void reset();
  // Room for steps of up to n fragments, every id new included. May throw std::bad_alloc,
  // changing nothing of the state.
  void reserve(std::size_t n);
  // The constants of `count` cameras (valid, in [1, FRAGSIM_MAX_CAMERAS]). May throw
  // std::bad_alloc (a new camera's strategy), changing nothing. A controller has no camera
  // before the first call.
  void set_cameras(const fragsim_camera_def* cameras, int count);

  // One step over n fragments read from `source`, forces written to `sink` (on failure the caller
  // writes zeros, in guarded_step in c_api.cpp). May throw std::bad_alloc from the first phase.
  template <class Source, class Sink>
  fragsim_status step(const fragsim_step_input& in, const Source& source, std::size_t n,
                      const Sink& sink, fragsim_step_stats* stats);

  const char* error() const { return error_; }
  // A fixed buffer, so storing a message allocates nothing and cannot fail (a longer one is cut).
  void set_error(const char* why) noexcept;
  void clear_error() noexcept { error_[0] = '\0'; }

 private:
  explicit Controller(const fragsim_controller_def& def);
  ~Controller() = default;
  Controller(const Controller&) = delete;
  Controller& operator=(const Controller&) = delete;

  template <class S, class Params>
  StrategyPtr make_strategy(const Params& params, S** made);
  // A camera's strategy as the def says; its room made for room_ fragments.
  CameraSlot make_slot();

  fragsim_status failed(const Failure& f);
  // reserve() but for the id tables.
  void reserve_work(std::size_t n);
  void warn_once(std::uint32_t warnings, const fragsim_camera_def& camera,
                 const fragsim_camera_pose& pose);
  // One camera of this step, its constants and pose, in the strategies' frame.
  StepContext context_for(const fragsim_step_input& in, const fragsim_camera_def& camera,
                          const fragsim_camera_pose& pose, const GroundFrame& frame,
                          std::size_t m) const;
  void undo_carry_over(int cameras);

  // The stages of step(), in order, and what they pass on (StepState, in the .cpp). Those that can
  // fail set the error and return its status.
  struct StepState;
  // The cameras set and the step's input checked.
  fragsim_status check_input(const fragsim_step_input& in);
  // The usable fragments into states_ (in the strategies' frame), caller_index_ and ids_now_.
  template <class Source>
  void read_fragments(const fragsim_step_input& in, const Source& source, std::size_t n,
                      const GroundFrame& frame, StepState& this_step);
  // Which fragment of the last step each one was (previous_), refusing a duplicate id.
  fragsim_status match_ids(StepState& this_step);
  void make_contexts(const fragsim_step_input& in, const GroundFrame& frame,
                     StepState& this_step) const;
  // The strategies' state carried over to this step's ids, then each camera's strategy and their
  // join; out of memory rolls the carry-over back, or forgets every fragment.
  fragsim_status run_strategies(StepState& this_step);
  void carry_over_ids(const StepState& this_step);
  void ask_cameras(StepState& this_step);
  // The answer refused, and every fragment forgotten, when the workers broke the task system's
  // contract or a force is not finite.
  fragsim_status check_answer(const StepState& this_step);
  // The forces into the caller's places, back in the world's frame; the rest of the sink zeros.
  template <class Sink>
  void write_forces(const GroundFrame& frame, std::size_t n, const Sink& sink,
                    StepState& this_step) const;
  // The state the next step starts from: its ids, ground normal and camera count.
  void remember_step(const fragsim_step_input& in, const StepState& this_step);
  int count_unprotected() const;
  std::uint32_t warn(const fragsim_step_input& in, const StepState& this_step);
  void write_stats(const StepState& this_step, std::uint32_t warnings,
                   fragsim_step_stats& stats) const;

  HookResource hook_;  // first, as everything below is allocated from it
  MemoryResource* mem_ = &hook_;
  fragsim_controller_def def_;
  // The game's workers, when the def gives a task system.
  TaskSystem tasks_;
  const ParallelFor* parallel_ = nullptr;
  // slots_[0] always; more from set_cameras (room for FRAGSIM_MAX_CAMERAS made at creation, so
  // the slots never move).
  ResourceVector<CameraSlot> slots_{mem_};
  int camera_count_ = 0;   // cameras set by set_cameras (0 if none yet, and a step is refused)
  int last_cameras_ = 1;   // cameras of the last successful step
  JointPush joint_{mem_};  // several cameras' pushes joined
  bool undo_safe_ = true;  // a failure inside the strategy's step changed nothing
  char error_[Failure::kMessageSize] = {};
  std::uint32_t warned_ = 0;  // FRAGSIM_WARNING_* bits seen (printed once each in debug builds)

  // Work space kept between calls. The fragments usable this step, in the caller's order with the
  // skipped ones left out: their states (in the strategies' frame), their places in the caller's
  // arrays and their ids.
  ResourceVector<FragmentState> states_{mem_};
  ResourceVector<std::int32_t> caller_index_{mem_};
  ResourceVector<std::uint64_t> ids_now_{mem_};
  ResourceVector<int> previous_{mem_};  // this step's fragment k was previous_[k] last step, or -1
  StepOutput out_{mem_};  // the step's answer (slots_[0].out's for one camera, joint_'s for more)
  std::size_t room_ = 0;  // the fragment count reserve() made room for

  // The state kept between calls is the last successful step's ids, in order and as a table (the
  // other table is this step's), and the ground normal the strategies' state is in (if none, any
  // first step is in its frame).
  IdTable ids_[2] = {IdTable(mem_), IdTable(mem_)};
  int last_ = 0;
  ResourceVector<std::uint64_t> last_ids_{mem_};
  fragsim_vec3 last_normal_ = {0.0, 0.0, 0.0};
  bool has_normal_ = false;
};

}  // namespace fragsim::control
