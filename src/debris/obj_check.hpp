#pragma once
// The OBJ text checked before tinyobjloader reads it, for what that reader lets pass without a
// word. A vertex coordinate that is not a number ("nan", "inf", "abc", "1.2.3") becomes 0, a vertex
// with fewer than three coordinates gets 0 for the rest, and a face index beyond the vertices is
// known to it only after rebasing (-9 of 5 vertices comes out as -4). Here each is one line naming
// file:line and the token as written.

#include <string>

namespace fragsim {

// Throws InputError for the first bad `v` or `f` line of `text` (read from `path`). A coordinate
// must be a decimal number (a leading '+' allowed); one too large for a double (1e999) passes here
// and is refused as a non-finite vertex of its piece. A face's vertex index counts from 1 (when
// negative, back from the last vertex before its line) and must name a vertex of the file.
void check_obj_text(const std::string& text, const std::string& path);

}  // namespace fragsim
