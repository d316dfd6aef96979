// The command line: flags, dumps and traces, and bad input (exit code 2 with
// one line naming the flag, file, key or line). Most cases run Cli::run
// in-process, without any window front end and without SDL linked; a few run
// the real program (build/game) to check what a user sees, including the
// window path under SDL's dummy video driver.
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <charconv>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "scene/builtin_scenes.hpp"
#include "app/cli.hpp"
#include "app/dump.hpp"
#include "app/headless.hpp"
#include "course/entities/block.hpp"
#include "cli_helpers.hpp"
#include "scene/keys.hpp"
#include "scene/scene_json.hpp"

#include "png_decode.hpp"

// The file's own names, apart from the other test files' with which it is
// compiled (Makefile, TEST_UNITY).
namespace test_cli {

using namespace physics;
using namespace physics::test;
namespace fs = std::filesystem;

namespace {

std::vector<std::vector<std::string>> csv(const std::string& text) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    rows.emplace_back();
    std::istringstream cells(line);
    for (std::string c; std::getline(cells, c, ',');) rows.back().push_back(c);
  }
  return rows;
}

double number(const std::string& s) {
  double v = 0;
  std::from_chars(s.data(), s.data() + s.size(), v);
  return v;
}

std::string scene_file(const std::string& name) {
  return (fs::path(__FILE__).parent_path().parent_path() / "scenes" / (name + ".json")).string();
}

// The pixels of a PNG, decoded by stb_image (libstb-dev, like the writer):
// enough to compare two screenshots.
struct Picture {
  std::uint32_t width = 0, height = 0;
  std::vector<std::uint8_t> rgb;
};
Picture read_png(const std::string& path) {
  int w = 0, h = 0, channels = 0;
  std::uint8_t* data = stbi_load(path.c_str(), &w, &h, &channels, 3);
  if (data == nullptr) return {};
  Picture p{std::uint32_t(w), std::uint32_t(h), std::vector<std::uint8_t>(data, data + std::size_t(w) * h * 3)};
  stbi_image_free(data);
  return p;
}

bool is_png(const std::string& path) {
  const std::string head = read(path).substr(0, 8);
  return head == "\x89PNG\r\n\x1a\n";
}

// The line of --list-scenes whose first word is `name` (a scene file's
// path may start with the folder it was found in), or "".
std::string listed(const std::string& out, const std::string& name) {
  std::istringstream in(out);
  for (std::string line; std::getline(in, line);) {
    std::istringstream words(line);
    std::string first;
    words >> first;
    if (first == name || first.ends_with("/" + name)) return line;
  }
  return "";
}

}  // namespace

BOOST_AUTO_TEST_SUITE(cli_flags)

BOOST_AUTO_TEST_CASE(help_documents_every_flag) {
  const Ran r = cli({"--help"});
  BOOST_TEST(r.code == 0);
  for (const char* flag : {"--scene", "--headless", "--frames", "--dt", "--substeps", "--gravity", "--restitution",
                           "--seed", "--dump", "--trace", "--screenshot", "--ccd", "--solver", "--iterations", "--integrator",
                           "--list-scenes", "--print-scene", "--overlays", "--friction", "--events", "--save", "--threads"})
    BOOST_TEST(has(r.out, flag), flag);
}

// The world keys' flags come from the key table: each marked row is an
// option, with its range and default in the help, and reads as the row does.
BOOST_AUTO_TEST_CASE(world_flags_are_the_key_tables_rows) {
  std::string help;  // Boost wraps the help: one space for each run of blanks
  for (const char c : cli({"--help"}).out)
    if (!std::isspace(static_cast<unsigned char>(c)) || (!help.empty() && help.back() != ' '))
      help += std::isspace(static_cast<unsigned char>(c)) ? ' ' : c;
  std::vector<std::string> names;
  for (const auto& k : scene_io::world_keys()) {
    if (!k.doc.flag) continue;
    names.emplace_back(k.doc.name());
    BOOST_TEST(has(help, "--" + names.back() + " "), names.back());
    const std::string range = k.doc.range.empty() ? "(" : "in " + std::string(k.doc.range) + ", ";
    if (k.doc.type != "string") BOOST_TEST(has(help, range + "default " + std::string(k.doc.fallback)), names.back());
  }
  BOOST_TEST(has(help, "(in [0, 1], default 1.0); given here, it also replaces every block's own"), help);
  BOOST_TEST(names == (std::vector<std::string>{"dt", "substeps", "gravity", "restitution", "ccd", "solver",
                                                "iterations", "friction", "integrator"}),
             boost::test_tools::per_element());
  BOOST_TEST(has(help, "--ccd alone means on"));
  BOOST_TEST(has(help, "--solver course|stable|auto"));
  expect_bad({"--width", "100"}, "unrecognised option '--width'");  // a world key, but no flag
  expect_bad({"--substeps", "1e3"}, "--substeps: must be an integer in [1, 1000] (got '1e3')");
}

