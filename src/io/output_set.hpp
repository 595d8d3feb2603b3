#pragma once
// Files that appear together or not at all (a run's CSV files, its report, its bakes). Each is
// written to a temporary file (AtomicFile); commit() first checks that every one was written whole,
// and only then renames them into place, so a full disk part way leaves none of the new files and
// every earlier one as it was.

#include <cstddef>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "io/atomic_file.hpp"

namespace fragsim {

class OutputSet {
 public:
  // Opens `path`'s temporary file and returns its stream; throws std::runtime_error naming the
  // path if it cannot be created.
  std::ostream& add(const std::string& path);
  // Adds `path` with `text` as its whole content.
  void add(const std::string& path, const std::string& text);

  std::size_t size() const { return files_.size(); }
  std::ostream& out(std::size_t i) { return files_[i]->out(); }
  const std::string& path(std::size_t i) const { return files_[i]->path(); }

  // Finishes every file, then renames each into place; throws std::runtime_error naming the file
  // that failed. A failure before the renames leaves no new file. A rename failing part way (rare:
  // the temporary files sit beside their targets) names the files already in place.
  void commit();

 private:
  std::vector<std::unique_ptr<AtomicFile>> files_;
};

}  // namespace fragsim
