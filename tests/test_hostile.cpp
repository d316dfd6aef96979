// Hostile input (issue 23, items 5 and 6): each case is refused with one line
// and exit code 2, or runs within a documented bound; never an abort, a hang,
// a forged line or a non-finite figure (docs/reliability.md, "Bad input").
#include <sys/stat.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <cctype>
#include <sstream>
#include <thread>

#include "app/cli.hpp"
#include "app/headless.hpp"
#include "app/input_log.hpp"
#include "app/testbed.hpp"
#include "cli_helpers.hpp"
#include "course/utils/random.hpp"
#include "engine/limits.hpp"
#include "scene/scene_json.hpp"

// The file's own names, apart from the other test files' with which it is
// compiled (Makefile, TEST_UNITY).
namespace test_hostile {

using namespace physics;
using namespace physics::test;

namespace {

// Whether an output text holds a non-finite figure (nan, -nan, inf, -inf as
// a word: "finite" in a note is none).
// (A scan, not std::regex: GCC 12 warns inside <regex> under the sanitizers.)
bool non_finite_text(const std::string& s) {
  std::string low(s);
  for (char& c : low) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  const auto letter = [&](std::size_t i) { return i < low.size() && low[i] >= 'a' && low[i] <= 'z'; };
  for (const char* word : {"nan", "inf"})
    for (std::size_t at = low.find(word); at != std::string::npos; at = low.find(word, at + 1))
      if (!(at > 0 && letter(at - 1)) && !letter(at + 3)) return true;
  return false;
}

std::string scene_json(const std::string& world, const std::string& blocks) {
  return R"({"name": "h", "world": {)" + world + R"(}, "blocks": [)" + blocks + "]}";
}

}  // namespace

BOOST_AUTO_TEST_SUITE(hostile_input)

// Masses beyond [min_mass, max_mass] are refused: 1e308 at 1e6 px/ms printed
// "kinetic energy: inf" and two of them moving apart "momentum: (-nan, 0)".
BOOST_AUTO_TEST_CASE(masses_that_would_overflow_are_refused) {
  TempDir d;
  const std::string world = R"("gravity": [0, 0], "walls": false)";
  const auto f = d.file("m.json", scene_json(world, R"({"pos": [100, 100], "size": [40, 40], "mass": 1e308,
                                                       "velocity": [1000000, 0]})"));
  expect_bad({"--headless", "--scene", f}, "blocks[0].mass: must be in [1e-300, 1e+150] or \"inf\" (got 1e+308)");
  const auto tiny = d.file("t.json", scene_json(world, R"({"pos": [100, 100], "size": [4, 4], "mass": 1e-320})"));
  expect_bad({"--headless", "--scene", tiny}, "blocks[0].mass: must be in [1e-300, 1e+150]");
  const auto range = d.file("r.json", scene_json(world, R"({"random": {"count": 3, "size": [4, 4],
                                                           "mass": [1, 1e200]}})"));
  expect_bad({"--headless", "--scene", range}, "blocks[0].random.mass: must be in [1e-300, 1e+150]");
}

