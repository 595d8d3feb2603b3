#pragma once
// Text without the blanks around it, as every reader of fragsim's text formats (scene files, CSV
// tracks, --vary lists) takes a value. Spaces, tabs and line ends (a file saved on Windows ends
// its lines in \r\n) around a value are not part of it.

#include <string>

namespace fragsim {

std::string trim(const std::string& s);

}  // namespace fragsim
