#pragma once
// The one error type of bad input (a malformed or unreadable file, a setting out of its range, an
// unknown key or strategy). Its message is one line naming file:line, the path or --option. It is
// an std::invalid_argument because that is what it is to the code that passed the input, so every
// handler of bad arguments (the command line's, the sweep's) handles it without a case of its own.

#include <stdexcept>

namespace fragsim {

class InputError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

}  // namespace fragsim
