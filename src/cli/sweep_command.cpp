#include "cli/sweep_command.hpp"

#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <set>
#include <sstream>

#include "cli/command_line.hpp"
#include "cli/table.hpp"
#include "experiments/evaluation.hpp"
#include "experiments/sweep.hpp"
#include "io/atomic_file.hpp"
#include "io/input_file.hpp"
#include "report/csv_export.hpp"
#include "sim/scene_file.hpp"
#include "sim/scene_strategies.hpp"

namespace fragsim::cli {
namespace {

namespace po = boost::program_options;
namespace fs = std::filesystem;

// Everything a worker needs, fixed before the first fork.
struct SweepPlan {
  std::string scene_text;               // the --scene file's text, read once
  std::string origin;                   // its path, for messages
  std::vector<SceneOverride> base;      // the --section.key options
  std::vector<SweepAxis> axes;          // the --vary options
  std::vector<SweepJob> jobs;           // in output order
  std::vector<std::string> strategies;  // in --strategies order
  bool occlusion = true;
  std::string out;
  std::size_t workers = 1;
};

std::vector<SceneOverride> overrides_for(const SweepPlan& plan,
                                         const std::vector<std::size_t>& value_index,
                                         std::uint64_t seed) {
  std::vector<SceneOverride> o = plan.base;
  for (std::size_t k = 0; k < plan.axes.size(); ++k) {
    o.push_back({plan.axes[k].key, plan.axes[k].values[value_index[k]]});
  }
  o.push_back({"simulation.seed", std::to_string(seed)});
  return o;
}

// "a=1, b=2": one combination of the varied values, for messages.
std::string describe(const SweepPlan& plan, const std::vector<std::size_t>& value_index) {
  std::string s;
  for (std::size_t k = 0; k < plan.axes.size(); ++k) {
    s += (k > 0 ? ", " : "") + plan.axes[k].key + "=" + plan.axes[k].values[value_index[k]];
  }
  return s;
}

std::string describe(const SweepPlan& plan, const SweepJob& job) {
  return describe(plan, job.value_index) + ", seed " + std::to_string(job.seed);
}

// SceneError messages for an override start with "--KEY: "; the caller names --vary instead.
std::string without_option_prefix(const std::string& message, const std::string& key) {
  const std::string prefix = "--" + key + ": ";
  return message.rfind(prefix, 0) == 0 ? message.substr(prefix.size()) : message;
}

// The rows' columns: the varied keys, the seed, then summary.csv's columns but its own seed (the
// same number; a second `seed` column would make readers rename one).
std::vector<std::string> sweep_columns(const SweepPlan& plan, std::size_t& seed_column) {
  std::vector<std::string> cols;
  for (const SweepAxis& a : plan.axes) cols.push_back(a.key);
  cols.emplace_back("seed");
  const std::vector<std::string> summary = summary_csv_columns();
  seed_column = summary.size();
  for (std::size_t i = 0; i < summary.size(); ++i) {
    if (summary[i] == "seed") {
      seed_column = i;
    } else {
      cols.push_back(summary[i]);
    }
  }
  return cols;
}

std::string join(const std::vector<std::string>& cells) {
  std::string s;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (i > 0) s += ',';
    s += cells[i];
  }
  return s;
}

// ---- Parsing and validation: everything that can be wrong is found here, before any fork. ----

SweepPlan plan_sweep(const ParsedCommand& p) {
  SweepPlan plan;
  if (!p.options.count("vary")) throw UsageError("--vary: at least one KEY=SPEC is needed");
  std::set<std::string> varied;
  for (const std::string& text : p.options["vary"].as<std::vector<std::string>>()) {
    SweepAxis axis;
    try {
      axis = parse_vary(text);
    } catch (const SweepError& e) {
      throw UsageError("--vary " + text + ": " + e.what());
    }
    if (!scene_options().find_nothrow(axis.key, false)) {
      throw UsageError("--vary " + text + ": unknown scene key '" + axis.key + "'");
    }
    if (axis.key == "simulation.seed") {
      throw UsageError("--vary " + text + ": vary the seed with --seeds N or --seed-list a,b,c");
    }
    if (p.options.count(axis.key)) {
      throw UsageError("--vary " + text + ": --" + axis.key + " is also given; keep one");
    }
    if (!varied.insert(axis.key).second) {
      throw UsageError("--vary " + text + ": " + axis.key + " is varied twice");
    }
    plan.axes.push_back(std::move(axis));
  }

  std::vector<std::uint64_t> seeds;
  const bool n_seeds = p.options.count("seeds") > 0, list = p.options.count("seed-list") > 0;
  if (n_seeds && list) throw UsageError("--seeds and --seed-list: give one");
  if ((n_seeds || list) && p.options.count("simulation.seed")) {
    throw UsageError("--simulation.seed: the sweep's seeds come from --seeds or --seed-list");
  }
  try {
    if (n_seeds) {
      seeds = seeds_up_to(p.options["seeds"].as<long long>());
    } else if (list) {
      seeds = parse_seed_list(p.options["seed-list"].as<std::string>());
    } else {
      seeds = {p.scene.sim.seed};  // the scene's own seed (or --simulation.seed)
    }
  } catch (const SweepError& e) {
    throw UsageError(std::string(n_seeds ? "--seeds: " : "--seed-list: ") + e.what());
  }

  plan.strategies = split_list(p.options["strategies"].as<std::string>());
  if (plan.strategies.empty()) throw UsageError("--strategies: no strategy named");
  std::set<std::string> named;
  for (const std::string& n : plan.strategies) {
    if (!named.insert(n).second) throw UsageError("--strategies: '" + n + "' is named twice");
  }
  for (const std::string& n : plan.strategies) {
    try {
      make_strategy(n, p.scene);
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string("--strategies: ") + e.what());
    }
  }
  plan.occlusion = p.options.count("no-occlusion") == 0;

