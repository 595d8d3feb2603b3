#pragma once
// Cheap, conservative tests that settle, before any root solve, that a fragment's ballistic path
// cannot meet a region: the camera's reachable ball (`edge`, docs/method.md section 3) or the
// protected box (`edge-min`, section 4). They only ever answer "certainly clear"; anything in
// doubt goes on to the exact solve, so the strategies' results do not change. Each keeps a margin
// far beyond the root solver's rounding (first_root.hpp judges "touching" within ~1e-15 of the
// terms' size): a path these call clear, the exact solve also finds clear.
//
// Each test comes twice: for one path, and batched (BallClearance, BoxClearance) with the same
// answers, as passes over many paths two at a time without a branch on the data inside a pass,
// so the processor overlaps paths instead of waiting on each one's latency chain.

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "geometry/fragment_state.hpp"
#include "geometry/parabola.hpp"
#include "memory/memory_resource.hpp"
#include "strategies/parallel_for.hpp"

namespace fragsim {

// The one-path tests take the path relative to the region's centre (Parabola::relative_to),
// x(t) = d + v t + a t^2 with d = p0, v = v0 and a half its acceleration, for t in [0, t_end];
// the batched ones take d and v per path and the half acceleration a (`a_mps2`) shared by all.

// True when |x(t)| > r0 + growth t for every t in [0, t_end]: the path certainly stays outside
// the ball (fixed when growth = 0, growing otherwise). Q(t) = |x(t)|^2 - (r0 + growth t)^2 is a
// quartic; its Bernstein coefficients on an interval bound it there (the convex hull property),
// so all of them above the margin prove Q > 0. The whole interval first, then halves, quarters
// and eighths of it (de Casteljau's subdivision), only where still in doubt. False when in doubt
// (non-finite input, t_end < 0, a path that starts inside or is inside at a piece's end).
bool path_clears_ball(const Parabola& path, double r0_m, double growth_mps, double t_end_s);

// path_clears_ball for many paths under one acceleration and one growth.
class BallClearance {
 public:
  explicit BallClearance(MemoryResource* mem = default_memory_resource()) : mem_(mem) {}
  // Room for n paths, then each one set by index.
  void resize(std::size_t n);
  // Room for runs over up to n paths, set later by resize: such a run allocates nothing while at
  // most two pieces per path stay in doubt.
  void reserve(std::size_t n);
  void set(std::size_t i, const Eigen::Vector3d& d_m, const Eigen::Vector3d& v_mps, double r0_m,
           double t_end_s) {
    set_path(i, d_m, v_mps);
    set_ball(i, r0_m, t_end_s);
  }
  // The same in two parts, for a caller that knows the ball only after the path.
  void set_path(std::size_t i, const Eigen::Vector3d& d_m, const Eigen::Vector3d& v_mps) {
    dx_[i] = d_m.x();
    dy_[i] = d_m.y();
    dz_[i] = d_m.z();
    vx_[i] = v_mps.x();
    vy_[i] = v_mps.y();
    vz_[i] = v_mps.z();
  }
  void set_ball(std::size_t i, double r0_m, double t_end_s) {
    r0_[i] = r0_m;
    t_end_[i] = t_end_s;
  }
  std::size_t size() const { return size_; }
  // One flag per path, in order: 1 when it clears its ball. Valid until the next call.
  std::span<const char> run(const Eigen::Vector3d& a_mps2, double growth_mps);

