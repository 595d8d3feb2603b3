#pragma once
// The one door every input file comes through (scene files, camera tracks). A path that is a
// directory, cannot be opened or cannot be read is named in one line, and a UTF-8 byte-order mark
// (as some Windows editors save) is dropped so it is not glued to the first key or column name.

#include <string>

#include "io/input_error.hpp"

namespace fragsim {

// The whole text of the file at `path`, without a leading UTF-8 byte-order mark. `what` names the
// kind of file in messages ("scene file", "camera track"). Throws InputError.
std::string read_input_file(const std::string& path, const std::string& what);

// The same for the tool's own text files (scene files, camera tracks, slices, summaries), with
// Windows line ends ("\r\n", as an editor or a checkout on Windows saves them) made "\n", so no
// value or cell ends in a stray '\r'. Binary files (a .glb, a PNG) use read_input_file.
std::string read_text_file(const std::string& path, const std::string& what);

// `text` with every "\r\n" made "\n".
std::string without_carriage_returns(std::string text);

}  // namespace fragsim
