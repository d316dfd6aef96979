#include "app/cli.hpp"

#include <algorithm>
#include <boost/program_options.hpp>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <limits>
#include <optional>
#include <sstream>
#include <tuple>

#include "scene/builtin_scenes.hpp"
#include "app/course_world.hpp"
#include "app/dump.hpp"
#include "app/headless.hpp"
#include "app/offscreen.hpp"
#include "scene/save.hpp"
#include "scene/scene_json.hpp"

namespace physics::Cli {
namespace po = boost::program_options;
namespace {

constexpr std::int64_t max_screenshot_pixels = std::int64_t{1} << 26;

[[noreturn]] void bad(const std::string& flag, const std::string& problem, const std::string& value) {
  throw UsageError(flag + ": " + problem + " (got '" + value + "')");
}

std::int64_t integer(const std::string& flag, const std::string& s, std::int64_t lo, std::int64_t hi) {
  std::int64_t v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc{} || end != s.data() + s.size() || v < lo || v > hi)
    bad(flag, "must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]", s);
  return v;
}

Overlays overlays(const std::string& s) {
  Overlays o;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, ',');) {
    if (item == "aabb") o.aabb = true;
    else if (item == "velocity") o.velocity = true;
    else if (item == "contacts") o.contacts = true;
    else if (item == "help") o.help = true;
    else if (item == "nohud") o.hud = false;
    else if (item == "times") o.times = true;
    else if (item == "all") o.aabb = o.velocity = o.contacts = true;
    else bad("--overlays", "must be a comma-separated list of aabb, velocity, contacts, help, nohud, times, all", s);
  }
  return o;
}

// The world keys that are flags (--dt, --gravity...), each from its row of
// the key table: its value's syntax and help.
void world_options(po::options_description& d) {
  for (const WorldFlag& f : world_flags()) {
    auto* value = po::value<std::string>()->value_name(f.value);
    if (f.boolean) value->implicit_value("on");
    d.add_options()(f.name.c_str(), value, f.help.c_str());
  }
}

// Each world flag given, read and checked through its row now (bad input
// before anything runs), kept as given for apply().
void world_values(const po::variables_map& vm, Overrides& ov) {
  for (const WorldFlag& f : world_flags()) {
    if (!vm.count(f.name)) continue;
    const std::string& text = vm[f.name].as<std::string>();
    SceneSpec scratch;
    try {
      read_world_flag(scratch, f.name, text);
    } catch (const SceneError& e) {
      throw UsageError(e.what());
    }
    ov.world.emplace_back(f.name, text);
  }
}

po::options_description descriptions() {
  po::options_description d("options");
  d.add_options()
      ("help,h", "print this help and exit")
      ("list-scenes", "list the built-in scenes, the scene files in scenes/ and the maps in scenes/maps/ (games "
       "marked), and exit")
      ("scene", po::value<std::string>()->value_name("NAME|FILE"),
       "a built-in scene (see --list-scenes; default many), a scene file (.json) or a map (.tmj, .ldtk)")
      ("course", "build the sheet's scenes (walls, drift, impulse, bounce, many) with the course's own functions "
       "(src/course/game.cpp) as the sheet's main program does, not from their descriptions (make exercise-run "
       "shows your answers so)")
      ("print-scene", "print the scene, with the values given here, as a scene file (JSON) and exit (no output "
       "or run flag with it)")
      ("headless", "run without a window and print a summary (also when there is no display)")
      ("frames", po::value<std::string>()->value_name("N"),
       "frames to run: headless default 600; in a window, quit after N (default: when the user quits)")
      ("threads", po::value<std::string>()->value_name("N"),
       "threads of the stable and auto solvers' loops and their broad phase (in [1, 64], default 1; the course "
       "solver runs on one): the same results, bit for bit, for any number (docs/performance.md)");
  world_options(d);
  d.add_options()
      ("seed", po::value<std::string>()->value_name("S"),
       "seed of the random generators (the k-th generator gets S + k)")
      ("dump", po::value<std::string>()->value_name("FILE.csv"),
       "write the final state as CSV: id,x,y,w,h,vx,vy,mass")
      ("events", po::value<std::string>()->value_name("FILE.csv"),
       "write the contact events of every step as CSV: frame,event,a,b,nx,ny,depth,jn,jt")
      ("save", po::value<std::string>()->value_name("FILE.json"),
       "write the final state as a scene file that runs on bit for bit (--scene FILE.json)")
      ("trace", po::value<std::string>()->value_name("FILE.csv"),
       "write every frame as CSV: frame,id,x,y,w,h,vx,vy,mass (frame 0 = the initial state)")
      ("screenshot", po::value<std::string>()->value_name("FILE.png"),
       "save the last frame as PNG (window, or offscreen when headless); 60 frames unless --frames")
      ("record", po::value<std::string>()->value_name("FILE"),
       "window: write every input event (keys, mouse) with its tick to FILE, an input log for --replay")
      ("replay", po::value<std::string>()->value_name("FILE"),
       "play an input log written by --record, in a window (live input only quits) or with --headless, with the "
       "same physics bit for bit; the scene is the log's unless --scene is given; --frames N stops after N steps")
      ("strict", "exit with code 3 when a body leaves the world (a non-finite value always does)")
      ("overlays", po::value<std::string>()->value_name("LIST"),
       "window overlays at start: aabb,velocity,contacts,help,nohud,times or all")
      ("style", po::value<std::string>()->value_name("plain|speed|sprite"),
       "drawing style (window and screenshots): the course's boxes (plain), movable blocks coloured by speed "
       "from blue at rest to red at 1 px/ms and above (speed), or a shape in each box by its tag (sprite)");
  return d;
}

