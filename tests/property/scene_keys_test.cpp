// The property test over the scene keys: random legal values of every key that has a range (or a
// list of choices), several keys at once, extremes favoured, each case a short comparison of
// `none` and one strategy in a child process. No case may abort, hang or leave a non-finite
// number in its outputs; a case refused with one line (InputError) is fine, but most must run.
//
// The keys and their ranges are read from the keys' own rules (the message each gives a value
// out of range), so a key added to the table is covered without a word here.
//
// FRAGSIM_SCENE_KEYS_CASES (default 500) and FRAGSIM_SCENE_KEYS_SEED (default 1) choose the cases
// (scripts/soak_scene_keys.sh runs 10,000); a failure prints the case as a fragsim command line.

#include <gtest/gtest.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <optional>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include "experiments/evaluation.hpp"
#include "io/input_error.hpp"
#include "report/csv_export.hpp"
#include "sim/scene_file.hpp"
#include "strategies/registry.hpp"

namespace fragsim {
namespace {

// What a key takes, as its rule says.
struct KeyRule {
  enum class Kind { kReal, kInteger, kSeed, kVector, kChoice } kind = Kind::kReal;
  std::string name;
  double lo = 0.0, hi = 0.0;
  bool lo_open = false, hi_open = false;
  int count = 1;                     // kVector: how many numbers
  bool inf_allowed = false;          // real_or_inf: "inf" is legal too
  std::vector<std::string> choices;  // kChoice (booleans: on, off)
};

// The message a key gives `value`, or empty if it takes it.
std::string message_for(const std::string& key, const std::string& value) {
  try {
    parse_scene("", "", {{key, value}});
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

double number(const std::string& text) {
  return std::strtod(text.c_str(), nullptr);
}

// The interval in "... must be in [lo, hi)" at the end of `message`, with an optional
// ", or inf" after it when `inf_suffix` allows. Parsed by hand: GCC 12 warns inside <regex>
// (maybe-uninitialized) under -O1, and the sanitizer build treats warnings as errors.
bool parse_interval(const std::string& message, bool inf_suffix, KeyRule& r) {
  const std::string lead = "must be in ";
  const std::size_t at = message.find(lead);
  if (at == std::string::npos) return false;
  std::size_t i = at + lead.size();
  if (i >= message.size() || (message[i] != '[' && message[i] != '(')) return false;
  const char open = message[i++];
  const std::size_t comma = message.find(", ", i);
  if (comma == std::string::npos || comma == i) return false;
  const std::size_t close = message.find_first_of("])", comma + 2);
  if (close == std::string::npos || close == comma + 2) return false;
  std::string rest = message.substr(close + 1);
  bool inf = false;
  if (inf_suffix && rest == ", or inf") {
    inf = true;
    rest.clear();
  }
  if (!rest.empty()) return false;
  r.lo_open = open == '(';
  r.lo = number(message.substr(i, comma - i));
  r.hi = number(message.substr(comma + 2, close - comma - 2));
  r.hi_open = message[close] == ')';
  r.inf_allowed = inf;
  return true;
}

// "... must be a whole number in [lo, hi]" at the end of `message`.
bool parse_whole(const std::string& message, KeyRule& r) {
  const std::string lead = "must be a whole number in [";
  const std::size_t at = message.find(lead);
  if (at == std::string::npos || message.empty() || message.back() != ']') return false;
  const std::size_t from = at + lead.size();
  const std::size_t comma = message.find(", ", from);
  if (comma == std::string::npos) return false;
  r.lo = number(message.substr(from, comma - from));
  r.hi = number(message.substr(comma + 2, message.size() - 1 - comma - 2));
  return true;
}

// The word after "expected " and before " numbers", or empty.
std::string count_word(const std::string& message) {
  const std::string lead = "expected ";
  const std::size_t at = message.find(lead);
  if (at == std::string::npos) return "";
  const std::size_t from = at + lead.size();
  const std::size_t space = message.find(' ', from);
  if (space == std::string::npos || message.compare(space, 8, " numbers") != 0) return "";
  return message.substr(from, space - from);
}

// The key's rule, from what it says of values out of any range; nullopt for keys without one
// (names, file names, lists of points).
std::optional<KeyRule> rule_of(const std::string& key) {
  KeyRule r;
  r.name = key;
  const std::string big = message_for(key, "1e308");
  if (parse_interval(big, true, r)) {
    r.kind = KeyRule::Kind::kReal;
    return r;
  }
  if (big.find("must be a whole number in [0, 2^64)") != std::string::npos) {
    r.kind = KeyRule::Kind::kSeed;
    return r;
  }
  const std::string huge = message_for(key, "1000000000000");
  if (parse_whole(huge, r)) {
    r.kind = KeyRule::Kind::kInteger;
    return r;
  }
  // A fixed count of numbers ("expected three numbers x y z", "expected four numbers ..."),
  // each in one interval.
  const std::map<std::string, int> counts = {{"two", 2}, {"three", 3}, {"four", 4}};
  const std::string word = count_word(big);
  if (counts.count(word)) {
    r.count = counts.at(word);
    std::string many;
    for (int i = 0; i < r.count; ++i) many += (i ? " " : "") + std::string("1e308");
    if (parse_interval(message_for(key, many), false, r)) {
      r.kind = KeyRule::Kind::kVector;
      return r;
    }
  }
  const std::string odd = message_for(key, "#");
  const std::size_t expected_at = odd.find(": expected ");
  if (expected_at != std::string::npos) {
    const std::string list = odd.substr(expected_at + 11);
    if (!list.empty() && list != "three numbers x y z") {
      r.kind = KeyRule::Kind::kChoice;
      if (list == "on or off") {
        r.choices = {"on", "off"};
      } else {
        for (std::size_t at = 0;;) {
          const std::size_t bar = list.find(" | ", at);
          r.choices.push_back(list.substr(at, bar - at));
          if (bar == std::string::npos) break;
          at = bar + 3;
        }
      }
      return r;
    }
  }
  return std::nullopt;
}

struct KeyTable {
  std::vector<KeyRule> ranged;
  std::vector<std::string> unranged;
};

const KeyTable& key_table() {
  static const KeyTable table = [] {
    KeyTable t;
    for (const auto& option : scene_options().options()) {
      const std::string key = option->long_name();
      if (auto r = rule_of(key)) {
        t.ranged.push_back(*r);
      } else {
        t.unranged.push_back(key);
      }
    }
    return t;
  }();
  return table;
}

std::string text_of(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

// A value of an interval, extremes favoured: its least or greatest legal value, or a random one
// (log-uniform where the interval spans more than three decades).
double draw_real(std::mt19937_64& rng, double lo, double hi, bool lo_open, bool hi_open) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const int mode = static_cast<int>(rng() % 3);
  if (mode == 0) {
    if (!lo_open) return lo;
    // Just above an open end: by a little, or by the least a double can.
    const double step = std::max(std::fabs(lo), 1.0) * std::pow(10.0, -1.0 - 9.0 * unit(rng));
    return rng() % 4 == 0 ? std::nextafter(lo, hi) : lo + step;
  }
  if (mode == 1) {
    if (!hi_open) return hi;
    return rng() % 4 == 0
               ? std::nextafter(hi, lo)
               : hi - std::max(std::fabs(hi), 1.0) * std::pow(10.0, -1.0 - 9.0 * unit(rng));
  }
  if (lo >= 0.0 && hi > 1e3 * std::max(lo, 1e-9)) {
    const double a = std::log(std::max(lo, hi * 1e-12)), b = std::log(hi);
    return std::clamp(std::exp(a + (b - a) * unit(rng)), std::nextafter(lo, hi), hi);
  }
  if (lo < 0.0 && hi > 0.0 && hi - lo > 1e3 && rng() % 2 == 0) {
    const double magnitude = std::exp(std::log(1e-6) + (std::log(hi) - std::log(1e-6)) * unit(rng));
    return std::clamp(rng() % 2 ? magnitude : -magnitude, lo, hi);
  }
  return lo + (hi - lo) * unit(rng);
}

std::string draw_value(std::mt19937_64& rng, const KeyRule& r) {
  switch (r.kind) {
    case KeyRule::Kind::kReal:
      if (r.inf_allowed && rng() % 6 == 0) return "inf";
      return text_of(draw_real(rng, r.lo, r.hi, r.lo_open, r.hi_open));
    case KeyRule::Kind::kInteger: {
      const auto lo = static_cast<long long>(r.lo), hi = static_cast<long long>(r.hi);
      const int mode = static_cast<int>(rng() % 3);
      if (mode == 0) return std::to_string(lo);
      if (mode == 1) return std::to_string(hi);
      const double x = draw_real(rng, r.lo, r.hi, false, false);
      return std::to_string(std::clamp(std::llround(x), lo, hi));
    }
    case KeyRule::Kind::kSeed: {
      const int mode = static_cast<int>(rng() % 3);
      if (mode == 0) return "0";
      if (mode == 1) return "18446744073709551615";
      return std::to_string(rng());
    }
    case KeyRule::Kind::kVector: {
      std::string v;
      for (int i = 0; i < r.count; ++i) {
        v += (i ? " " : "") + text_of(draw_real(rng, r.lo, r.hi, r.lo_open, r.hi_open));
      }
      return v;
    }
    case KeyRule::Kind::kChoice:
      return r.choices[rng() % r.choices.size()];
  }
  return "";
}

// One case: the keys it sets (in order) and the strategy compared with `none`.
struct Case {
  std::vector<SceneOverride> overrides;
  std::string strategy;
  bool occlusion = false;

  std::string command_line() const {
    std::string s = "fragsim compare --strategies none," + strategy +
                    (occlusion ? std::string() : std::string(" --no-occlusion"));
    for (const SceneOverride& o : overrides) s += " --" + o.key + " '" + o.value + "'";
    return s;
  }
};

const std::string* find(const std::map<std::string, std::string>& set, const std::string& key) {
  const auto it = set.find(key);
  return it == set.end() ? nullptr : &it->second;
}

// Kept short: at most 64 fragments and a few dozen steps, whatever the keys chose (a long run of
// legal extremes, such as 262,144 fragments or 3.6 million steps, is the user's to ask for, not
// a fault; the steps are bounded by the longest step the keys allow, 1 s, times 3,600 s).
Case make_case(std::uint64_t seed, int index) {
  std::mt19937_64 rng(seed * 0x9E3779B97F4A7C15ull + static_cast<std::uint64_t>(index));
  const KeyTable& table = key_table();
  const int count = 1 + static_cast<int>(rng() % 6);
  std::map<std::string, std::string> chosen;
  std::vector<std::string> order;
  while (static_cast<int>(chosen.size()) < count) {
    const KeyRule& r = table.ranged[rng() % table.ranged.size()];
    if (chosen.count(r.name)) continue;
    chosen[r.name] = draw_value(rng, r);
    order.push_back(r.name);
  }
  auto cap_integer = [&](const std::string& key, long long cap, long long fallback) {
    if (const std::string* v = find(chosen, key)) {
      chosen[key] = std::to_string(std::min(std::atoll(v->c_str()), cap));
    } else {
      chosen[key] = std::to_string(fallback);
      order.push_back(key);
    }
  };
  cap_integer("object.splits", 4, 2);
  cap_integer("object.pieces", 40, 8);
  cap_integer("metrics.grid_width_px", 64, 32);
  // The steps: at most 40 unless duration_s alone asks for more than 40 s (up to 3,600 steps).
  const std::string* dt = find(chosen, "simulation.dt_s");
  const std::string* duration = find(chosen, "simulation.duration_s");
  constexpr double kSteps = 40.0;
  if (dt && duration) {
    const double d = number(*dt);
    if (number(*duration) / d > kSteps) chosen["simulation.duration_s"] = text_of(d * kSteps);
  } else if (dt) {
    chosen["simulation.duration_s"] = text_of(std::min(3600.0, number(*dt) * kSteps));
    order.push_back("simulation.duration_s");
  } else if (duration) {
    chosen["simulation.dt_s"] = text_of(std::min(1.0, number(*duration) / kSteps));
    order.push_back("simulation.dt_s");
  } else {
    chosen["simulation.duration_s"] = "0.25";
    order.push_back("simulation.duration_s");
  }
  Case c;
  for (const std::string& key : order) c.overrides.push_back({key, chosen[key]});
  const std::vector<std::string>& names = strategy_names();
  c.strategy = names[rng() % names.size()];
  c.occlusion = rng() % 2 == 0;
  return c;
}

enum class Outcome { kRan, kRefused, kFailed };

struct Result {
  Outcome outcome = Outcome::kFailed;
  std::string detail;
};

// Every cell of summary.csv and every per-step number: finite, or the case fails.
std::string non_finite_in(const Scene& scene, const std::vector<Evaluation>& runs) {
  const std::string csv = summary_csv(scene, runs);
  for (const char* bad : {"nan", "inf", "NaN", "Inf"}) {
    if (csv.find(bad) != std::string::npos) return "summary.csv holds '" + std::string(bad) + "'";
  }
  for (const Evaluation& e : runs) {
    if (e.summary.health.nonfinite_fragments != 0) {
      return e.summary.strategy + ": " + std::to_string(e.summary.health.nonfinite_fragments) +
             " fragments went non-finite";
    }
    for (const std::vector<double>* series :
         {&e.occlusion_per_step, &e.central_occlusion_per_step}) {
      for (double v : *series) {
        if (!std::isfinite(v)) return e.summary.strategy + ": a non-finite occlusion";
      }
    }
    for (const CameraPose& p : e.camera) {
      if (!p.eye_m.allFinite() || !p.forward.allFinite()) {
        return e.summary.strategy + ": a non-finite camera pose";
      }
    }
  }
  return "";
}

// The case in a child process: an abort or a hang there is a finding here, not the end of the
// test. The child writes one line: "ran", "refused: why" or "failed: why".
Result run_case(const Case& c, double limit_s) {
  int fds[2];
  if (pipe(fds) != 0) return {Outcome::kFailed, "pipe failed"};
  std::fflush(nullptr);
  const pid_t pid = fork();
  if (pid < 0) return {Outcome::kFailed, "fork failed"};
  if (pid == 0) {
    close(fds[0]);
    std::string line;
    try {
      const Scene scene = parse_scene("", "", c.overrides);
      const std::vector<Evaluation> runs = compare(scene, {"none", c.strategy}, c.occlusion);
      const std::string bad = non_finite_in(scene, runs);
      line = bad.empty() ? "ran" : "failed: " + bad;
    } catch (const std::invalid_argument& e) {  // InputError, and bad strategy parameters
      line = std::string("refused: ") + e.what();
    } catch (const std::exception& e) {
      line = std::string("failed: exception: ") + e.what();
    }
    line += "\n";
    const ssize_t written = write(fds[1], line.data(), line.size());
    _exit(written == static_cast<ssize_t>(line.size()) ? 0 : 3);
  }
  close(fds[1]);
  std::string out;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(limit_s);
  bool hung = false;
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      hung = true;
      break;
    }
    pollfd p{fds[0], POLLIN, 0};
    const int ready = poll(&p, 1, static_cast<int>(std::min<long long>(left.count(), 1000)));
    if (ready < 0 && errno == EINTR) continue;
    if (ready <= 0) continue;
    char buf[4096];
    const ssize_t n = read(fds[0], buf, sizeof buf);
    if (n <= 0) break;
    out.append(buf, static_cast<std::size_t>(n));
  }
  close(fds[0]);
  if (hung) kill(pid, SIGKILL);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (hung) return {Outcome::kFailed, "hang: no answer within " + text_of(limit_s) + " s"};
  if (WIFSIGNALED(status)) {
    return {Outcome::kFailed, "killed by signal " + std::to_string(WTERMSIG(status)) + " " + out};
  }
  while (!out.empty() && out.back() == '\n') out.pop_back();
  if (out.rfind("ran", 0) == 0) return {Outcome::kRan, ""};
  if (out.rfind("refused: ", 0) == 0) {
    const std::string why = out.substr(9);
    if (why.find('\n') != std::string::npos)
      return {Outcome::kFailed, "refusal of more than one line: " + why};
    return {Outcome::kRefused, why};
  }
  return {Outcome::kFailed,
          out.empty() ? "exit status " + std::to_string(WEXITSTATUS(status)) : out};
}

long env_number(const char* name, long fallback) {
  const char* v = std::getenv(name);
  return v && *v ? std::atol(v) : fallback;
}

TEST(SceneKeys, EveryRangedKeyIsFound) {
  const KeyTable& t = key_table();
  // The keys without a range are the free texts and lists of points; anything else is a key
  // whose rule this test could not read.
  const std::set<std::string> free_text = {"name",
                                           "object.mesh_file",
                                           "camera.waypoints_m",
                                           "camera.look_at_m",
                                           "camera.track_file",
                                           "camera.track_strategy"};
  for (const std::string& k : t.unranged) {
    EXPECT_TRUE(free_text.count(k)) << k << ": its rule could not be read from its message";
  }
  EXPECT_GE(t.ranged.size(), 60u);
}

TEST(SceneKeys, RandomLegalValuesRunOrAreRefusedWithOneLine) {
  const long cases = env_number("FRAGSIM_SCENE_KEYS_CASES", 500);
  const auto seed = static_cast<std::uint64_t>(env_number("FRAGSIM_SCENE_KEYS_SEED", 1));
  const double limit_s = static_cast<double>(env_number("FRAGSIM_SCENE_KEYS_LIMIT_S", 60));
  long ran = 0, refused = 0, failed = 0;
  std::map<std::string, long> refusals;  // by the message's first words, for the summary
  const auto start = std::chrono::steady_clock::now();
  for (long i = 0; i < cases; ++i) {
    const Case c = make_case(seed, static_cast<int>(i));
    const Result r = run_case(c, limit_s);
    switch (r.outcome) {
      case Outcome::kRan:
        ++ran;
        break;
      case Outcome::kRefused:
        ++refused;
        ++refusals[r.detail.substr(0, std::min(r.detail.find(' '), r.detail.find(':')))];
        break;
      case Outcome::kFailed:
        ++failed;
        ADD_FAILURE() << "case " << i << " (seed " << seed << "): " << r.detail << "\n  "
                      << c.command_line();
        break;
    }
  }
  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("scene keys: %ld cases (seed %llu): %ld ran, %ld refused, %ld failed, %.1f s\n",
              cases, static_cast<unsigned long long>(seed), ran, refused, failed, wall_s);
  for (const auto& [why, n] : refusals) std::printf("  refused %5ld x %s\n", n, why.c_str());
  EXPECT_GE(ran, cases / 2) << "most legal cases must run, not be refused";
}

}  // namespace
}  // namespace fragsim
