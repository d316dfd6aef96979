// The games (src/games, docs/games.md) driven through the testbed as a
// player would: keys and slingshot drags in, the level's rules out.
#include <filesystem>
#include <map>
#include <ostream>
#include <string>
#include <vector>

#include "app/input_log.hpp"
#include "scene/scene_json.hpp"
#include "app/testbed.hpp"
#include "games/platformer.hpp"
#include "games/targets.hpp"
#include "cli_helpers.hpp"

// For Boost.Test's messages (in namespace physics, for lookup by argument).
namespace physics {
std::ostream& operator<<(std::ostream& o, Level::Outcome x) {
  return o << (x == Level::Outcome::won ? "won" : x == Level::Outcome::lost ? "lost" : "playing");
}
}  // namespace physics

// The file's own names, apart from the other test files' with which it is
// compiled (Makefile, TEST_UNITY).
namespace test_games {

using namespace physics;
using namespace physics::test;

namespace {


// The command line, headless, on a committed replay of a game.
std::string replay_headless(const std::string& game) {
  const Ran r = cli({"--replay", replay_path(game), "--scene", scene_path(game), "--headless"});
  BOOST_TEST(r.code == 0, r.err);
  BOOST_TEST(r.err.empty(), r.err);
  return r.out;
}

Testbed level(const std::string& name) { return Testbed({load_scene_file(scene_path(name))}, 0); }

// The first body of the testbed's scene tagged `tag`.
EntityId first_tagged(const Testbed& tb, const std::string& tag) {
  const auto roles = tb.roles();
  for (EntityId e = 0; e < roles.size(); ++e)
    if (roles[e].tag == tag) return e;
  BOOST_FAIL("no body tagged " << tag);
  return 0;
}

// The same replay through the testbed itself, played to its end.
Testbed replayed(const std::string& game) {
  Testbed tb = level(game);
  tb.replay(read_input_log(replay_path(game)));
  tb.play();
  return tb;
}

InputEvent press(int k) { return {InputEvent::Kind::key, k}; }

// Steps the testbed `n` times, handing it `events` (by tick from now) first.
void play(Testbed& tb, int n, const std::multimap<int, InputEvent>& events = {}) {
  for (int t = 0; t < n; ++t) {
    const auto [from, to] = events.equal_range(t);
    for (auto it = from; it != to; ++it) tb.handle(it->second);
    tb.step();
  }
}

// A slingshot drag from (300, 300) pulled back by (px, py): the shot leaves
// at 0.005 px/ms per px of pull (Testbed::fling_scale).
void shoot(Testbed& tb, int px, int py) {
  tb.handle({InputEvent::Kind::mouse_down, 0, 300, 300, 1});
  tb.handle({InputEvent::Kind::mouse_move, 0, 300 - px, 300 - py, 0});
  tb.handle({InputEvent::Kind::mouse_up, 0, 300 - px, 300 - py, 1});
}

const Platformer& platformer(const Testbed& tb) { return dynamic_cast<const Platformer&>(*tb.level()); }
const Targets& targets(const Testbed& tb) { return dynamic_cast<const Targets&>(*tb.level()); }

// The error loading `text` as a scene gives (one line).
std::string error_of(const std::string& text) {
  try {
    const SceneSpec s = parse_scene(text, "bad.json");
    Testbed tb({s}, 0);
  } catch (const SceneError& e) {
    const std::string msg = e.what();
    BOOST_TEST(msg.find('\n') == std::string::npos);
    return msg;
  }
  BOOST_ERROR("no error for: " << text);
  return "";
}

}  // namespace

BOOST_AUTO_TEST_SUITE(games)

BOOST_AUTO_TEST_CASE(the_player_runs_and_collects_a_coin_on_contact) {
  Testbed tb = level("platformer");
  const EntityId coin = first_tagged(tb, "coin");  // on the ground ahead
  play(tb, 10);
  BOOST_TEST(platformer(tb).grounded());
  BOOST_TEST(platformer(tb).coins() == 0);
  play(tb, 40, {{0, press(key::right)}});
  BOOST_TEST(platformer(tb).coins() == 1);
  BOOST_TEST(!tb.world().alive(coin));
  BOOST_TEST(position(platformer(tb).player()).x > 150.0);
}

// docs/games.md: take the coins, then the flag. Running into the flag with
// a coin still out wins nothing (the HUD says why); with every coin taken
// on the way, the same run wins.
BOOST_AUTO_TEST_CASE(the_flag_wins_only_once_every_coin_is_taken) {
  const auto run = [](const char* coin_pos, int frames) {
    const std::string text = std::string(R"({"game": {"kind": "platformer"}, "world": {"gravity": [0, 0.0015], "walls": false, "restitution": 0},
      "blocks": [{"pos": [0, 560], "size": [800, 40], "mass": "inf"},
                 {"pos": [40, 528], "size": [24, 32], "mass": 1, "tag": "player"},
                 {"pos": )") + coin_pos + R"(, "size": [16, 16], "mass": "inf", "sensor": true, "tag": "coin"},
                 {"pos": [300, 500], "size": [24, 60], "mass": "inf", "sensor": true, "tag": "goal"}]})";
    Testbed tb({parse_scene(text, "flag.json")}, 0);
    play(tb, frames, {{0, press(key::right)}});
    return tb;
  };
  const Testbed at_flag = run("[600, 300]", 63);  // out of reach; the player in the flag
  BOOST_TEST(at_flag.outcome() == Level::Outcome::playing);
  BOOST_TEST(has(at_flag.level()->hud().front(), "the flag wants every coin first"), at_flag.level()->hud().front());
  const Testbed missing = run("[600, 300]", 120);  // past it
  BOOST_TEST(missing.outcome() == Level::Outcome::playing);
  BOOST_TEST(platformer(missing).coins() == 0);
  const Testbed taken = run("[150, 540]", 120);  // on the way
  BOOST_TEST(platformer(taken).coins() == 1);
  BOOST_TEST(taken.outcome() == Level::Outcome::won);
}

