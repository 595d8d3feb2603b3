#include "experiments/evaluation_codec.hpp"

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <type_traits>

#include "metrics/run_summary.hpp"

namespace fragsim {
namespace {

class Writer {
 public:
  template <typename T>
  void put(const T& v) {
    static_assert(std::is_arithmetic_v<T>);
    out.append(reinterpret_cast<const char*>(&v), sizeof v);
  }
  void put(const std::string& s) {
    put<std::uint64_t>(s.size());
    out += s;
  }
  template <typename T>
  void put(const std::vector<T>& v) {
    put<std::uint64_t>(v.size());
    for (const T& x : v) put(x);
  }
  void put(const Eigen::Vector3d& v) {
    for (int k = 0; k < 3; ++k) put(v[k]);
  }
  void put(const CameraPose& c) {
    for (const Eigen::Vector3d* v : {&c.eye_m, &c.right, &c.up, &c.forward}) put(*v);
    for (double d : {c.fovy_deg, c.aspect, c.near_m, c.far_m}) put(d);
  }
  std::string out;
};

class Reader {
 public:
  explicit Reader(const std::string& s) : in_(s) {}
  template <typename T>
  void get(T& v) {
    static_assert(std::is_arithmetic_v<T>);
    need(sizeof v);
    std::memcpy(&v, in_.data() + pos_, sizeof v);
    pos_ += sizeof v;
  }
  void get(std::string& s) {
    std::uint64_t n = 0;
    get(n);
    need(n);
    s.assign(in_, pos_, n);
    pos_ += n;
  }
  template <typename T>
  void get(std::vector<T>& v) {
    std::uint64_t n = 0;
    get(n);
    if (n > in_.size()) throw std::runtime_error("evaluation bytes: bad length");
    v.resize(n);
    for (T& x : v) get(x);
  }
  void get(Eigen::Vector3d& v) {
    for (int k = 0; k < 3; ++k) get(v[k]);
  }
  void get(CameraPose& c) {
    for (Eigen::Vector3d* v : {&c.eye_m, &c.right, &c.up, &c.forward}) get(*v);
    for (double* d : {&c.fovy_deg, &c.aspect, &c.near_m, &c.far_m}) get(*d);
  }
  bool at_end() const { return pos_ == in_.size(); }

 private:
  void need(std::uint64_t n) const {
    if (in_.size() - pos_ < n) throw std::runtime_error("evaluation bytes: truncated");
  }
  const std::string& in_;
  std::size_t pos_ = 0;
};

}  // namespace

std::string encode_evaluation(const Evaluation& e) {
  Writer w;
  const RunSummary& s = e.summary;
  w.put(summary_fields(s));
  for (double d : {s.cost.physics_ms_median, s.cost.physics_ms_p95, s.cost.strategy_ms_median,
                   s.cost.strategy_ms_p95, s.cost.wall_s}) {
    w.put(d);
  }
  w.put<std::uint8_t>(e.has_deviation ? 1 : 0);
  w.put(e.near_per_step);
  w.put(e.candidates_per_step);
  w.put(e.occlusion_per_step);
  w.put(e.central_occlusion_per_step);
  w.put(e.physics_s_per_step);
  w.put(e.strategy_s_per_step);
  w.put(e.camera);
  return w.out;
}

Evaluation decode_evaluation(const std::string& bytes) {
  Reader r(bytes);
  Evaluation e;
  RunSummary& s = e.summary;
  std::vector<std::string> fields;
  r.get(fields);
  set_summary_fields(s, fields);
  for (double* d : {&s.cost.physics_ms_median, &s.cost.physics_ms_p95, &s.cost.strategy_ms_median,
                    &s.cost.strategy_ms_p95, &s.cost.wall_s}) {
    r.get(*d);
  }
  std::uint8_t dev = 0;
  r.get(dev);
  e.has_deviation = dev != 0;
  r.get(e.near_per_step);
  r.get(e.candidates_per_step);
  r.get(e.occlusion_per_step);
  r.get(e.central_occlusion_per_step);
  r.get(e.physics_s_per_step);
  r.get(e.strategy_s_per_step);
  r.get(e.camera);
  if (!r.at_end()) throw std::runtime_error("evaluation bytes: trailing data");
  return e;
}

std::string encode_evaluations(const std::vector<Evaluation>& evaluations) {
  Writer w;
  w.put<std::uint64_t>(evaluations.size());
  for (const Evaluation& e : evaluations) w.put(encode_evaluation(e));
  return w.out;
}

std::vector<Evaluation> decode_evaluations(const std::string& bytes) {
  Reader r(bytes);
  std::vector<std::string> each;
  r.get(each);
  if (!r.at_end()) throw std::runtime_error("evaluation bytes: trailing data");
  std::vector<Evaluation> out;
  out.reserve(each.size());
  for (const std::string& one : each) out.push_back(decode_evaluation(one));
  return out;
}

}  // namespace fragsim
