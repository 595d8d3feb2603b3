#pragma once
// Independent tasks in forked worker processes, results back in task order. Processes, never
// threads: Debian's ODE is built without per-thread collision storage, so two worlds must not be
// stepped from two threads of one process (and ODE's own thread pool was 8-10x slower on 2 cores).

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace fragsim {

// Runs task(i) for i in [0, count) on `jobs` worker processes (task i on worker i % jobs) and
// returns the strings they produced, in task order, so the result never depends on `jobs`. With
// jobs <= 1 or a single task everything runs in this process. A worker that throws, exits or is
// killed makes this throw std::runtime_error naming the task (after stopping the others).
// Call it with no output file open for writing that a child could corrupt by exiting: children
// leave through _exit and never run destructors or atexit handlers.
// `on_done`, if set, is called in this process with the number of tasks finished so far each time
// one finishes (for a progress line; results may finish out of order).
std::vector<std::string> run_in_processes(
    std::size_t count, int jobs, const std::function<std::string(std::size_t)>& task,
    const std::function<void(std::size_t done)>& on_done = nullptr);

// The number of online processors (at least 1).
int online_cpus();

}  // namespace fragsim