BOOST_AUTO_TEST_CASE(the_player_jumps_only_from_the_ground) {
  Testbed tb = level("platformer");
  play(tb, 10);
  const BodyId p = platformer(tb).player();
  const double y0 = position(p).y;
  play(tb, 1, {{0, press(key::space)}});
  BOOST_TEST(!platformer(tb).grounded());
  BOOST_TEST(platformer(tb).player_velocity().y < -0.6);
  BOOST_TEST(position(p).y < y0);
  BOOST_TEST(mass(p) == fixed_mass);  // a mover: the level places it
  // A second press in the air changes nothing: the rise goes on slowing down.
  play(tb, 10);
  const double vy = platformer(tb).player_velocity().y;
  play(tb, 1, {{0, press(key::up)}});
  BOOST_TEST(platformer(tb).player_velocity().y > vy);
  // Back on the ground it jumps again.
  play(tb, 60);
  BOOST_TEST(platformer(tb).grounded());
  BOOST_TEST(position(p).y == y0);
  play(tb, 1, {{0, press(key::up)}});
  BOOST_TEST(platformer(tb).player_velocity().y < -0.6);
}

BOOST_AUTO_TEST_CASE(falling_off_the_world_restarts_the_level) {
  Testbed tb = level("platformer");
  // Run into the gap without jumping.
  std::int64_t restarted_at = -1;
  std::multimap<int, InputEvent> keys{{0, press(key::right)}};
  for (int t = 0; t < 200 && restarted_at < 0; ++t) {
    const std::int64_t before = tb.world().frame;
    play(tb, 1, t == 0 ? keys : std::multimap<int, InputEvent>{});
    if (tb.world().frame < before) restarted_at = t;
  }
  BOOST_TEST(restarted_at > 0);
  BOOST_TEST(has(tb.message(), "lost"));
  BOOST_TEST(tb.outcome() == Level::Outcome::playing);
  BOOST_TEST(platformer(tb).coins() == 0);  // a fresh level
}

