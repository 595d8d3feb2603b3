#pragma once
// Slices of a plan (`--shard K/N` of `fragsim sweep` and `fragsim suite`) and their merge
// (`fragsim merge`). A plan of M jobs in its fixed order is cut into N contiguous slices, slice K
// holding jobs [K M / N, (K + 1) M / N), so a job array on a cluster runs one slice per task and
// the slices' rows, joined in K order, are the unsharded file's rows in its order.

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace fragsim {

// A bad --shard or a set of slices that cannot be merged. One line; the caller names the option.
class ShardError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The most slices one plan may be cut into.
inline constexpr std::size_t kMaxShards = 1000000;

struct Shard {
  std::size_t index = 0;  // K, from 0
  std::size_t count = 1;  // N
};

// "K/N" with 0 <= K < N <= kMaxShards, plain decimal digits. Throws ShardError.
Shard parse_shard(const std::string& text);

// The jobs [begin, end) of slice `shard` of a plan of `jobs` jobs (empty when N > jobs).
struct JobRange {
  std::size_t begin = 0;
  std::size_t end = 0;
};
JobRange shard_range(std::size_t jobs, const Shard& shard);

// FNV-1a 64 of the bytes, as 16 lower-case hex digits.
std::string plan_fingerprint(const std::string& plan_text);

// Builds a plan's text for plan_fingerprint, each part length-prefixed, so no two different lists
// of parts give the same text.
class PlanText {
 public:
  PlanText& add(const std::string& part);
  PlanText& add(std::uint64_t number) { return add(std::to_string(number)); }
  const std::string& text() const { return text_; }

 private:
  std::string text_;
};

// What the first line of a slice file says.
struct SliceHeader {
  std::string command;  // "sweep" or "suite"
  Shard shard;
  std::string plan;  // fingerprint
  JobRange range;
  std::size_t total_jobs = 0;
  std::size_t rows = 0;  // CSV rows after the column header
};

// The slice line (with its '\n') for `csv`, the unsharded CSV of the slice's jobs.
std::string slice_line(const std::string& command, const Shard& shard, const std::string& plan,
                       std::size_t total_jobs, const std::string& csv);

// A slice file given to merge, with its name (for messages) and its bytes.
struct SliceFile {
  std::string name;
  std::string bytes;
};

// The merged CSV, the column header once, then every slice's rows in K order. Throws ShardError,
// one line naming the file (and line) at fault, for: no or a malformed slice line, slices of
// different commands, plans or numbers of slices, a slice given twice, slices missing, a column
// header or a row count that disagrees with the slice line. `command`, if given, gets the slices'
// command.
std::string merge_slices(const std::vector<SliceFile>& files, std::string* command = nullptr);

}  // namespace fragsim
