#pragma once
// three.js (npm package `three`, MIT licence) as the build found it. scripts/install_three.sh puts
// the pinned version into build/npm, and the build embeds its single-file module build and its
// LICENSE into the binary (cmake/embed_text.cmake), so a report written anywhere carries the same
// bytes and opens offline. Nothing is read from disk at report time. A build without it (not
// installed when configuring, or FRAGSIM_THREE_JS=OFF) still writes reports, without the 3D view.

#include <string_view>

namespace fragsim {

struct BundledThreeJs {
  std::string_view version;    // "0.170.0"; empty when not bundled
  std::string_view module_js;  // build/three.module.min.js, one ES module with no imports
  std::string_view licence;    // the package's LICENSE file
  std::string_view missing;    // why it is not bundled (empty when it is)

  bool available() const { return !module_js.empty() && !licence.empty(); }
};

BundledThreeJs bundled_three_js();

// The viewer's script (src/report/report_viewer.js), embedded the same way.
std::string_view report_viewer_js();

}  // namespace fragsim
