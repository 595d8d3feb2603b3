#pragma once
// The folder a command writes its files into (--csv DIR, --report DIR, --out DIR). A folder the
// command had to create is removed again when the command fails or is interrupted before keep():
// nothing of a failed output remains, not even an empty folder. A folder that existed is left as
// it was found.

#include <string>
#include <vector>

namespace fragsim {

class OutputFolder {
 public:
  // Creates `dir` and any missing parents. An existing folder with files in it is refused unless
  // `force`, as is a path that is not a folder (std::runtime_error naming the folder).
  OutputFolder(const std::string& dir, bool force);
  ~OutputFolder();
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;

  const std::string& path() const { return dir_; }
  // The output is complete, so the folder stays.
  void keep();

 private:
  void release_tickets();

  std::string dir_;
  std::vector<std::string> created_;  // outermost first
  std::vector<int> tickets_;          // the interrupt handler's, one per created folder
};

}  // namespace fragsim