BOOST_AUTO_TEST_CASE(list_scenes_names_every_builtin_and_every_scene_file) {
  const Ran r = cli({"--list-scenes"});
  BOOST_TEST(r.code == 0);
  for (const SceneSpec& s : builtin_scenes()) BOOST_TEST(has(listed(r.out, s.name), s.description), s.name);
  // Every file of the project's scenes/ (found here or beside the program),
  // with its own description; a game's level is marked by its kind.
  std::size_t files = 0;
  for (const auto& e : fs::directory_iterator(fs::path(scene_file("x")).parent_path())) {
    if (e.path().extension() != ".json") continue;
    ++files;
    const SceneSpec s = read_scene_file(e.path().string());
    const std::string line = listed(r.out, "scenes/" + e.path().filename().string());
    BOOST_TEST(has(line, s.description), e.path().filename() << ": " << line);
    BOOST_TEST(has(line, "[") == !s.game.kind.empty(), line);
  }
  BOOST_TEST(files >= 15u);
  // Then every map of scenes/maps/, a Tiled or LDtk file, as --scene reads it.
  std::size_t maps = 0;
  for (const auto& e : fs::directory_iterator(fs::path(scene_file("x")).parent_path() / "maps")) {
    if (e.path().extension() != ".tmj" && e.path().extension() != ".ldtk") continue;
    ++maps;
    const SceneSpec s = read_scene_file(e.path().string());
    const std::string line = listed(r.out, "scenes/maps/" + e.path().filename().string());
    BOOST_TEST(!s.description.empty(), e.path().filename());
    BOOST_TEST(has(line, s.description), e.path().filename() << ": " << line);
  }
  BOOST_TEST(maps >= 2u);
  BOOST_TEST(!has(r.out, "props.tsj"));  // a tileset is not a scene
  BOOST_TEST(has(listed(r.out, "scenes/targets-2.json"), "[targets] the target game, level 2"));
}

BOOST_AUTO_TEST_CASE(help_names_the_games_and_how_to_run_them) {
  const Ran r = cli({"--help"});
  BOOST_TEST(has(r.out, "build/game --scene scenes/maps/platformer.tmj"), r.out);
  BOOST_TEST(has(r.out, "build/game --scene scenes/targets-1.json"));
  BOOST_TEST(has(r.out, "--list-scenes lists every scene"));
}

BOOST_AUTO_TEST_CASE(the_default_is_the_many_scene_headless_without_a_front_end) {
  const Ran r = cli({"--frames", "10"});
  BOOST_TEST(r.code == 0);
  BOOST_TEST(has(r.out, "ran headless: no window front end"));
  BOOST_TEST(has(r.out, "scene:           many"));
  BOOST_TEST(has(r.out, "frames:          10"));
  BOOST_TEST(has(r.out, "bodies:          15 (11 mobile)"));
}

BOOST_AUTO_TEST_CASE(command_line_values_override_the_scene) {
  const Ran r = cli({"--scene", "bounce", "--headless", "--frames", "3", "--dt", "5", "--substeps", "2"});
  BOOST_TEST(r.code == 0);
  BOOST_TEST(has(r.out, "dt = 5 ms, 2 substep(s)"), r.out);
  const Ran p = cli({"--scene", "gas", "--print-scene", "--ccd", "--solver", "stable", "--iterations", "5",
                     "--gravity=0,-0.001", "--restitution", "0.5", "--seed", "9"});
  BOOST_TEST_REQUIRE(p.code == 0);
  const SceneSpec s = parse_scene(p.out, "printed.json");
  BOOST_TEST(s.params.ccd);
  BOOST_TEST((s.params.solver == Solver::stable));
  BOOST_TEST(s.params.iterations == 5);
  BOOST_TEST(s.params.gravity.y == -0.001);
  BOOST_TEST(s.restitution == 0.5);
  BOOST_TEST(std::get<RandomSpec>(s.blocks[0]).seed == 9u);
  const Ran off = cli({"--scene", "gas", "--print-scene", "--ccd=off"});
  BOOST_TEST(!parse_scene(off.out, "p.json").params.ccd);
}

BOOST_AUTO_TEST_CASE(integrator_flag_sets_the_scenes_integrator) {
  const Ran p = cli({"--scene", "bounce", "--print-scene", "--integrator", "exact"});
  BOOST_TEST_REQUIRE(p.code == 0, p.err);
  BOOST_TEST((parse_scene(p.out, "printed.json").params.integrator == Integrator::exact));
  const Ran course = cli({"--scene", "bounce", "--print-scene", "--integrator=course"});
  BOOST_TEST((parse_scene(course.out, "printed.json").params.integrator == Integrator::course));
  const Ran run = cli({"--scene", "bounce", "--headless", "--frames", "3", "--integrator", "exact"});
  BOOST_TEST(run.code == 0, run.err);
  BOOST_TEST(has(run.out, "1 substep(s), exact integrator)"), run.out);
  BOOST_TEST(!has(cli({"--scene", "bounce", "--headless", "--frames", "3"}).out, "integrator"));
  expect_bad({"--integrator", "verlet"}, "--integrator: must be \"course\" or \"exact\" (got 'verlet')");
  expect_bad({"--integrator", "Exact"}, "--integrator: must be \"course\" or \"exact\" (got 'Exact')");
}

// --frames 0 runs nothing: the summary says so instead of "after frame 1".
BOOST_AUTO_TEST_CASE(zero_frames_says_no_frame_ran) {
  const Ran r = cli({"--scene", "many", "--headless", "--frames", "0"});
  BOOST_TEST(r.code == 0, r.err);
  BOOST_TEST(has(r.out, "frames:          0 "), r.out);
  BOOST_TEST(has(r.out, "kinetic energy:  0 (no frame ran)"), r.out);
  BOOST_TEST(has(r.out, "(no frame ran)\nescaped:"), r.out);
  BOOST_TEST(!has(r.out, "after frame 1"), r.out);
  const Ran one = cli({"--scene", "many", "--headless", "--frames", "1"});
  BOOST_TEST(has(one.out, "after frame 1"), one.out);
}

