#include "experiments/sweep.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <set>
#include <sstream>

#include "experiments/evaluation_codec.hpp"
#include "experiments/process_runner.hpp"
#include "experiments/shard.hpp"
#include "io/number_format.hpp"
#include "io/trim.hpp"

namespace fragsim {
namespace {

// Splits on `sep`, keeping empty items so "1,,2" can be reported rather than silently read.
std::vector<std::string> split_keep_empty(const std::string& text, char sep) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (true) {
    const auto at = text.find(sep, start);
    out.push_back(text.substr(start, at == std::string::npos ? std::string::npos : at - start));
    if (at == std::string::npos) return out;
    start = at + 1;
  }
}

std::optional<double> to_number(const std::string& text) {
  const std::string s = trim(text);
  double v = 0.0;
  const auto res = std::from_chars(s.data(), s.data() + s.size(), v);
  if (s.empty() || res.ec != std::errc() || res.ptr != s.data() + s.size() || !std::isfinite(v)) {
    return std::nullopt;
  }
  return v;
}

// Digits after the decimal point as written, or -1 when the number has an exponent (then the
// written decimals say nothing about the value's precision).
int written_decimals(const std::string& text) {
  if (text.find_first_of("eE") != std::string::npos) return -1;
  const auto dot = text.find('.');
  return dot == std::string::npos ? 0 : static_cast<int>(text.size() - dot - 1);
}

// lo + i step as text, rounded to the decimals the user wrote, so 0.1 + 2 * 0.1 reads 0.3, as the
// exact value of a decimal range has no more decimals than lo and step. Then written as the
// shortest text that reads back the same (number_format.hpp), as scene files write numbers.
std::string range_value(double v, int decimals) {
  if (decimals >= 0 && decimals <= 17) {
    char buf[400];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    v = std::strtod(buf, nullptr);
  }
  if (v == 0.0) v = 0.0;  // no "-0" from a range through zero
  return format_double(v);
}

void check_value_text(const std::string& value) {
  if (value.empty()) throw SweepError("empty value");
  if (value.find_first_of("\"\r\n") != std::string::npos) {
    throw SweepError("value '" + value + "': no quotes or line breaks");
  }
}

std::vector<std::string> parse_range(const std::string& spec) {
  const std::vector<std::string> parts = split_keep_empty(spec, ':');
  if (parts.size() != 3) throw SweepError("range '" + spec + "': expected lo:hi:step");
  double num[3];
  for (int k = 0; k < 3; ++k) {
    const auto v = to_number(parts[k]);
    if (!v) {
      throw SweepError("range '" + spec + "': '" + trim(parts[k]) +
                       "' is not a number (ranges are for numeric keys; list other values, "
                       "vectors too, with commas: KEY=0 1.6 -5,0 1.6 -7)");
    }
    num[k] = *v;
  }
  const double lo = num[0], hi = num[1], step = num[2];
  if (step <= 0.0) throw SweepError("range '" + spec + "': step must be > 0");
  if (hi < lo) throw SweepError("range '" + spec + "': hi must be >= lo");
  const double r = (hi - lo) / step;
  if (!std::isfinite(r) || r >= static_cast<double>(kMaxRangeValues)) {
    throw SweepError("range '" + spec + "': more than " + std::to_string(kMaxRangeValues) +
                     " values");
  }
  // The tolerance keeps hi when (hi - lo) / step lands just below a whole number (0.4 / 0.1).
  const auto n = static_cast<std::size_t>(std::floor(r + 1e-9 * std::max(1.0, r)));
  if (n + 1 > kMaxRangeValues) {
    throw SweepError("range '" + spec + "': more than " + std::to_string(kMaxRangeValues) +
                     " values");
  }
  const int d_lo = written_decimals(trim(parts[0]));
  const int d_step = written_decimals(trim(parts[2]));
  const int decimals = (d_lo < 0 || d_step < 0) ? -1 : std::max(d_lo, d_step);
  std::vector<std::string> out;
  out.reserve(n + 1);
  for (std::size_t i = 0; i <= n; ++i) {
    // lo + i step each time, never a running sum, so rounding does not accumulate.
    const double v = std::min(lo + static_cast<double>(i) * step, hi);
    out.push_back(range_value(v, decimals));
  }
  return out;
}

// The size of the cartesian product, checked without overflow.
std::size_t combination_count(const std::vector<SweepAxis>& axes) {
  std::size_t count = 1;
  for (const SweepAxis& a : axes) {
    if (a.values.empty()) throw SweepError(a.key + ": no values");
    if (count > kMaxSweepJobs / a.values.size()) {
      throw SweepError("more than " + std::to_string(kMaxSweepJobs) + " combinations");
    }
    count *= a.values.size();
  }
  return count;
}

}  // namespace