  if (!p.options.count("out")) throw UsageError("--out: the output file is needed");
  plan.out = p.options["out"].as<std::string>();
  if (plan.out.empty()) throw UsageError("--out: empty file name");
  std::error_code ec;
  if (fs::is_directory(plan.out, ec)) throw UsageError("--out " + plan.out + ": is a folder");
  if (fs::exists(plan.out, ec) && !p.options.count("force")) {
    throw UsageError("--out " + plan.out + ": exists (use --force to overwrite)");
  }

  long jobs = p.options.count("jobs") ? p.options["jobs"].as<int>() : sysconf(_SC_NPROCESSORS_ONLN);
  if (p.options.count("jobs") && (jobs < 1 || jobs > 1024)) {
    throw UsageError("--jobs " + std::to_string(jobs) + ": must be in [1, 1024]");
  }
  if (jobs < 1) jobs = 1;  // sysconf failed

  // The scene file's text, read once: every job's scene is parsed from it with its overrides.
  if (p.options.count("scene")) {
    plan.origin = p.options["scene"].as<std::string>();
    try {
      plan.scene_text = read_input_file(plan.origin, "scene file");
    } catch (const InputError& e) {
      throw UsageError(e.what());
    }
  }
  for (const auto& opt : scene_options().options()) {
    const std::string& key = opt->long_name();
    if (p.options.count(key)) plan.base.push_back({key, p.options[key].as<std::string>()});
  }

  std::vector<std::vector<std::size_t>> combos;
  try {
    combos = sweep_combinations(plan.axes);
    plan.jobs = sweep_jobs(plan.axes, seeds);
  } catch (const SweepError& e) {
    throw UsageError(std::string("--vary: ") + e.what());
  }
  plan.workers = std::min(static_cast<std::size_t>(jobs), plan.jobs.size());

  // Each value alone first, so a bad value is reported against its own --vary option.
  for (std::size_t k = 0; k < plan.axes.size(); ++k) {
    const SweepAxis& a = plan.axes[k];
    for (const std::string& v : a.values) {
      std::vector<SceneOverride> o = plan.base;
      o.push_back({a.key, v});
      try {
        parse_scene(plan.scene_text, plan.origin, o);
      } catch (const SceneError& e) {
        throw UsageError("--vary " + a.key + "=" + v + ": " +
                         without_option_prefix(e.what(), a.key));
      }
    }
  }
  // Then every combination, for the rules across keys (near < far, ...) and strategy parameters.
  // (The seed cannot make a scene invalid: any whole number is a seed.)
  for (const auto& c : combos) {
    try {
      const Scene scene =
          parse_scene(plan.scene_text, plan.origin, overrides_for(plan, c, seeds.front()));
      for (const std::string& n : plan.strategies) make_strategy(n, scene);
    } catch (const SceneError& e) {
      throw UsageError("--vary " + describe(plan, c) + ": " + e.what());
    } catch (const std::invalid_argument& e) {
      throw UsageError("--vary " + describe(plan, c) + ": " + e.what());
    }
  }
  return plan;
}