BOOST_AUTO_TEST_CASE(the_seed_changes_the_random_scene) {
  TempDir dir;
  const auto a = dir.file("a.csv"), b = dir.file("b.csv"), c = dir.file("c.csv");
  BOOST_TEST(cli({"--frames", "0", "--dump", a}).code == 0);
  BOOST_TEST(cli({"--frames", "0", "--dump", b, "--seed", "42"}).code == 0);
  BOOST_TEST(cli({"--frames", "0", "--dump", c, "--seed", "43"}).code == 0);
  BOOST_TEST(read(a) == read(b));
  BOOST_TEST(read(a) != read(c));
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(cli_dump_trace)

BOOST_AUTO_TEST_CASE(dump_is_the_final_state_exactly) {
  TempDir dir;
  const auto path = dir.file("final.csv");
  const Ran r = cli({"--scene", "many", "--frames", "120", "--dump", path});
  BOOST_TEST_REQUIRE(r.code == 0);
  World w = make_world(*find_builtin("many"), false);
  for (int i = 0; i < 120; ++i) Game::step(w);
  const auto rows = csv(read(path));
  BOOST_TEST_REQUIRE(rows.size() == 1 + w.components.size());
  const std::vector<std::string> header{"id", "x", "y", "w", "h", "vx", "vy", "mass"};
  BOOST_TEST(rows[0] == header, boost::test_tools::per_element());
  for (std::size_t e = 0; e < w.components.size(); ++e) {
    const auto& row = rows[e + 1];
    BOOST_TEST_REQUIRE(row.size() == 8u);
    BOOST_TEST(row[0] == std::to_string(e));  // creation order, walls first
    // Full precision: every number reads back as the same double.
    BOOST_TEST(number(row[1]) == w.components.position[e].x);
    BOOST_TEST(number(row[2]) == w.components.position[e].y);
    BOOST_TEST(row[3] == std::to_string(w.components.box[e].width));
    BOOST_TEST(row[4] == std::to_string(w.components.box[e].height));
    BOOST_TEST(number(row[5]) == w.components.velocity[e].x);
    BOOST_TEST(number(row[6]) == w.components.velocity[e].y);
    if (e < 4) BOOST_TEST(row[7] == "inf");
    else BOOST_TEST(number(row[7]) == w.components.mass[e]);
  }
}

// --events: the CSV of the contact events, in the header's columns; two
// blocks meeting head on give one begin and one end for their pair.
BOOST_AUTO_TEST_CASE(events_are_written_as_csv) {
  TempDir dir;
  const auto scene = dir.file("two.json", R"({"world": {"walls": false}, "blocks": [
    {"pos": [100, 100], "size": [40, 40], "mass": 1, "velocity": [0.3, 0]},
    {"pos": [300, 100], "size": [40, 40], "mass": 1, "velocity": [-0.3, 0]}]})");
  const auto path = dir.file("events.csv");
  const Ran r = cli({"--scene", scene, "--frames", "120", "--solver", "stable", "--events", path});
  BOOST_TEST_REQUIRE(r.code == 0);
  const auto rows = csv(read(path));
  BOOST_TEST_REQUIRE(rows.size() == 3u);
  const std::vector<std::string> header{"frame", "event", "a", "b", "nx", "ny", "depth", "jn", "jt"};
  BOOST_TEST(rows[0] == header, boost::test_tools::per_element());
  BOOST_TEST(rows[1][1] == "begin");
  BOOST_TEST(rows[2][1] == "end");
  BOOST_TEST((rows[1][2] == "0" && rows[1][3] == "1" && rows[1][4] == "-1" && rows[1][5] == "0"));
  BOOST_TEST(number(rows[1][7]) == 0.6);  // m·2v, exchanged in the step it began
  BOOST_TEST(std::stoi(rows[1][0]) < std::stoi(rows[2][0]));
}

// --save writes a scene file; --scene on it runs on to the same dump as a
// run that never stopped.
BOOST_AUTO_TEST_CASE(a_saved_run_continues_bit_for_bit) {
  TempDir dir;
  for (const std::vector<std::string>& mode : {std::vector<std::string>{"--solver", "course"},
                                              {"--solver", "stable", "--friction", "0.5"}, {"--ccd", "on"}}) {
    const auto whole = dir.file("whole.csv"), rest = dir.file("rest.csv"), saved = dir.file("saved.json");
    std::vector<std::string> a{"--scene", "stack", "--frames", "600", "--dump", whole};
    std::vector<std::string> b{"--scene", "stack", "--frames", "300", "--save", saved};
    a.insert(a.end(), mode.begin(), mode.end());
    b.insert(b.end(), mode.begin(), mode.end());
    BOOST_TEST_REQUIRE(cli(a).code == 0);
    BOOST_TEST_REQUIRE(cli(b).code == 0);
    BOOST_TEST(has(read(saved), "\"state\""));
    BOOST_TEST_REQUIRE(cli({"--scene", saved, "--frames", "300", "--dump", rest}).code == 0);
    BOOST_TEST(read(rest) == read(whole));
  }
}

BOOST_AUTO_TEST_CASE(numbers_round_trip) {
  for (const double v : {0.1, 1.0 / 3.0, 16.666666666666668, -2.5e-300, 123456789.125}) {
    const std::string s = Dump::number(v);
    BOOST_TEST(number(s) == v, s);
  }
  BOOST_TEST(Dump::number(infinity) == "inf");
  BOOST_TEST(Dump::number(100.0) == "100");
}

BOOST_AUTO_TEST_CASE(trace_has_every_frame_and_ends_on_the_dump) {
  TempDir dir;
  const auto trace = dir.file("trace.csv"), dump = dir.file("dump.csv");
  BOOST_TEST_REQUIRE(cli({"--scene", "bounce", "--frames", "30", "--trace", trace, "--dump", dump}).code == 0);
  const auto rows = csv(read(trace));
  const std::size_t n = 6;  // 4 walls + the red block + the platform
  BOOST_TEST_REQUIRE(rows.size() == 1 + 31 * n);
  const std::vector<std::string> header{"frame", "id", "x", "y", "w", "h", "vx", "vy", "mass"};
  BOOST_TEST(rows[0] == header, boost::test_tools::per_element());
  BOOST_TEST(rows[1][0] == "0");  // the initial state
  BOOST_TEST(rows[1 + 4][2] == "100");
  BOOST_TEST(rows.back()[0] == "30");
  // The last frame's rows are the dump's rows with the frame in front.
  const auto final_rows = csv(read(dump));
  for (std::size_t e = 0; e < n; ++e) {
    std::vector<std::string> row(rows[rows.size() - n + e].begin() + 1, rows[rows.size() - n + e].end());
    BOOST_TEST(row == final_rows[1 + e], boost::test_tools::per_element());
  }
}

