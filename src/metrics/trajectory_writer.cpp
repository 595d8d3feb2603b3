#include "metrics/trajectory_writer.hpp"

#include "geometry/orientation.hpp"
#include "io/number_format.hpp"

namespace fragsim {

const char* TrajectoryWriter::header() {
  return "strategy,step,t_s,fragment,x_m,y_m,z_m,vx_mps,vy_mps,vz_mps,candidate,fx_N,fy_N,fz_N,qx,"
         "qy,"
         "qz,qw\n";
}

TrajectoryWriter::TrajectoryWriter(std::ostream& out) : out_(out) {
  out_ << header();
}

void TrajectoryWriter::begin(const RunInfo& info, const StepSnapshot& initial) {
  strategy_ = info.strategy;
  candidate_.assign(static_cast<std::size_t>(info.fragment_count), 0);
  force_N_.assign(static_cast<std::size_t>(info.fragment_count), Eigen::Vector3d::Zero());
  write(initial);
}

void TrajectoryWriter::observe(const StepSnapshot& snap) {
  for (int i : snap.candidates) candidate_[static_cast<std::size_t>(i)] = 1;
  for (const AppliedForce& f : snap.forces)
    force_N_[static_cast<std::size_t>(f.fragment)] = f.force_N;
  write(snap);
  // Clear only what was set, so a step costs what the strategy touched, not the fragment count.
  for (int i : snap.candidates) candidate_[static_cast<std::size_t>(i)] = 0;
  for (const AppliedForce& f : snap.forces) {
    force_N_[static_cast<std::size_t>(f.fragment)] = Eigen::Vector3d::Zero();
  }
}

void TrajectoryWriter::end() {
  out_ << buffer_;
  buffer_.clear();
}

void TrajectoryWriter::write(const StepSnapshot& snap) {
  const std::string prefix =
      strategy_ + "," + std::to_string(snap.step) + "," + format_double(snap.t_s) + ",";
  for (std::size_t i = 0; i < snap.fragments.size(); ++i) {
    const FragmentState& f = snap.fragments[i];
    buffer_ += prefix;
    buffer_ += std::to_string(i);
    for (const Eigen::Vector3d* v : {&f.position_m, &f.velocity_mps}) {
      for (int k = 0; k < 3; ++k) {
        buffer_ += ',';
        append_double(buffer_, (*v)[k]);
      }
    }
    buffer_ += candidate_[i] ? ",1" : ",0";
    for (int k = 0; k < 3; ++k) {
      buffer_ += ',';
      append_double(buffer_, force_N_[i][k]);
    }
    const Eigen::Quaterniond q = orientation_quaternion(f.rotation);
    for (double c : {q.x(), q.y(), q.z(), q.w()}) {
      buffer_ += ',';
      append_double(buffer_, c);
    }
    buffer_ += '\n';
  }
  if (buffer_.size() > (1u << 20)) {
    out_ << buffer_;
    buffer_.clear();
  }
}

}  // namespace fragsim
