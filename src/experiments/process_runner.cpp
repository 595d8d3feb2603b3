#include "experiments/process_runner.hpp"

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <stdexcept>

namespace fragsim {
namespace {

// Frames on a worker's pipe: task index, status (0 ok, 1 error), length, bytes.
struct FrameHeader {
  std::uint64_t task;
  std::uint64_t status;
  std::uint64_t length;
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

[[noreturn]] void worker(int fd, int w, int jobs, std::size_t count,
                         const std::function<std::string(std::size_t)>& task) {
  for (std::size_t i = static_cast<std::size_t>(w); i < count;
       i += static_cast<std::size_t>(jobs)) {
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
  std::string buffer;  // bytes read, not yet a whole frame
};

std::string exit_text(int status) {
  if (WIFEXITED(status)) return "exited with status " + std::to_string(WEXITSTATUS(status));
  if (WIFSIGNALED(status)) return std::string("was killed by ") + strsignal(WTERMSIG(status));
  return "stopped";
}

}  // namespace

int online_cpus() {
  const long n = ::sysconf(_SC_NPROCESSORS_ONLN);
  return n > 0 ? static_cast<int>(n) : 1;
}

std::vector<std::string> run_in_processes(std::size_t count, int jobs,
                                          const std::function<std::string(std::size_t)>& task,
                                          const std::function<void(std::size_t done)>& on_done) {
  std::vector<std::string> results(count);
  if (jobs <= 1 || count <= 1) {
    for (std::size_t i = 0; i < count; ++i) {
      results[i] = task(i);
      if (on_done) on_done(i + 1);
    }
    return results;
  }
  jobs = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(jobs), count));
  std::vector<Worker> workers(static_cast<std::size_t>(jobs));
  auto stop_all = [&workers] {
    for (Worker& wk : workers) {
      if (wk.pid > 0) ::kill(wk.pid, SIGTERM);
    }
    for (Worker& wk : workers) {
      if (wk.fd >= 0) ::close(wk.fd);
      if (wk.pid > 0) ::waitpid(wk.pid, nullptr, 0);
      wk.pid = -1;
      wk.fd = -1;
    }
  };
  for (int w = 0; w < jobs; ++w) {
    int fds[2];
    if (::pipe(fds) != 0) {
      stop_all();
      throw std::runtime_error(std::string("cannot create a pipe: ") + std::strerror(errno));
    }
    const pid_t pid = ::fork();
    if (pid < 0) {
      ::close(fds[0]);
      ::close(fds[1]);
      stop_all();
      throw std::runtime_error(std::string("cannot fork: ") + std::strerror(errno));
    }
    if (pid == 0) {
      ::close(fds[0]);
      for (int o = 0; o < w; ++o) ::close(workers[static_cast<std::size_t>(o)].fd);
      worker(fds[1], w, jobs, count, task);
    }
    ::close(fds[1]);
    workers[static_cast<std::size_t>(w)] = {pid, fds[0], {}};
  }

  std::size_t done = 0;
  std::string failure;
  std::vector<pollfd> polls;
  while (failure.empty()) {
    polls.clear();
    for (const Worker& wk : workers) {
      if (wk.fd >= 0) polls.push_back({wk.fd, POLLIN, 0});
    }
    if (polls.empty()) break;
    if (::poll(polls.data(), polls.size(), -1) < 0) {
      if (errno == EINTR) continue;
      failure = std::string("poll failed: ") + std::strerror(errno);
      break;
    }
    for (Worker& wk : workers) {
      if (wk.fd < 0) continue;
      bool readable = false;
      for (const pollfd& p : polls) readable = readable || (p.fd == wk.fd && p.revents != 0);
      if (!readable) continue;
      char chunk[1 << 16];
      const ssize_t n = ::read(wk.fd, chunk, sizeof chunk);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {  // the worker closed its end: finished or died
        ::close(wk.fd);
        wk.fd = -1;
        continue;
      }
      wk.buffer.append(chunk, static_cast<std::size_t>(n));
      while (wk.buffer.size() >= sizeof(FrameHeader)) {
        FrameHeader h;
        std::memcpy(&h, wk.buffer.data(), sizeof h);
        if (wk.buffer.size() < sizeof h + h.length) break;
        std::string body = wk.buffer.substr(sizeof h, h.length);
        wk.buffer.erase(0, sizeof h + h.length);
        if (h.task >= count) {
          failure = "a worker sent a result for an unknown task";
        } else if (h.status != 0) {
          failure = "task " + std::to_string(h.task) + ": " + body;
        } else {
          results[h.task] = std::move(body);
          ++done;
          if (on_done) on_done(done);
        }
      }
    }
  }
  if (!failure.empty()) {
    stop_all();
    throw std::runtime_error(failure);
  }
  for (Worker& wk : workers) {
    int status = 0;
    ::waitpid(wk.pid, &status, 0);
    const pid_t pid = wk.pid;
    wk.pid = -1;
    if (!(WIFEXITED(status) && WEXITSTATUS(status) == 0) && failure.empty()) {
      failure = "worker process " + std::to_string(pid) + " " + exit_text(status);
    }
  }
  if (failure.empty() && done != count) {
    failure =
        "workers finished " + std::to_string(done) + " of " + std::to_string(count) + " tasks";
  }
  if (!failure.empty()) throw std::runtime_error(failure);
  return results;
}

}  // namespace fragsim