BOOST_AUTO_TEST_CASE(scene_files_give_the_same_dump_as_the_builtins) {
  TempDir dir;
  for (const SceneSpec& s : builtin_scenes()) {
    const auto a = dir.file(s.name + "-builtin.csv"), b = dir.file(s.name + "-file.csv");
    BOOST_TEST_REQUIRE(cli({"--scene", s.name, "--frames", "200", "--dump", a}).code == 0);
    BOOST_TEST_REQUIRE(cli({"--scene", scene_file(s.name), "--frames", "200", "--dump", b}).code == 0);
    BOOST_TEST(read(a) == read(b), s.name);
    BOOST_TEST(read(a).size() > 30u);
  }
}

BOOST_AUTO_TEST_CASE(headless_screenshot_is_an_offscreen_png) {
  TempDir dir;
  const auto png = dir.file("shot.png");
  const Ran r = cli({"--scene", "bounce", "--headless", "--screenshot", png});
  BOOST_TEST(r.code == 0);
  BOOST_TEST(has(r.out, "frames:          60"));  // --screenshot alone runs 60 frames
  BOOST_TEST(is_png(png));
}

BOOST_AUTO_TEST_SUITE_END()

// One case per kind of bad input the issue lists for flags and scenes.
BOOST_AUTO_TEST_SUITE(cli_bad_input)

BOOST_AUTO_TEST_CASE(unknown_flags_and_missing_values) {
  expect_bad({"--sceen", "many"}, "unrecognised option '--sceen'");
  expect_bad({"--frames"}, "--frames");
  expect_bad({"many"}, "unexpected argument 'many' (scenes are given with --scene");
  expect_bad({"--frames", "3", "many"}, "unexpected argument 'many'");
  expect_bad({"--dt=5", "--headless", "x"}, "unexpected argument 'x'");
  expect_bad({"--dt", "1", "--dt", "2"}, "--dt");
}

// A load validates the scene once: after the flags are applied, and the
// world is built from the bodies of that validation (no second check in
// the reader, none in make_world).
BOOST_AUTO_TEST_CASE(a_scene_file_is_validated_once) {
  TempDir dir;
  const auto file = dir.file("ok.json", R"({"blocks": [{"pos": [100, 100], "size": [4, 4], "mass": 1},
                                                     {"grid": {"pos": [200, 200], "size": [4, 4], "mass": 1,
                                                               "count": [3, 2]}}]})");
  for (const std::string& scene : {file, std::string("many")}) {
    const std::int64_t before = validation_count();
    const Ran r = cli({"--scene", scene, "--headless", "--frames", "0", "--restitution", "0.5"});
    BOOST_TEST(r.code == 0, r.err);
    BOOST_TEST(validation_count() - before == 1, scene);
  }
}

// Overlapping blocks in a file are legitimate: the run goes on, with one
// warning line naming the first pair.
BOOST_AUTO_TEST_CASE(overlapping_blocks_in_a_file_get_one_warning) {
  TempDir dir;
  const auto file = dir.file("ov.json", R"({"blocks": [{"pos": [100, 100], "size": [20, 20], "mass": 1},
                                                     {"pos": [300, 100], "size": [20, 20], "mass": 1},
                                                     {"pos": [110, 105], "size": [20, 20], "mass": 1},
                                                     {"pos": [115, 105], "size": [20, 20], "mass": 1}]})");
  const Ran r = cli({"--scene", file, "--headless", "--frames", "1"});
  BOOST_TEST(r.code == 0);
  BOOST_TEST(r.err == "warning: " + file + ": blocks[0] and blocks[2] overlap at the start\n");
  BOOST_TEST(has(r.out, "frames:          1"));
  BOOST_TEST(cli({"--scene", "stack", "--headless", "--frames", "1"}).err.empty());
}

BOOST_AUTO_TEST_CASE(course_builds_the_sheet_s_scenes_and_refuses_what_it_would_ignore) {
  const Ran course = cli({"--course", "--scene", "bounce", "--headless", "--frames", "120"});
  const Ran scene = cli({"--scene", "bounce", "--headless", "--frames", "120"});
  BOOST_TEST(course.code == 0);
  BOOST_TEST(has(course.out, "bodies:          6 (1 mobile)"));
  // The same run: the summaries differ only in their timings.
  BOOST_TEST(course.out.substr(0, course.out.find("physics ms")) == scene.out.substr(0, scene.out.find("physics ms")));
  expect_bad({"--course", "--scene", "cradle"},
             "--course: the course's functions build the sheet's scenes (walls, drift, impulse, bounce, many), not "
             "'cradle'");
  expect_bad({"--course", "--friction", "0.5"}, "--course and --friction: the course's functions give each body");
  expect_bad({"--course", "--print-scene"}, "--print-scene and --course:");
}

BOOST_AUTO_TEST_CASE(unknown_scene) {
  expect_bad({"--scene", "nope"}, "unknown scene 'nope' (built-in scenes: walls, drift, impulse, bounce, many,");
}

BOOST_AUTO_TEST_CASE(unreadable_scene_file) {
  expect_bad({"--scene", "/nonexistent/x.json"}, "/nonexistent/x.json: cannot read the scene file");
  TempDir dir;
  expect_bad({"--scene", dir.path.string() + "/"}, "is a directory");
}

