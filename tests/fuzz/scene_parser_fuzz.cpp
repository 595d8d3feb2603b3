// libFuzzer target: the bytes are a scene file's text for parse_scene.
//
// Invariants, each a __builtin_trap() when broken:
//  - bad input throws SceneError and nothing else (any other exception is a bug);
//  - a scene that parses is written by scene_to_ini as a file that parses again and is written
//    back as the same text (the round trip is exact).
// Crashes, sanitizer reports, leaks and hangs (-timeout) are reported by libFuzzer itself.

#include <cstddef>
#include <cstdint>
#include <string>

#include "sim/scene_file.hpp"

namespace {

fragsim::Scene parse_or_trap(const std::string& text, const std::string& origin, bool* ok) {
  *ok = false;
  try {
    fragsim::Scene scene = fragsim::parse_scene(text, origin);
    *ok = true;
    return scene;
  } catch (const fragsim::SceneError&) {
    return {};
  } catch (...) {
    __builtin_trap();  // only SceneError may leave parse_scene on bad input
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  bool ok = false;
  const fragsim::Scene scene = parse_or_trap(text, "fuzz.ini", &ok);
  if (!ok) return 0;

  const std::string ini = fragsim::scene_to_ini(scene);
  const fragsim::Scene back = parse_or_trap(ini, "roundtrip.ini", &ok);
  if (!ok) __builtin_trap();  // a resolved scene must read back
  if (fragsim::scene_to_ini(back) != ini) __builtin_trap();
  return 0;
}
