// Input logs (--record, --replay): the file format and its errors, a
// session recorded on one testbed and replayed on another (headless and the
// window's clock-driven path) giving the same physics bit for bit, and the
// command line's headless replay of a committed log.
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "scene/builtin_scenes.hpp"
#include "app/cli.hpp"
#include "app/dump.hpp"
#include "app/input_log.hpp"
#include "app/testbed.hpp"
#include "cli_helpers.hpp"

// The file's own names, apart from the other test files' with which it is
// compiled (Makefile, TEST_UNITY).
namespace test_replay {

using namespace physics;
using namespace physics::test;
namespace fs = std::filesystem;

namespace {

using Kind = InputEvent::Kind;

std::vector<SceneSpec> all_scenes() { return {builtin_scenes().begin(), builtin_scenes().end()}; }

Testbed on(const std::string& name) {
  const auto scenes = all_scenes();
  std::size_t i = 0;
  while (scenes[i].name != name) ++i;
  return Testbed(scenes, i);
}

InputEvent press(int k) { return {Kind::key, k}; }
InputEvent release(int k) { return {Kind::key_up, k}; }
InputEvent down(int x, int y, int b = 1) { return {Kind::mouse_down, 0, x, y, b}; }
InputEvent move(int x, int y) { return {Kind::mouse_move, 0, x, y, 0}; }
InputEvent up(int x, int y, int b = 1) { return {Kind::mouse_up, 0, x, y, b}; }

InputLog parse(const std::string& text) { return parse_input_log(text, "t.log"); }

std::string written(const InputLog& log) {
  std::ostringstream out;
  write_input_log(out, log);
  return out.str();
}

const std::string head = "# physics input log v1\ntick,kind,key,x,y,button\n";

// Same bodies, same positions and velocities to the bit, same clock.
void expect_same_state(const Testbed& a, const Testbed& b) {
  BOOST_TEST(a.ticks() == b.ticks());
  BOOST_TEST(a.world().frame == b.world().frame);
  BOOST_TEST(a.current() == b.current());
  const Components &ca = a.world().components, &cb = b.world().components;
  BOOST_TEST_REQUIRE(ca.size() == cb.size());
  for (std::size_t e = 0; e < ca.size(); ++e) {
    // Exact: == on doubles, not a tolerance.
    BOOST_TEST((ca.position[e].x == cb.position[e].x && ca.position[e].y == cb.position[e].y), "position of " << e);
    BOOST_TEST((ca.velocity[e].x == cb.velocity[e].x && ca.velocity[e].y == cb.velocity[e].y), "velocity of " << e);
  }
}

std::string dump_of(const World& w) {
  std::ostringstream out;
  out.precision(17);
  Dump::write_state(out, w);
  return out.str();
}

// Absolute: the program tests run the game in a scratch directory.
std::string replays_dir() { return fs::absolute(fs::path(__FILE__).parent_path() / "replays").string(); }

std::size_t csv_rows(const std::string& text) { return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')); }

// A session as the window would drive it (events in, then the clock), on a
// scene with gravity: a click that spawns a block, a slingshot shot, a pause
// with single steps and a key in it, a reset, a scene switch and back, and a
// click after the last step (at the end tick). Returns the testbed.
Testbed record_session(InputLog& log) {
  Testbed tb = on("stack");
  log.scene = "stack";
  tb.record(&log);
  const auto frames = [&](int n, double ms = course_dt) {
    for (int i = 0; i < n; ++i) tb.advance(ms);
  };
  frames(3, course_dt * 1.5);  // two steps, then one, ...: ticks are not frames of the display
  tb.handle(move(300, 150));
  tb.handle(down(300, 150));
  tb.handle(up(300, 150));  // a click: a block between the first two towers
  BOOST_TEST_REQUIRE(tb.world().components.size() == 20u);
  frames(10);
  tb.handle(down(470, 200));
  frames(2);
  tb.handle(move(455, 215));  // the sling stays drawn across steps
  tb.handle(up(440, 230));    // pulled down-left: flies up-right
  BOOST_TEST_REQUIRE(tb.world().components.size() == 21u);
  frames(20);
  tb.handle(press(' '));
  frames(5);  // paused: no step
  tb.handle(press('n'));
  tb.handle(press(key::right));
  tb.handle(press('a'));
  tb.handle(release('a'));
  tb.handle(press(' '));
  frames(15, course_dt * 0.7);
  tb.handle(press('r'));  // the frame restarts, the tick does not
  frames(8);
  tb.handle(down(300, 100));
  tb.handle(up(300, 100));
  frames(30);
  tb.handle(press(key::tab));  // the next scene, then back to the stack
  frames(4);
  tb.handle(press('8'));
  frames(12);
  tb.handle(down(470, 150));
  tb.handle(up(470, 150));  // after the last step: at the end tick
  tb.handle({Kind::quit});
  log.end = tb.ticks();
  return tb;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(input_log_format)

BOOST_AUTO_TEST_CASE(write_then_read_gives_the_same_log) {
  InputLog log;
  log.scene = "scenes/my scene.json";
  log.events = {{0, press(key::right)}, {0, move(-5, 1'000'000)}, {7, release(key::right)}, {7, down(10, 20, 3)},
                {9, up(11, 21, 3)},      {9, press('q')},            {12, {Kind::quit}}};
  log.end = 40;
  const std::string text = written(log);
  BOOST_TEST(text.rfind("# physics input log v1\n# scene: scenes/my scene.json\ntick,kind,key,x,y,button\n", 0) == 0u,
             text);
  BOOST_TEST(has(text, "0,key,1073741903,0,0,0\n"));
  BOOST_TEST(has(text, "\n40,end,0,0,0,0\n"));
  const InputLog back = parse(text);
  BOOST_TEST(back.scene == log.scene);
  BOOST_TEST(back.end == 40);
  BOOST_TEST_REQUIRE(back.events.size() == log.events.size());
  for (std::size_t i = 0; i < log.events.size(); ++i) BOOST_TEST((back.events[i] == log.events[i]), "event " << i);
  BOOST_TEST(written(back) == text);
}

BOOST_AUTO_TEST_CASE(comments_blank_lines_and_crlf_are_accepted) {
  const InputLog log = parse("# a comment\r\n\r\ntick,kind,key,x,y,button\r\n# between\r\n3,key,32,0,0,0\r\n\r\n"
                             "5,end,0,0,0,0\r\n\r\n# after\r\n");
  BOOST_TEST(log.scene.empty());
  BOOST_TEST_REQUIRE(log.events.size() == 1u);
  BOOST_TEST((log.events[0] == LoggedEvent{3, press(' ')}));
  BOOST_TEST(log.end == 5);
  BOOST_TEST(parse(head + "0,end,0,0,0,0\n").events.empty());
}

BOOST_AUTO_TEST_CASE(each_malformed_input_names_its_line) {
  const std::vector<std::pair<std::string, std::string>> cases{
      {head + "0,jump,32,0,0,0\n1,end,0,0,0,0\n", "t.log:3: unknown kind 'jump'"},
      {head + "x,key,32,0,0,0\n1,end,0,0,0,0\n", "t.log:3: tick must be an integer (got 'x')"},
      {head + "1.5,key,32,0,0,0\n2,end,0,0,0,0\n", "t.log:3: tick must be an integer (got '1.5')"},
      {head + "0,key,32,0,,0\n1,end,0,0,0,0\n", "t.log:3: y must be an integer (got '')"},
      {head + "0,key,99999999999,0,0,0\n1,end,0,0,0,0\n", "t.log:3: key must be an integer"},
      {head + "-1,key,32,0,0,0\n1,end,0,0,0,0\n", "t.log:3: tick must be in [0, 10000000] (got -1)"},
      // Past the log's limit (max_log_ticks): a run that would not end.
      {head + "9000000000000000000,end,0,0,0,0\n", "t.log:3: tick must be in [0, 10000000]"},
      {head + "5,key,32,0,0,0\n4,key,32,0,0,0\n9,end,0,0,0,0\n", "t.log:4: tick 4 is before the previous line's 5"},
      {head + "5,key,32,0,0,0\n4,end,0,0,0,0\n", "t.log:4: tick 4 is before the previous line's 5"},
      {head + "0,key,32,0,0,0\n", "t.log:4: missing the end line"},
      {"", "t.log:1: missing the end line (tick,end,0,0,0,0) and the header"},
      {head + "0,key,32\n1,end,0,0,0,0\n", "t.log:3: expected 6 fields tick,kind,key,x,y,button (got 3)"},
      {head + "\x01\xff garbage\n1,end,0,0,0,0\n", "t.log:3: expected 6 fields"},
      {head + "0,key,32,0,0,0,7\n1,end,0,0,0,0\n", "t.log:3: expected 6 fields tick,kind,key,x,y,button (got 7)"},
      {"0,key,32,0,0,0\n1,end,0,0,0,0\n", "t.log:1: expected the header 'tick,kind,key,x,y,button'"},
      {head + "1,end,0,0,0,0\n2,key,32,0,0,0\n", "t.log:4: a line after the end line"},
      {head + " 0,key,32,0,0,0\n1,end,0,0,0,0\n", "t.log:3: tick must be an integer (got ' 0')"},
  };
  for (const auto& [text, expected] : cases) {
    try {
      parse(text);
      BOOST_ERROR("accepted: " << text);
    } catch (const InputLogError& e) {
      BOOST_TEST(has(e.what(), expected), "'" << expected << "' in: " << e.what());
      BOOST_TEST(!has(e.what(), "\n"));
    }
  }
}

BOOST_AUTO_TEST_CASE(an_unreadable_file_is_an_error_naming_it) {
  BOOST_CHECK_EXCEPTION(read_input_log("/nonexistent/x.log"), InputLogError, [](const InputLogError& e) {
    return std::string(e.what()) == "/nonexistent/x.log: cannot read the input log: no such file";
  });
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(replay_session)

BOOST_AUTO_TEST_CASE(ticks_count_the_steps_run_not_the_frame) {
  Testbed tb = on("stack");
  tb.advance(course_dt * 3);
  tb.handle(press(' '));
  tb.advance(1000.0);  // paused: no tick
  tb.handle(press('n'));
  BOOST_TEST(tb.ticks() == 4);
  tb.handle(press('r'));
  BOOST_TEST(tb.world().frame == 0);
  BOOST_TEST(tb.ticks() == 4);
  tb.handle(press('n'));
  BOOST_TEST(tb.ticks() == 5);
  BOOST_TEST(tb.world().frame == 1);
}

BOOST_AUTO_TEST_CASE(recording_logs_every_event_with_its_tick) {
  InputLog log;
  Testbed tb = on("stack");
  tb.handle(move(1, 2));  // before recording: not logged
  tb.record(&log);
  tb.handle(press(' '));
  tb.handle(press('n'));
  tb.handle(release('n'));
  tb.handle(press(' '));
  tb.advance(course_dt * 2);
  tb.handle({Kind::quit});
  tb.record(nullptr);
  tb.handle(press('a'));
  const std::vector<LoggedEvent> expected{
      {0, press(' ')}, {0, press('n')}, {1, release('n')}, {1, press(' ')}, {3, {Kind::quit}}};
  BOOST_TEST_REQUIRE(log.events.size() == expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) BOOST_TEST((log.events[i] == expected[i]), "event " << i);
}

BOOST_AUTO_TEST_CASE(a_recorded_session_replays_bit_for_bit_headless) {
  InputLog log;
  const Testbed recorded = record_session(log);
  BOOST_TEST(recorded.ticks() > recorded.world().frame);  // R reset the frame
  BOOST_TEST(recorded.world().components.size() == 20u);  // the stack again, and the last click's block
  // Through the file, as --replay reads it.
  const InputLog read = parse(written(log));
  Testbed replayed = on("stack");
  replayed.replay(read);
  replayed.play();
  BOOST_TEST(!replayed.replaying());
  BOOST_TEST(replayed.replayed() == log.events.size());
  BOOST_TEST(replayed.ticks() == log.end);
  BOOST_TEST(replayed.paused());  // the replay ends paused at its end tick
  expect_same_state(recorded, replayed);
  BOOST_TEST(dump_of(recorded.world()) == dump_of(replayed.world()));
}

BOOST_AUTO_TEST_CASE(the_window_path_replays_the_same_whatever_the_clock) {
  // advance() as the window calls it, with frame times that are not dt:
  // several steps in one frame, frames without a step.
  InputLog log;
  const Testbed recorded = record_session(log);
  for (const double ms : {7.0, 16.0, 41.0, 58.0, 83.0}) {
    Testbed tb = on("stack");
    tb.replay(log);
    for (int guard = 0; tb.replaying() && guard < 100'000; ++guard) tb.advance(ms);
    BOOST_TEST(!tb.replaying());
    expect_same_state(recorded, tb);
    BOOST_TEST(tb.advance(1000.0) == 0);  // paused at the end: the user takes over
  }
}

BOOST_AUTO_TEST_CASE(recording_a_replay_gives_the_same_log) {
  InputLog log;
  record_session(log);
  InputLog again;
  Testbed tb = on("stack");
  tb.record(&again);
  tb.replay(log);
  tb.play();
  again.end = tb.ticks();
  again.scene = log.scene;
  BOOST_TEST(written(again) == written(log));
}

BOOST_AUTO_TEST_CASE(events_at_the_end_tick_are_handled_after_the_last_step) {
  const InputLog log = parse(head + "3,mouse_down,0,300,150,1\n3,mouse_up,0,300,150,1\n3,end,0,0,0,0\n");
  Testbed tb = on("stack");
  tb.replay(log);
  tb.play();
  BOOST_TEST(tb.ticks() == 3);
  BOOST_TEST(tb.world().components.size() == 20u);
  BOOST_TEST(tb.world().components.velocity.back().y == 0.0);  // spawned after the step: not yet fallen
}

BOOST_AUTO_TEST_CASE(a_paused_replay_with_nothing_due_stops) {
  // Paused at tick 2, but the next event is logged at tick 9: unreachable
  // (a log made on another scene, or by hand). play() returns, still replaying.
  const InputLog log = parse(head + "2,key,32,0,0,0\n9,key,32,0,0,0\n20,end,0,0,0,0\n");
  Testbed tb = on("stack");
  tb.replay(log);
  tb.play();
  BOOST_TEST(tb.ticks() == 2);
  BOOST_TEST(tb.replaying());
  BOOST_TEST(tb.replayed() == 1u);
}

BOOST_AUTO_TEST_CASE(live_input_only_quits_while_replaying) {
  Testbed tb = on("stack");
  tb.replay(parse(head + "100,end,0,0,0,0\n"));
  BOOST_TEST((tb.live(press(' ')) == Testbed::Action::none));
  BOOST_TEST((tb.live(down(300, 150)) == Testbed::Action::none));
  BOOST_TEST((tb.live(up(300, 150)) == Testbed::Action::none));
  BOOST_TEST(!tb.paused());
  BOOST_TEST(tb.world().components.size() == 19u);
  BOOST_TEST((tb.live(press(key::escape)) == Testbed::Action::quit));
  BOOST_TEST((tb.live(press('Q')) == Testbed::Action::quit));
  BOOST_TEST((tb.live({Kind::quit}) == Testbed::Action::quit));
  tb.play();
  BOOST_TEST(!tb.replaying());
  BOOST_TEST((tb.live(press('n')) == Testbed::Action::none));  // the replay is over: live input again
  BOOST_TEST(tb.ticks() == 101);
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(replay_cli)

BOOST_AUTO_TEST_CASE(the_committed_log_replays_headless_to_its_frame) {
  const std::string log = replays_dir() + "/spawn.log";
  TempDir dir;
  const Ran r = cli({"--replay", log, "--headless", "--dump", dir.file("d.csv")});
  BOOST_TEST_REQUIRE(r.code == 0, r.err);
  BOOST_TEST(r.err.empty(), r.err);
  BOOST_TEST(has(r.out, "ran headless: --headless given\nscene:           stack "), r.out);  // the log's scene
  BOOST_TEST(has(r.out, "frames:          90 "), r.out);
  BOOST_TEST(has(r.out, "bodies:          21 (17 mobile)"), r.out);  // both spawns landed
  BOOST_TEST(has(r.out, "\nreplay: 9 events over 90 ticks, ended at frame 90\n"), r.out);
  // The dump is the testbed's replayed state.
  Testbed tb = on("stack");
  tb.replay(read_input_log(log));
  tb.play();
  BOOST_TEST(read(dir.file("d.csv")) == dump_of(tb.world()));
}

BOOST_AUTO_TEST_CASE(frames_stops_the_replay_earlier) {
  const Ran r = cli({"--replay", replays_dir() + "/spawn.log", "--headless", "--frames", "20"});
  BOOST_TEST_REQUIRE(r.code == 0, r.err);
  BOOST_TEST(r.err.empty(), r.err);
  BOOST_TEST(has(r.out, "\nreplay: 3 events over 20 ticks, ended at frame 20\n"), r.out);
  BOOST_TEST(has(r.out, "bodies:          20 "), r.out);
}

BOOST_AUTO_TEST_CASE(scene_given_overrides_the_logs_and_an_unreachable_event_warns) {
  TempDir dir;
  const std::string log = dir.file("p.log", head + "2,key,32,0,0,0\n9,key,32,0,0,0\n20,end,0,0,0,0\n");
  const Ran r = cli({"--replay", log, "--scene", "bounce"});  // no front end: headless
  BOOST_TEST_REQUIRE(r.code == 0, r.err);
  BOOST_TEST(has(r.out, "scene:           bounce "), r.out);
  BOOST_TEST(has(r.out, "\nreplay: 1 events over 2 ticks, ended at frame 2\n"), r.out);
  BOOST_TEST(has(r.err, "warning: " + log + ": the replay stopped paused at tick 2 with 1 events left"), r.err);
}

BOOST_AUTO_TEST_CASE(bad_logs_and_flags_exit_2_with_one_line) {
  TempDir dir;
  const std::string bad = dir.file("bad.log", head + "0,key,32,0,0,0\n0,jump,0,0,0,0\n1,end,0,0,0,0\n");
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
      {{"--replay", bad, "--headless"}, "game: " + bad + ":4: unknown kind 'jump'"},
      {{"--replay", "/nonexistent/r.log"}, "game: /nonexistent/r.log: cannot read the input log"},
      {{"--replay", ""}, "game: --replay: a file name must not be empty"},
      {{"--record", dir.file("r.log"), "--replay", bad}, "game: --record and --replay: give one of them"},
      {{"--record", dir.file("r.log"), "--headless"}, "game: --record: nothing to record in a --headless run"},
      {{"--record", dir.file("r.log")}, "game: --record: needs a window, and this run is headless"},
  };
  for (const auto& [args, expected] : cases) {
    const Ran r = cli(args);
    BOOST_TEST(r.code == 2, expected);
    BOOST_TEST(r.err.rfind(expected, 0) == 0u, "'" << expected << "' at the start of: " << r.err);
    BOOST_TEST(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    BOOST_TEST(r.out.empty());
  }
}

BOOST_AUTO_TEST_CASE(a_refused_record_leaves_no_file) {
  TempDir dir;
  BOOST_TEST(cli({"--record", dir.file("r.log")}).code == 2);  // no window front end
  BOOST_TEST(!fs::exists(dir.file("r.log")));
}

BOOST_AUTO_TEST_CASE(the_window_records_and_replays_like_the_headless_run) {
  // SDL's dummy video driver: the real window loop, no display. Nobody types,
  // so the recorded log is its scene and its end tick.
  TempDir dir;
  const Ran rec = program(dir, no_display + " SDL_VIDEODRIVER=dummy", {"--scene", "stack", "--frames", "5", "--record", "r.log"});
  BOOST_TEST_REQUIRE(rec.code == 0, rec.err);
  BOOST_TEST(read(dir.file("r.log")) == "# physics input log v1\n# scene: stack\ntick,kind,key,x,y,button\n"
                                         "5,end,0,0,0,0\n");
  const Ran bad = program(dir, no_display + " SDL_VIDEODRIVER=dummy", {"--record", "/nonexistent/r.log"});
  BOOST_TEST(bad.code == 2);
  BOOST_TEST(bad.err == "game: --record: cannot write /nonexistent/r.log: No such file or directory\n");
  // The committed log in a window (paced by the clock: 1.5 s), then headless: the same final state.
  const std::string log = replays_dir() + "/spawn.log";
  const Ran win = program(dir, no_display + " SDL_VIDEODRIVER=dummy", {"--replay", log, "--frames", "90", "--dump", "w.csv"});
  BOOST_TEST_REQUIRE(win.code == 0, win.err);
  BOOST_TEST(!has(win.out, "ran headless"));
  const Ran headless = program(dir, no_display, {"--replay", log, "--dump", "h.csv"});
  BOOST_TEST_REQUIRE(headless.code == 0, headless.err);
  BOOST_TEST(has(headless.out, "ran headless: no display"));
  BOOST_TEST(csv_rows(read(dir.file("h.csv"))) == 22u);
  BOOST_TEST(read(dir.file("w.csv")) == read(dir.file("h.csv")));
}

BOOST_AUTO_TEST_CASE(help_documents_record_and_replay) {
  const Ran r = cli({"--help"});
  BOOST_TEST(has(r.out, "--record FILE"));
  BOOST_TEST(has(r.out, "--replay FILE"));
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace test_replay