BOOST_AUTO_TEST_CASE(scene_file_errors_name_the_file_and_the_line_or_key) {
  TempDir dir;
  const auto syntax = dir.file("syntax.json", "{\n  \"blocks\": [\n    {\"pos\": [1, 2]\n  ]\n}\n");
  expect_bad({"--scene", syntax}, syntax + ":4:3: invalid JSON");
  const auto key = dir.file("key.json", R"({"world": {"dtt": 5}})");
  expect_bad({"--scene", key}, key + ": world.dtt: unknown key (did you mean \"dt\"?)");
  const auto type = dir.file("type.json", R"({"world": {"gravity": "down"}})");
  expect_bad({"--scene", type}, type + ": world.gravity: must be an array of two numbers");
  const auto mass = dir.file("mass.json", R"({"blocks": [{"pos": [100, 100], "size": [4, 4], "mass": -1}]})");
  expect_bad({"--scene", mass}, mass + ": blocks[0].mass: must be > 0 or \"inf\" (got -1)");
  const auto size = dir.file("size.json", R"({"blocks": [{"pos": [100, 100], "size": [0, 4], "mass": 1}]})");
  expect_bad({"--scene", size}, size + ": blocks[0].size[0]: must be > 0");
  const auto dt = dir.file("dt.json", R"({"world": {"dt": 0}})");
  expect_bad({"--scene", dt}, dt + ": world.dt: must be > 0");
  const auto sub = dir.file("sub.json", R"({"world": {"substeps": 0}})");
  expect_bad({"--scene", sub}, sub + ": world.substeps");
  const auto e = dir.file("e.json", R"({"world": {"restitution": 2}})");
  expect_bad({"--scene", e}, e + ": world.restitution: must be in [0, 1]");
  const auto wall = dir.file("wall.json", R"({"blocks": [{"pos": [780, 100], "size": [40, 40], "mass": 1}]})");
  expect_bad({"--scene", wall}, wall + ": blocks[0]: block at (780, 100) of size 40x40");
  const auto inf = dir.file("inf.json", R"({"blocks": [{"pos": [100, 1e999], "size": [4, 4], "mass": 1}]})");
  expect_bad({"--scene", inf}, inf + ":1:");
}

BOOST_AUTO_TEST_CASE(non_finite_values_on_the_command_line) {
  expect_bad({"--dt", "nan"}, "--dt: must be a finite number (got 'nan')");
  expect_bad({"--dt", "inf"}, "--dt: must be a finite number");
  expect_bad({"--gravity", "inf,0"}, "--gravity: must be a finite number");
  expect_bad({"--restitution", "nan"}, "--restitution");
}

BOOST_AUTO_TEST_CASE(bad_values_on_the_command_line) {
  expect_bad({"--dt", "0"}, "--dt: must be > 0 (got '0')");
  expect_bad({"--dt=-1"}, "--dt: must be > 0");
  expect_bad({"--dt", "fast"}, "--dt: must be a number (got 'fast')");
  expect_bad({"--substeps", "0"}, "--substeps: must be an integer in [1, 1000] (got '0')");
  expect_bad({"--substeps", "2.5"}, "--substeps");
  expect_bad({"--iterations", "0"}, "--iterations");
  expect_bad({"--threads", "0"}, "--threads: must be an integer in [1, 64] (got '0')");
  expect_bad({"--threads", "65"}, "--threads");
  expect_bad({"--threads", "two"}, "--threads");
  expect_bad({"--restitution", "1.5"}, "--restitution: must be in [0, 1] (got '1.5')");
  expect_bad({"--restitution=-0.1"}, "--restitution");
  expect_bad({"--frames=-1"}, "--frames");
  expect_bad({"--frames", "ten"}, "--frames");
  expect_bad({"--gravity", "0"}, "--gravity: must be two numbers X,Y (got '0')");
  expect_bad({"--gravity", "0,x"}, "--gravity");
  expect_bad({"--gravity", "1,2,3"}, "--gravity: must be two numbers X,Y (got '1,2,3')");
  expect_bad({"--screenshot", "x.jpg"}, "--screenshot: only PNG is written: the name must end in .png (got 'x.jpg')");
  expect_bad({"--screenshot", "x"}, "--screenshot: only PNG is written");
  // Finite but beyond what a scene file accepts: the flag is named, not the scene.
  expect_bad({"--gravity", "1e7,0"}, "--gravity: must be within ±1000000 (got '1e7,0')");
  expect_bad({"--dt", "1e7"}, "--dt: must be <= 1000000 ms (got '1e7')");
  expect_bad({"--seed=-3"}, "--seed");
  expect_bad({"--solver", "fast"}, "--solver: must be \"course\", \"stable\" or \"auto\" (got 'fast')");
  expect_bad({"--ccd=maybe"}, "--ccd: must be on or off");
  expect_bad({"--overlays", "aabb,boxes"}, "--overlays");
  expect_bad({"--friction", "-1"}, "--friction: must be in [0, 1000] (got '-1')");
  expect_bad({"--friction", "slippery"}, "--friction: must be a number (got 'slippery')");
}

// Two outputs on one file would overwrite each other (and one on the
// replayed log would destroy it): refused naming both flags, and the file
// is left as it was.
BOOST_AUTO_TEST_CASE(two_outputs_naming_one_file_are_refused) {
  TempDir dir;
  const std::string same = dir.file("same.png", "kept"), log = dir.file("r.log", "kept");
  const std::vector<std::string> flags{"--dump", "--trace", "--events", "--save", "--screenshot", "--record"};
  for (std::size_t i = 0; i < flags.size(); ++i)
    for (std::size_t j = i + 1; j < flags.size(); ++j) {
      const Ran r = cli({"--scene", "bounce", flags[i], same, flags[j], same});
      BOOST_TEST(r.code == 2, flags[i] << " " << flags[j]);
      BOOST_TEST((has(r.err, flags[i]) && has(r.err, flags[j]) && has(r.err, "name one file")), r.err);
      BOOST_TEST(std::count(r.err.begin(), r.err.end(), '\n') == 1);
      BOOST_TEST(read(same) == "kept");
    }
  // Spelled differently, still one file.
  const std::string csv_file = dir.file("out.csv");
  expect_bad({"--dump", csv_file, "--trace", (dir.path / "." / "out.csv").string()},
             "--dump and --trace name one file (" + csv_file + "): give each output its own file");
  for (const char* flag : {"--dump", "--trace", "--events", "--save"}) {
    expect_bad({"--replay", log, flag, log}, "--replay and " + std::string(flag) + " name one file");
    BOOST_TEST(read(log) == "kept");
  }
  // Two files: both written.
  const std::string a = dir.file("a.csv"), b = dir.file("b.csv");
  BOOST_TEST(cli({"--scene", "bounce", "--frames", "2", "--dump", a, "--trace", b}).code == 0);
  BOOST_TEST((!read(a).empty() && !read(b).empty() && read(a) != read(b)));
}

