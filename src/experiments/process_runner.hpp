#pragma once
// The one pool of worker processes. It runs independent tasks in forked workers, results back in
// task order, with cancellation, stop signals and one text for a worker that failed. Processes, not
// threads, because Debian's ODE is built without per-thread collision storage, so two worlds must
// not be stepped from two threads of one process (and ODE's own thread pool is 8-10x slower on 2
// cores). compare (evaluation.cpp), sweep (sweep.cpp) and suite (suite.cpp) all run through it;
// bench runs in one process on purpose, so its timings do not compete.

#include <atomic>
#include <cstddef>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace fragsim {

struct ProcessRunOptions {
  // Worker processes. With jobs <= 1 or fewer than two tasks everything runs in this process, where
  // a stop signal meets the process's own disposition (fragsim removes its temporary files and
  // dies, io/atomic_file.hpp).
  int jobs = 1;
  // Called in this process once per finished task, in order of completion, with the task's index
  // and how many tasks have finished so far (for a progress line).
  std::function<void(std::size_t task, std::size_t done)> on_done;
  // Once true, no further task is started and running workers are stopped. Checked before each
  // task in this process, and whenever a worker reports or a signal arrives (so set it from
  // on_done, or from a signal handler that also interrupts this process).
  const std::atomic<bool>* cancel = nullptr;
  // Names task i in the failure text ("strategy edge"), or "task i" when unset.
  std::function<std::string(std::size_t task)> describe;
};

enum class RunStatus {
  kCompleted,    // every task finished; results are all set
  kFailed,       // a task threw or its worker crashed or exited; `failure` says which and how
  kCancelled,    // options.cancel was set
  kInterrupted,  // SIGINT, SIGTERM or SIGHUP reached this process; every worker was reaped
};

struct ProcessRunOutcome {
  RunStatus status = RunStatus::kCompleted;
  // In task order whatever the order of completion; nullopt for a task that did not finish.
  std::vector<std::optional<std::string>> results;
  std::string failure;  // for kFailed, one line from failure_text()
  int signal = 0;       // for kInterrupted, the signal
};

// Runs task(i) for i in [0, count) on options.jobs worker processes (task i on worker i % jobs, so
// a worker's sequence of tasks never depends on timing). A task reports failure by throwing, and
// its worker then stops. On any failure, cancellation or stop signal the remaining workers are
// killed and reaped before this returns, so none outlives the call. While workers run, SIGINT,
// SIGTERM and SIGHUP (unless ignored on entry) only mark the run interrupted; in workers they take
// their default action (a worker owns no file), and workers die with this process
// (PR_SET_PDEATHSIG), even of SIGKILL. Call it with no output file open for writing that a child
// could corrupt by exiting, because children leave through _exit and never run destructors or
// atexit handlers.
ProcessRunOutcome run_processes(std::size_t count,
                                const std::function<std::string(std::size_t)>& task,
                                const ProcessRunOptions& options = {});

// A stop signal ended the run; every worker was stopped and reaped. The caller unwinds (output
// files removed by their destructors) and then dies of `signal` (main does).
class Interrupted : public std::runtime_error {
 public:
  explicit Interrupted(int signal);
  int signal() const { return signal_; }

 private:
  int signal_;
};

// A task failed; what() is the one failure text.
class TaskFailed : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// run_processes, with the outcome as results or an exception (TaskFailed, Interrupted, or
// TaskFailed("cancelled") when options.cancel stopped it).
std::vector<std::string> run_in_processes(std::size_t count,
                                          const std::function<std::string(std::size_t)>& task,
                                          const ProcessRunOptions& options = {});

// The one failure text, "<task>: <what>" for a task that threw, and "<task>: the worker process
// <how>" for a worker that crashed or exited while running it (how from worker_exit_text).
std::string failure_text(const std::string& task, const std::string& what);
// A waitpid status as text, "was killed by signal 6 (Aborted)" or "exited with status 3".
std::string worker_exit_text(int wait_status);

// The number of online processors (at least 1), the default for --jobs.
int online_cpus();

// The most worker processes --jobs may ask for.
inline constexpr int kMaxJobs = 1024;

// Parses --jobs' value, a whole number in [1, kMaxJobs]. Throws std::invalid_argument with the one
// text, "--jobs TEXT: must be a whole number in [1, 1024]".
int parse_jobs(const std::string& text);

}  // namespace fragsim