 private:
  // A piece of a path in doubt: the path and Q's five Bernstein coefficients on the piece.
  struct Piece {
    std::int32_t path;
    double b[5];
  };
  std::size_t size_ = 0;
  MemoryResource* mem_;
  // Padded to whole lanes.
  ResourceVector<double> dx_{mem_}, dy_{mem_}, dz_{mem_}, vx_{mem_}, vy_{mem_}, vz_{mem_},
      r0_{mem_}, t_end_{mem_};
  ResourceVector<double> tol_{mem_};
  ResourceVector<char> clears_{mem_};
  ResourceVector<Piece> pieces_{mem_};
  ResourceVector<Piece> next_{mem_};
};

// The axis-aligned box lo <= x(t) <= hi (per coordinate). True when no t in [0, t_end] has all
// three coordinates inside it: first each coordinate's range over the whole interval (ends and
// vertex), then the x and y ranges over the times z is inside its slab. False when in doubt.
bool path_clears_box(const Parabola& path, const Eigen::Vector3d& lo_m, const Eigen::Vector3d& hi_m,
                     double t_end_s);

// A moving frame for BoxClearance: paths given in world coordinates are seen from it, x along
// axes[0], y along axes[1], z along axes[2] (a camera's right, up and forward).
struct BoxFrame {
  Eigen::Vector3d origin_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d axes[3] = {Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(),
                             Eigen::Vector3d::UnitZ()};
  Eigen::Vector3d velocity_mps = Eigen::Vector3d::Zero();
};

// path_clears_box for many fragments, whose paths are given in world coordinates, seen from one
// frame, under one acceleration (in the frame's axes), against one box grown per fragment by its
// bounding radius, over one interval. A first stage (x's range alone) runs over every fragment,
// straight from their states, the full test over those it left in doubt.
class BoxClearance {
 public:
  explicit BoxClearance(MemoryResource* mem = default_memory_resource()) : mem_(mem) {}
  // One flag per fragment: 1 when, in `frame`, its path x(t) = position + velocity t + a t^2
  // clears lo - radius <= x(t) <= hi + radius. Valid until the next call.
  std::span<const char> run(std::span<const FragmentState> fragments, const BoxFrame& frame,
                            const Eigen::Vector3d& a_mps2, const Eigen::Vector3d& lo_m,
                            const Eigen::Vector3d& hi_m, double t_end_s);

