// The one worker-process pool: results in task order whatever the order of completion, progress
// once per task as tasks finish, one failure text for a task that threw, crashed or exited,
// cancellation and stop signals that leave no worker behind, and the --jobs check. Finish orders
// are forced through pipes, never by sleeping.

#include "experiments/process_runner.hpp"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <stdexcept>

namespace fragsim {
namespace {

// A pipe both ends of which the workers inherit: a task blocks reading it until this process
// writes (or forever, the read end never seeing end-of-file while a worker holds the write end).
class Gate {
 public:
  Gate() {
    if (::pipe(fds_) != 0) throw std::runtime_error("pipe");
  }
  ~Gate() {
    ::close(fds_[0]);
    ::close(fds_[1]);
  }
  Gate(const Gate&) = delete;
  Gate& operator=(const Gate&) = delete;
  void open() const {
    const char c = 1;
    if (::write(fds_[1], &c, 1) != 1) std::abort();
  }
  void wait() const {
    char c = 0;
    while (::read(fds_[0], &c, 1) < 0 && errno == EINTR) {
    }
  }

 private:
  int fds_[2];
};

// Every worker reaped: this test process has no child left.
void expect_no_child_left() {
  errno = 0;
  EXPECT_EQ(::waitpid(-1, nullptr, WNOHANG), -1);
  EXPECT_EQ(errno, ECHILD);
}

TEST(ProcessRunner, ResultsComeInTaskOrderAndProgressInOrderOfCompletion) {
  // Worker 0 runs tasks 0 and 2, worker 1 tasks 1 and 3; task 0 waits until this process has
  // seen task 3 finish, so tasks finish as 1, 3, 0, 2.
  const Gate gate;
  std::vector<std::size_t> finished, done_counts;
  ProcessRunOptions options;
  options.jobs = 2;
  options.on_done = [&](std::size_t task, std::size_t done) {
    finished.push_back(task);
    done_counts.push_back(done);
    if (task == 3) gate.open();
  };
  const ProcessRunOutcome outcome = run_processes(
      4,
      [&gate](std::size_t i) {
        if (i == 0) gate.wait();
        return "r" + std::to_string(i);
      },
      options);
  ASSERT_EQ(outcome.status, RunStatus::kCompleted) << outcome.failure;
  EXPECT_EQ(finished, (std::vector<std::size_t>{1, 3, 0, 2}));
  EXPECT_EQ(done_counts, (std::vector<std::size_t>{1, 2, 3, 4}));
  ASSERT_EQ(outcome.results.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(outcome.results[i], "r" + std::to_string(i));
  expect_no_child_left();

  options.on_done = nullptr;
  EXPECT_EQ(run_in_processes(
                5, [](std::size_t i) { return std::to_string(i * i); }, options),
            (std::vector<std::string>{"0", "1", "4", "9", "16"}));
}

TEST(ProcessRunner, OneProcessCallsProgressOncePerTaskInOrder) {
  std::vector<std::size_t> finished;
  ProcessRunOptions options;  // jobs = 1: in this process
  options.on_done = [&](std::size_t task, std::size_t done) {
    EXPECT_EQ(done, task + 1);
    finished.push_back(task);
  };
  const pid_t self = ::getpid();
  const ProcessRunOutcome outcome = run_processes(
      3,
      [self](std::size_t i) {
        EXPECT_EQ(::getpid(), self);
        return std::to_string(i);
      },
      options);
  EXPECT_EQ(outcome.status, RunStatus::kCompleted);
  EXPECT_EQ(finished, (std::vector<std::size_t>{0, 1, 2}));
}

TEST(ProcessRunner, ACrashingWorkerGivesTheOneFailureText) {
  const Gate never;  // task 0 blocks for good: the failure must stop its worker too
  ProcessRunOptions options;
  options.jobs = 2;
  options.describe = [](std::size_t i) { return "strategy s" + std::to_string(i); };
  const ProcessRunOutcome crashed = run_processes(
      2,
      [&never](std::size_t i) -> std::string {
        if (i == 1) {
          const rlimit no_core{0, 0};  // a crash on purpose leaves no core file
          ::setrlimit(RLIMIT_CORE, &no_core);
          std::abort();
        }
        never.wait();
        return "unreachable";
      },
      options);
  EXPECT_EQ(crashed.status, RunStatus::kFailed);
  EXPECT_EQ(crashed.failure, "strategy s1: the worker process was killed by signal 6 (Aborted)");
  EXPECT_FALSE(crashed.results[0].has_value());
  expect_no_child_left();

  const auto exits = [](std::size_t i) -> std::string {
    if (i == 2) ::_exit(7);
    return "ok";
  };
  options.describe = nullptr;
  const ProcessRunOutcome exited = run_processes(3, exits, options);
  EXPECT_EQ(exited.status, RunStatus::kFailed);
  EXPECT_EQ(exited.failure, "task 2: the worker process exited with status 7");
  try {
    run_in_processes(3, exits, options);
    ADD_FAILURE() << "no exception";
  } catch (const TaskFailed& e) {
    EXPECT_STREQ(e.what(), "task 2: the worker process exited with status 7");
  }
  expect_no_child_left();
}

TEST(ProcessRunner, AThrowingTaskGivesItsMessageInProcessAndInWorkers) {
  const auto task = [](std::size_t i) -> std::string {
    if (i == 1) throw std::runtime_error("boom\nsecond line");
    return "ok";
  };
  for (int jobs : {1, 2}) {
    ProcessRunOptions options;
    options.jobs = jobs;
    const ProcessRunOutcome outcome = run_processes(3, task, options);
    EXPECT_EQ(outcome.status, RunStatus::kFailed) << jobs;
    EXPECT_EQ(outcome.failure, "task 1: boom second line") << jobs;
  }
  expect_no_child_left();
}

TEST(ProcessRunner, CancellationStopsTheRemainingTasks) {
  // Task 1 would never finish; cancelling once task 0 is done must stop it and start nothing.
  const Gate never;
  std::atomic<bool> cancel{false};
  std::vector<std::size_t> finished;
  ProcessRunOptions options;
  options.jobs = 2;
  options.cancel = &cancel;
  options.on_done = [&](std::size_t task, std::size_t) {
    finished.push_back(task);
    cancel = true;
  };
  const ProcessRunOutcome outcome = run_processes(
      6,
      [&never](std::size_t i) {
        if (i % 2 == 1) never.wait();
        return std::to_string(i);
      },
      options);
  EXPECT_EQ(outcome.status, RunStatus::kCancelled);
  EXPECT_EQ(finished, (std::vector<std::size_t>{0}));
  EXPECT_EQ(outcome.results[0], "0");
  for (std::size_t i = 1; i < 6; ++i) EXPECT_FALSE(outcome.results[i].has_value()) << i;
  expect_no_child_left();

  // In this process: the tasks after the cancellation do not run at all.
  cancel = false;
  finished.clear();
  options.jobs = 1;
  int ran = 0;
  const ProcessRunOutcome here = run_processes(
      4,
      [&ran](std::size_t i) {
        ++ran;
        return std::to_string(i);
      },
      options);
  EXPECT_EQ(here.status, RunStatus::kCancelled);
  EXPECT_EQ(ran, 1);
  EXPECT_EQ(finished, (std::vector<std::size_t>{0}));
}

TEST(ProcessRunner, AStopSignalInterruptsAndReapsEveryWorker) {
  struct sigaction before {};
  sigaction(SIGTERM, nullptr, &before);
  // Task 0 signals this process, as a user's `kill` would, and then never finishes; nor does 1.
  const Gate never;
  ProcessRunOptions options;
  options.jobs = 2;
  const auto task = [&never](std::size_t i) {
    if (i == 0) ::kill(::getppid(), SIGTERM);
    never.wait();
    return std::string();
  };
  const ProcessRunOutcome outcome = run_processes(2, task, options);
  EXPECT_EQ(outcome.status, RunStatus::kInterrupted);
  EXPECT_EQ(outcome.signal, SIGTERM);
  expect_no_child_left();
  try {
    run_in_processes(2, task, options);
    ADD_FAILURE() << "no exception";
  } catch (const Interrupted& e) {
    EXPECT_EQ(e.signal(), SIGTERM);
  }
  expect_no_child_left();

  // The disposition and the signal mask found on entry are back.
  struct sigaction after {};
  sigaction(SIGTERM, nullptr, &after);
  EXPECT_EQ(after.sa_handler, before.sa_handler);
  sigset_t mask;
  sigprocmask(SIG_SETMASK, nullptr, &mask);
  EXPECT_EQ(sigismember(&mask, SIGTERM), 0);
}

TEST(ProcessRunner, JobsMustBeAWholeNumberInRange) {
  EXPECT_EQ(parse_jobs("1"), 1);
  EXPECT_EQ(parse_jobs("1024"), 1024);
  for (const std::string bad : {"0", "-1", "abc", "", "1025", "2x", " 2", "1e3"}) {
    try {
      parse_jobs(bad);
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()), "--jobs " + bad + ": must be a whole number in [1, 1024]");
    }
  }
  EXPECT_GE(online_cpus(), 1);
}

TEST(ProcessRunner, ExitTextsNameTheSignalOrTheStatus) {
  EXPECT_EQ(worker_exit_text(9), "was killed by signal 9 (Killed)");  // raw status: signal 9
  EXPECT_EQ(worker_exit_text(3 << 8), "exited with status 3");
}

}  // namespace
}  // namespace fragsim