// --print-scene prints and exits: a flag it would ignore (a file it would
// not write, a run it would not do) is refused rather than dropped silently.
// Two outputs naming one file would overwrite each other, and an output on
// the --replay log would destroy it: refused too.
void conflicts(const po::variables_map& vm) {
  if (vm.count("print-scene"))
    for (const char* flag : {"dump", "trace", "events", "save", "screenshot", "record", "replay", "headless",
                             "frames", "strict", "overlays", "course", "threads"})
      if (vm.count(flag))
        throw UsageError(std::string("--print-scene and --") + flag + ": --print-scene prints the scene and exits, "
                         "it would ignore --" + flag + " (give one of them)");
  const auto same_file = [](const std::string& a, const std::string& b) {
    std::error_code ec1, ec2;
    const auto pa = std::filesystem::weakly_canonical(std::filesystem::absolute(a), ec1);
    const auto pb = std::filesystem::weakly_canonical(std::filesystem::absolute(b), ec2);
    return ec1 || ec2 ? a == b : pa == pb;
  };
  const char* files[] = {"replay", "dump", "trace", "events", "save", "screenshot", "record"};
  for (std::size_t i = 0; i < std::size(files); ++i)
    for (std::size_t j = i + 1; j < std::size(files); ++j) {
      if (!vm.count(files[i]) || !vm.count(files[j])) continue;
      const std::string& a = vm[files[i]].as<std::string>();
      if (!same_file(a, vm[files[j]].as<std::string>())) continue;
      throw UsageError(std::string("--") + files[i] + " and --" + files[j] + " name one file (" + a + "): " +
                       (i == 0 ? "writing it would destroy the input log" : "give each output its own file"));
    }
}

// --course builds the sheet's scenes as its functions do: another scene, or
// a value they would not take (each body's restitution and friction are
// theirs), is refused rather than ignored.
void course_conflicts(const Options& o) {
  if (!CourseWorld::builds(o.scene)) {
    std::string names;
    for (const std::string_view n : CourseWorld::scenes()) names += (names.empty() ? "" : ", ") + std::string(n);
    throw UsageError("--course: the course's functions build the sheet's scenes (" + names + "), not '" + o.scene + "'");
  }
  for (const auto& [name, text] : o.overrides.world)
    if (name == "restitution" || name == "friction")
      throw UsageError("--course and --" + name + ": the course's functions give each body its own " + name +
                       " (give one of them)");
}

// The scene files to list: scenes/ in the working directory (where `make
// run` runs, and where --scene reads relative paths from), else the
// project's scenes/ beside the program (build/game, build/optO0/game), as a
// path from here so that it can be given to --scene. Empty if neither.
std::filesystem::path scenes_folder() {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::is_directory("scenes", ec)) return "scenes";
  fs::path dir = fs::read_symlink("/proc/self/exe", ec).parent_path();
  for (int up = 0; up < 3 && dir.has_relative_path(); ++up, dir = dir.parent_path())
    if (fs::is_directory(dir / "scenes", ec)) {
      // "../scenes" from build/; from farther away the whole path reads better.
      const fs::path near = (dir / "scenes").lexically_proximate(fs::current_path(ec));
      return std::distance(near.begin(), near.end()) <= 2 ? near : dir / "scenes";
    }
  return {};
}

