#include "io/atomic_file.hpp"

#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace fragsim {
namespace {

// Temporary files and new output folders a signal handler may have to remove. The handler may
// only call async-signal-safe functions, so the paths live in fixed storage, claimed and released
// with atomics (there are a few dozen live output files and folders at most).
constexpr std::size_t kMaxLive = 64;
constexpr std::size_t kMaxPath = 4096;
std::array<std::atomic<bool>, kMaxLive> g_slot_used{};
std::array<bool, kMaxLive> g_slot_is_folder{};
std::array<std::array<char, kMaxPath>, kMaxLive> g_slot_path{};

int claim_slot(const std::string& path, bool is_folder) {
  if (path.size() >= kMaxPath) return -1;
  for (std::size_t i = 0; i < kMaxLive; ++i) {
    bool expected = false;
    if (g_slot_used[i].compare_exchange_strong(expected, true)) {
      std::memcpy(g_slot_path[i].data(), path.c_str(), path.size() + 1);
      g_slot_is_folder[i] = is_folder;
      return static_cast<int>(i);
    }
  }
  return -1;  // untracked, so only an interrupt's cleanup misses it
}

void release_slot(int slot) {
  if (slot >= 0) g_slot_used[static_cast<std::size_t>(slot)].store(false);
}

extern "C" void on_interrupt(int sig) {
  for (std::size_t i = 0; i < kMaxLive; ++i) {
    if (g_slot_used[i].load() && !g_slot_is_folder[i]) ::unlink(g_slot_path[i].data());
  }
  // A nested folder empties its parent only once it is gone itself, and slots are in no
  // particular order, so one pass per possible level removes every empty one. rmdir leaves a
  // folder that holds anything.
  for (std::size_t pass = 0; pass < kMaxLive; ++pass) {
    for (std::size_t i = 0; i < kMaxLive; ++i) {
      if (g_slot_used[i].load() && g_slot_is_folder[i]) ::rmdir(g_slot_path[i].data());
    }
  }
  // Die of the signal itself, as without this handler (a shell reads 128 + sig), so whoever
  // waits for fragsim sees how it ended.
  ::signal(sig, SIG_DFL);
  ::raise(sig);
}

}  // namespace

void remove_temporaries_on_interrupt() {
  struct sigaction action {};
  action.sa_handler = &on_interrupt;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

AtomicFile::AtomicFile(std::string path)
    : path_(std::move(path)), temp_path_(path_ + ".tmp." + std::to_string(::getpid())) {
  // A folder in the way would only show when renaming, after other files of the same output are
  // in place, so refuse it before anything is written.
  std::error_code ec;
  if (std::filesystem::is_directory(path_, ec)) throw std::runtime_error(path_ + ": is a folder");
  slot_ = claim_slot(temp_path_, false);
  out_.open(temp_path_, std::ios::binary | std::ios::trunc);
  if (!out_) {
    release_slot(slot_);
    throw std::runtime_error(path_ + ": cannot write (" + std::strerror(errno) + ")");
  }
}

AtomicFile::~AtomicFile() {
  if (!committed_) {
    out_.close();
    std::remove(temp_path_.c_str());
  }
  release_slot(slot_);
}

void AtomicFile::finish() {
  if (finished_) return;
  finished_ = true;
  out_.flush();
  const bool ok = static_cast<bool>(out_);
  out_.close();
  if (!ok || out_.fail()) {
    std::remove(temp_path_.c_str());
    committed_ = true;
    throw std::runtime_error(path_ + ": write failed (disk full?)");
  }
}

void AtomicFile::commit() {
  if (committed_) throw std::logic_error(path_ + ": committed twice");
  finish();
  if (std::rename(temp_path_.c_str(), path_.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    std::remove(temp_path_.c_str());
    committed_ = true;
    throw std::runtime_error(path_ + ": cannot rename into place (" + why + ")");
  }
  committed_ = true;
}

int track_created_folder(const std::string& path) {
  return claim_slot(path, true);
}

void forget_created_folder(int ticket) {
  release_slot(ticket);
}

void write_file_atomically(const std::string& path, const std::string& text) {
  AtomicFile f(path);
  f.out() << text;
  f.commit();
}

}  // namespace fragsim