std::vector<std::string> parse_sweep_values(const std::string& spec) {
  const std::string s = trim(spec);
  if (s.empty()) throw SweepError("no values");
  if (s.find(':') != std::string::npos && s.find(',') == std::string::npos) return parse_range(s);
  std::vector<std::string> out;
  std::set<std::string> seen;
  for (const std::string& item : split_keep_empty(s, ',')) {
    const std::string v = trim(item);
    check_value_text(v);
    if (!seen.insert(v).second) throw SweepError("value '" + v + "' is listed twice");
    out.push_back(v);
  }
  return out;
}

SweepAxis parse_vary(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos) throw SweepError("expected KEY=SPEC");
  SweepAxis axis;
  axis.key = trim(text.substr(0, eq));
  if (axis.key.empty()) throw SweepError("expected KEY=SPEC, the key is empty");
  axis.values = parse_sweep_values(text.substr(eq + 1));
  return axis;
}

std::vector<std::uint64_t> seeds_up_to(long long n) {
  if (n < 1 || static_cast<unsigned long long>(n) > kMaxSweepJobs) {
    throw SweepError("must be a whole number in [1, " + std::to_string(kMaxSweepJobs) + "]");
  }
  std::vector<std::uint64_t> out;
  for (long long s = 1; s <= n; ++s) out.push_back(static_cast<std::uint64_t>(s));
  return out;
}

std::vector<std::uint64_t> parse_seed_list(const std::string& text) {
  std::vector<std::uint64_t> out;
  std::set<std::uint64_t> seen;
  for (const std::string& item : split_keep_empty(text, ',')) {
    const std::string s = trim(item);
    std::uint64_t seed = 0;
    const auto res = std::from_chars(s.data(), s.data() + s.size(), seed);
    if (s.empty() || res.ec != std::errc() || res.ptr != s.data() + s.size()) {
      throw SweepError("'" + s + "' is not a whole number in [0, 2^64)");
    }
    if (!seen.insert(seed).second) throw SweepError("seed " + s + " is listed twice");
    out.push_back(seed);
  }
  if (out.size() > kMaxSweepJobs) throw SweepError("too many seeds");
  return out;
}

std::vector<std::vector<std::size_t>> sweep_combinations(const std::vector<SweepAxis>& axes) {
  const std::size_t count = combination_count(axes);
  std::vector<std::vector<std::size_t>> out;
  out.reserve(count);
  std::vector<std::size_t> index(axes.size(), 0);
  for (std::size_t c = 0; c < count; ++c) {
    out.push_back(index);
    // An odometer, where the last axis turns fastest, so the first axis varies slowest.
    for (std::size_t k = axes.size(); k-- > 0;) {
      if (++index[k] < axes[k].values.size()) break;
      index[k] = 0;
    }
  }
  return out;
}