// --print-scene prints and exits: a flag it would ignore is refused, not
// dropped; the scene's own values (--dt, --ccd, --style...) still apply.
BOOST_AUTO_TEST_CASE(print_scene_refuses_the_flags_it_would_ignore) {
  TempDir dir;
  const std::string out = dir.file("out.png");
  for (const std::vector<std::string>& ignored :
       {std::vector<std::string>{"--dump", out}, {"--trace", out}, {"--events", out}, {"--save", out},
        {"--screenshot", out}, {"--record", out}, {"--replay", out}, {"--headless"}, {"--frames", "10"},
        {"--strict"}, {"--overlays", "aabb"}}) {
    std::vector<std::string> args{"--scene", "bounce", "--print-scene"};
    args.insert(args.end(), ignored.begin(), ignored.end());
    expect_bad(args, "--print-scene and " + ignored[0] + ": --print-scene prints the scene and exits, it would "
                     "ignore " + ignored[0] + " (give one of them)");
    BOOST_TEST(!fs::exists(out), ignored[0]);
  }
  const Ran p = cli({"--scene", "bounce", "--print-scene", "--dt", "5", "--style", "speed"});
  BOOST_TEST_REQUIRE(p.code == 0, p.err);
  BOOST_TEST(parse_scene(p.out, "p.json").params.dt == 5.0);
}

BOOST_AUTO_TEST_CASE(unwritable_outputs_fail_before_the_run) {
  expect_bad({"--dump", "/nonexistent/dir/x.csv"}, "--dump: cannot write /nonexistent/dir/x.csv");
  expect_bad({"--trace", "/nonexistent/dir/x.csv"}, "--trace: cannot write");
  expect_bad({"--screenshot", "/nonexistent/dir/x.png", "--headless"}, "--screenshot: cannot write /nonexistent/dir/x.png");
  expect_bad({"--dump", ""}, "must not be empty");
  expect_bad({"--events", "/nonexistent/dir/x.csv"}, "--events: cannot write /nonexistent/dir/x.csv");
  expect_bad({"--save", "/nonexistent/dir/x.json"}, "--save: cannot write /nonexistent/dir/x.json");
  expect_bad({"--save", ""}, "must not be empty");
}

BOOST_AUTO_TEST_SUITE_END()

// The real program: what a user sees.
BOOST_AUTO_TEST_SUITE(cli_program)

