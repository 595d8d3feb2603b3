#pragma once
// Text for HTML and SVG, the five characters with a meaning in markup escaped, so scene names,
// strategy names and settings can never open a tag or end an attribute.

#include <string>
#include <string_view>

namespace fragsim {

// & < > " ' as entities; everything else as it is (UTF-8 passes through).
std::string html_escape(std::string_view text);

}  // namespace fragsim
