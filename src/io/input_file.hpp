#pragma once
// The one door every input file comes through (scene files, camera tracks): a path that is a
// directory, cannot be opened or cannot be read is named in one line, and a UTF-8 byte-order mark
// (as some Windows editors save) is dropped so it is not glued to the first key or column name.

#include <stdexcept>
#include <string>

namespace fragsim {

// A bad input file or setting. The message is one line naming file:line, the path or --option.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The whole text of the file at `path`, without a leading UTF-8 byte-order mark. `what` names the
// kind of file in messages ("scene file", "camera track"). Throws InputError.
std::string read_input_file(const std::string& path, const std::string& what);

}  // namespace fragsim