// ---- Workers: separate processes, because ODE (built without per-thread collision storage)
// must never step two worlds from two threads of one process. ----

// Runs jobs w, w + J, ... and appends "job,row" lines to `path`; reports each finished job on
// `fd` as "done J\n", or "error J message\n" before exiting with status 1. Never returns: the
// parent's objects in this copy of the process must not be destroyed twice.
[[noreturn]] void run_worker(const SweepPlan& plan, std::size_t w, const std::string& path,
                             int fd) {
  std::size_t current = w;
  auto report = [fd](const std::string& line) {
    // A pipe write this short is atomic; a failure means the parent is gone.
    if (::write(fd, line.data(), line.size()) != static_cast<ssize_t>(line.size())) ::_exit(1);
  };
  try {
    std::size_t seed_column = 0;
    sweep_columns(plan, seed_column);
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error(path + ": cannot write (" + std::strerror(errno) + ")");
    for (; current < plan.jobs.size(); current += plan.workers) {
      const SweepJob& job = plan.jobs[current];
      const Scene scene =
          parse_scene(plan.scene_text, plan.origin, overrides_for(plan, job.value_index, job.seed));
      const std::vector<Evaluation> runs = compare(scene, plan.strategies, plan.occlusion);
      std::string text;
      for (const Evaluation& e : runs) {
        std::vector<std::string> cells;
        for (std::size_t k = 0; k < plan.axes.size(); ++k) {
          cells.push_back(plan.axes[k].values[job.value_index[k]]);
        }
        cells.push_back(std::to_string(job.seed));
        const std::vector<std::string> summary = summary_csv_cells(scene, e.summary);
        for (std::size_t i = 0; i < summary.size(); ++i) {
          if (i != seed_column) cells.push_back(summary[i]);
        }
        text += std::to_string(current) + "," + join(cells) + "\n";
      }
      out << text;
      out.flush();
      if (!out) throw std::runtime_error(path + ": write failed (disk full?)");
      report("done " + std::to_string(current) + "\n");
    }
    out.close();
    if (out.fail()) throw std::runtime_error(path + ": write failed (disk full?)");
  } catch (const std::exception& e) {
    std::string what = e.what();
    for (char& c : what) {
      if (c == '\n') c = ' ';
    }
    report("error " + std::to_string(current) + " " + what.substr(0, 3000) + "\n");
    ::_exit(1);
  } catch (...) {
    report("error " + std::to_string(current) + " unknown exception\n");
    ::_exit(1);
  }
  ::_exit(0);
}

// SIGINT, SIGTERM and SIGHUP only set a flag while the sweep runs, so the parent can stop the
// workers and remove the temporary files before it dies of the same signal.
volatile std::sig_atomic_t g_signal = 0;
void note_signal(int signo) {
  g_signal = signo;
}

constexpr int kStopSignals[] = {SIGINT, SIGTERM, SIGHUP};

class SignalGuard {
 public:
  SignalGuard() {
    struct sigaction sa {};
    sa.sa_handler = note_signal;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = 0;  // no SA_RESTART: poll() returns EINTR and the loop sees the flag
    for (std::size_t i = 0; i < std::size(kStopSignals); ++i) {
      sigaction(kStopSignals[i], nullptr, &old_[i]);
      // A signal ignored on entry (nohup, a background job) stays ignored, here and in workers.
      if (old_[i].sa_handler != SIG_IGN) sigaction(kStopSignals[i], &sa, nullptr);
    }
  }
  ~SignalGuard() { restore(); }
  SignalGuard(const SignalGuard&) = delete;
  SignalGuard& operator=(const SignalGuard&) = delete;

