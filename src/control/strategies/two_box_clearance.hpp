#pragma once
// edge-min's cheap rejection (docs/method.md section 4), the protected box and the robust camera
// models' grown box in one pass. What every cheap rejection promises is in cheap_rejection.hpp.

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <span>

#include "control/geometry/fragment_state.hpp"
#include "control/memory/memory_resource.hpp"
#include "control/strategies/box_clearance.hpp"
#include "control/strategies/parallel_for.hpp"

namespace fragsim {

// edge-min's whole rejection in one pass over the fragments, of the protected box and, for the
// robust camera models, the grown box, each over the fragment's own look-ahead rather than one
// interval for all. A fragment's interval is edge-min's (EdgeMinStrategy::time_to_ground_s), until
// its path y(t) = y + v_y t + half_gy t^2 comes down through ground + radius, within [floor, cap],
// here bounded from above (the .cpp's HorizonBound) so never shorter than the solve's, and a
// fragment at rest on the ground is examined for one step instead of the cap. The grown box's
// interval is the smaller of that and the robust models' window.
//
// Two tiers. First, over every fragment, a distance bound in world coordinates (no change of axes),
// as a path that stays farther from the frame's origin than the box's farthest corner plus the
// fragment's radius cannot touch the box (the argument is at its test in the .cpp). Then, for the
// fragments it leaves in doubt, path_clears_box in the frame's axes for each box. Both only ever
// answer "certainly clear".
class TwoBoxClearance {
 public:
  // The first tier four lanes wide where the processor has AVX2, else two (the same answers).
  explicit TwoBoxClearance(MemoryResource* mem = default_memory_resource());
  // For tests, false keeps to the narrow lanes even where the wide ones are available.
  void use_wide_lanes(bool wide);
  struct Boxes {
    BoxFrame frame;                                    // the protected box's frame
    Eigen::Vector3d a_mps2 = Eigen::Vector3d::Zero();  // half the acceleration, in the frame's axes
    Eigen::Vector3d lo_m = Eigen::Vector3d::Zero();
    Eigen::Vector3d hi_m = Eigen::Vector3d::Zero();
    // Each path's interval is max(min(time to the ground, cap), floor).
    double cap_s = 0.0;
    double floor_s = 0.0;
    double ground_m = 0.0;      // -infinity for no ground
    double half_gy_mps2 = 0.0;  // half the world acceleration's y (the ground's normal)
    // The grown box is the protected box grown by grow_lo_m below lo and grow_hi_m above hi (per
    // axis, each >= 0), seen from a frame with the protected box's origin and axes but velocity
    // grown_velocity_mps, over at most window_s.
    bool grown = false;
    Eigen::Vector3d grown_velocity_mps = Eigen::Vector3d::Zero();
    Eigen::Vector3d grow_lo_m = Eigen::Vector3d::Zero();
    Eigen::Vector3d grow_hi_m = Eigen::Vector3d::Zero();
    double window_s = 0.0;
    // The window in `pieces` equal pieces (0 for none), for the paths the whole window leaves in
    // doubt. Piece j covers [window_s j / pieces, window_s (j + 1) / pieces] and grows each side by
    // piece_grow_*_m[j], at least the growth at the piece's end (the growth only increases with
    // time). A path clear of each piece's box over that piece's times is clear of the grown box.
    // The growth at the window's end is the most, and passing early it is far less.
    static constexpr int kMaxPieces = 4;
    int pieces = 0;
    std::array<Eigen::Vector3d, kMaxPieces> piece_grow_lo_m{};
    std::array<Eigen::Vector3d, kMaxPieces> piece_grow_hi_m{};
  };
  void run(std::span<const FragmentState> fragments, const Boxes& boxes);
  // The same answers, the fragments cut into chunks of kChunk that run in ranges on `parallel`'s
  // workers (on the calling thread when it is nullptr). Each chunk writes its own fragments' flags
  // and its own slice of the unsettled list, which are joined in chunk order afterwards. Every
  // fragment's answer is its own, whatever its neighbours (the lanes' tests promise it), and a
  // chunk starts on a whole group of four, so each fragment even goes through the same lanes as in
  // run(). Allocates nothing after reserve() and set_workers() for as many workers as `parallel`
  // has; it grows the work spaces on the calling thread otherwise.
  void run(std::span<const FragmentState> fragments, const Boxes& boxes,
           const ParallelFor* parallel);
  // Fragments per chunk, a whole number of groups of four, and enough that a chunk's start (its
  // second tier's constants) costs little beside it.
  static constexpr std::int32_t kChunk = 512;
  // Room for runs over up to n fragments, so such a run allocates nothing.
  void reserve(std::size_t n);
  // A work space for each of `workers` chunks running at once (the run with a ParallelFor).
  void set_workers(int workers);
  // One flag per fragment, 1 when its path clears the protected box (clears) or the grown box
  // (grown_clears, all 1 without a grown box). Valid until the next run.
  std::span<const char> clears() const { return {clears_.data(), size_}; }
  std::span<const char> grown_clears() const { return {grown_clears_.data(), size_}; }
  // The fragments not cleared of both, in increasing order.
  std::span<const std::int32_t> unsettled() const { return {unsettled_.data(), unsettled_count_}; }
  // The largest radius of the run's fragments (0 for none).
  double max_radius_m() const { return max_radius_m_; }
  // How many fragments the first tier left to the second.
  std::size_t first_tier_doubts() const { return doubts_; }