// At the limits (the largest mass head on with itself and with the smallest,
// one at the largest speed, the largest gravity), every output stays finite.
BOOST_AUTO_TEST_CASE(every_output_is_finite_at_the_limits) {
  TempDir d;
  const auto f = d.file("big.json", scene_json(R"("gravity": [0, 1000000], "walls": false, "width": 100000, "height": 100000)",
      R"({"pos": [1000, 1000], "size": [40, 40], "mass": 1e150, "velocity": [1, 0]},
         {"pos": [1045, 1000], "size": [40, 40], "mass": 1e150, "velocity": [-1, 0]},
         {"pos": [1000, 3000], "size": [40, 40], "mass": 1e150, "velocity": [1, 0]},
         {"pos": [1045, 3000], "size": [4, 4], "mass": 1e-300, "velocity": [-1, 0]},
         {"pos": [5000, 5000], "size": [40, 40], "mass": 1e150, "velocity": [1000000, -1000000]})"));
  for (const char* solver : {"course", "stable", "auto"}) {
    const Ran r = cli({"--headless", "--scene", f, "--frames", "20", "--solver", solver, "--dump", d.file("d.csv"),
                       "--trace", d.file("t.csv"), "--events", d.file("e.csv"), "--save", d.file("s.json")});
    BOOST_TEST(r.code == 0, solver << ": " << r.err);
    BOOST_TEST(!non_finite_text(r.out), solver << ": " << r.out);
    for (const char* file : {"d.csv", "t.csv", "e.csv", "s.json"})
      BOOST_TEST(!non_finite_text(read((d.path / file).string())), solver << ": " << file);
    BOOST_TEST(has(read((d.path / "e.csv").string()), "begin"), solver);  // the bodies did collide
  }
}

// /dev/zero (a device: no size) is read up to the 64 MB limit, not until
// memory runs out, as a scene and as a replay's scene or log.
BOOST_AUTO_TEST_CASE(a_device_is_read_within_the_size_limit) {
  BOOST_CHECK_EXCEPTION(read_input_file("/dev/zero", "scene file"), SceneError, [](const SceneError& e) {
    return std::string(e.what()) == "/dev/zero: cannot read the scene file: larger than 64 MB";
  });
  expect_bad({"--headless", "--scene", "/dev/zero"}, "/dev/zero: cannot read the scene file: larger than 64 MB");
  expect_bad({"--headless", "--replay", "/dev/zero"}, "/dev/zero: cannot read the input log: larger than 64 MB");
  TempDir d;
  const auto log = d.file("z.log", "# scene: /dev/zero\ntick,kind,key,x,y,button\n5,end,0,0,0,0\n");
  expect_bad({"--headless", "--replay", log}, "/dev/zero: cannot read the scene file: larger than 64 MB");
  BOOST_TEST(read_input_file("/dev/null", "scene file").empty());
  // A pipe (no size either) reads whole, up to its end.
  const std::string fifo = (d.path / "scene.fifo").string();
  BOOST_TEST_REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  const std::string text = scene_json(R"("walls": false)", R"({"pos": [1, 2], "size": [3, 4], "mass": 5})");
  std::thread writer([&] { std::ofstream(fifo) << text; });
  const std::string got = read_input_file(fifo, "scene file");
  writer.join();
  BOOST_TEST(got == text);
}

// 40 000 blocks on one spot (8 * 10^8 pairs) aborted with bad_alloc; a grid
// of touching blocks, at 4 pairs a body, still loads.
BOOST_AUTO_TEST_CASE(bodies_piled_beyond_the_pair_bound_are_refused) {
  TempDir d;
  const std::string world = R"("gravity": [0, 0], "walls": false)";
  const auto pile = d.file("p.json", scene_json(world, R"({"random": {"count": 40000, "size": [10, 10], "mass": 1,
                                                          "area": {"pos": [100, 100], "size": [10, 10]}}})"));
  expect_bad({"--headless", "--frames", "1", "--scene", pile},
             "blocks: more than 1048576 pairs of bodies touch or overlap at the start");
  const std::string grid = R"({"grid": {"count": [400, 400], "pos": [0, 0], "size": [1, 1], "mass": 1}})";
  BOOST_CHECK_NO_THROW(parse_scene(scene_json(R"("walls": false, "width": 400, "height": 400)", grid), "g"));
}