BOOST_AUTO_TEST_CASE(the_moving_platform_turns_at_both_ends) {
  Testbed tb = level("platformer");
  const EntityId platform = first_tagged(tb, "platform");
  double lo = 1e9, hi = -1e9;
  for (int t = 0; t < 450; ++t) {
    play(tb, 1);
    const double x = tb.world().components.position[platform].x;
    lo = std::min(lo, x), hi = std::max(hi, x);
  }
  // Start 380, "travel" 100: it stays within a step's motion (1 px) of [380, 480].
  BOOST_TEST(lo >= 379.0);
  BOOST_TEST(lo <= 381.0);
  BOOST_TEST(hi >= 479.0);
  BOOST_TEST(hi <= 481.0);
}

BOOST_AUTO_TEST_CASE(a_tower_at_rest_stays_put_and_breaks_no_target) {
  for (const char* name : {"targets-1", "targets-2", "targets-3"}) {
    Testbed tb = level(name);
    const int count = targets(tb).targets_left();
    const std::vector<Vector> start = tb.world().components.position;
    double moved = 0.0;
    for (int t = 0; t < 300; ++t) {
      play(tb, 1);
      for (std::size_t e = 0; e < start.size(); ++e)
        moved = std::max(moved, Vector::norm(tb.world().components.position[e] - start[e]));
    }
    BOOST_TEST(moved < 0.01, name << ": a block moved " << moved << " px");
    BOOST_TEST(targets(tb).targets_left() == count, name);
    BOOST_TEST(tb.outcome() == Level::Outcome::playing, name);
  }
}

BOOST_AUTO_TEST_CASE(a_shot_leaves_from_the_sling_and_breaks_a_target) {
  Testbed tb = level("targets-1");
  play(tb, 62);
  const std::size_t bodies = tb.world().components.size();
  shoot(tb, 240, -30);
  BOOST_TEST(tb.world().components.size() == bodies + 1);
  BOOST_TEST(tb.roles().back().tag == "shot");
  // It leaves from the sling's centre (90 + 10, 400 + 10), whatever the press point.
  const Vector p = tb.world().components.position[bodies];
  BOOST_TEST(p.x == 100.0 - Targets::shot_size / 2.0);
  BOOST_TEST(p.y == 410.0 - Targets::shot_size / 2.0);
  BOOST_TEST(targets(tb).shots_left() == 2);
  play(tb, 60);
  BOOST_TEST(targets(tb).targets_left() == 1);
  BOOST_TEST(targets(tb).score() == Targets::points);
}

BOOST_AUTO_TEST_CASE(spent_shots_lose_the_level_which_starts_again) {
  Testbed tb = level("targets-1");
  for (int i = 0; i < 3; ++i) {
    shoot(tb, 150, 150);  // downwards into the floor, far from the tower
    play(tb, 5);
  }
  BOOST_TEST(targets(tb).shots_left() == 0);
  const std::size_t bodies = tb.world().components.size();
  shoot(tb, 150, 150);  // no shot left: nothing is launched
  BOOST_TEST(tb.world().components.size() == bodies);
  play(tb, Targets::settle_frames + 5);
  BOOST_TEST(has(tb.message(), "lost"));
  BOOST_TEST(targets(tb).shots_left() == 3);  // the level again, from the start
}

