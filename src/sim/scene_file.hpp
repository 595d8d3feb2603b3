#pragma once
// Scene settings from a scene file (Boost.Program_options' INI syntax) and from the command line
// (--section.key value). One table of keys serves both, with every key's unit, default and range.
// The table is the scene's own keys (declared in scene_file.cpp) and every registered strategy's
// (declared in the strategy's own files, strategies/registry.hpp); the functions that take a
// StrategyTable use its strategies instead of the registry's (a test's table, say).

#include <boost/program_options/options_description.hpp>
#include <boost/program_options/parsers.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/input_file.hpp"
#include "sim/scene.hpp"
#include "strategies/registry.hpp"

namespace fragsim {

// A bad scene file or setting. The message is one line naming file:line or --option, the key,
// the value and what was expected.
class SceneError : public InputError {
 public:
  using InputError::InputError;
};

// Every scene key as a string-valued option, for the CLI's parser and its --help.
const boost::program_options::options_description& scene_options();
boost::program_options::options_description scene_options(const StrategyTable& table);

// A key set on the command line, with the name without dashes and its value.
struct SceneOverride {
  std::string key;
  std::string value;
};

// The scene keys among options parsed from a command line that included scene_options().
std::vector<SceneOverride> scene_overrides(const boost::program_options::parsed_options& parsed);

// Defaults, then the file (if `path` is not empty), then the overrides; validated as a whole. A
// rule across keys broken by a key the user set, against one left at its default, is reported at
// the key set (file:line or --option). With `warnings`, gets one line each (without the
// "warning: " prefix) for a camera track that does not cover the run (camera_track_file.hpp)
// and for a key set in the file or as an override that has no effect in the modes chosen
// (key_relevance.hpp), naming where it was set; a file written by scene_to_ini holds every key
// and gets no warning of the second kind.
Scene load_scene(const std::string& path, const std::vector<SceneOverride>& overrides = {},
                 std::vector<std::string>* warnings = nullptr);

// The same from a string holding a scene file's text; `origin` names it in messages.
Scene parse_scene(const std::string& text, const std::string& origin,
                  const std::vector<SceneOverride>& overrides = {},
                  std::vector<std::string>* warnings = nullptr);
Scene parse_scene(const std::string& text, const std::string& origin,
                  const std::vector<SceneOverride>& overrides, const StrategyTable& table);

// The fully resolved scene as a scene file, which reads back as the same Scene bit for bit.
std::string scene_to_ini(const Scene& scene);
std::string scene_to_ini(const Scene& scene, const StrategyTable& table);

// Checks across keys (near < far, look_at off the path, ...), the strategies' included. Throws
// SceneError.
void validate_scene(const Scene& scene, const StrategyTable& table = strategy_table());

}  // namespace fragsim