 private:
  MemoryResource* mem_;
  ResourceVector<char> clears_{mem_};
  ResourceVector<std::int32_t> doubt_{mem_};  // fragments the first stage left in doubt
};

// edge-min's whole rejection in one pass over the fragments: the protected box and, for the
// robust camera models, the grown box, each over the fragment's own look-ahead rather than one
// interval for all. A fragment's interval is edge-min's (EdgeMinStrategy::time_to_ground_s):
// until its path y(t) = y + v_y t + half_gy t^2 comes down through ground + radius, within
// [floor, cap]; computed here with the same operations in the same order, so the same number, and
// a fragment at rest on the ground is examined for one step instead of the cap. The grown box's
// interval is the smaller of that and the robust models' window.
//
// Two tiers. First, over every fragment, a distance bound in world coordinates (no change of
// axes): a path that stays farther from the frame's origin than the box's farthest corner plus
// the fragment's radius cannot touch the box (the argument is at its test in the .cpp). Then, for
// the fragments it leaves in doubt, path_clears_box in the frame's axes for each box. Both only
// ever answer "certainly clear".
class TwoBoxClearance {
 public:
  // The first tier four lanes wide where the processor has AVX2, else two (the same answers).
  explicit TwoBoxClearance(MemoryResource* mem = default_memory_resource());
  // For tests: the narrow lanes even where the wide ones are available (false).
  void use_wide_lanes(bool wide);
  struct Boxes {
    BoxFrame frame;                                    // the protected box's frame
    Eigen::Vector3d a_mps2 = Eigen::Vector3d::Zero();  // half the acceleration, in the frame's axes
    Eigen::Vector3d lo_m = Eigen::Vector3d::Zero();
    Eigen::Vector3d hi_m = Eigen::Vector3d::Zero();
    // Each path's interval: max(min(time to the ground, cap), floor).
    double cap_s = 0.0;
    double floor_s = 0.0;
    double ground_m = 0.0;      // -infinity: no ground
    double half_gy_mps2 = 0.0;  // half the world acceleration's y (the ground's normal)
    // The grown box: the protected box grown by grow_lo_m below lo and grow_hi_m above hi (per
    // axis, each >= 0), seen from a frame with the protected box's origin and axes but velocity
    // grown_velocity_mps, over at most window_s.
    bool grown = false;
    Eigen::Vector3d grown_velocity_mps = Eigen::Vector3d::Zero();
    Eigen::Vector3d grow_lo_m = Eigen::Vector3d::Zero();
    Eigen::Vector3d grow_hi_m = Eigen::Vector3d::Zero();
    double window_s = 0.0;
    // The window in `pieces` equal pieces (0: none), for the paths the whole window leaves in
    // doubt: piece j covers [window_s j / pieces, window_s (j + 1) / pieces] and grows each side
    // by piece_grow_*_m[j], at least the growth at the piece's end (the growth only increases
    // with time). A path clear of each piece's box over that piece's times is clear of the
    // grown box: the growth at the window's end is the most, and passing early it is far less.
    static constexpr int kMaxPieces = 4;
    int pieces = 0;
    std::array<Eigen::Vector3d, kMaxPieces> piece_grow_lo_m{};
    std::array<Eigen::Vector3d, kMaxPieces> piece_grow_hi_m{};
  };
  void run(std::span<const FragmentState> fragments, const Boxes& boxes);
  // The same answers, the fragments cut into chunks of kChunk that run in ranges on `parallel`'s
  // workers (on the calling thread when it is nullptr). Each chunk writes its own fragments'
  // flags and its own slice of the unsettled list, which are joined in chunk order afterwards:
  // every fragment's answer is its own, whatever its neighbours (the lanes' tests promise it),
  // and a chunk starts on a whole group of four, so each fragment even goes through the same
  // lanes as in run(). Allocates nothing after reserve() and set_workers() for as many workers
  // as `parallel` has; it grows the work spaces on the calling thread otherwise.
  void run(std::span<const FragmentState> fragments, const Boxes& boxes,
           const ParallelFor* parallel);
  // Fragments per chunk: a whole number of groups of four, and enough that a chunk's start (its
  // second tier's constants) costs little beside it.
  static constexpr std::int32_t kChunk = 512;
  // Room for runs over up to n fragments: such a run allocates nothing.
  void reserve(std::size_t n);
  // A work space for each of `workers` chunks running at once (the run with a ParallelFor).
  void set_workers(int workers);
  // One flag per fragment: 1 when its path clears the protected box (clears), the grown box
  // (grown_clears; all 1 without a grown box). Valid until the next run.
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
    // For each of those groups, what the first tier found, kept for the second rather than
    // gathered and tested again: four lanes of each of its numbers (positions relative to the
    // frame, velocities, radii, intervals), and which lanes it cleared of which box (then the
    // second tier's verdict).
    ResourceVector<double> kept;
    ResourceVector<std::int32_t> verdicts;
    // The lanes left for the grown box's pieces, packed into full groups of four: their numbers,
    // row by row, and each one's group and lane.
    ResourceVector<double> piece_rows;
    ResourceVector<std::int32_t> piece_lanes;
    // A chunk's unsettled fragments, before they go to the run's list (the chunked run's work
    // spaces only: kChunk entries).
    ResourceVector<std::int32_t> unsettled;
    // Whether the next pass's first loop keeps them: the last pass left more than a few groups
    // in doubt (at first yes, as an explosion's first step has all in doubt). It changes how fast
    // a pass is, never what it answers.
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

// The first tier's bound on the interval of one path (TwoBoxClearance::Boxes): at least
// max(min(EdgeMinStrategy::time_to_ground_s(y, v_y, half_gy, ground_m), cap), floor). For tests.
double interval_bound_s(double y_m, double vy_mps, double half_gy_mps2, double ground_m,
                        double cap_s, double floor_s);

}  // namespace fragsim
