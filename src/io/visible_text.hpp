#pragma once
// Text from an input quoted into a message, made visible. A NUL byte would end the message where
// it stands (what() is a C string) and other control characters garble the terminal, so each is
// written as an escape (\x00, \t, \r, \x1b). Every message that quotes what a file held goes
// through here.

#include <cstddef>
#include <string>

namespace fragsim {

// `text` with control characters (bytes below 0x20, and 0x7f) as C-style escapes; every
// other byte (UTF-8, a backslash) as it is. Longer than `max_chars`, it is
// cut there and ends in "...".
std::string visible_text(const std::string& text, std::size_t max_chars = 200);

}  // namespace fragsim
