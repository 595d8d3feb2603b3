#include "render/frame_recorder.hpp"

#include <algorithm>
#include <cassert>

namespace fragsim {

RecordedFrame::RecordedFrame(const StepSnapshot& snap)
    : step(snap.step),
      t_s(snap.t_s),
      camera(snap.camera),
      camera_velocity_mps(snap.camera_velocity_mps),
      camera_body_half_m(snap.camera_body_half_m),
      fragments(snap.fragments.begin(), snap.fragments.end()),
      forces(snap.forces.begin(), snap.forces.end()),
      candidates(snap.candidates.begin(), snap.candidates.end()),
      capped(snap.capped.begin(), snap.capped.end()),
      camera_hits(snap.camera_hits.begin(), snap.camera_hits.end()),
      opacity(snap.opacity.begin(), snap.opacity.end()) {}

StepSnapshot RecordedFrame::view() const {
  StepSnapshot s;
  s.step = step;
  s.t_s = t_s;
  s.camera = camera;
  s.camera_velocity_mps = camera_velocity_mps;
  s.camera_body_half_m = camera_body_half_m;
  s.fragments = fragments;
  s.forces = forces;
  s.candidates = candidates;
  s.capped = capped;
  s.camera_hits = camera_hits;
  s.opacity = opacity;
  return s;
}

FrameRecorder::FrameRecorder(std::vector<int> steps) : steps_(std::move(steps)) {
  std::sort(steps_.begin(), steps_.end());
  steps_.erase(std::unique(steps_.begin(), steps_.end()), steps_.end());
}

void FrameRecorder::begin(const RunInfo& info, const StepSnapshot& initial) {
  auto it = std::find_if(runs_.begin(), runs_.end(),
                         [&](const Run& r) { return r.strategy == info.strategy; });
  if (it == runs_.end()) {
    runs_.push_back({info.strategy, {}, {}});
    it = runs_.end() - 1;
  }
  current_ = &*it;
  current_->frames.clear();
  current_->shapes.clear();
  keep(initial);
}

void FrameRecorder::observe(const StepSnapshot& snap) {
  keep(snap);
}

void FrameRecorder::keep(const StepSnapshot& snap) {
  assert(current_ && "begin() names the run");
  if (std::binary_search(steps_.begin(), steps_.end(), snap.step)) {
    RecordedFrame& frame = current_->frames.emplace_back(snap);
    for (FragmentState& f : frame.fragments) {
      if (!f.shape) continue;
      std::shared_ptr<const ConvexShape>& copy = current_->shapes[f.shape];
      if (!copy) copy = std::make_shared<const ConvexShape>(*f.shape);
      f.shape = copy.get();
    }
  }
}

std::vector<std::string> FrameRecorder::strategies() const {
  std::vector<std::string> names;
  for (const Run& r : runs_) names.push_back(r.strategy);
  return names;
}

const std::vector<RecordedFrame>* FrameRecorder::frames(const std::string& strategy) const {
  for (const Run& r : runs_) {
    if (r.strategy == strategy) return &r.frames;
  }
  return nullptr;
}

const RecordedFrame* FrameRecorder::frame(const std::string& strategy, int step) const {
  const std::vector<RecordedFrame>* fs = frames(strategy);
  if (!fs) return nullptr;
  for (const RecordedFrame& f : *fs) {
    if (f.step == step) return &f;
  }
  return nullptr;
}

}  // namespace fragsim