// --list-scenes: the built-in scenes, then the scene files and the maps (a
// game's level marked by its kind), each with its "description". A file that does not
// read is listed with its error: the listing is not the place to stop.
void list_scenes(std::ostream& out) {
  out << "built-in scenes (--scene NAME):\n";
  for (const SceneSpec& s : builtin_scenes()) {
    std::string name = Headless::printable(s.name);
    name.resize(std::max<std::size_t>(name.size(), 10), ' ');
    out << "  " << name << Headless::printable(s.description) << "\n";
  }
  const std::filesystem::path dir = scenes_folder();
  if (dir.empty()) {
    out << "no scenes/ folder here or beside the program: run from the project's folder to list its scene files\n";
    return;
  }
  // The scene files, then the maps of scenes/maps/ (Tiled .tmj, LDtk .ldtk:
  // --scene reads them by name as it reads a scene file).
  std::vector<std::filesystem::path> files, maps;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(dir, ec))
    if (e.path().extension() == ".json") files.push_back(e.path());
  for (const auto& e : std::filesystem::directory_iterator(dir / "maps", ec))
    if (is_map_file(e.path().string())) maps.push_back(e.path());
  std::sort(files.begin(), files.end());
  std::sort(maps.begin(), maps.end());
  files.insert(files.end(), maps.begin(), maps.end());
  std::size_t width = 0;
  for (const auto& f : files) width = std::max(width, f.string().size() + 2);
  out << "scene files in " << dir.string() << "/ and maps in " << dir.string()
      << "/maps/ (--scene FILE; [game] marks a game's level):\n";
  for (const auto& f : files) {
    std::string path = f.string(), line;
    try {
      const SceneSpec s = read_scene_file(path);
      line = (s.game.kind.empty() ? "" : "[" + s.game.kind + "] ") + Headless::printable(s.description);
    } catch (const SceneError& e) {
      line = std::string("(does not read: ") + Headless::printable(e.what()) + ")";
    }
    path.resize(width, ' ');
    out << "  " << path << line << "\n";
  }
}

// Where the scene came from, for messages: its file, or "scene NAME".
std::string scene_source(const std::string& name_or_file) {
  return find_builtin(name_or_file) ? "scene " + name_or_file : name_or_file;
}

// The testbed's scenes: the built-ins, and a scene file joins them as the
// ninth; `current` is o.scene's. The window and a headless replay use the
// same list, so that a replayed digit or Tab picks the same scene.
std::vector<SceneSpec> testbed_scenes(const Options& o, std::size_t& current) {
  std::vector<SceneSpec> scenes(builtin_scenes().begin(), builtin_scenes().end());
  current = scenes.size();
  for (std::size_t i = 0; i < scenes.size(); ++i)
    if (scenes[i].name == o.scene) current = i;
  if (current == scenes.size()) scenes.push_back(resolve_scene(o.scene));
  return scenes;
}

// --strict: an escape exits with code 3 (after the summary and the files).
bool strict_failure(const World& w, const Options& o, std::ostream& err) {
  if (!o.strict || w.health.escaped == 0) return false;
  err << "game: --strict: " << w.health.escaped << " bod" << (w.health.escaped == 1 ? "y" : "ies")
      << " left the world (the first: body " << w.health.first_escape->id << ", by frame "
      << w.health.first_escape->frame << ")\n";
  return true;
}

// A world stopped on a non-finite value: no summary nor dump of a state that
// is not one (the trace keeps the frames before, which show how it came to
// this), the error line; exit 3.
bool stopped_non_finite(const World& w, Recorder& rec, std::ostream& err) {
  if (w.health.finite()) return false;
  rec.abandon();
  err << "game: " << Headless::non_finite_line(w) << "\n";
  return true;
}