BOOST_AUTO_TEST_CASE(a_level_missing_what_its_game_needs_is_an_error) {
  BOOST_TEST(has(error_of(R"({"game": {"kind": "platformer"}, "blocks": []})"), "exactly one block with \"tag\": \"player\""));
  BOOST_TEST(has(error_of(R"({"game": {"kind": "targets"}, "blocks": [{"pos": [100, 100], "size": [10, 10], "mass": 1, "tag": "target"}]})"),
                 "\"tag\": \"sling\""));
  BOOST_TEST(has(error_of(R"({"game": {"kind": "golf"}, "blocks": []})"), "game.kind"));
  BOOST_TEST(has(error_of(R"({"game": {"kind": "targets", "shots": 0}, "blocks": []})"), "game.shots"));
  BOOST_TEST(has(error_of(R"({"game": {"shots": 3}, "blocks": []})"), "missing key \"kind\""));
  BOOST_TEST(has(error_of(R"({"blocks": [{"pos": [100, 100], "size": [10, 10], "mass": 1, "tag": "Player!"}]})"),
                 "blocks[0].tag"));
  BOOST_TEST(has(error_of(R"({"blocks": [{"pos": [100, 100], "size": [10, 10], "mass": 1, "strength": -1}]})"),
                 "blocks[0].strength"));
  BOOST_TEST(has(error_of(R"({"blocks": [{"pos": [100, 100], "size": [10, 10], "mass": 1, "travel": 0}]})"),
                 "blocks[0].travel"));
  BOOST_TEST(has(error_of(R"({"blocks": [{"pos": [100, 100], "size": [10, 10], "mass": 1, "travel": 50}]})"),
                 "only a block with \"tag\": \"platform\" travels"));
  const std::string player = R"({"pos": [50, 50], "size": [10, 10], "mass": 1, "tag": "player"})";
  BOOST_TEST(has(error_of(R"({"game": {"kind": "platformer"}, "blocks": [)" + player +
                          R"(, {"pos": [100, 100], "size": [50, 10], "mass": "inf", "tag": "platform", "travel": 50}]})"),
                 "needs a \"velocity\" and a \"travel\""));
  BOOST_TEST(has(error_of(R"({"game": {"kind": "platformer"}, "blocks": [)" + player +
                          R"(, {"pos": [100, 100], "size": [50, 10], "mass": "inf", "tag": "platform", "velocity": [0.1, 0]}]})"),
                 "needs a \"velocity\" and a \"travel\""));
}

BOOST_AUTO_TEST_CASE(game_keys_print_and_read_back) {
  const SceneSpec s = load_scene_file(scene_path("targets-1"));
  const SceneSpec again = parse_scene(to_json(s), "again.json");
  BOOST_TEST(again.game.kind == "targets");
  BOOST_TEST(again.game.shots == 3);
  BOOST_TEST(again.game.next == "targets-2.json");
  BOOST_TEST((again.blocks == s.blocks));
  const SceneSpec p = load_scene_file(scene_path("platformer"));
  BOOST_TEST((parse_scene(to_json(p), "again.json").blocks == p.blocks));
}

BOOST_AUTO_TEST_CASE(enter_after_a_win_loads_the_next_level) {
  Testbed tb = level("targets-1");
  play(tb, 62);
  shoot(tb, 240, -30);
  play(tb, 90);
  shoot(tb, 300, -40);
  play(tb, 60);
  BOOST_TEST(tb.outcome() == Level::Outcome::won);
  BOOST_TEST(tb.paused());
  tb.handle(press(key::enter));
  BOOST_TEST(tb.scene().name == "targets-2");
  BOOST_TEST(tb.outcome() == Level::Outcome::playing);
  BOOST_TEST(!tb.paused());
  BOOST_TEST(targets(tb).targets_left() == 3);
}

// The committed replays (replays/, recorded in the format of --record) win
// their levels headless, as `build/game --replay replays/X.log --headless`.
BOOST_AUTO_TEST_CASE(the_committed_platformer_replay_wins_with_every_coin) {
  const std::string out = replay_headless("platformer");
  BOOST_TEST(has(out, "\nreplay: 13 events over 435 ticks, ended at frame 435\n"), out);
  BOOST_TEST(has(out, "\ngame: won: coins 4/4 "), out);
  // The same through the testbed itself: won at frame 435, every coin taken.
  const Testbed tb = replayed("platformer");
  BOOST_TEST(tb.outcome() == Level::Outcome::won);
  BOOST_TEST(tb.world().frame == 435);
  BOOST_TEST(platformer(tb).coins() == 4);
  BOOST_TEST(platformer(tb).coins_total() == 4);
}