std::vector<SweepJob> sweep_jobs(const std::vector<SweepAxis>& axes,
                                 const std::vector<std::uint64_t>& seeds) {
  if (seeds.empty()) throw SweepError("no seeds");
  if (combination_count(axes) > kMaxSweepJobs / seeds.size()) {
    throw SweepError("more than " + std::to_string(kMaxSweepJobs) + " runs (combinations x seeds)");
  }
  const auto combos = sweep_combinations(axes);
  std::vector<SweepJob> jobs;
  jobs.reserve(combos.size() * seeds.size());
  for (const auto& c : combos) {
    for (std::uint64_t seed : seeds) jobs.push_back({c, seed});
  }
  return jobs;
}

std::vector<SweepOutcome> read_sweep_outcomes(const std::string& csv, const std::string& key) {
  std::istringstream in(csv);
  std::string line;
  if (!std::getline(in, line)) throw std::runtime_error("sweep CSV: no header");
  const std::vector<std::string> header = split_keep_empty(line, ',');
  auto column = [&header](const std::string& name) {
    const auto it = std::find(header.begin(), header.end(), name);
    if (it == header.end()) throw std::runtime_error("sweep CSV: no column '" + name + "'");
    return static_cast<std::size_t>(it - header.begin());
  };
  const std::size_t c_value = column(key), c_seed = column("seed"), c_strategy = column("strategy"),
                    c_near = column("near_fragments"), c_cam = column("camera_hit_fragments"),
                    c_dev = column("deviation_mean_m");
  std::vector<SweepOutcome> out;
  int number = 1;
  while (std::getline(in, line)) {
    ++number;
    const std::vector<std::string> cells = split_keep_empty(line, ',');
    if (cells.size() != header.size()) {
      throw std::runtime_error("sweep CSV:" + std::to_string(number) + ": expected " +
                               std::to_string(header.size()) + " cells");
    }
    SweepOutcome o;
    try {
      o.value = cells[c_value];
      o.seed = std::stoull(cells[c_seed]);
      o.strategy = cells[c_strategy];
      o.intersections = std::stoi(cells[c_near]) + std::stoi(cells[c_cam]);
      o.deviation_mean_m = std::stod(cells[c_dev]);
    } catch (const std::logic_error&) {
      throw std::runtime_error("sweep CSV:" + std::to_string(number) + ": unreadable number");
    }
    out.push_back(std::move(o));
  }
  return out;
}

bool sweep_values_numeric(const std::vector<SweepOutcome>& rows) {
  return std::all_of(rows.begin(), rows.end(),
                     [](const SweepOutcome& o) { return to_number(o.value).has_value(); });
}

std::vector<SweepStrategyStats> summarise_single_key(const std::vector<SweepOutcome>& rows) {
  std::vector<SweepStrategyStats> out;
  std::map<std::string, std::size_t> strategy_at;
  std::vector<std::map<std::string, std::size_t>> value_at;
  for (const SweepOutcome& o : rows) {
    auto [s, new_strategy] = strategy_at.emplace(o.strategy, out.size());
    if (new_strategy) {
      out.push_back({o.strategy, {}, std::nullopt});
      value_at.emplace_back();
    }
    SweepStrategyStats& st = out[s->second];
    auto [v, new_value] = value_at[s->second].emplace(o.value, st.values.size());
    if (new_value) st.values.push_back({o.value});
    SweepValueStats& vs = st.values[v->second];
    ++vs.seeds;
    vs.zero_seeds += o.intersections == 0 ? 1 : 0;
    vs.deviation_mean_m += o.deviation_mean_m;  // a sum until divided below
  }
  const bool numeric = sweep_values_numeric(rows);
  for (SweepStrategyStats& st : out) {
    for (SweepValueStats& vs : st.values) vs.deviation_mean_m /= vs.seeds;
    if (numeric) {
      std::stable_sort(st.values.begin(), st.values.end(),
                       [](const SweepValueStats& a, const SweepValueStats& b) {
                         return *to_number(a.value) < *to_number(b.value);
                       });
    }
    // The threshold starts the longest run of all-zero values that reaches the largest value.
    for (std::size_t i = st.values.size(); i-- > 0 && st.values[i].all_zero();) st.threshold = i;
  }
  return out;
}

