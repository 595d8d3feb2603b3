// The fragsim a test can stop at a known step: the tool itself (the same objects as `fragsim`),
// linked with ODE's two step functions wrapped (ld --wrap) so that each physics step is counted
// here, and a signal sent at the step the environment names. A test so lands SIGINT, SIGTERM or
// SIGKILL inside a run, never after a guessed time, while the shipped binary has no test code.
//
//   FRAGSIM_TEST_RAISE_AT_STEP=N  FRAGSIM_TEST_RAISE_SIGNAL=INT|TERM|HUP|KILL
//   [FRAGSIM_TEST_RAISE_IN=self]
//
// The N-th physics step this process takes, counted over all its runs (a forked worker goes on
// from its parent's count), sends the signal to the process that started (a worker's signal
// reaches its parent, as a user's would), or with FRAGSIM_TEST_RAISE_IN=self to the process that
// took the step (a worker that crashes). A run's step is one ODE step, except the rare exact step
// redone by the iterative solver, which counts twice.

#include <ode/ode.h>
#include <signal.h>
#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <utility>

namespace {

struct TestSignal {
  int signo = 0;  // 0: not armed
  long at_step = 0;
  long steps = 0;
  pid_t target = 0;  // 0: the process that takes the step
};

TestSignal armed_from_environment() {
  const char* step = std::getenv("FRAGSIM_TEST_RAISE_AT_STEP");
  const char* name = std::getenv("FRAGSIM_TEST_RAISE_SIGNAL");
  if (!step || !name) return {};
  const long at = std::strtol(step, nullptr, 10);
  int signo = 0;
  for (const auto& [n, s] : {std::pair{"INT", SIGINT}, std::pair{"TERM", SIGTERM},
                             std::pair{"HUP", SIGHUP}, std::pair{"KILL", SIGKILL}}) {
    if (std::strcmp(name, n) == 0) signo = s;
  }
  if (at < 1 || signo == 0) return {};
  const char* in = std::getenv("FRAGSIM_TEST_RAISE_IN");
  const bool self = in && std::strcmp(in, "self") == 0;
  return {signo, at, 0, self ? 0 : ::getpid()};
}

// Read before main, in the process that starts; plain data, so fork copies it into workers.
TestSignal g_signal = armed_from_environment();

void count_step() {
  if (g_signal.signo != 0 && ++g_signal.steps == g_signal.at_step) {
    ::kill(g_signal.target != 0 ? g_signal.target : ::getpid(), g_signal.signo);
  }
}

}  // namespace

extern "C" {
int __real_dWorldStep(dWorldID w, dReal stepsize);
int __real_dWorldQuickStep(dWorldID w, dReal stepsize);

int __wrap_dWorldStep(dWorldID w, dReal stepsize) {
  const int ok = __real_dWorldStep(w, stepsize);
  count_step();
  return ok;
}

int __wrap_dWorldQuickStep(dWorldID w, dReal stepsize) {
  const int ok = __real_dWorldQuickStep(w, stepsize);
  count_step();
  return ok;
}
}