  // The dispositions found on entry; also what a worker runs with.
  void restore() const {
    for (std::size_t i = 0; i < std::size(kStopSignals); ++i) {
      sigaction(kStopSignals[i], &old_[i], nullptr);
    }
  }

 private:
  struct sigaction old_[std::size(kStopSignals)]{};
};

struct Interrupted {
  int signo;
};

void check_signal() {
  if (g_signal != 0) throw Interrupted{g_signal};
}

// The workers' temporary files, removed whatever happens (the parent's copy only).
class TempFiles {
 public:
  ~TempFiles() {
    for (const std::string& p : paths_) std::remove(p.c_str());
  }
  void add(std::string path) { paths_.push_back(std::move(path)); }
  const std::string& operator[](std::size_t i) const { return paths_[i]; }

 private:
  std::vector<std::string> paths_;
};

struct Worker {
  pid_t pid = -1;
  int fd = -1;  // read end of its report pipe
  std::string pending;
  std::size_t next_job = 0;  // the job it runs now, in its share
  std::string error;         // its "error" report, if any
  bool running = false;
};

// The running workers; on any early exit (a failure, an exception, a signal) the rest are killed
// and reaped so none outlives the sweep or writes after its files are removed.
class WorkerSet {
 public:
  ~WorkerSet() { stop(); }
  void stop() {
    for (Worker& w : workers) {
      if (w.running) ::kill(w.pid, SIGTERM);
    }
    for (Worker& w : workers) {
      if (w.running) {
        while (::waitpid(w.pid, nullptr, 0) < 0 && errno == EINTR) {
        }
        w.running = false;
      }
      if (w.fd >= 0) ::close(w.fd);
      w.fd = -1;
    }
  }
  std::vector<Worker> workers;
};

std::string exit_text(int status) {
  if (WIFSIGNALED(status)) {
    return "was killed by signal " + std::to_string(WTERMSIG(status)) + " (" +
           strsignal(WTERMSIG(status)) + ")";
  }
  return "exited with status " + std::to_string(WEXITSTATUS(status));
}

void show_progress(std::size_t done, std::size_t total) {
  std::fprintf(stderr, "\r sweep: %zu/%zu runs", done, total);
  std::fflush(stderr);
}

