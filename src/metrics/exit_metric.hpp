#pragma once
// Exits and near misses (docs/method.md section 6). A fragment is on screen when its centre lies in
// the view frustum of that snapshot's camera. When it goes from on screen to off screen between two
// snapshots its exit is the near plane (its depth is then short of the near distance, or behind the
// eye) or else the border its centre is furthest past; a later re-entry and exit replaces the
// earlier one. A near miss is a centre path passing within near_miss_m of the eye by a fragment
// whose box (for a convex piece, the polytope for the near rectangle and its hull's camera-aligned
// box for the camera body, never its looser body box) never met the near rectangle or the camera
// body (swept_box.hpp, or the physics' sensor). That is the fly-by that makes the shot, not a clip.
// The centre is a convex piece's centre of mass. The same exits are also counted over the pushed
// fragments alone (any force in any step), as a strategy changes only their exits, so their shares
// show where it sends debris (edge-min.edge_weights).

#include <string_view>
#include <vector>

#include "geometry/swept_box.hpp"
#include "metrics/run_summary.hpp"
#include "sim/run_observer.hpp"
#include "sim/scene.hpp"

namespace fragsim {

// How a fragment left the screen. kNone is never on screen, kStayed on screen at the last snapshot.
enum class Exit { kNone, kTop, kBottom, kLeft, kRight, kNear, kStayed };

// Lower-case name for CSV columns: "none", "top", "bottom", "left", "right", "near", "stayed".
std::string_view exit_name(Exit exit);

class ExitMetric final : public RunObserver {
 public:
  explicit ExitMetric(const MetricsDef& def) : near_miss_m_(def.near_miss_m) {}

  void begin(const RunInfo& info, const StepSnapshot& initial) override;
  void observe(const StepSnapshot& snap) override;
  void fill(RunSummary& summary) const;

  int fragments() const { return static_cast<int>(prev_.size()); }
  // As of the last snapshot observed.
  Exit exit(int fragment) const {
    const auto i = static_cast<std::size_t>(fragment);
    return on_screen_[i] ? Exit::kStayed : last_exit_[i];
  }
  bool near_miss(int fragment) const {
    const auto i = static_cast<std::size_t>(fragment);
    return passed_close_[i] && !touched_[i];
  }
  // Whether the fragment met the near rectangle or the camera body.
  bool touched(int fragment) const { return touched_[static_cast<std::size_t>(fragment)] != 0; }
  // Whether the strategy gave the fragment a force in any step so far.
  bool pushed(int fragment) const { return pushed_[static_cast<std::size_t>(fragment)] != 0; }

 private:
  // Whether the piece met the near rectangle between the two snapshots (its sweep ends ea, eb).
  bool meets_near(const CameraPose& camera_a, const FragmentState& a, const CameraPose& camera_b,
                  const FragmentState& b, const SweepEnd& ea, const SweepEnd& eb);

  double near_miss_m_;
  std::vector<SweepEnd> prev_;
  std::vector<FragmentState> prev_state_;  // the last snapshot's convex pieces (boxes not copied)
  CameraPose prev_camera_;
  HullSweep hull_sweep_;
  std::vector<char> on_screen_;
  std::vector<Exit> last_exit_;
  std::vector<char> passed_close_;
  std::vector<char> touched_;
  std::vector<char> pushed_;
};

}  // namespace fragsim