// After a headless run's summary: the recorder's files, --strict, and the
// --screenshot in the scene's style. Returns the exit code.
int finish_files(const World& w, const SceneSpec& scene, std::span<const BlockRole> roles, const Options& o,
                 Recorder& rec, std::ostream& err) {
  rec.finish(w, scene, roles);
  if (strict_failure(w, o, err)) return 3;
  if (!o.screenshot.empty() &&
      !Offscreen::screenshot(w, scene.width, scene.height, o.screenshot, scene.style, roles)) {
    err << "game: --screenshot: cannot write " << o.screenshot << "\n";
    return exit_write_failed;
  }
  return 0;
}

// `bodies`: the scene's, from the one expand() (validation) of this load.
int headless_run(const SceneSpec& spec, const std::vector<Body>& bodies, const Options& o, Recorder& rec,
                 const std::string& why, std::ostream& out, std::ostream& err) {
  const bool picture = !o.screenshot.empty();
  World w = world_maker(o)(spec, bodies, picture && spec.systems.draw);
  rec.start(w);
  const std::int64_t frames = o.frames.value_or(picture ? screenshot_frames : headless_frames);
  const auto summary = Headless::run(w, frames, [&](const World& world) { rec.after_step(world); });
  if (stopped_non_finite(w, rec, err)) return 3;
  Headless::print_summary(out, w, summary, why, spec.name);
  return finish_files(w, spec, roles_by_entity(spec, bodies), o, rec, err);
}

// "won: coins 4/4 ...": how a game's level stands, and its HUD's first line.
std::string game_line(const Level& level, Level::Outcome outcome) {
  const char* state = outcome == Level::Outcome::won ? "won" : outcome == Level::Outcome::lost ? "lost" : "playing";
  const std::vector<std::string> hud = level.hud();
  return std::string(state) + (hud.empty() ? "" : ": " + hud.front());
}

// --replay --headless: the testbed the window would run, driven by the log
// tick by tick (Testbed::play) instead of by the clock, so the same code
// handles the events; --frames N stops after N steps (ticks). Also a game's
// headless run without --replay (an empty log).
int replay_run(const InputLog& log, const Options& o, Recorder& rec, const std::string& why, std::ostream& out,
               std::ostream& err) {
  std::size_t current = 0;
  std::vector<SceneSpec> scenes = testbed_scenes(o, current);
  Testbed tb(std::move(scenes), current, o.overrides, o.overlays, world_maker(o));
  Headless::Summary s;
  rec.start(tb.world());
  tb.on_step = [&](const World& w) {
    rec.after_step(w);
    if (tb.ticks() == 1) Headless::start_measures(s, w);
  };
  tb.on_reset = [&](const World&) { rec.restart(tb.world()); };
  tb.replay(log);
  tb.play(o.frames.value_or(std::numeric_limits<std::int64_t>::max()));
  World& w = tb.world();
  if (stopped_non_finite(w, rec, err)) return 3;
  Headless::end_measures(s, w, tb.ticks());
  Headless::print_summary(out, w, s, why, tb.scene().name);
  if (!o.replay.empty())
    out << "replay: " << tb.replayed() << " events over " << tb.ticks() << " ticks, ended at frame " << w.frame
        << "\n";
  if (const Level* level = tb.level()) out << "game: " << game_line(*level, tb.outcome()) << "\n";
  // Paused with events still to come: they can never be reached.
  if (tb.replayed() < log.events.size() && !(o.frames && tb.ticks() >= *o.frames))
    err << "warning: " << o.replay << ": the replay stopped paused at tick " << tb.ticks() << " with "
        << log.events.size() - tb.replayed() << " events left (logged to tick " << log.end
        << "): was it recorded on this scene with these options?\n";
  SceneSpec scene = tb.scene();
  apply(scene, o.overrides);
  return finish_files(w, scene, tb.roles(), o, rec, err);
}

