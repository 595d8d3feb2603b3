#include "experiments/process_runner.hpp"

#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <iterator>

namespace fragsim {
namespace {

// Frames on a worker's pipe hold the task index, status (0 ok, 1 the task threw), length and bytes.
struct FrameHeader {
  std::uint64_t task;
  std::uint64_t status;
  std::uint64_t length;
};

constexpr int kStopSignals[] = {SIGINT, SIGTERM, SIGHUP};

volatile std::sig_atomic_t g_stop_signal = 0;
extern "C" void note_stop_signal(int signo) {
  g_stop_signal = signo;
}

// While workers run, the stop signals only set a flag, and are blocked except inside ppoll, so a
// signal always interrupts the wait (no window between checking the flag and waiting).
class StopSignals {
 public:
  StopSignals() {
    g_stop_signal = 0;
    sigemptyset(&caught_);
    struct sigaction sa {};
    sa.sa_handler = note_stop_signal;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = 0;
    for (std::size_t i = 0; i < std::size(kStopSignals); ++i) {
      sigaction(kStopSignals[i], nullptr, &old_[i]);
      // A signal ignored on entry (nohup, a background job) stays ignored, here and in workers.
      if (old_[i].sa_handler == SIG_IGN) continue;
      sigaction(kStopSignals[i], &sa, nullptr);
      sigaddset(&caught_, kStopSignals[i]);
    }
    sigprocmask(SIG_BLOCK, &caught_, &entry_mask_);
  }
  // The entry dispositions come back first, so a signal still pending reaches them (fragsim's:
  // remove temporary files and die) rather than being lost.
  ~StopSignals() {
    restore_handlers();
    sigprocmask(SIG_SETMASK, &entry_mask_, nullptr);
  }
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;

  // A worker owns no output file, so the default action (die) is right for it, whatever handler
  // this process had; ignored signals stay ignored.
  void reset_in_child() const {
    for (std::size_t i = 0; i < std::size(kStopSignals); ++i) {
      if (old_[i].sa_handler != SIG_IGN) std::signal(kStopSignals[i], SIG_DFL);
    }
    sigprocmask(SIG_SETMASK, &entry_mask_, nullptr);
  }

  const sigset_t& wait_mask() const { return entry_mask_; }

  // The stop signal caught or pending, taking a pending one (0 for none).
  int take() const {
    if (g_stop_signal != 0) return g_stop_signal;
    const timespec zero{0, 0};
    const int signo = sigtimedwait(&caught_, nullptr, &zero);
    if (signo > 0) g_stop_signal = signo;
    return signo > 0 ? signo : 0;
  }

