#include "control/api/joint_push.hpp"

#include <algorithm>
#include <new>

#include "control/geometry/vec3_sums.hpp"
#include "control/strategies/edge_min_strategy.hpp"
#include "fragsim/control.h"

namespace fragsim::control {
namespace {

constexpr std::uint16_t kCapped = 1u << 8;
constexpr std::uint16_t kTouched = 1u << 9;
constexpr std::uint16_t kCandidateBits = 0xFF;
static_assert(FRAGSIM_MAX_CAMERAS <= 8, "one candidate bit per camera");

// A probe's answer this small against the push so far is rounding, since the pushed path grazes the
// grown box's edge by construction, and the probe's roots see it from either side.
bool negligible(const Eigen::Vector3d& extra, const Eigen::Vector3d& accel) {
  return norm3(extra) <= 1e-9 * std::max(1.0, norm3(accel));
}

}  // namespace

JointPush::JointPush(MemoryResource* mem)
    : mem_(mem), probe_out_(mem), force_N_(mem), owner_(mem), marks_(mem), touched_(mem) {}

JointPush::~JointPush() {
  if (probe_ == nullptr) return;
  probe_->~EdgeMinStrategy();
  mem_->deallocate(probe_, sizeof(EdgeMinStrategy), alignof(EdgeMinStrategy));
}

void JointPush::make_probe(const EdgeMinParams& params) {
  if (probe_ != nullptr) return;
  EdgeMinParams p = params;
  p.max_solves = 0;   // a budget keeps forces by index between calls
  p.cover_max = 1.0;  // the occlusion bound keeps state, and is about the view, not the lens
  probe_out_.reserve(1);
  void* memory = mem_->allocate(sizeof(EdgeMinStrategy), alignof(EdgeMinStrategy));
  try {
    auto* probe = new (memory) EdgeMinStrategy(p, mem_);
    try {
      probe->reserve(1);
      probe->reset(0);
    } catch (...) {
      probe->~EdgeMinStrategy();
      throw;
    }
    probe_ = probe;
  } catch (...) {
    mem_->deallocate(memory, sizeof(EdgeMinStrategy), alignof(EdgeMinStrategy));
    throw;
  }
  a_max_mps2_ = params.a_max_mps2;
}

void JointPush::reserve(std::size_t n) {
  // Each grows on its own, so a failed allocation half way leaves the others to grow next time.
  if (force_N_.size() < n) force_N_.resize(n, Eigen::Vector3d::Zero());
  if (owner_.size() < n) owner_.resize(n, -1);
  if (marks_.size() < n) marks_.resize(n, 0);
  touched_.reserve(n);
}

void JointPush::touch(int k) {
  const auto i = static_cast<std::size_t>(k);
  if ((marks_[i] & kTouched) == 0) touched_.push_back(k);
  marks_[i] |= kTouched;
}

Eigen::Vector3d JointPush::extra_push(const StepContext& ctx, const FragmentState& f,
                                      const Eigen::Vector3d& accel_mps2, bool* capped) {
  FragmentState pushed = f;
  pushed.velocity_mps += 0.5 * ctx.dt_s * accel_mps2;
  StepContext c = ctx;
  c.gravity_mps2 += accel_mps2;
  c.fragments = std::span<const FragmentState>(&pushed, 1);
  probe_out_.clear();
  probe_->step(c, probe_out_);
  *capped = !probe_out_.activity.capped.empty();
  if (probe_out_.forces.empty()) return Eigen::Vector3d::Zero();
  return probe_out_.forces.front().force_N / f.mass_kg;
}

bool JointPush::settle(std::span<const StepContext> contexts, const FragmentState& f, int owner,
                       Eigen::Vector3d& accel_mps2) {
  const auto n = static_cast<int>(contexts.size());
  const unsigned all = (1u << n) - 1u;
  unsigned clear = 1u << owner;
  for (int round = 0; round < FRAGSIM_CAMERA_ROUNDS && clear != all; ++round) {
    for (int j = 0; j < n; ++j) {
      if ((clear & (1u << j)) != 0) continue;
      bool capped = false;
      const Eigen::Vector3d extra =
          extra_push(contexts[static_cast<std::size_t>(j)], f, accel_mps2, &capped);
      if (negligible(extra, accel_mps2)) {
        clear |= 1u << j;
        continue;
      }
      accel_mps2 += extra;
      // Its least extra push clears camera j unless the cap cut it; every other camera must be
      // asked again about the new path.
      clear = capped ? 0u : 1u << j;
    }
  }
  return clear == all;
}

JointPush::Conflicts JointPush::join(std::span<const StepContext> contexts,
                                     std::span<const StepOutput* const> outs,
                                     std::span<const FragmentState> fragments, StepOutput& out) {
  const bool rounds = probe_ != nullptr && contexts.size() > 1;
  out.activity.rejected_cheaply = static_cast<int>(fragments.size());
  for (std::size_t j = 0; j < outs.size(); ++j) {
    const StepOutput& o = *outs[j];
    for (const int k : o.activity.candidates) {
      touch(k);
      marks_[static_cast<std::size_t>(k)] |= static_cast<std::uint16_t>(1u << j);
    }
    for (const int k : o.activity.capped) {
      touch(k);
      marks_[static_cast<std::size_t>(k)] |= kCapped;
    }
    for (const AppliedForce& a : o.forces) {
      touch(a.fragment);
      const auto i = static_cast<std::size_t>(a.fragment);
      if (!rounds) {
        force_N_[i] += a.force_N;
        owner_[i] = static_cast<std::int8_t>(j);
      } else if (owner_[i] < 0 || squared_norm3(a.force_N) > squared_norm3(force_N_[i])) {
        force_N_[i] = a.force_N;
        owner_[i] = static_cast<std::int8_t>(j);
      }
    }
    out.activity.guarded += o.activity.guarded;
    out.activity.deferred += o.activity.deferred;
    out.activity.rejected_cheaply =
        std::min(out.activity.rejected_cheaply, o.activity.rejected_cheaply);
  }

  Conflicts conflicts;
  for (const std::int32_t k : touched_) {
    const auto i = static_cast<std::size_t>(k);
    if ((marks_[i] & kCandidateBits) != 0) out.activity.candidates.push_back(k);
    if (owner_[i] >= 0) {
      const FragmentState& f = fragments[i];
      Eigen::Vector3d force_N = force_N_[i];
      if (rounds && f.mass_kg > 0.0) {
        Eigen::Vector3d accel_mps2 = force_N / f.mass_kg;
        if (!settle(contexts, f, owner_[i], accel_mps2)) {
          ++conflicts.count;
          if (conflicts.first < 0 || k < conflicts.first) conflicts.first = k;
        }
        const double a = norm3(accel_mps2);
        if (a > a_max_mps2_) {
          accel_mps2 *= a_max_mps2_ / a;
          marks_[i] |= kCapped;
        }
        force_N = f.mass_kg * accel_mps2;
      }
      out.forces.push_back({k, force_N});
    }
    if ((marks_[i] & kCapped) != 0) out.activity.capped.push_back(k);
    force_N_[i] = Eigen::Vector3d::Zero();
    owner_[i] = -1;
    marks_[i] = 0;
  }
  touched_.clear();
  return conflicts;
}

}  // namespace fragsim::control
