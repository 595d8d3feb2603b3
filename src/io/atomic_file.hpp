#pragma once
// An output file that appears whole or not at all, being written to a temporary file in the same
// folder and renamed over the target on commit(). Destroyed without commit (an exception, an early
// return), it removes the temporary file and leaves any old target untouched.

#include <fstream>
#include <string>

namespace fragsim {

class AtomicFile {
 public:
  // Throws std::runtime_error naming the path if the temporary file cannot be created.
  explicit AtomicFile(std::string path);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::ostream& out() { return out_; }
  // Flushes and closes the temporary file, and checks every write succeeded; throws naming the
  // path if not (a full disk shows here). Commit calls it; a set of files calls it on each before
  // renaming any (OutputSet), so a failure leaves none of them in place.
  void finish();
  // Finishes (if not yet) and renames into place; throws naming the path if either fails.
  void commit();
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::string temp_path_;
  std::ofstream out_;
  bool finished_ = false;
  bool committed_ = false;
  int slot_ = -1;  // where the interrupt handler finds the temporary path
};

// On SIGINT or SIGTERM, removes every temporary file of a live AtomicFile, then dies of the
// signal, so an interrupted run leaves the previous files or none, and no debris. (SIGKILL
// cannot be caught; its debris is named PATH.tmp.PID.) Call once, from main.
void remove_temporaries_on_interrupt();

// Marks `path`, a folder this process created for its output, for removal by the interrupt
// handler (after the temporary files, and only while empty). Returns a ticket for
// forget_created_folder, or -1 when there is no room to track it.
int track_created_folder(const std::string& path);
void forget_created_folder(int ticket);

// Writes `text` to `path` through an AtomicFile.
void write_file_atomically(const std::string& path, const std::string& text);

}  // namespace fragsim