  // What one pass of both tiers over some fragments works in (all of them for run(), a chunk on
  // one worker for the run with a ParallelFor). Public only for the .cpp's free functions.
  struct WorkSpace {
    explicit WorkSpace(MemoryResource* mem)
        : doubt(mem),
          groups(mem),
          kept(mem),
          verdicts(mem),
          piece_rows(mem),
          piece_lanes(mem),
          unsettled(mem) {}
    // Room for a pass over n fragments, every page touched (`unsettled` aside).
    void reserve(std::size_t n);
    // Sized for a pass over n fragments, within reserve()'s room after it (`unsettled` aside).
    void size_for(std::size_t n);

    ResourceVector<std::int32_t> doubt;   // fragments the first tier left in doubt
    ResourceVector<std::int32_t> groups;  // groups of four with one in doubt (wide lanes)
    // For each of those groups, what the first tier found, kept for the second rather than gathered
    // and tested again, as four lanes of each of its numbers (positions relative to the frame,
    // velocities, radii, intervals), and which lanes it cleared of which box (then the second
    // tier's verdict).
    ResourceVector<double> kept;
    ResourceVector<std::int32_t> verdicts;
    // The lanes left for the grown box's pieces, packed into full groups of four, with their
    // numbers row by row and each one's group and lane.
    ResourceVector<double> piece_rows;
    ResourceVector<std::int32_t> piece_lanes;
    // A chunk's unsettled fragments, before they go to the run's list (kChunk entries, in the
    // chunked run's work spaces only).
    ResourceVector<std::int32_t> unsettled;
    // Whether the next pass's first loop keeps them, set when the last pass left more than a few
    // groups in doubt (at first yes, as an explosion's first step has all in doubt). It changes how
    // fast a pass is, never what it answers.
    bool keep_rows = true;
  };

 private:
  // What one chunk found besides its flags, for the join.
  struct ChunkResult {
    std::size_t unsettled = 0;
    std::size_t doubts = 0;
    double max_radius_m = 0.0;
  };
  // Sets the flags to "clear" and the counts to zero for a run over n fragments.
  void start_run(std::size_t n);
  // The chunks' unsettled slices, counts and radii joined in chunk order.
  void join_chunks(std::size_t chunks);

  std::size_t size_ = 0;
  MemoryResource* mem_;
  ResourceVector<char> clears_{mem_};
  ResourceVector<char> grown_clears_{mem_};
  [[maybe_unused]] bool wide_ = false;       // unused where there are no wide lanes
  WorkSpace whole_{mem_};                    // run()'s, for every fragment at once
  ResourceVector<WorkSpace> workers_{mem_};  // the chunked run's, one per worker
  ResourceVector<ChunkResult> chunks_{mem_};
  ResourceVector<std::int32_t> unsettled_{mem_};
  std::size_t unsettled_count_ = 0;
  std::size_t doubts_ = 0;
  double max_radius_m_ = 0.0;
};

// The first tier's bound on the interval of one path (TwoBoxClearance::Boxes), at least
// max(min(EdgeMinStrategy::time_to_ground_s(y, v_y, half_gy, ground_m), cap), floor). For tests.
double interval_bound_s(double y_m, double vy_mps, double half_gy_mps2, double ground_m,
                        double cap_s, double floor_s);

}  // namespace fragsim
