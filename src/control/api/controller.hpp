#pragma once
// One controller of the C API: the strategy it runs (the same compiled classes fragsim runs), the
// fragments it keeps by id between calls, and the work space of its steps.
//
// A step runs in two phases. The first checks the input and makes room (every allocation that
// depends on the fragment count happens here); it changes no state, so a refusal or a failed
// allocation leaves the controller as it was. The second runs the strategy in that room, which
// allocates nothing; should it still run out of memory (the occlusion bound, edge-min's
// cover_max < 1, allocates as it steps), the re-indexing by id is undone, or, where the strategy
// had already changed its state, every fragment is forgotten and the message says so.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "api/id_table.hpp"
#include "api/input_checks.hpp"
#include "fragsim/control.h"
#include "geometry/fragment_state.hpp"
#include "strategies/strategy.hpp"

namespace fragsim {
class EdgeStrategy;
class EdgeMinStrategy;
}  // namespace fragsim

namespace fragsim::control {

class Controller {
 public:
  explicit Controller(const fragsim_controller_def& def);

  // Forgets every fragment; keeps the room made.
  void reset();
  // Room for steps of up to n fragments, every id new included. May throw std::bad_alloc,
  // changing nothing of the state.
  void reserve(std::size_t n);

  // One step over n fragments read from `source`, forces written to `sink` (zeros on failure are
  // the caller's: see guarded_step in c_api.cpp). May throw std::bad_alloc from the first phase.
  template <class Source, class Sink>
  fragsim_status step(const fragsim_step_input& in, const Source& source, std::size_t n,
                      const Sink& sink, fragsim_step_stats* stats);

  const std::string& error() const { return error_; }
  // Never throws: a message that cannot be stored is dropped (the status still says why).
  void set_error(const char* why) noexcept {
    try {
      error_ = why;
    } catch (...) {
      error_.clear();
    }
  }
  void clear_error() { error_.clear(); }

 private:
  fragsim_status failed(Failure f);
  // reserve() but for the id tables.
  void reserve_work(std::size_t n);
  void warn_once(std::uint32_t warnings, const fragsim_camera& camera);

  std::unique_ptr<Strategy> strategy_;
  EdgeStrategy* edge_ = nullptr;         // the same object, when it keeps per-fragment state
  EdgeMinStrategy* edge_min_ = nullptr;  // likewise (its budget's last forces)
  bool undo_safe_ = true;                // a failure inside the strategy's step changed nothing
  std::string error_;
  std::uint32_t warned_ = 0;  // FRAGSIM_WARNING_* bits seen (printed once each in debug builds)

  // Work space kept between calls. The fragments usable this step, in the caller's order with the
  // skipped ones left out: their states, their places in the caller's arrays and their ids.
  std::vector<FragmentState> states_;
  std::vector<std::int32_t> caller_index_;
  std::vector<std::uint64_t> ids_now_;
  std::vector<int> previous_;  // this step's fragment k was previous_[k] at the last step, or -1
  StepOutput out_;
  std::size_t room_ = 0;  // the fragment count reserve() made room for

  // The state kept between calls: the last successful step's ids, in order, and as a table; the
  // other table is this step's.
  IdTable ids_[2];
  int last_ = 0;
  std::vector<std::uint64_t> last_ids_;
};

}  // namespace fragsim::control
