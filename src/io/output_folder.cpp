#include "io/output_folder.hpp"

#include <filesystem>
#include <stdexcept>

#include "io/atomic_file.hpp"

namespace fragsim {

namespace fs = std::filesystem;

OutputFolder::OutputFolder(const std::string& dir, bool force) : dir_(dir) {
  std::error_code ec;
  if (fs::exists(dir, ec)) {
    if (!fs::is_directory(dir, ec)) throw std::runtime_error(dir + ": exists and is not a folder");
    if (!force && !fs::is_empty(dir, ec)) {
      throw std::runtime_error(dir + ": folder exists and is not empty (use --force to overwrite)");
    }
    return;
  }
  // One level at a time, outermost first, so each folder made here is known and can go.
  fs::path deepest = fs::path(dir).lexically_normal();
  if (!deepest.has_filename()) deepest = deepest.parent_path();  // "out/" names "out"
  std::vector<fs::path> missing;
  for (fs::path p = deepest; !p.empty() && !fs::exists(p, ec); p = p.parent_path()) {
    missing.push_back(p);
    if (p == p.parent_path()) break;
  }
  for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
    if (!fs::create_directory(*it, ec) && ec) {
      const std::string why = ec.message();
      release_tickets();
      for (auto made = created_.rbegin(); made != created_.rend(); ++made) fs::remove(*made, ec);
      throw std::runtime_error(dir + ": cannot create folder (" + why + ")");
    }
    created_.push_back(it->string());
    tickets_.push_back(track_created_folder(created_.back()));
  }
}

OutputFolder::~OutputFolder() {
  release_tickets();
  std::error_code ec;
  // Innermost first; fs::remove leaves a folder that is not empty (something not ours).
  for (auto it = created_.rbegin(); it != created_.rend(); ++it) fs::remove(*it, ec);
}

void OutputFolder::keep() {
  release_tickets();
  created_.clear();
}

void OutputFolder::release_tickets() {
  for (int t : tickets_) forget_created_folder(t);
  tickets_.clear();
}

}  // namespace fragsim
