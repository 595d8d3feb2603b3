#include "report/bundled_three_js.hpp"

#if !defined(FRAGSIM_THREE_VERSION) || !defined(FRAGSIM_THREE_MISSING)
#error "FRAGSIM_THREE_VERSION, FRAGSIM_THREE_MISSING: set by CMakeLists.txt"
#endif

namespace fragsim {
namespace embedded {
// Generated at configure time (cmake/embed_text.cmake); empty when not bundled.
std::string_view three_module_js();
std::string_view three_licence();
std::string_view report_viewer_script();
}  // namespace embedded

BundledThreeJs bundled_three_js() {
  BundledThreeJs t;
  t.module_js = embedded::three_module_js();
  t.licence = embedded::three_licence();
  if (t.available()) {
    t.version = FRAGSIM_THREE_VERSION;
  } else {
    t.module_js = {};
    t.licence = {};
    t.missing = FRAGSIM_THREE_MISSING;
    if (t.missing.empty()) t.missing = "the build embedded an empty three.js";
  }
  return t;
}

std::string_view report_viewer_js() {
  return embedded::report_viewer_script();
}

}  // namespace fragsim
