#include "io/input_file.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>

namespace fragsim {

std::string read_input_file(const std::string& path, const std::string& what) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::exists(status)) throw InputError(path + ": no such " + what);
  if (std::filesystem::is_directory(status)) {
    throw InputError(path + ": is a directory, not a " + what);
  }
  // A device or a pipe could be endless (/dev/zero); inputs are files.
  if (!std::filesystem::is_regular_file(status)) {
    throw InputError(path + ": not a regular file, not a " + what);
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open " + what);
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError(path + ": cannot read " + what);
  std::string s = std::move(text).str();
  if (s.compare(0, 3, "\xEF\xBB\xBF") == 0) s.erase(0, 3);
  return s;
}

std::string without_carriage_returns(std::string text) {
  std::size_t out = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\r' && i + 1 < text.size() && text[i + 1] == '\n') continue;
    text[out++] = text[i];
  }
  text.resize(out);
  return text;
}

std::string read_text_file(const std::string& path, const std::string& what) {
  return without_carriage_returns(read_input_file(path, what));
}

}  // namespace fragsim