// --replay: the log, read and checked before anything runs; without --scene
// its scene is the log's. --record: a window must be due (`why` says why
// not), and the file writable (like --dump). Returns 0, or 2 after one line
// on `err`.
int prepare_logs(Options& o, std::optional<InputLog>& log, const std::string& why, std::ostream& err) {
  if (!o.replay.empty()) {
    try {
      log = read_input_log(o.replay);
    } catch (const InputLogError& e) {
      err << "game: " << Headless::printable(e.what()) << "\n";
      return 2;
    }
    if (!o.scene_given && !log->scene.empty()) o.scene = log->scene;
  }
  if (!o.record.empty() && !why.empty()) {
    err << "game: --record: needs a window, and this run is headless (" << why << ")\n";
    return 2;
  }
  // Opened to append, not emptied: a run refused later (a bad --scene) leaves
  // an earlier log as it was; the log is written whole at the end.
  if (!o.record.empty() && !std::ofstream(o.record, std::ios::binary | std::ios::app)) {
    err << "game: --record: cannot write " << o.record << ": " << std::strerror(errno) << "\n";
    return 2;
  }
  return 0;
}

}  // namespace

std::string usage() {
  std::ostringstream o;
  o << "usage: game [--scene NAME|FILE] [--headless] [--frames N] [options]\n"
       "  Runs a scene of the 2D physics engine in a window (the testbed; H lists its keys,\n"
       "  Esc quits), or headless with a summary when --headless is given or there is no display.\n"
       "  Values given here override the scene's. Bad input exits with code 2; a non-finite\n"
       "  position or velocity stops the run with code 3 (also an escape, with --strict); an\n"
       "  output file that fails while written (a full disk) exits with code 4 after the run.\n\n"
    << descriptions()
    << "\nValues may follow the flag or an '=' (--gravity=0,-0.001 for a value starting with '-').\n"
       "\nGames (scene files with a \"game\" key, played in the window; docs/games.md):\n"
       "  build/game --scene scenes/maps/platformer.tmj   the platformer (a Tiled map): arrows run, Space or Up\n"
       "                                              jumps, Down+Space drops through, R restarts\n"
       "  build/game --scene scenes/targets-1.json    the target game: drag and release to launch, Enter after a\n"
       "                                              win for the next level (targets-2, targets-3)\n"
       "--list-scenes lists every scene: the built-in ones, the files in scenes/ and the maps in scenes/maps/.\n";
  return o.str();
}

Options parse(std::span<const std::string> args) {
  po::variables_map vm;
  try {
    std::vector<std::string> argv(args.begin(), args.end());
    po::store(po::command_line_parser(argv).options(descriptions()).positional({}).run(), vm);
    po::notify(vm);
  } catch (const po::too_many_positional_options_error&) {
    // Boost does not say which word: find the first one that no flag took.
    const auto& opts = descriptions();
    for (std::size_t i = 0; i < args.size(); ++i) {
      const std::string& a = args[i];
      if (a.starts_with("-")) {
        const std::string name = a.substr(a.find_first_not_of('-'), a.find('=') - a.find_first_not_of('-'));
        const auto* d = opts.find_nothrow(name, false);
        if (a.find('=') == std::string::npos && d && d->semantic()->max_tokens() > 0) ++i;  // its value
        continue;
      }
      throw UsageError("unexpected argument '" + a + "' (scenes are given with --scene; see --help)");
    }
    throw UsageError("unexpected argument (see --help)");
  } catch (const po::error& e) {
    throw UsageError(std::string(e.what()) + " (see --help)");
  }
  Options o;
  const auto has = [&](const char* k) { return vm.count(k) > 0; };
  const auto get = [&](const char* k) { return vm[k].as<std::string>(); };
  o.help = has("help");
  o.list_scenes = has("list-scenes");
  o.print_scene = has("print-scene");
  o.headless = has("headless");
  o.strict = has("strict");
  if (has("scene")) {
    o.scene = get("scene");
    o.scene_given = true;
    if (o.scene.empty()) throw UsageError("--scene: needs a scene name or a file");
  }
  if (has("frames")) o.frames = integer("--frames", get("frames"), 0, max_frames);
  if (has("threads")) o.threads = static_cast<int>(integer("--threads", get("threads"), 1, max_threads));
  Overrides& ov = o.overrides;
  world_values(vm, ov);
  if (has("seed")) {
    const std::string s = get("seed");
    std::uint64_t v = 0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc{} || end != s.data() + s.size()) bad("--seed", "must be an integer >= 0", s);
    ov.seed = v;
  }
  if (has("dump")) o.dump = get("dump");
  if (has("trace")) o.trace = get("trace");
  if (has("events")) o.events = get("events");
  if (has("save")) o.save = get("save");
  if (has("screenshot")) {
    o.screenshot = get("screenshot");
    std::string ext = std::filesystem::path(o.screenshot).extension().string();
    for (char& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    if (!o.screenshot.empty() && ext != ".png")
      bad("--screenshot", "only PNG is written: the name must end in .png", o.screenshot);
  }
  if (has("record")) o.record = get("record");
  if (has("replay")) o.replay = get("replay");
  if (has("record") && has("replay"))
    throw UsageError("--record and --replay: give one of them (a replay would record its own log again)");
  if (has("record") && o.headless) throw UsageError("--record: nothing to record in a --headless run (no input)");
  for (const char* flag : {"dump", "trace", "screenshot", "events", "save", "record", "replay"})
    if (vm.count(flag) && get(flag).empty()) throw UsageError("--" + std::string(flag) + ": a file name must not be empty");
  if (has("overlays")) o.overlays = overlays(get("overlays"));
  if (has("style")) {
    o.overrides.style = style_from_name(get("style"));
    if (!o.overrides.style) bad("--style", "must be plain, speed or sprite", get("style"));
  }
  conflicts(vm);
  o.course = has("course");
  if (o.course) course_conflicts(o);
  return o;
}

