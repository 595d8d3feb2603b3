#pragma once
// `fragsim render` (frames of one strategy's run as PNG files) and the contact sheet option of
// `fragsim compare` / `run` (--sheet FILE.png). Both draw from the snapshots of the run itself,
// kept by a FrameRecorder attached as an extra observer.

#include <boost/program_options.hpp>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "cli/command_line.hpp"
#include "render/frame_recorder.hpp"
#include "render/frame_renderer.hpp"
#include "sim/run_observer.hpp"

namespace fragsim::cli {

// Parses, runs the strategy with a recorder attached, writes DIR/frame_NNNNN.png for each chosen
// step. Returns the exit status; throws UsageError for bad input, before anything runs.
int cmd_render(const std::vector<std::string>& args);

// The option parsers, each throwing a one-line UsageError naming the option.
// "a:b:every", "a:b" or "a" for steps a to b inclusive, every `every`-th;
// 0 <= a <= b <= step_count.
std::vector<int> parse_steps(const std::string& spec, int step_count);
// "WIDTHxHEIGHT", each in [16, 8192].
std::pair<int, int> parse_size(const std::string& spec);
// Comma-separated candidates, forces, central, cuts ("" or "none" for no overlay); errors name
// `option`.
FrameOverlays parse_overlays(const std::string& spec, const std::string& option = "--overlays");

// --sheet FILE.png, --sheet-steps a,b,c and --sheet-overlays LIST for compare and run.
void add_sheet_options(boost::program_options::options_description& own);
struct SheetRequest {
  std::string path;
  std::vector<int> steps;
  FrameOverlays overlays;
};
// The request, validated (the file's folder must exist, the steps lie in the run); nullopt when
// --sheet is not given.
std::optional<SheetRequest> sheet_request(const ParsedCommand& p);
// Draws the sheet (rows in `strategies` order) and writes it whole or not at all.
void write_sheet(const SheetRequest& request, const Scene& scene, const FrameRecorder& recorder,
                 const std::vector<std::string>& strategies, std::ostream& out);

// Hands every event to each of several observers in order (compare takes one extra observer).
class ObserverFanOut final : public RunObserver {
 public:
  void add(RunObserver* o) {
    if (o) observers_.push_back(o);
  }
  // What to hand to compare(), this or null when nothing was added.
  RunObserver* or_null() { return observers_.empty() ? nullptr : this; }

  void begin(const RunInfo& info, const StepSnapshot& initial) override {
    for (RunObserver* o : observers_) o->begin(info, initial);
  }
  void observe(const StepSnapshot& snap) override {
    for (RunObserver* o : observers_) o->observe(snap);
  }
  void end() override {
    for (RunObserver* o : observers_) o->end();
  }

 private:
  std::vector<RunObserver*> observers_;
};

}  // namespace fragsim::cli