// A hand-added "state": {} let a block start at (1e300, -1e300); a saved
// body that left the world (within the bound) still loads.
BOOST_AUTO_TEST_CASE(a_state_key_does_not_skip_the_placement_check) {
  const std::string far = R"({"pos": [1e300, -1e300], "size": [10, 10], "mass": 1})";
  BOOST_CHECK_EXCEPTION(parse_scene(R"({"state": {}, "blocks": [)" + far + "]}", "s.json"), SceneError,
                        [](const SceneError& e) {
                          return has(e.what(), "s.json: blocks[0]: block at (1e+300, -1e+300) in a saved state");
                        });
  const std::string out = R"({"pos": [-500, 20], "size": [10, 10], "mass": 1})";
  BOOST_CHECK_NO_THROW(parse_scene(R"({"state": {"frame": 40}, "blocks": [)" + out + "]}", "s.json"));
  BOOST_CHECK_THROW(parse_scene(R"({"blocks": [)" + out + "]}", "s.json"), SceneError);
}

// Control characters in a name reach no terminal raw: an ANSI escape, a
// newline forging a summary line, a C1 CSI; UTF-8 text stays.
BOOST_AUTO_TEST_CASE(control_characters_in_names_are_escaped) {
  BOOST_TEST(Headless::printable("a\x1b[31mb\nc\x7f") == "a\\x1b[31mb\\x0ac\\x7f");
  BOOST_TEST(Headless::printable("\xc2\x9b" "2J caf\xc3\xa9") == "\\xc2\\x9b2J caf\xc3\xa9");
  TempDir d;
  const auto f = d.file("n.json", R"({"name": "x\nkinetic energy:  0 forged\u001b[2J", "description": "d\u001b[31m",
                                      "blocks": []})");
  const Ran r = cli({"--headless", "--frames", "1", "--scene", f});
  BOOST_TEST(r.code == 0);
  BOOST_TEST(!has(r.out, "\x1b"));
  BOOST_TEST(has(r.out, "scene:           x\\x0akinetic energy:  0 forged\\x1b[2J (systems"));
  const Ran plain = cli({"--headless", "--frames", "1", "--scene", d.file("p.json", R"({"name": "x", "blocks": []})")});
  BOOST_TEST(std::count(r.out.begin(), r.out.end(), '\n') == std::count(plain.out.begin(), plain.out.end(), '\n'));
  // --list-scenes lists the descriptions of scenes/ here.
  const auto cwd = std::filesystem::current_path();
  std::filesystem::create_directory(d.path / "scenes");
  std::filesystem::copy_file(f, d.path / "scenes" / "n.json");
  std::filesystem::current_path(d.path);
  const Ran list = cli({"--list-scenes"});
  std::filesystem::current_path(cwd);
  BOOST_TEST(has(list.out, "d\\x1b[31m"));
  BOOST_TEST(!has(list.out, "\x1b"));
}

// An error line quotes what a file gave it (a log's scene name): escaped
// too, and one line.
BOOST_AUTO_TEST_CASE(control_characters_in_error_lines_are_escaped) {
  TempDir d;
  const auto log = d.file("e.log", "# scene: x\x1b[2Jy\ntick,kind,key,x,y,button\n5,end,0,0,0,0\n");
  expect_bad({"--headless", "--replay", log}, "unknown scene 'x\\x1b[2Jy'");
}

// The parser stopped at a NUL: what followed was accepted unread.
BOOST_AUTO_TEST_CASE(a_nul_byte_is_refused) {
  using namespace std::string_literals;
  BOOST_CHECK_EXCEPTION(parse_scene("{\"blocks\": []}\n\0garbage"s, "n.json"), SceneError, [](const SceneError& e) {
    return std::string(e.what()) == "n.json:2:1: a NUL byte: a scene file is text";
  });
  const std::string log = "# scene: many\0x\ntick,kind,key,x,y,button\n5,end,0,0,0,0\n"s;
  BOOST_CHECK_EXCEPTION(parse_input_log(log, "n.log"), InputLogError, [](const InputLogError& e) {
    return std::string(e.what()) == "n.log:1: a NUL byte: an input log is text";
  });
}

// Outputs: a device that takes no data is found before the run (exit 2, no
// summary) for the CSV files; what fails at the end (a save, a picture)
// gives exit code 4 and one line, not the undocumented 1.
BOOST_AUTO_TEST_CASE(unwritable_outputs_are_found_and_reported_with_their_code) {
  for (const char* flag : {"--dump", "--trace", "--events"})
    expect_bad({"--headless", "--frames", "1", flag, "/dev/full"},
               std::string(flag) + ": cannot write /dev/full: No space left on device");
  TempDir d;
  for (const auto& [flag, name] : {std::pair{"--save", "full.json"}, {"--screenshot", "full.png"}}) {
    const auto link = d.path / name;
    std::filesystem::create_symlink("/dev/full", link);
    const Ran r = cli({"--headless", "--frames", "1", flag, link.string()});
    BOOST_TEST(r.code == Cli::exit_write_failed, flag);
    BOOST_TEST(r.err == "game: " + std::string(flag) + ": cannot write " + link.string() +
                            (std::string(flag) == "--save" ? ": No space left on device" : "") + "\n");
  }
  BOOST_TEST(has(Cli::usage(), "exits with code 4"));
}

// A log's ticks are bounded: one ending at 2^53 ran headless for ever.
BOOST_AUTO_TEST_CASE(replay_ticks_are_bounded) {
  TempDir d;
  const auto log = d.file("l.log", "tick,kind,key,x,y,button\n9007199254740992,end,0,0,0,0\n");
  expect_bad({"--headless", "--replay", log, "--scene", "many"},
             "l.log:2: tick must be in [0, " + std::to_string(max_log_ticks) + "] (got 9007199254740992)");
  const auto ok = d.file("ok.log", "tick,kind,key,x,y,button\n" + std::to_string(max_log_ticks) + ",key,32,0,0,0\n" +
                                       std::to_string(max_log_ticks) + ",end,0,0,0,0\n");
  BOOST_CHECK_NO_THROW(read_input_log(ok));
}

// Spawning is exact (every click accepted or refused as a scan of every
// body would) and linear: 100 000 clicks in one tick (a scan per click took
// about 27 s for 50 000, quadratic).
BOOST_AUTO_TEST_CASE(spawning_is_exact_and_linear) {
  const SceneSpec s = parse_scene(R"({"name": "e", "world": {"width": 12000, "height": 12000, "gravity": [0, 0]},
      "blocks": [{"pos": [500, 500], "size": [300, 20], "mass": "inf"}, {"pos": [900, 900], "size": [7, 9], "mass": 1}]})",
                                  "e");
  Testbed tb({s}, 0);
  Random rng(7);
  const auto brute = [&](Vector pos) {  // the old scan
    const Components& c = tb.world().components;
    for (std::size_t e = 0; e < c.size(); ++e) {
      const auto [p, r] = Rect::mdiff(pos, Rect{Testbed::spawn_size, Testbed::spawn_size}, c.position[e], c.box[e]);
      if (Rect::has_origin(p, r)) return false;
    }
    return true;
  };
  int accepted = 0, refused = 0;
  for (int i = 0; i < 3000; ++i) {
    if (i % 500 == 0) tb.step();  // the index is rebuilt after a step
    const Vector centre{std::round(rng.uniform(40, 1500)), std::round(rng.uniform(40, 1500))};
    const bool room = brute(centre - Vector{Testbed::spawn_size / 2.0, Testbed::spawn_size / 2.0});
    BOOST_TEST(tb.spawn(centre, {}) == room, "click " << i);
    (room ? accepted : refused) += 1;
  }
  BOOST_TEST(accepted > 100);
  BOOST_TEST(refused > 100);
  Testbed big({s}, 0);
  const auto t0 = std::chrono::steady_clock::now();
  int spawned = 0;
  for (int i = 0; i < 100000; ++i) spawned += big.spawn({60.0 + 31 * (i % 380), 1060.0 + 31 * (i / 380)}, {});
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  BOOST_TEST(spawned == 100000);
  BOOST_TEST(seconds < 5.0);  // about 0.2 s; a scan per click: minutes
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace test_hostile