std::vector<SceneOverride> sweep_overrides(const SweepPlan& plan,
                                           const std::vector<std::size_t>& value_index,
                                           std::uint64_t seed) {
  std::vector<SceneOverride> o = plan.base;
  for (std::size_t k = 0; k < plan.axes.size(); ++k) {
    o.push_back({plan.axes[k].key, plan.axes[k].values[value_index[k]]});
  }
  o.push_back({"simulation.seed", std::to_string(seed)});
  return o;
}

std::string describe_combination(const SweepPlan& plan,
                                 const std::vector<std::size_t>& value_index) {
  std::string s;
  for (std::size_t k = 0; k < plan.axes.size(); ++k) {
    s += (k > 0 ? ", " : "") + plan.axes[k].key + "=" + plan.axes[k].values[value_index[k]];
  }
  return s;
}

std::string sweep_plan_fingerprint(const SweepPlan& plan, const std::string& columns) {
  // The scene file's path is left out, because the same scene read from another folder (another
  // node's checkout) makes the same rows.
  PlanText t;
  t.add("fragsim sweep plan 1").add(plan.scene_text).add(plan.base.size());
  for (const SceneOverride& o : plan.base) t.add(o.key).add(o.value);
  t.add(plan.axes.size());
  for (const SweepAxis& a : plan.axes) {
    t.add(a.key).add(a.values.size());
    for (const std::string& v : a.values) t.add(v);
  }
  t.add(plan.jobs.size());
  for (const SweepJob& j : plan.jobs) {
    for (std::size_t i : j.value_index) t.add(i);
    t.add(j.seed);
  }
  t.add(plan.strategies.size());
  for (const std::string& n : plan.strategies) t.add(n);
  t.add(plan.occlusion ? 1u : 0u).add(columns);
  return plan_fingerprint(t.text());
}

std::string describe_sweep_job(const SweepPlan& plan, const SweepJob& job) {
  return describe_combination(plan, job.value_index) + ", seed " + std::to_string(job.seed);
}

std::vector<std::vector<Evaluation>> run_sweep(
    const SweepPlan& plan, int jobs, const std::function<void(std::size_t done)>& on_done) {
  ProcessRunOptions options;
  options.jobs = jobs;
  if (on_done) options.on_done = [&on_done](std::size_t, std::size_t done) { on_done(done); };
  options.describe = [&plan](std::size_t j) {
    return "job " + std::to_string(plan.first_job + j + 1) + " (" +
           describe_sweep_job(plan, plan.jobs[j]) + ")";
  };
  const std::vector<std::string> encoded = run_in_processes(
      plan.jobs.size(),
      [&plan](std::size_t j) {
        const SweepJob& job = plan.jobs[j];
        const Scene scene = parse_scene(plan.scene_text, plan.origin,
                                        sweep_overrides(plan, job.value_index, job.seed));
        // Summaries only, because the rows read nothing else.
        std::vector<Evaluation> summaries;
        for (const Evaluation& e : compare(scene, plan.strategies, plan.occlusion)) {
          Evaluation& one = summaries.emplace_back();
          one.summary = e.summary;
          one.has_deviation = e.has_deviation;
        }
        return encode_evaluations(summaries);
      },
      options);
  std::vector<std::vector<Evaluation>> out;
  out.reserve(encoded.size());
  for (std::size_t j = 0; j < encoded.size(); ++j) {
    out.push_back(decode_evaluations(encoded[j]));
    if (out.back().size() != plan.strategies.size()) {
      throw std::runtime_error("job " + std::to_string(plan.first_job + j + 1) + " (" +
                               describe_sweep_job(plan, plan.jobs[j]) +
                               "): strategies missing in the worker's result");
    }
  }
  return out;
}

}  // namespace fragsim
