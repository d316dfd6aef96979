// The command line: options, choosing the scene, the headless run, and the
// hand-over to the window front end. No SDL here: game.cpp's main() passes
// the window front end in; the tests pass none, and so run every headless
// path and every bad-input case in-process, without SDL linked at all.
//
// Exit codes: 0 done, 2 bad input (flag, value, scene name or scene file, an
// output that cannot be opened or written before the run), with one line on
// stderr naming the flag, file, key or line, and the problem; 3 a bad state
// (non-finite, or an escape with --strict); 4 an output file that could not
// be written at the end (a disk full: exit_write_failed); 1 any other
// failure at run time.
#pragma once

#include <cstdint>
#include <fstream>
#include <functional>
#include <iosfwd>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/input_log.hpp"
#include "scene/scene.hpp"
#include "app/testbed.hpp"

namespace physics::Cli {

inline constexpr std::int64_t headless_frames = 600;
inline constexpr int exit_write_failed = 4;
inline constexpr std::int64_t screenshot_frames = 60;  // --screenshot without --frames

struct Options {
  bool help = false, list_scenes = false, print_scene = false, headless = false;
  bool strict = false;  // an escape exits with code 3
  bool course = false;  // the sheet's scenes built by the course's functions (app/course_world.hpp)
  std::string scene{"many"};
  bool scene_given = false;  // --scene was given (else a replay runs on its log's scene)
  std::optional<std::int64_t> frames;
  int threads = 1;  // World::workers
  Overrides overrides;
  std::string dump, trace, screenshot, events, save;
  std::string record, replay;  // input logs (app/input_log.hpp)
  Overlays overlays;
};

// Bad flag or value: the message names the flag (main prefixes "game: ").
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};
// An output that failed while being written ("--save: cannot write F: No
// space left on device"): exit code exit_write_failed.
struct WriteError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// What builds the worlds of the run: --course's course functions, or make_world.
WorldMaker world_maker(const Options& o);

// Throws UsageError, also for flags that contradict each other: two outputs
// (or an output and --replay) naming one file, --print-scene with a flag it
// would ignore.
Options parse(std::span<const std::string> args);
std::string usage();

// A built-in name, else a file (a name that is neither is an error listing
// the built-in scenes). A file is read (read_scene_file), not yet validated:
// the caller applies its overrides, then expands (validates) once. Throws
// SceneError.
SceneSpec resolve_scene(const std::string& name_or_file);

// --dump, --trace, --events and --save files, opened before the run so that
// a bad path is bad input (exit 2) rather than a lost run; the CSV files'
// headers are written and flushed then too, so that a device that takes no
// data (/dev/full) is found before the run.
class Recorder {
 public:
  explicit Recorder(const Options& o);  // throws UsageError
  void start(World& w);             // trace: frame 0; events: enabled in w
  void after_step(const World& w);  // trace: this frame; events: this step's
  void restart(World& w);           // a new world (testbed reset): its frame 0, its events
  // dump: the final state; save: the world as the scene `scene` (it was made
  // from, after overrides) continued. Throws WriteError on I/O error.
  void finish(const World& w, const SceneSpec& scene, std::span<const BlockRole> roles);
  void abandon();                   // dump and save: removed, the run ended on a non-finite state

 private:
  std::string dump_path_, trace_path_, events_path_, save_path_;
  std::ofstream dump_, trace_, events_, save_;
};

// What the window front end runs: the testbed over `scenes`, starting at
// `current`, for `frames` frames (until the user quits if unset).
struct Session {
  std::vector<SceneSpec> scenes;
  std::size_t current = 0;
  Options options;
  Recorder* recorder = nullptr;
  std::ostream* err = nullptr;
  std::optional<InputLog> replay;  // --replay: read and checked
};

// Thrown by the front end when no window can be opened: the run goes on headless.
struct NoWindow : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct WindowFrontEnd {
  std::function<bool()> display_available;
  std::function<int(Session&)> run;
};

// The whole program but the window. `window` may be null (tests): then
// every run is headless.
int run(std::span<const std::string> args, std::ostream& out, std::ostream& err,
        const WindowFrontEnd* window = nullptr);

}  // namespace physics::Cli