// The large level: a Tiled map of 220 x 50 tiles of 16 px (3520 x 800 px, a
// camera's worth of scrolling), won by its replay with its six coins; the
// run drops through a one-way trapdoor and rides the moving platform.
BOOST_AUTO_TEST_CASE(the_committed_replay_of_the_large_level_wins_with_every_coin) {
  const std::string out = replay_headless("platformer-big");
  BOOST_TEST(has(out, "\nreplay: 31 events over 955 ticks, ended at frame 955\n"), out);
  BOOST_TEST(has(out, "\ngame: won: coins 6/6 "), out);
  const Testbed tb = replayed("platformer-big");
  BOOST_TEST(tb.outcome() == Level::Outcome::won);
  BOOST_TEST(platformer(tb).coins() == 6);
  BOOST_REQUIRE_EQUAL(tb.scene().tiles.size(), 1u);
  BOOST_TEST(tb.world().tiles.layers()[0].grid().columns == 220);
  BOOST_TEST(tb.world().tiles.layers()[0].grid().rows == 50);
  BOOST_TEST(tb.scene().width == 3520.0);
  const Vec2 at = *platformer(tb).focus();  // what the camera follows: the player, by the flag far right
  BOOST_TEST(at.x > 3200.0);
  BOOST_TEST(at.y < 200.0);
}

// Down + Space on a one-way floor drops through it, on a one-way block and on
// a one-way tile alike; Space alone jumps from it, and Down + Space on a
// solid floor jumps too.
BOOST_AUTO_TEST_CASE(down_and_jump_drop_through_one_way_blocks_and_tiles) {
  const std::string world = R"({"game": {"kind": "platformer"}, "world": {"gravity": [0, 0.0015], "walls": false,
    "restitution": 0}, "blocks": [{"pos": [0, 560], "size": [800, 40], "mass": "inf"},
    {"pos": [100, 368], "size": [24, 32], "mass": 1, "tag": "player"})";
  const std::string block = world + R"(, {"pos": [50, 400], "size": [200, 16], "mass": "inf", "one_way": "up"}]})";
  const std::string tiles = world + R"(], "tiles": [{"pos": [48, 400], "cell": 16, "rows": ["==========="]}]})";
  for (const std::string& text : {block, tiles}) {
    const auto after = [&](std::multimap<int, InputEvent> keys) {
      Testbed tb({parse_scene(text, "drop.json")}, 0);
      play(tb, 5);
      BOOST_TEST(platformer(tb).grounded());
      play(tb, 40, keys);
      return position(platformer(tb).player()).y;
    };
    BOOST_TEST(after({{0, press(key::down)}, {1, press(key::space)}}) == 528.0);  // through, down to the floor
    BOOST_TEST(after({{1, press(key::space)}}) < 368.0);                           // a jump
    BOOST_TEST(after({}) == 368.0);                                                // standing
  }
  Testbed solid({parse_scene(world + "]}", "solid.json")}, 0);
  play(solid, 60);
  BOOST_TEST(platformer(solid).grounded());
  const double y = position(platformer(solid).player()).y;
  play(solid, 10, {{0, press(key::down)}, {1, press(key::space)}});
  BOOST_TEST(position(platformer(solid).player()).y < y);
}

BOOST_AUTO_TEST_CASE(the_committed_targets_replay_wins_level_one_with_two_shots) {
  const std::string out = replay_headless("targets-1");
  BOOST_TEST(has(out, "\nreplay: 6 events over 177 ticks, ended at frame 177\n"), out);
  BOOST_TEST(has(out, "\ngame: won: targets left 0   shots 1/3   score 200 "), out);
  const Testbed tb = replayed("targets-1");
  BOOST_TEST(tb.outcome() == Level::Outcome::won);
  BOOST_TEST(tb.world().frame == 177);
  BOOST_TEST(targets(tb).targets_left() == 0);
  BOOST_TEST(targets(tb).shots_left() == 1);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace test_games
