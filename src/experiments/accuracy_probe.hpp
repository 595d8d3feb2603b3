#pragma once
// What `fragsim bench` compares between a configuration and the reference run: fragment positions
// at shared sample times, which fragments the strategy ever took for candidates, and how far the
// strategy's predictor was off when each fragment first touched something. It is an observer and
// only reads snapshots.

#include <Eigen/Core>
#include <vector>

#include "control/strategies/collision_prediction.hpp"
#include "sim/run_observer.hpp"

namespace fragsim {

class AccuracyProbe final : public RunObserver {
 public:
  // Positions are kept every sample_dt_s, which must be a whole number of the run's steps (the
  // bench samples at 1/30 s, a multiple of every dt it tries). `predictor` is the one whose error
  // is measured (the strategy's own, for the time-vs-error table).
  AccuracyProbe(double sample_dt_s, Predictor predictor);

  void begin(const RunInfo& info, const StepSnapshot& initial) override;
  void observe(const StepSnapshot& snap) override;

  // samples()[j][i] is fragment i at t = (j + 1) sample_dt_s.
  const std::vector<std::vector<Eigen::Vector3d>>& samples() const { return samples_; }
  const std::vector<char>& ever_candidate() const { return ever_candidate_; }
  // The end of each fragment's flight, the time of the step in which it first touched something
  // (its positions before then are pure flight), or infinity if it never did.
  const std::vector<double>& first_contact_s() const { return first_contact_s_; }

  // The prediction made at t = 0, evaluated at the last step before the fragment first touched the
  // ground, the camera or anything else, against where the simulation had it then. Only fragments
  // no strategy force had pushed by then, as a pushed path is not ballistic.
  int predicted_contacts() const { return predicted_contacts_; }
  double prediction_error_mean_m() const;
  double prediction_error_max_m() const { return prediction_error_max_m_; }

 private:
  double sample_dt_s_;
  Predictor predictor_;
  int stride_ = 1;
  double dt_s_ = 0.0;
  std::vector<BallisticPath> paths_;
  std::vector<Eigen::Vector3d> previous_m_;
  std::vector<char> forced_;
  std::vector<double> first_contact_s_;
  std::vector<char> ever_candidate_;
  std::vector<std::vector<Eigen::Vector3d>> samples_;
  int predicted_contacts_ = 0;
  double prediction_error_sum_m_ = 0.0;
  double prediction_error_max_m_ = 0.0;
};

}  // namespace fragsim