// Forks the workers, follows their reports and returns the merged CSV text. Throws
// std::runtime_error naming the failed job, or Interrupted.
std::string run_workers(const SweepPlan& plan, const TempFiles& temp, const SignalGuard& signals) {
  const bool progress = ::isatty(STDERR_FILENO) == 1;
  std::cout.flush();  // buffered output would be written again by every child at exit
  std::cerr.flush();
  std::fflush(nullptr);
  WorkerSet set;
  sigset_t block, previous;
  sigemptyset(&block);
  for (int s : kStopSignals) sigaddset(&block, s);
  for (std::size_t w = 0; w < plan.workers; ++w) {
    int fds[2];
    if (::pipe(fds) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
    // Stop signals wait until the child has its own dispositions back (a worker hit by Ctrl-C
    // dies at once) and until the parent has recorded the child, so it is always stopped.
    sigprocmask(SIG_BLOCK, &block, &previous);
    const pid_t pid = ::fork();
    if (pid == 0) {
      signals.restore();
      sigprocmask(SIG_SETMASK, &previous, nullptr);
      ::close(fds[0]);
      for (const Worker& other : set.workers) ::close(other.fd);
      run_worker(plan, w, temp[w], fds[1]);
    }
    const int fork_errno = errno;
    ::close(fds[1]);
    if (pid < 0) {
      ::close(fds[0]);
      sigprocmask(SIG_SETMASK, &previous, nullptr);
      throw std::runtime_error(std::string("cannot start a worker process: ") +
                               std::strerror(fork_errno));
    }
    Worker worker;
    worker.pid = pid;
    worker.fd = fds[0];
    worker.next_job = w;
    worker.running = true;
    set.workers.push_back(worker);
    sigprocmask(SIG_SETMASK, &previous, nullptr);
  }

  std::size_t done = 0;
  if (progress) show_progress(done, plan.jobs.size());
  auto fail = [&plan](const Worker& w, const std::string& what) {
    const std::string job = w.next_job < plan.jobs.size()
                                ? " on job " + std::to_string(w.next_job + 1) + " (" +
                                      describe(plan, plan.jobs[w.next_job]) + ")"
                                : "";
    throw std::runtime_error("worker " + std::to_string(w.pid) + job + ": " + what);
  };
  std::size_t running = set.workers.size();
  while (running > 0) {
    check_signal();
    std::vector<pollfd> polled;
    std::vector<Worker*> who;
    for (Worker& w : set.workers) {
      if (w.running) {
        polled.push_back({w.fd, POLLIN, 0});
        who.push_back(&w);
      }
    }
    if (::poll(polled.data(), polled.size(), -1) < 0) {
      if (errno == EINTR) continue;
      throw std::runtime_error(std::string("poll: ") + std::strerror(errno));
    }
    for (std::size_t i = 0; i < polled.size(); ++i) {
      if (polled[i].revents == 0) continue;
      Worker& w = *who[i];
      char buf[4096];
      const ssize_t n = ::read(w.fd, buf, sizeof buf);
      if (n < 0) {
        if (errno == EINTR || errno == EAGAIN) continue;
        throw std::runtime_error(std::string("read from a worker: ") + std::strerror(errno));
      }
      if (n > 0) {
        w.pending.append(buf, static_cast<std::size_t>(n));
        for (auto nl = w.pending.find('\n'); nl != std::string::npos; nl = w.pending.find('\n')) {
          const std::string line = w.pending.substr(0, nl);
          w.pending.erase(0, nl + 1);
          if (line.rfind("done ", 0) == 0) {
            ++done;
            w.next_job += plan.workers;
            if (progress) show_progress(done, plan.jobs.size());
          } else if (line.rfind("error ", 0) == 0) {
            const auto space = line.find(' ', 6);
            w.error = space == std::string::npos ? line.substr(6) : line.substr(space + 1);
          }
        }
        continue;
      }
      // End of file: the worker has exited (or is about to); its status says how.
      int status = 0;
      while (::waitpid(w.pid, &status, 0) < 0 && errno == EINTR) {
      }
      w.running = false;
      --running;
      ::close(w.fd);
      w.fd = -1;
      // Workers hit by the same Ctrl-C are not a failure to report: the sweep was interrupted.
      check_signal();
      if (progress && !(WIFEXITED(status) && WEXITSTATUS(status) == 0)) std::fputc('\n', stderr);
      if (!w.error.empty()) fail(w, w.error);
      if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) fail(w, exit_text(status));
      if (w.next_job < plan.jobs.size()) fail(w, "stopped before its last job");
    }
  }
  if (progress) std::fputc('\n', stderr);
  check_signal();

  // Merge in job order: the file is the same whatever the number of workers.
  std::vector<std::string> rows(plan.jobs.size());
  std::vector<std::size_t> count(plan.jobs.size(), 0);
  for (std::size_t w = 0; w < plan.workers; ++w) {
    std::ifstream in(temp[w], std::ios::binary);
    if (!in) throw std::runtime_error(temp[w] + ": cannot read a worker's rows");
    std::string line;
    while (std::getline(in, line)) {
      const auto comma = line.find(',');
      std::size_t job = plan.jobs.size();
      try {
        job = std::stoul(line.substr(0, comma));
      } catch (const std::exception&) {
      }
      if (comma == std::string::npos || job >= plan.jobs.size() || job % plan.workers != w) {
        throw std::runtime_error(temp[w] + ": malformed worker row");
      }
      rows[job].append(line, comma + 1).push_back('\n');
      ++count[job];
    }
  }
  std::size_t seed_column = 0;
  std::string csv = join(sweep_columns(plan, seed_column)) + "\n";
  for (std::size_t j = 0; j < rows.size(); ++j) {
    if (count[j] != plan.strategies.size()) {
      throw std::runtime_error("job " + std::to_string(j + 1) + " (" +
                               describe(plan, plan.jobs[j]) + "): rows missing in worker output");
    }
    csv += rows[j];
  }
  return csv;
}

// ---- The single-key summary. ----