BOOST_AUTO_TEST_CASE(bad_input_exits_with_code_2_and_one_line) {
  TempDir dir;
  const Ran r = program(dir, no_display, {"--scene", "nope"});
  BOOST_TEST(r.code == 2);
  BOOST_TEST(has(r.err, "game: unknown scene 'nope'"));
  BOOST_TEST(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  const Ran f = program(dir, no_display, {"--dt", "0"});
  BOOST_TEST(f.code == 2);
}

BOOST_AUTO_TEST_CASE(without_a_display_it_runs_headless_and_says_so) {
  // No DISPLAY, WAYLAND_DISPLAY or SDL_VIDEODRIVER: SDL is never initialised.
  TempDir dir;
  const Ran r = program(dir, no_display, {"--scene", "gas", "--frames", "20", "--dump", "gas.csv"});
  BOOST_TEST(r.code == 0);
  BOOST_TEST(has(r.out, "ran headless: no display"), r.out);
  BOOST_TEST(r.err.empty(), r.err);
  BOOST_TEST(csv(read(dir.file("gas.csv"))).size() == 305u);
}

BOOST_AUTO_TEST_CASE(a_window_run_draws_and_saves_a_screenshot) {
  // SDL's dummy video driver: a real window path (renderer, font, HUD,
  // overlays) with no display at all.
  TempDir dir;
  const Ran r = program(dir, no_display + " SDL_VIDEODRIVER=dummy",
                        {"--scene", "bounce", "--frames", "10", "--screenshot", "w.png", "--overlays", "all",
                         "--dump", "w.csv"});
  BOOST_TEST(r.code == 0, r.err);
  BOOST_TEST(!has(r.out, "ran headless"));
  BOOST_TEST(is_png(dir.file("w.png")));
  BOOST_TEST(csv(read(dir.file("w.csv"))).size() == 7u);
}

BOOST_AUTO_TEST_CASE(the_window_draws_the_same_bodies_as_the_offscreen_picture) {
  // The window's picture (SDL renderer) and the headless one (Offscreen) of
  // the same frame: below the HUD they must agree, so the window really
  // draws the bodies where they are.
  TempDir dir;
  const std::vector<std::string> args{"--scene", "many", "--frames", "30"};
  auto with = [&](std::vector<std::string> a, const std::string& png) {
    a.insert(a.end(), {"--screenshot", png});
    return a;
  };
  BOOST_TEST_REQUIRE(program(dir, no_display + " SDL_VIDEODRIVER=dummy", with(args, "window.png")).code == 0);
  BOOST_TEST_REQUIRE(program(dir, no_display, with(args, "offscreen.png")).code == 0);
  const Picture w = read_png(dir.file("window.png")), h = read_png(dir.file("offscreen.png"));
  BOOST_TEST_REQUIRE(w.width == 800u);
  BOOST_TEST_REQUIRE(w.height == 600u);
  BOOST_TEST_REQUIRE(h.rgb.size() == w.rgb.size());
  std::size_t painted = 0, differ = 0, compared = 0;
  for (std::size_t y = 200; y < 600; ++y)  // below the HUD's lines
    for (std::size_t x = 0; x < 800; ++x) {
      const std::size_t i = (y * 800 + x) * 3;
      const bool white = w.rgb[i] == 255 && w.rgb[i + 1] == 255 && w.rgb[i + 2] == 255;
      painted += !white;
      differ += w.rgb[i] != h.rgb[i] || w.rgb[i + 1] != h.rgb[i + 1] || w.rgb[i + 2] != h.rgb[i + 2];
      ++compared;
    }
  BOOST_TEST(painted > compared / 10, painted << " painted pixels of " << compared);  // walls and blocks
  BOOST_TEST(differ < compared / 200, differ << " pixels differ of " << compared);    // edge rounding at most
}

// --list-scenes reads scenes/ where the program runs: a file that does not
// read is listed with its error, the others still are.
BOOST_AUTO_TEST_CASE(list_scenes_reads_the_scenes_folder_where_it_runs) {
  TempDir dir;
  fs::create_directories(dir.path / "scenes");
  dir.file("scenes/mine.json", R"({"description": "my own scene", "blocks": []})");
  dir.file("scenes/level.json", R"({"description": "my level", "game": {"kind": "targets"}, "blocks": [
    {"pos": [100, 500], "size": [30, 30], "mass": "inf", "tag": "sling"},
    {"pos": [600, 500], "size": [20, 20], "mass": 1, "tag": "target"}]})");
  dir.file("scenes/broken.json", "{\"blocks\": [");
  fs::create_directories(dir.path / "scenes/maps");
  dir.file("scenes/maps/room.tmj", R"({"orientation": "orthogonal", "width": 4, "height": 3, "tilewidth": 32,
    "tileheight": 32, "properties": [{"name": "description", "type": "string", "value": "my map"},
                                     {"name": "walls", "type": "bool", "value": false}],
    "layers": [{"type": "tilelayer", "width": 4, "height": 3, "data": [0,0,0,0, 0,0,0,0, 1,1,1,1]}],
    "tilesets": [{"firstgid": 1, "tilewidth": 32, "tileheight": 32, "tilecount": 1}]})");
  dir.file("scenes/maps/broken.ldtk", R"({"levels": []})");
  dir.file("scenes/maps/notes.txt", "not a map");
  const Ran r = program(dir, no_display, {"--list-scenes"});
  BOOST_TEST(r.code == 0, r.err);
  BOOST_TEST(has(r.out, "scene files in scenes/"), r.out);
  BOOST_TEST(has(listed(r.out, "scenes/mine.json"), "my own scene"), r.out);
  BOOST_TEST(has(listed(r.out, "scenes/level.json"), "[targets] my level"), r.out);
  BOOST_TEST(has(listed(r.out, "scenes/broken.json"), "(does not read: "), r.out);
  BOOST_TEST(has(listed(r.out, "scenes/maps/room.tmj"), "my map"), r.out);
  BOOST_TEST(has(listed(r.out, "scenes/maps/broken.ldtk"), "(does not read: scenes/maps/broken.ldtk: the project has no level)"), r.out);
  BOOST_TEST(!has(r.out, "notes.txt"), r.out);
  BOOST_TEST(!has(r.out, "platformer"));  // this folder's files, not the project's
}

// A window closed before --frames (Esc, Q, the close button; here SIGTERM,
// which SDL turns into the same quit event) saves the last frame it showed,
// and says so, rather than leaving an empty PNG behind.
BOOST_AUTO_TEST_CASE(a_window_closed_early_saves_the_last_frame_shown) {
  TempDir dir;
  // The trace's first rows on disk mean the window is open (SDL catches
  // SIGTERM from then on). --frames 3000 bounds the run (50 s) if it did not.
  const std::string cmd =
      "cd " + quote(dir.path.string()) + " && { env " + no_display + " SDL_VIDEODRIVER=dummy " +
      quote(game_binary()) + " --scene gas --frames 3000 --screenshot early.png --trace t.csv >stdout 2>stderr "
      "</dev/null & p=$!; i=0; while [ ! -s t.csv ] && [ $i -lt 400 ]; do sleep 0.05; i=$((i+1)); done; "
      "sleep 0.3; kill -TERM $p; wait $p; }";
  const int status = std::system(cmd.c_str());
  const std::string err = read(dir.file("stderr"));
  BOOST_TEST_REQUIRE(WIFEXITED(status), err);
  BOOST_TEST(WEXITSTATUS(status) == 0, err);
  BOOST_TEST(has(err, "game: --screenshot: the window was closed at frame "), err);
  BOOST_TEST(has(err, ", before frame 3000: early.png shows frame "), err);
  const Picture p = read_png(dir.file("early.png"));
  BOOST_TEST((p.width == 800u && p.height == 600u));
  BOOST_TEST(std::count(p.rgb.begin(), p.rgb.end(), 255) < std::ptrdiff_t(p.rgb.size()), "not all white");
}

BOOST_AUTO_TEST_CASE(a_missing_font_turns_the_hud_off_with_a_warning) {
  TempDir dir;
  const Ran r = program(dir, no_display + " SDL_VIDEODRIVER=dummy PHYSICS_FONT=/nonexistent/font.ttf",
                        {"--scene", "walls", "--frames", "3", "--screenshot", "nofont.png"});
  BOOST_TEST(r.code == 0, r.err);
  BOOST_TEST(has(r.err, "warning: font /nonexistent/font.ttf not found"), r.err);
  BOOST_TEST(has(r.err, "HUD off"));
  BOOST_TEST(is_png(dir.file("nofont.png")));
}

