#include "io/output_set.hpp"

#include <stdexcept>

namespace fragsim {

std::ostream& OutputSet::add(const std::string& path) {
  files_.push_back(std::make_unique<AtomicFile>(path));
  return files_.back()->out();
}

void OutputSet::add(const std::string& path, const std::string& text) {
  add(path) << text;
}

void OutputSet::commit() {
  for (const std::unique_ptr<AtomicFile>& f : files_) f->finish();
  std::string renamed;
  for (const std::unique_ptr<AtomicFile>& f : files_) {
    try {
      f->commit();
    } catch (const std::runtime_error& e) {
      if (renamed.empty()) throw;
      throw std::runtime_error(std::string(e.what()) + "; already in place: " + renamed);
    }
    renamed += (renamed.empty() ? "" : ", ") + f->path();
  }
}

}  // namespace fragsim
