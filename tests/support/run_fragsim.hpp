#pragma once
// Runs the fragsim executable (the FRAGSIM_BINARY this build made) for end-to-end tests.

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

namespace fragsim::test {

struct Result {
  int status = -1;  // the exit status; -1 if it did not exit normally
  std::string out;  // stdout and stderr together
};

inline Result run_fragsim(const std::string& args) {
  const std::string cmd = std::string(FRAGSIM_BINARY) + " " + args + " 2>&1";
  Result r;
  FILE* pipe = popen(cmd.c_str(), "r");
  if (!pipe) return r;
  std::array<char, 4096> buf{};
  while (fgets(buf.data(), static_cast<int>(buf.size()), pipe)) r.out += buf.data();
  const int raw = pclose(pipe);
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  return r;
}

}  // namespace fragsim::test
