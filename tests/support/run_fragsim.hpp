#pragma once
// Runs the fragsim executable (the FRAGSIM_BINARY this build made) for end-to-end tests. A test
// that sets FRAGSIM_TEST_RAISE_AT_STEP, to stop a run at a known step, gets the same tool built
// with the step counter (FRAGSIM_SIGNAL_BINARY, support/signal_at_step.cpp) instead.

#include <stdlib.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace fragsim::test {

struct Result {
  int status = -1;  // the exit status; -1 if it did not exit normally
  std::string out;  // stdout and stderr together
};

inline Result run_fragsim(const std::string& args) {
  const char* binary =
      ::getenv("FRAGSIM_TEST_RAISE_AT_STEP") ? FRAGSIM_SIGNAL_BINARY : FRAGSIM_BINARY;
  const std::string cmd = std::string(binary) + " " + args + " 2>&1";
  Result r;
  FILE* pipe = popen(cmd.c_str(), "r");
  if (!pipe) return r;
  std::array<char, 4096> buf{};
  while (fgets(buf.data(), static_cast<int>(buf.size()), pipe)) r.out += buf.data();
  const int raw = pclose(pipe);
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  return r;
}

// Runs fragsim with extra environment variables, its output discarded, and returns the raw wait
// status, so a death by a signal is told apart from an exit (WIFSIGNALED, WTERMSIG).
inline int run_fragsim_status(const std::string& args,
                              const std::vector<std::pair<std::string, std::string>>& env = {}) {
  const char* binary = FRAGSIM_BINARY;
  for (const auto& [name, value] : env) {
    if (name == "FRAGSIM_TEST_RAISE_AT_STEP") binary = FRAGSIM_SIGNAL_BINARY;
  }
  // exec: the shell becomes fragsim, so the status is fragsim's own, not the shell's report of it.
  const std::string cmd = "exec " + std::string(binary) + " " + args + " >/dev/null 2>&1";
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if (pid < 0) return -1;
  if (pid == 0) {
    for (const auto& [name, value] : env) ::setenv(name.c_str(), value.c_str(), 1);
    ::execl("/bin/sh", "sh", "-c", cmd.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
  }
  return status;
}

// A folder of its own under the test temporary folder (mkdtemp), removed with everything in it
// when destroyed: two checkouts testing at once never share a path.
class UniqueDir {
 public:
  explicit UniqueDir(const std::string& stem) {
    std::string pattern =
        (std::filesystem::path(std::filesystem::temp_directory_path()) / (stem + ".XXXXXX"))
            .string();
    if (!::mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp " + pattern);
    path_ = pattern;
  }
  ~UniqueDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  UniqueDir(const UniqueDir&) = delete;
  UniqueDir& operator=(const UniqueDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::string str() const { return path_.string(); }

 private:
  std::filesystem::path path_;
};

}  // namespace fragsim::test