 private:
  void restore_handlers() const {
    for (std::size_t i = 0; i < std::size(kStopSignals); ++i) {
      sigaction(kStopSignals[i], &old_[i], nullptr);
    }
  }
  struct sigaction old_[std::size(kStopSignals)]{};
  sigset_t caught_{};
  sigset_t entry_mask_{};
};

bool write_all(int fd, const void* data, std::size_t n) {
  const char* p = static_cast<const char*>(data);
  while (n > 0) {
    const ssize_t w = ::write(fd, p, n);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) return false;
    p += w;
    n -= static_cast<std::size_t>(w);
  }
  return true;
}

// Never returns, as the parent's objects in this copy of the process must not be destroyed twice.
[[noreturn]] void worker_main(int fd, std::size_t first, std::size_t stride, std::size_t count,
                              const std::function<std::string(std::size_t)>& task) {
  for (std::size_t i = first; i < count; i += stride) {
    std::string out;
    std::uint64_t status = 0;
    try {
      out = task(i);
    } catch (const std::exception& e) {
      out = e.what();
      status = 1;
    } catch (...) {
      out = "unknown error";
      status = 1;
    }
    const FrameHeader h{i, status, out.size()};
    if (!write_all(fd, &h, sizeof h) || !write_all(fd, out.data(), out.size()) || status != 0) {
      ::_exit(status != 0 ? 3 : 4);
    }
  }
  ::_exit(0);
}

struct Worker {
  pid_t pid = -1;
  int fd = -1;
  std::string buffer;    // bytes read, not yet a whole frame
  std::size_t next = 0;  // the task it is running
  bool running = false;  // not yet reaped
};

// Whatever ends the run (a result, a failure, an exception from a callback), no worker outlives it.
// The rest are killed (they hold no file to clean up) and reaped.
class WorkerSet {
 public:
  ~WorkerSet() { stop(); }
  void stop() {
    for (Worker& w : workers) {
      if (w.running) ::kill(w.pid, SIGKILL);
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

std::string name_of(const ProcessRunOptions& options, std::size_t task) {
  return options.describe ? options.describe(task) : "task " + std::to_string(task);
}

bool cancelled(const ProcessRunOptions& options) {
  return options.cancel && options.cancel->load();
}

ProcessRunOutcome run_here(std::size_t count, const std::function<std::string(std::size_t)>& task,
                           const ProcessRunOptions& options) {
  ProcessRunOutcome outcome;
  outcome.results.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    if (cancelled(options)) {
      outcome.status = RunStatus::kCancelled;
      return outcome;
    }
    try {
      outcome.results[i] = task(i);
    } catch (const std::exception& e) {
      outcome.status = RunStatus::kFailed;
      outcome.failure = failure_text(name_of(options, i), e.what());
      return outcome;
    }
    if (options.on_done) options.on_done(i, i + 1);
  }
  return outcome;
}

}  // namespace

Interrupted::Interrupted(int signal)
    : std::runtime_error(std::string("interrupted by signal ") + std::to_string(signal) + " (" +
                         strsignal(signal) + ")"),
      signal_(signal) {}

std::string failure_text(const std::string& task, const std::string& what) {
  std::string one_line = what;
  for (char& c : one_line) {
    if (c == '\n') c = ' ';
  }
  return task + ": " + one_line;
}

std::string worker_exit_text(int wait_status) {
  if (WIFSIGNALED(wait_status)) {
    return "was killed by signal " + std::to_string(WTERMSIG(wait_status)) + " (" +
           strsignal(WTERMSIG(wait_status)) + ")";
  }
  if (WIFEXITED(wait_status))
    return "exited with status " + std::to_string(WEXITSTATUS(wait_status));
  return "stopped";
}

int online_cpus() {
  const long n = ::sysconf(_SC_NPROCESSORS_ONLN);
  return n > 0 ? static_cast<int>(std::min<long>(n, kMaxJobs)) : 1;
}

int parse_jobs(const std::string& text) {
  int jobs = 0;
  const auto res = std::from_chars(text.data(), text.data() + text.size(), jobs);
  if (text.empty() || res.ec != std::errc() || res.ptr != text.data() + text.size() || jobs < 1 ||
      jobs > kMaxJobs) {
    throw std::invalid_argument("--jobs " + text + ": must be a whole number in [1, " +
                                std::to_string(kMaxJobs) + "]");
  }
  return jobs;
}

ProcessRunOutcome run_processes(std::size_t count,
                                const std::function<std::string(std::size_t)>& task,
                                const ProcessRunOptions& options) {
  if (options.jobs <= 1 || count <= 1) return run_here(count, task, options);
  const std::size_t stride = std::min(static_cast<std::size_t>(options.jobs), count);
  ProcessRunOutcome outcome;
  outcome.results.resize(count);

  // Buffered output would otherwise be written again by nobody but lost to a child's _exit;
  // flushed here it appears once, before the workers' progress.
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  const StopSignals signals;
  WorkerSet set;
  const pid_t parent = ::getpid();
  auto fail = [&outcome](std::string text) {
    outcome.status = RunStatus::kFailed;
    outcome.failure = std::move(text);
  };
  for (std::size_t w = 0; w < stride; ++w) {
    int fds[2];
    if (::pipe(fds) != 0) {
      fail(std::string("cannot create a pipe: ") + std::strerror(errno));
      return outcome;  // the set stops the workers started so far
    }
    const pid_t pid = ::fork();
    if (pid == 0) {
      // Dies with the parent, even of SIGKILL, instead of computing for nobody.
      ::prctl(PR_SET_PDEATHSIG, SIGKILL);
      if (::getppid() != parent) ::_exit(1);
      ::close(fds[0]);
      for (const Worker& other : set.workers) ::close(other.fd);
      signals.reset_in_child();
      worker_main(fds[1], w, stride, count, task);
    }
    const int fork_errno = errno;
    ::close(fds[1]);
    if (pid < 0) {
      ::close(fds[0]);
      fail(std::string("cannot start a worker process: ") + std::strerror(fork_errno));
      return outcome;
    }
    set.workers.push_back({pid, fds[0], {}, w, true});
  }

  std::size_t done = 0;
  std::vector<pollfd> polls;
  std::vector<Worker*> polled;
  // One event at a time, then the loop's checks; a failure, a cancellation or a signal ends it.
  while (outcome.status == RunStatus::kCompleted) {
    if (const int signo = signals.take()) {
      outcome.status = RunStatus::kInterrupted;
      outcome.signal = signo;
      break;
    }
    if (cancelled(options)) {
      outcome.status = RunStatus::kCancelled;
      break;
    }
    polls.clear();
    polled.clear();
    for (Worker& w : set.workers) {
      if (w.fd >= 0) {
        polls.push_back({w.fd, POLLIN, 0});
        polled.push_back(&w);
      }
    }
    if (polls.empty()) break;
    if (::ppoll(polls.data(), polls.size(), nullptr, &signals.wait_mask()) < 0) {
      if (errno == EINTR) continue;
      fail(std::string("poll failed: ") + std::strerror(errno));
      break;
    }
    for (std::size_t p = 0; p < polls.size() && outcome.status == RunStatus::kCompleted; ++p) {
      if (polls[p].revents == 0) continue;
      Worker& w = *polled[p];
      char chunk[1 << 16];
      const ssize_t n = ::read(w.fd, chunk, sizeof chunk);
      if (n < 0) {
        if (errno == EINTR || errno == EAGAIN) continue;
        fail(std::string("cannot read from a worker process: ") + std::strerror(errno));
        break;
      }
      if (n == 0) {  // the worker closed its end, finished or dead
        int status = 0;
        while (::waitpid(w.pid, &status, 0) < 0 && errno == EINTR) {
        }
        w.running = false;
        ::close(w.fd);
        w.fd = -1;
        if (WIFEXITED(status) && WEXITSTATUS(status) == 0 && w.next >= count) continue;
        // Workers killed by the same Ctrl-C as this process are no failure, because the run is
        // interrupted (the process group's signal is already pending here).
        if (signals.take() != 0) break;
        const std::string how = "the worker process " + worker_exit_text(status);
        fail(w.next < count ? failure_text(name_of(options, w.next), how)
                            : "a worker process, after its last task, " + worker_exit_text(status));
        break;
      }
      w.buffer.append(chunk, static_cast<std::size_t>(n));
      // A cancellation from on_done leaves the rest unread, so no result comes after it.
      while (w.buffer.size() >= sizeof(FrameHeader) && outcome.status == RunStatus::kCompleted &&
             !cancelled(options)) {
        FrameHeader h;
        std::memcpy(&h, w.buffer.data(), sizeof h);
        if (w.buffer.size() - sizeof h < h.length) break;
        std::string body = w.buffer.substr(sizeof h, h.length);
        w.buffer.erase(0, sizeof h + h.length);
        if (h.task != w.next) {
          fail("a worker process sent a result for an unexpected task");
        } else if (h.status != 0) {
          fail(failure_text(name_of(options, h.task), body));
        } else {
          outcome.results[h.task] = std::move(body);
          w.next += stride;
          ++done;
          if (options.on_done) options.on_done(h.task, done);
        }
      }
    }
  }
  set.stop();
  // A stop signal that came with the last result still wins, because the caller must not go on.
  if (outcome.status != RunStatus::kInterrupted) {
    if (const int signo = signals.take()) {
      outcome.status = RunStatus::kInterrupted;
      outcome.signal = signo;
    }
  }
  if (outcome.status == RunStatus::kInterrupted && outcome.signal == 0) {
    outcome.signal = g_stop_signal;
  }
  if (outcome.status == RunStatus::kCompleted && done != count) {
    fail("the worker processes finished " + std::to_string(done) + " of " + std::to_string(count) +
         " tasks");
  }
  return outcome;
}

std::vector<std::string> run_in_processes(std::size_t count,
                                          const std::function<std::string(std::size_t)>& task,
                                          const ProcessRunOptions& options) {
  ProcessRunOutcome outcome = run_processes(count, task, options);
  switch (outcome.status) {
    case RunStatus::kCompleted:
      break;
    case RunStatus::kFailed:
      throw TaskFailed(outcome.failure);
    case RunStatus::kCancelled:
      throw TaskFailed("cancelled");
    case RunStatus::kInterrupted:
      throw Interrupted(outcome.signal);
  }
  std::vector<std::string> results;
  results.reserve(count);
  for (std::optional<std::string>& r : outcome.results) results.push_back(std::move(*r));
  return results;
}

}  // namespace fragsim