WorldMaker world_maker(const Options& o) {
  const WorldMaker make = o.course ? WorldMaker(CourseWorld::make) : WorldMaker(make_scene_world);
  if (o.threads == 1) return make;
  return [make, threads = o.threads](const SceneSpec& s, const std::vector<Body>& bodies, bool with_draw) {
    World w = make(s, bodies, with_draw);
    w.workers = Workers(threads);
    return w;
  };
}

SceneSpec resolve_scene(const std::string& name) {
  if (const SceneSpec* s = find_builtin(name)) return *s;
  const bool looks_like_file = name.find('/') != std::string::npos || name.ends_with(".json") || is_map_file(name);
  std::error_code ec;
  if (!looks_like_file && !std::filesystem::exists(name, ec)) {
    std::string list;
    for (const SceneSpec& s : builtin_scenes()) list += (list.empty() ? "" : ", ") + s.name;
    throw SceneError("unknown scene '" + name + "' (built-in scenes: " + list + "; or give a .json file)");
  }
  return read_scene_file(name);
}

Recorder::Recorder(const Options& o)
    : dump_path_(o.dump), trace_path_(o.trace), events_path_(o.events), save_path_(o.save) {
  const auto open = [](std::ofstream& f, const std::string& path, const char* flag, void (*header)(std::ostream&)) {
    if (path.empty()) return;
    f.open(path, std::ios::binary | std::ios::trunc);
    if (!f) throw UsageError(std::string(flag) + ": cannot write " + path + ": " + std::strerror(errno));
    f.precision(17);
    if (!header) return;
    errno = 0;
    header(f);
    if (!f.flush())
      throw UsageError(std::string(flag) + ": cannot write " + path + ": " +
                       (errno ? std::strerror(errno) : "write error"));
  };
  open(dump_, dump_path_, "--dump", Dump::write_header);
  open(trace_, trace_path_, "--trace", Dump::write_trace_header);
  open(events_, events_path_, "--events", Dump::write_events_header);
  open(save_, save_path_, "--save", nullptr);
}

void Recorder::start(World& w) {
  if (events_.is_open()) w.enable_events();
  if (trace_.is_open()) Dump::write_trace_rows(trace_, w);
}

void Recorder::after_step(const World& w) {
  if (trace_.is_open()) Dump::write_trace_rows(trace_, w);
  if (events_.is_open()) Dump::write_events(events_, w);
}

void Recorder::restart(World& w) {
  if (events_.is_open()) w.enable_events();
  if (trace_.is_open()) Dump::write_trace_rows(trace_, w);
}

void Recorder::abandon() {
  std::error_code ec;
  for (auto [file, path] : {std::pair{&dump_, &dump_path_}, {&save_, &save_path_}}) {
    if (!file->is_open()) continue;
    file->close();
    std::filesystem::remove(*path, ec);
  }
}

