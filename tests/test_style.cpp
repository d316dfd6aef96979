// The drawing styles (app/style.hpp, --style, scene key "style"): plain is
// today's picture byte for byte; speed colours movable blocks by speed; sprite
// draws a shape inside each box by its tag and nothing outside it; every scene
// draws in every style; bad values are bad input. Pictures are the offscreen
// renderer's, which shares app/style.cpp with the window; one case checks the
// window's picture (SDL's dummy driver) against it.
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "scene/builtin_scenes.hpp"
#include "app/cli.hpp"
#include "app/offscreen.hpp"
#include "scene/scene_json.hpp"
#include "app/style.hpp"
#include "app/testbed.hpp"
#include "cli_helpers.hpp"

#include "png_decode.hpp"

// The file's own names, apart from the other test files' with which it is
// compiled (Makefile, TEST_UNITY).
namespace test_style {

using namespace physics;
using namespace physics::test;
namespace fs = std::filesystem;

namespace {

constexpr Style all_styles[] = {Style::plain, Style::speed, Style::sprite};
constexpr Color background{255, 255, 255, 255};

// An offscreen picture and its pixels.
struct Picture {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;
  Color at(int x, int y) const {
    const std::size_t i = (static_cast<std::size_t>(y) * width + x) * 3;
    return {rgb[i], rgb[i + 1], rgb[i + 2], 255};
  }
  // Pixels of colour c in [x0, x1) x [y0, y1).
  int count(Color c, int x0, int y0, int x1, int y1) const {
    int n = 0;
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) n += at(x, y) == c;
    return n;
  }
};

// The scene drawn at frame 0 (nothing moved yet) in `style`, with its roles.
Picture draw(const SceneSpec& s, Style style) {
  const std::vector<Body> bodies = expand(s, s.name);
  const World w = make_world(s, bodies, true);
  return {s.width, s.height, Offscreen::render(w, s.width, s.height, style, roles_by_entity(s, bodies))};
}

BlockSpec block(Vector pos, int w, int h, double mass, std::string tag = "", Vector v = {}) {
  BlockSpec b;
  b.pos = pos;
  b.width = w;
  b.height = h;
  b.mass = mass;
  b.tag = std::move(tag);
  b.velocity = v;
  b.color = Color{200, 40, 40, 255};
  return b;
}

// A scene of the given blocks, walls on, no gravity.
SceneSpec scene(std::vector<BlockSpec> blocks, bool walls = true) {
  SceneSpec s;
  s.name = "test";
  s.walls = walls;
  for (BlockSpec& b : blocks) s.blocks.emplace_back(std::move(b));
  return s;
}

std::vector<std::string> scene_files() {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(fs::path(__FILE__).parent_path().parent_path() / "scenes"))
    if (e.path().extension() == ".json") out.push_back(e.path().string());
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(style_plain)

BOOST_AUTO_TEST_CASE(plain_is_todays_picture_byte_for_byte) {
  // Today's picture is Offscreen::render without a style (the course's Draw).
  for (const char* name : {"walls", "bounce", "many", "cradle", "stack", "gas"}) {
    World w = make_world(*find_builtin(name), true);
    for (int frame = 0; frame < 30; ++frame) Game::step(w);
    const auto today = Offscreen::render(w, 800, 600);
    BOOST_TEST((Offscreen::render(w, 800, 600, Style::plain, {}) == today), name);
  }
  // The same through the command line: --style plain, or none, gives one PNG.
  TempDir dir;
  for (const std::string& file : scene_files()) {
    if (has(file, "gas10k")) continue;  // 10 000 bodies: the built-in gas covers the crowd
    const std::string a = dir.file("a.png"), b = dir.file("b.png");
    BOOST_TEST_REQUIRE(cli({"--scene", file, "--frames", "5", "--screenshot", a}).code == 0);
    BOOST_TEST_REQUIRE(cli({"--scene", file, "--frames", "5", "--screenshot", b, "--style", "plain"}).code == 0);
    std::ifstream fa(a, std::ios::binary), fb(b, std::ios::binary);
    const std::string pa{std::istreambuf_iterator<char>(fa), {}}, pb{std::istreambuf_iterator<char>(fb), {}};
    // A scene that asks for a style itself (styles.json, the games) differs from plain.
    if (load_scene_file(file).style == Style::plain) BOOST_TEST((pa == pb), file);
    else BOOST_TEST((pa != pb), file);
  }
}

BOOST_AUTO_TEST_CASE(a_scene_of_walls_only_looks_the_same_in_every_style) {
  // Walls and fixed untagged blocks keep today's look in every style.
  const SceneSpec s = scene({block({300, 300}, 80, 20, infinity)});
  const Picture plain = draw(s, Style::plain);
  for (const Style st : all_styles) BOOST_TEST((draw(s, st).rgb == plain.rgb), name(st));
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(style_speed)

BOOST_AUTO_TEST_CASE(the_ramp_runs_from_blue_at_rest_to_red_at_the_top_speed) {
  BOOST_TEST((Styles::speed_color(0) == Styles::slow_color));
  BOOST_TEST((Styles::speed_color(Styles::top_speed) == Styles::fast_color));
  BOOST_TEST((Styles::speed_color(50 * Styles::top_speed) == Styles::fast_color));
  BOOST_TEST((Styles::speed_color(std::nan("")) == Styles::slow_color));
  BOOST_TEST(Styles::slow_color.b > 200);
  BOOST_TEST(Styles::fast_color.r > 200);
  const Color mid = Styles::speed_color(0.4 * Styles::top_speed);  // green, going yellow
  BOOST_TEST((mid.g > mid.r && mid.g > mid.b));
  // Each step of speed changes the colour a little: a ramp, not a few bins.
  for (double v = 0; v < Styles::top_speed; v += 0.01) {
    const Color a = Styles::speed_color(v), b = Styles::speed_color(v + 0.01);
    BOOST_TEST(std::abs(a.r - b.r) + std::abs(a.g - b.g) + std::abs(a.b - b.b) <= 24, v);
  }
}

BOOST_AUTO_TEST_CASE(a_resting_block_is_the_slow_colour_and_a_fast_one_the_fast_colour) {
  SceneSpec s = scene({block({100, 100}, 40, 40, 1), block({300, 300}, 40, 40, 1, "", {1.5, 0}),
                       block({500, 200}, 40, 40, 1, "", {0, 0.4 * Styles::top_speed}),
                       block({200, 400}, 80, 20, infinity)});
  BlockSpec sensor = block({600, 400}, 40, 40, infinity);
  sensor.contact.rules.sensor = true;
  s.blocks.emplace_back(sensor);
  const Picture p = draw(s, Style::speed);
  BOOST_TEST((p.at(120, 120) == Styles::slow_color));
  BOOST_TEST(p.count(Styles::slow_color, 100, 100, 140, 140) == 38 * 38);  // all but the 1 px outline
  BOOST_TEST((p.at(101, 101) == Styles::slow_color));
  BOOST_TEST((p.at(100, 100) == outline_color(Styles::slow_color)));
  BOOST_TEST((p.at(320, 320) == Styles::fast_color));
  BOOST_TEST(p.count(Styles::fast_color, 300, 300, 340, 340) == 38 * 38);
  BOOST_TEST((p.at(520, 220) == Styles::speed_color(0.4 * Styles::top_speed)));
  BOOST_TEST((p.at(240, 410) == Color{200, 40, 40, 255}));  // fixed: its own colour
  BOOST_TEST((p.at(620, 420) == background));               // a sensor stays an outline
  BOOST_TEST((p.at(600, 420) == Color{200, 40, 40, 255}));
  BOOST_TEST((p.at(400, 10) == Game::wall_blue));
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(style_sprite)

BOOST_AUTO_TEST_CASE(a_coin_is_a_gold_disc_inside_its_box) {
  const Picture p = draw(scene({block({200, 200}, 40, 40, 1, "coin")}), Style::sprite);
  BOOST_TEST((p.at(220, 220) == Styles::coin_gold));
  BOOST_TEST(p.count(Styles::coin_gold, 200, 200, 240, 240) > 400);  // about pi (0.78 * 20)^2 = 764
  for (const auto& [x, y] : {std::pair{200, 200}, {239, 200}, {200, 239}, {239, 239}, {203, 203}})
    BOOST_TEST((p.at(x, y) == background), x << "," << y);  // a disc, not a square
  // Plain fills the whole box.
  BOOST_TEST((draw(scene({block({200, 200}, 40, 40, 1, "coin")}), Style::plain).at(200, 200) ==
              outline_color(Color{200, 40, 40, 255})));
}

BOOST_AUTO_TEST_CASE(a_player_is_a_little_character) {
  const Picture p = draw(scene({block({300, 200}, 40, 60, 1, "player")}), Style::sprite);
  BOOST_TEST(p.count(Styles::skin, 300, 200, 340, 222) > 60);      // the head, on top
  BOOST_TEST(p.count(Styles::skin, 300, 230, 340, 260) == 0);
  BOOST_TEST(p.count(Styles::trousers, 300, 243, 340, 260) > 60);  // the legs, below
  BOOST_TEST(p.count(Styles::trousers, 300, 200, 340, 240) == 0);
  BOOST_TEST(p.count(Color{200, 40, 40, 255}, 300, 222, 340, 242) > 100);  // the body, the block's colour
  BOOST_TEST(p.count(Color{30, 30, 30, 255}, 300, 200, 340, 222) >= 2);  // the eyes
  BOOST_TEST((p.at(300, 200) == background));
  BOOST_TEST((p.at(339, 259) == background));  // between and beside the legs
}

BOOST_AUTO_TEST_CASE(a_target_is_red_and_white_rings) {
  const Picture p = draw(scene({block({300, 200}, 50, 50, infinity, "target")}), Style::sprite);
  BOOST_TEST((p.at(325, 225) == Styles::target_red));  // the bull's eye
  BOOST_TEST((p.at(325 + 8, 225) == background));      // the first white ring, r in [5, 10)
  BOOST_TEST((p.at(325 + 12, 225) == Styles::target_red));
  BOOST_TEST((p.at(300, 200) == background));
}

BOOST_AUTO_TEST_CASE(an_untagged_movable_block_is_a_crate_and_fixed_blocks_stay_plain) {
  const Picture p = draw(scene({block({200, 200}, 42, 42, 1), block({300, 300}, 80, 20, infinity),
                                block({400, 200}, 42, 42, 1, "someone_elses_tag")}),
                         Style::sprite);
  for (const int x0 : {200, 400}) {
    BOOST_TEST((p.at(x0 + 31, 210) == Styles::crate_wood));  // above the brace
    BOOST_TEST((p.at(x0 + 21, 221) != Styles::crate_wood));  // on the brace
    BOOST_TEST((p.at(x0 + 1, 221) != Styles::crate_wood));   // the frame
  }
  BOOST_TEST((p.at(340, 310) == Color{200, 40, 40, 255}));
  BOOST_TEST((p.at(10, 300) == Game::wall_black));
}

BOOST_AUTO_TEST_CASE(every_sprite_stays_inside_its_box_at_every_size) {
  // The collisions use the box: a sprite drawn outside it would lie.
  for (const char* tag : {"player", "coin", "goal", "target", "platform", "crate", ""})
    for (const auto& [w, h] : {std::pair{1, 1}, {2, 9}, {7, 3}, {13, 29}, {40, 60}, {300, 24}, {160, 160}}) {
      BlockSpec b = block({101.5, 100.25}, w, h, 1, tag);
      const Picture p = draw(scene({b}, false), Style::sprite);
      // The pixels whose centres lie in the box: x in [101, 101 + w), y in [100, 100 + h).
      int inside = 0, outside = 0;
      for (int y = 0; y < p.height; ++y)
        for (int x = 0; x < p.width; ++x) {
          if (p.at(x, y) == background) continue;
          const bool in = x >= 101 && x < 101 + w && y >= 100 && y < 100 + h;
          ++(in ? inside : outside);
        }
      BOOST_TEST(outside == 0, tag << " " << w << "x" << h);
      if (w >= 7 && h >= 7) BOOST_TEST(inside > 0, tag << " " << w << "x" << h);
    }
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(style_everywhere)

BOOST_AUTO_TEST_CASE(every_scene_draws_in_every_style) {
  std::vector<SceneSpec> scenes(builtin_scenes().begin(), builtin_scenes().end());
  for (const std::string& f : scene_files())
    if (!has(f, "gas10k")) scenes.push_back(load_scene_file(f));
  for (const SceneSpec& s : scenes) {
    const Picture plain = draw(s, Style::plain);
    for (const Style st : all_styles) {
      const Picture p = draw(s, st);
      BOOST_TEST(p.rgb.size() == std::size_t(s.width) * s.height * 3, s.name);
      BOOST_TEST((p.at(s.width / 2, 10) == plain.at(s.width / 2, 10)), s.name << " " << name(st));  // the walls
    }
    // A scene with a movable block looks different in sprite (crates at least).
    const bool moving = s.name != "walls";
    BOOST_TEST((draw(s, Style::sprite).rgb != plain.rgb) == moving, s.name);
  }
  // Headless screenshots from the command line, every built-in scene, every style.
  TempDir dir;
  for (const SceneSpec& s : builtin_scenes())
    for (const Style st : all_styles) {
      const Ran r = cli({"--scene", s.name, "--frames", "3", "--style", std::string(name(st)), "--screenshot",
                         dir.file("s.png")});
      BOOST_TEST(r.code == 0, s.name << " " << name(st) << ": " << r.err);
    }
}

BOOST_AUTO_TEST_CASE(the_style_key_and_flag_are_read_printed_and_overridden) {
  TempDir dir;
  const std::string file = dir.file("s.json", R"({"style": "speed", "blocks": [{"pos": [100, 100], "size": [20, 20], "mass": 1}]})");
  BOOST_TEST((read_scene_file(file).style == Style::speed));
  const Ran printed = cli({"--scene", file, "--print-scene"});
  BOOST_TEST(has(printed.out, "\"style\": \"speed\""), printed.out);
  BOOST_TEST((read_scene(printed.out, "printed.json").style == Style::speed));
  BOOST_TEST(has(cli({"--scene", file, "--print-scene", "--style", "sprite"}).out, "\"style\": \"sprite\""));
  // plain is the default and is not printed: today's files print as before.
  BOOST_TEST(!has(cli({"--scene", file, "--print-scene", "--style", "plain"}).out, "style"));
  BOOST_TEST(!has(cli({"--scene", "many", "--print-scene"}).out, "style"));
  BOOST_TEST(has(cli({"--help"}).out, "--style"));
  // The testbed hands the window the style: the flag's, else the scene's.
  SceneSpec s = read_scene_file(file);
  BOOST_TEST((Testbed({s}, 0).view(0, 0).style == Style::speed));
  Overrides o;
  o.style = Style::sprite;
  BOOST_TEST((Testbed({s}, 0, o).view(0, 0).style == Style::sprite));
}

BOOST_AUTO_TEST_CASE(bad_style_values_are_one_line_errors_with_exit_2) {
  expect_bad({"--style", "fancy"}, "game: --style: must be plain, speed or sprite (got 'fancy')");
  expect_bad({"--style", ""}, "--style: must be plain, speed or sprite (got '')");
  expect_bad({"--style", "Sprite"}, "--style: must be plain, speed or sprite (got 'Sprite')");
  TempDir dir;
  const std::string bad_value = dir.file("v.json", R"({"style": "fancy", "blocks": []})");
  expect_bad({"--scene", bad_value}, bad_value + ": style: must be \"plain\", \"speed\" or \"sprite\" (got the string \"fancy\")");
  const std::string bad_type = dir.file("t.json", R"({"style": 3, "blocks": []})");
  expect_bad({"--scene", bad_type}, bad_type + ": style: ");
  const std::string misspelt = dir.file("k.json", R"({"styel": "speed", "blocks": []})");
  expect_bad({"--scene", misspelt}, "unknown key (did you mean \"style\"?)");
}

BOOST_AUTO_TEST_CASE(the_window_draws_the_styles_as_the_offscreen_picture) {
  // The window (SDL, dummy video driver) and the headless picture share
  // app/style.cpp: without the HUD, the two pictures of a frame agree.
  TempDir dir;
  // Absolute: the program runs in the scratch directory.
  const std::string scenes = (fs::absolute(__FILE__).parent_path().parent_path() / "scenes" / "styles.json").string();
  const auto run = [&](const std::string& env, const std::string& style, std::vector<std::string> args,
                       const std::string& png) {
    args.insert(args.end(), {"--scene", scenes, "--frames", "20", "--style", style, "--screenshot", dir.file(png)});
    return program(dir, no_display + " " + env, args).code;
  };
  const auto load = [&](const std::string& png) {
    Picture p;
    int n = 0;
    std::uint8_t* data = stbi_load(dir.file(png).c_str(), &p.width, &p.height, &n, 3);
    if (data) p.rgb.assign(data, data + std::size_t(p.width) * p.height * 3);
    stbi_image_free(data);
    return p;
  };
  for (const char* st : {"sprite", "speed"}) {
    BOOST_TEST_REQUIRE(run("SDL_VIDEODRIVER=dummy", st, {"--overlays", "nohud"}, "window.png") == 0);
    BOOST_TEST_REQUIRE(run("", st, {}, "offscreen.png") == 0);
    const Picture a = load("window.png"), b = load("offscreen.png");
    BOOST_TEST_REQUIRE((a.width == 800 && b.width == 800 && a.rgb.size() == b.rgb.size()));
    std::size_t differ = 0;
    for (std::size_t i = 0; i < a.rgb.size(); i += 3)
      differ += a.rgb[i] != b.rgb[i] || a.rgb[i + 1] != b.rgb[i + 1] || a.rgb[i + 2] != b.rgb[i + 2];
    // Sprites are runs of whole pixels: the same pixels exactly. Speed fills
    // the boxes where they are, as plain, and SDL rounds a box at a fractional
    // position its own way: an edge row or column at most per block.
    if (std::string(st) == "sprite") BOOST_TEST(differ == 0u, st << ": " << differ << " pixels differ");
    else BOOST_TEST(differ < 800u * 600u / 200u, st << ": " << differ << " pixels differ");
    BOOST_TEST(a.count(background, 0, 0, 800, 600) < 800 * 600 * 3 / 4, st);  // something drawn
  }
  // With the HUD, speed has its legend: the ramp's two ends, near the HUD's
  // lines (no block there has exactly those colours).
  BOOST_TEST_REQUIRE(run("SDL_VIDEODRIVER=dummy", "speed", {}, "legend.png") == 0);
  const Picture l = load("legend.png");
  BOOST_TEST_REQUIRE(l.width == 800);
  BOOST_TEST(l.count(Styles::slow_color, 40, 40, 300, 300) >= 10);
  BOOST_TEST(l.count(Styles::fast_color, 40, 40, 300, 300) >= 10);
  BOOST_TEST_REQUIRE(run("SDL_VIDEODRIVER=dummy", "sprite", {}, "nolegend.png") == 0);
  BOOST_TEST(load("nolegend.png").count(Styles::fast_color, 40, 40, 300, 300) == 0);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace test_style