void print_single_key_tables(const SweepPlan& plan, const std::string& csv, std::ostream& out) {
  const std::string& key = plan.axes.front().key;
  const std::vector<SweepOutcome> rows = read_sweep_outcomes(csv, key);
  const std::vector<SweepStrategyStats> stats = summarise_single_key(rows);
  const bool numeric = sweep_values_numeric(rows);
  const std::size_t seeds = plan.jobs.size() / plan.axes.front().values.size();
  for (const SweepStrategyStats& st : stats) {
    out << "\n"
        << st.strategy << ": seeds with zero intersections (near-plane and camera) out of " << seeds
        << ", mean of dev_mean_m over the seeds\n";
    Table t({key, "zero_seeds", "dev_mean_m"});
    for (const SweepValueStats& v : st.values) {
      t.add_row({v.value, std::to_string(v.zero_seeds) + "/" + std::to_string(v.seeds),
                 fixed(v.deviation_mean_m, 4)});
    }
    t.print(out);
  }
  out << "\nsmallest " << key << " from which the strategy keeps zero intersections on every "
      << "seed, at that value and every " << (numeric ? "larger" : "later")
      << " value in the sweep, and its mean dev_mean_m there ('-': never)\n";
  Table t({"strategy", key, "dev_mean_m"});
  for (const SweepStrategyStats& st : stats) {
    if (st.threshold) {
      const SweepValueStats& v = st.values[*st.threshold];
      t.add_row({st.strategy, v.value, fixed(v.deviation_mean_m, 4)});
    } else {
      t.add_row({st.strategy, "-", "-"});
    }
  }
  t.print(out);
}

}  // namespace

int cmd_sweep(const std::vector<std::string>& args) {
  po::options_description own("sweep options");
  std::string all_names;
  for (const std::string& n : strategy_names()) all_names += (all_names.empty() ? "" : ",") + n;
  own.add_options()(
      "vary", po::value<std::vector<std::string>>()->composing()->value_name("KEY=SPEC"),
      "a scene key and its values: a list 1,2,5 (vectors '0 1.6 -5,0 1.6 -7') or a range "
      "lo:hi:step (numeric keys only); repeat for the cartesian product")(
      "seeds", po::value<long long>()->value_name("N"),
      "run seeds 1..N (default: the scene's own seed)")(
      "seed-list", po::value<std::string>()->value_name("a,b,c"), "run these seeds")(
      "strategies", po::value<std::string>()->default_value(all_names),
      "comma-separated strategies to compare on every combination")(
      "jobs", po::value<int>()->value_name("J"),
      "worker processes (default: the number of online CPUs)")(
      "out", po::value<std::string>()->value_name("FILE"), "the CSV file to write")(
      "force", "overwrite an existing FILE")(
      "no-occlusion", "skip the screen-occlusion raster (faster; occlusion columns read 0)");
  const ParsedCommand p = parse_command("sweep", args, own);
  if (p.help_shown) return 0;
  const SweepPlan plan = plan_sweep(p);

  std::string csv;
  int signo = 0;
  {
    const SignalGuard guard;
    TempFiles temp;
    for (std::size_t w = 0; w < plan.workers; ++w) {
      // Next to the output so the final rename stays on one file system; the pid keeps two
      // sweeps into the same folder apart.
      temp.add(plan.out + ".part" + std::to_string(w) + "." + std::to_string(::getpid()));
      std::ofstream probe(temp[w], std::ios::binary | std::ios::trunc);
      if (!probe) {
        throw UsageError("--out " + plan.out + ": cannot write beside it (" + std::strerror(errno) +
                         ")");
      }
    }
    try {
      csv = run_workers(plan, temp, guard);
      AtomicFile file(plan.out);
      file.out() << csv;
      check_signal();
      file.commit();
    } catch (const Interrupted& i) {
      signo = i.signo;
    }
  }
  if (signo != 0) {
    // Die of the signal as if it had not been caught, now that nothing is left behind.
    std::signal(signo, SIG_DFL);
    std::raise(signo);
    return 128 + signo;
  }
  std::cout << "wrote " << plan.out << ": " << plan.jobs.size() * plan.strategies.size()
            << " rows (" << plan.jobs.size() << " runs x " << plan.strategies.size()
            << " strategies)\n";
  if (plan.axes.size() == 1) print_single_key_tables(plan, csv, std::cout);
  return 0;
}

}  // namespace fragsim::cli