void Recorder::finish(const World& w, const SceneSpec& scene, std::span<const BlockRole> roles) {
  errno = 0;
  if (dump_.is_open()) Dump::write_rows(dump_, w);
  if (save_.is_open()) save_ << to_json(Save::scene_of(w, scene, roles, save_path_));
  for (auto [file, path, flag] : {std::tuple{&dump_, &dump_path_, "--dump"}, {&trace_, &trace_path_, "--trace"},
                                  {&events_, &events_path_, "--events"}, {&save_, &save_path_, "--save"}}) {
    if (!file->is_open()) continue;
    file->flush();
    if (!*file)
      throw WriteError(std::string(flag) + ": cannot write " + *path + ": " +
                       (errno ? std::strerror(errno) : "write error"));
  }
}

int run(std::span<const std::string> args, std::ostream& out, std::ostream& err, const WindowFrontEnd* window) {
  Options o;
  try {
    o = parse(args);
  } catch (const UsageError& e) {
    err << "game: " << Headless::printable(e.what()) << "\n";
    return 2;
  }
  if (o.help) {
    out << usage();
    return 0;
  }
  if (o.list_scenes) {
    list_scenes(out);
    return 0;
  }
  // Why the run is headless, if it is (empty: a window).
  std::string why = o.headless ? "--headless given"
                    : !window  ? "no window front end"
                    : !window->display_available() ? "no display (DISPLAY, WAYLAND_DISPLAY and SDL_VIDEODRIVER unset)"
                                                   : "";
  std::optional<InputLog> log;
  if (const int code = prepare_logs(o, log, why, err); code != 0) return code;
  SceneSpec spec;
  std::vector<Body> bodies;
  try {
    // Read (a file: JSON, keys, types), apply the flags, then validate once:
    // the scene that runs is the one checked, and its bodies build the world.
    spec = resolve_scene(o.scene);
    apply(spec, o.overrides);
    bodies = expand(spec, scene_source(o.scene));
    // Legitimate, but easy to write by mistake in a file: one line.
    if (!find_builtin(o.scene))
      if (const std::string w = overlap_warning(spec, bodies, o.scene); !w.empty()) err << Headless::printable(w) << "\n";
  } catch (const SceneError& e) {
    err << "game: " << Headless::printable(e.what()) << "\n";
    return 2;
  }
  if (o.print_scene) {
    out << to_json(spec);
    return 0;
  }
  if (!o.screenshot.empty() && std::int64_t{spec.width} * spec.height > max_screenshot_pixels) {
    err << "game: --screenshot: the " << spec.width << "x" << spec.height << " world is too large to save\n";
    return 2;
  }
  // Like --dump and --trace: an unwritable picture is refused before the run,
  // not after it.
  if (!o.screenshot.empty() && !std::ofstream(o.screenshot, std::ios::binary | std::ios::app)) {
    err << "game: --screenshot: cannot write " << o.screenshot << ": " << std::strerror(errno) << "\n";
    return 2;
  }
  try {
    Recorder rec(o);
    if (why.empty()) {
      Session session;
      session.scenes = testbed_scenes(o, session.current);
      session.options = o;
      session.recorder = &rec;
      session.err = &err;
      session.replay = log;
      try {
        return window->run(session);
      } catch (const NoWindow& e) {
        if (!o.record.empty()) throw UsageError(std::string("--record: needs a window: ") + e.what());
        err << "game: " << e.what() << "; running headless\n";
        why = std::string("window failed: ") + e.what();
        rec = Recorder(o);  // start the files again
      }
    }
    if (log) return replay_run(*log, o, rec, why, out, err);
    // A game's level runs in its testbed, so that its rules apply (the
    // platforms move, the level can be lost), with no input.
    if (!spec.game.kind.empty()) {
      InputLog idle;
      idle.end = o.frames.value_or(o.screenshot.empty() ? headless_frames : screenshot_frames);
      return replay_run(idle, o, rec, why, out, err);
    }
    return headless_run(spec, bodies, o, rec, why, out, err);
  } catch (const UsageError& e) {
    err << "game: " << Headless::printable(e.what()) << "\n";
    return 2;
  } catch (const SceneError& e) {
    err << "game: " << Headless::printable(e.what()) << "\n";
    return 2;
  } catch (const WriteError& e) {
    err << "game: " << Headless::printable(e.what()) << "\n";
    return exit_write_failed;
  } catch (const std::exception& e) {
    err << "game: " << Headless::printable(e.what()) << "\n";
    return 1;
  }
}

}  // namespace physics::Cli