BOOST_AUTO_TEST_CASE(a_window_that_cannot_open_falls_back_to_headless) {
  TempDir dir;
  const Ran r = program(dir, no_display + " SDL_VIDEODRIVER=no-such-driver", {"--frames", "5"});
  BOOST_TEST(r.code == 0);
  BOOST_TEST(has(r.err, "running headless"), r.err);
  BOOST_TEST(has(r.out, "ran headless: window failed"));
}

BOOST_AUTO_TEST_SUITE_END()

// Physics health (engine/health.hpp): what cannot be checked up front is
// checked after every step; escapes are counted; known limits are named.
BOOST_AUTO_TEST_SUITE(cli_health)

BOOST_AUTO_TEST_CASE(a_dt_below_the_floor_is_refused) {
  expect_bad({"--headless", "--frames", "5", "--dt", "1e-320"}, "--dt: must be >= 1e-06 ms (got '1e-320')");
}

BOOST_AUTO_TEST_CASE(a_kick_that_overflows_is_refused_naming_the_block) {
  TempDir d;
  const auto f = d.file("m.json", R"({"blocks":[{"pos":[100,100],"size":[10,10],"mass":1e-300,"force":[1e6,0]}]})");
  expect_bad({"--headless", "--scene", f}, "blocks[0].mass: with a mass of 1e-300");
}

// An impulse reaches Forces as the force impulse/dt, which the public API
// (that builds the world) bounds as any force: a tiny dt makes it too large.
BOOST_AUTO_TEST_CASE(a_first_frame_force_beyond_the_limit_is_refused_naming_the_block) {
  TempDir d;
  const auto f = d.file("k.json", R"({"world":{"dt":0.001},"blocks":[{"pos":[100,100],"size":[10,10],"mass":1e9,
                                       "impulse":[10000,0]}]})");
  expect_bad({"--headless", "--scene", f},
             "blocks[0].impulse: with dt 0.001 ms, force + impulse/dt (the first frame's force) reaches 10000000 (at "
             "most 1000000)");
  const auto ok = d.file("ok.json", R"({"world":{"dt":0.001},"blocks":[{"pos":[100,100],"size":[10,10],"mass":1e9,
                                        "impulse":[1000,0]}]})");
  BOOST_TEST(cli({"--headless", "--frames", "1", "--scene", ok}).code == 0);
}

BOOST_AUTO_TEST_CASE(a_non_finite_velocity_stops_the_run_naming_body_and_frame) {
  World w(SystemSet{.forces = true, .move = true});
  const auto b = Block::make(w, 100, 100, 10, 10, Game::red, 1.0);
  Headless::run(w, 2);
  w.components.velocity[b.id] = {std::nan(""), 0.0};
  const auto s = Headless::run(w, 10);
  BOOST_TEST(s.frames == 3);
  BOOST_TEST(Headless::non_finite_line(w) == "body 0 has a non-finite position (nan, 100) after frame 3");
}

BOOST_AUTO_TEST_CASE(escapes_are_counted_and_strict_exits_3) {
  TempDir d;
  const auto f = d.file("e.json", R"({"world":{"walls":false},"blocks":[{"pos":[100,100],"size":[10,10],"mass":1,"velocity":[1,0]}]})");
  const Ran r = cli({"--headless", "--scene", f, "--frames", "60"});
  BOOST_TEST(r.code == 0);
  BOOST_TEST(has(r.out, "escaped:         1 (the first: body 0, by frame 44)"), r.out);
  BOOST_TEST(has(r.out, "--ccd on"));
  const Ran s = cli({"--headless", "--scene", f, "--frames", "60", "--strict"});
  BOOST_TEST(s.code == 3);
  BOOST_TEST(has(s.err, "game: --strict: 1 body left the world"), s.err);
}

BOOST_AUTO_TEST_CASE(a_sinking_tower_names_the_stable_solver) {
  TempDir d;
  const auto f = d.file("t.json", R"({"world":{"gravity":[0,0.001],"restitution":0},
    "blocks":[{"grid":{"pos":[380,160],"count":[1,10],"step":[0,40],"size":[40,40],"mass":1}}]})");
  const Ran r = cli({"--headless", "--scene", f, "--frames", "600"});
  BOOST_TEST(r.code == 0);
  BOOST_TEST((has(r.out, "note:") && has(r.out, "--solver stable") && has(r.out, "docs/numerics.md")), r.out);
  const Ran s = cli({"--headless", "--scene", f, "--frames", "600", "--solver", "stable"});
  BOOST_TEST(!has(s.out, "note:"), s.out);
}

// A crowd (gas10k.json) meets both limits without any stack or fast body: the
// note says what happened in general terms, and only names options not on.
BOOST_AUTO_TEST_CASE(the_note_says_what_happened_and_names_the_options_not_on) {
  World w;
  w.health.deep = DeepOverlap{2712, 2961, 1.5, 180};
  w.health.escaped = 6;
  BOOST_TEST(Headless::advice(w) ==
             "overlaps deeper than 1 px persist (bodies 2712 and 2961 after frame 180): the course solver's one pass "
             "per step leaves bodies pressed together overlapping (a stack sinks, a crowd pushes bodies into walls); "
             "--solver stable separates them; bodies left the world: fast ones tunnel through walls in one step (--ccd "
             "on stops that), pressed ones are pushed into or through walls by the course solver (--solver stable "
             "stops that); see docs/numerics.md");
  BOOST_TEST(!has(Headless::advice(w), "stacks sink"));
  w.params.ccd = true;
  BOOST_TEST(!has(Headless::advice(w), "--ccd on"));
  BOOST_TEST(has(Headless::advice(w), "bodies left the world: pressed ones are pushed"));
  w.params.solver = Solver::stable;
  BOOST_TEST(Headless::advice(w).empty());
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace test_cli
