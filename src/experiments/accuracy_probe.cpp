#include "experiments/accuracy_probe.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "sim/scene.hpp"

namespace fragsim {

AccuracyProbe::AccuracyProbe(double sample_dt_s, Predictor predictor)
    : sample_dt_s_(sample_dt_s), predictor_(predictor) {}

void AccuracyProbe::begin(const RunInfo& info, const StepSnapshot& initial) {
  dt_s_ = info.dt_s;
  const double ratio = sample_dt_s_ / dt_s_;
  stride_ = static_cast<int>(std::lround(ratio));
  if (stride_ < 1 || std::abs(ratio - stride_) > 1e-6 * ratio) {
    throw std::invalid_argument(
        "accuracy probe: the sample interval is not a whole number of steps");
  }
  const std::size_t n = initial.fragments.size();
  paths_.clear();
  paths_.reserve(n);
  previous_m_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    paths_.push_back(
        predicted_path(initial.fragments[i], info.scene->sim.gravity_mps2, predictor_, dt_s_));
    previous_m_[i] = initial.fragments[i].position_m;
  }
  forced_.assign(n, 0);
  first_contact_s_.assign(n, std::numeric_limits<double>::infinity());
  ever_candidate_.assign(n, 0);
  samples_.clear();
  predicted_contacts_ = 0;
  prediction_error_sum_m_ = 0.0;
  prediction_error_max_m_ = 0.0;
}

void AccuracyProbe::observe(const StepSnapshot& snap) {
  // A contact found in the step that led here acted during that step, so the position one step
  // earlier is still pure flight, and that is where the prediction is checked.
  const double tau_s = (snap.step - 1) * dt_s_;
  auto check = [&](std::size_t i) {
    if (first_contact_s_[i] != std::numeric_limits<double>::infinity()) return;
    first_contact_s_[i] = snap.t_s;
    if (forced_[i]) return;
    const double err_m = (paths_[i].at(tau_s) - previous_m_[i]).norm();
    ++predicted_contacts_;
    prediction_error_sum_m_ += err_m;
    prediction_error_max_m_ = std::max(prediction_error_max_m_, err_m);
  };
  for (std::size_t i = 0; i < snap.fragments.size(); ++i) {
    if (snap.fragments[i].touched) check(i);
  }
  for (int i : snap.camera_hits) check(static_cast<std::size_t>(i));
  // Forces of this step moved the positions at this step, not the one checked above.
  for (const AppliedForce& f : snap.forces) forced_[static_cast<std::size_t>(f.fragment)] = 1;
  for (int i : snap.candidates) ever_candidate_[static_cast<std::size_t>(i)] = 1;

  for (std::size_t i = 0; i < snap.fragments.size(); ++i) {
    previous_m_[i] = snap.fragments[i].position_m;
  }
  if (snap.step % stride_ == 0) {
    samples_.push_back(previous_m_);
  }
}

double AccuracyProbe::prediction_error_mean_m() const {
  return predicted_contacts_ > 0 ? prediction_error_sum_m_ / predicted_contacts_ : 0.0;
}

}  // namespace fragsim
