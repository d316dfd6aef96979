// The testbed's input handling without a window: events in, world changes out.
#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "scene/builtin_scenes.hpp"
#include "helpers.hpp"
#include "cli_helpers.hpp"
#include "scene/scene_json.hpp"
#include "app/camera.hpp"
#include "app/input_log.hpp"
#include "app/overlay.hpp"
#include "app/testbed.hpp"
#include "games/targets.hpp"

// The file's own names, apart from the other test files' with which it is
// compiled (Makefile, TEST_UNITY).
namespace test_testbed {

using namespace physics;

namespace {

std::vector<SceneSpec> all_scenes() { return {builtin_scenes().begin(), builtin_scenes().end()}; }

Testbed on(const char* name, Overlays o = {}) {
  const auto scenes = all_scenes();
  std::size_t i = 0;
  while (scenes[i].name != name) ++i;
  return Testbed(scenes, i, {}, o);
}

InputEvent press(int k) { return {InputEvent::Kind::key, k}; }
InputEvent down(int x, int y) { return {InputEvent::Kind::mouse_down, 0, x, y, 1}; }
InputEvent move(int x, int y) { return {InputEvent::Kind::mouse_move, 0, x, y, 0}; }
InputEvent up(int x, int y) { return {InputEvent::Kind::mouse_up, 0, x, y, 1}; }

}  // namespace

BOOST_AUTO_TEST_SUITE(testbed_input)

BOOST_AUTO_TEST_CASE(time_runs_fixed_steps) {
  Testbed tb = on("many");
  BOOST_TEST(tb.advance(course_dt * 2.5) == 2);
  BOOST_TEST(tb.world().frame == 2);
  BOOST_TEST(tb.advance(course_dt * 0.5) == 1);  // the half step left over completes
  // A long stall runs at most a few steps: the simulation slows down instead of freezing.
  BOOST_TEST(tb.advance(10'000.0) == Testbed::max_steps_per_frame);
  // Never past a frame limit (--frames).
  Testbed tb2 = on("many");
  tb2.advance(course_dt * 4, 2);
  BOOST_TEST(tb2.world().frame == 2);
}

BOOST_AUTO_TEST_CASE(space_pauses_and_resumes) {
  Testbed tb = on("many");
  tb.handle(press(' '));
  BOOST_TEST(tb.paused());
  BOOST_TEST(tb.advance(1000.0) == 0);
  BOOST_TEST(tb.world().frame == 0);
  tb.handle(press(' '));
  BOOST_TEST(!tb.paused());
  BOOST_TEST(tb.advance(course_dt) == 1);
}

BOOST_AUTO_TEST_CASE(n_or_right_arrow_steps_once_and_pauses) {
  Testbed tb = on("many");
  tb.handle(press('n'));
  BOOST_TEST(tb.world().frame == 1);
  BOOST_TEST(tb.paused());
  tb.handle(press(key::right));
  BOOST_TEST(tb.world().frame == 2);
  const auto pos = tb.world().components.position;
  BOOST_TEST(tb.advance(1000.0) == 0);
  BOOST_TEST((tb.world().components.position == pos));
}

BOOST_AUTO_TEST_CASE(r_resets_the_scene) {
  Testbed tb = on("many");
  const auto start = tb.world().components.position;
  for (int i = 0; i < 30; ++i) tb.step();
  bool spawned = false;  // somewhere free of the moving squares
  for (int x = 100; x < 700 && !spawned; x += 40)
    for (int y = 100; y < 500 && !spawned; y += 40) spawned = tb.spawn({double(x), double(y)}, {});
  BOOST_TEST(tb.world().components.size() == 16u);
  tb.handle(press('r'));
  BOOST_TEST(tb.world().frame == 0);
  BOOST_TEST(tb.world().components.size() == 15u);
  BOOST_TEST((tb.world().components.position == start));
}

BOOST_AUTO_TEST_CASE(digits_and_tab_switch_scenes) {
  Testbed tb = on("many");
  BOOST_TEST(tb.scene().name == "many");
  tb.handle(press('1'));
  BOOST_TEST(tb.scene().name == "walls");
  BOOST_TEST(tb.world().components.size() == 4u);
  BOOST_TEST(!tb.world().declares(SystemId::move));  // walls declares Draw only
  tb.handle(press('7'));
  BOOST_TEST(tb.scene().name == "gas");
  tb.handle(press('9'));  // there is no 9th scene: nothing changes
  BOOST_TEST(tb.scene().name == "gas");
  // The H list says so: 1-8 with the built-ins, 9 when a scene file joins them.
  const auto digits = [](std::size_t n) { return Testbed::key_list(n)[3]; };
  BOOST_TEST(digits(8).starts_with("1-8    choose a scene, Tab"), digits(8));
  BOOST_TEST(digits(9).starts_with("1-9    scene (9: the --scene file)"), digits(9));
  tb.handle(press('h'));
  BOOST_TEST(tb.view(60, 0).help[3] == digits(8));
  tb.handle(press(key::tab));
  BOOST_TEST(tb.scene().name == "stack");
  tb.handle(press(key::tab));
  BOOST_TEST(tb.scene().name == "walls");  // wraps
}

BOOST_AUTO_TEST_CASE(overrides_apply_to_every_scene_switched_to) {
  Overrides o;
  o.world = {{"gravity", "0,0.002"}};
  Testbed tb(all_scenes(), 0, o);
  tb.handle(press('7'));
  BOOST_TEST(tb.world().params.gravity.y == 0.002);
}

BOOST_AUTO_TEST_CASE(a_click_spawns_a_block_at_rest_centred_on_the_pointer) {
  Testbed tb = on("bounce");
  const std::size_t n = tb.world().components.size();
  tb.handle(down(400, 200));
  tb.handle(up(401, 201));  // moved less than the click radius
  BOOST_TEST_REQUIRE(tb.world().components.size() == n + 1);
  const EntityId e = static_cast<EntityId>(n);
  BOOST_TEST(tb.world().components.position[e].x == 400.0 - Testbed::spawn_size / 2.0);
  BOOST_TEST(tb.world().components.position[e].y == 200.0 - Testbed::spawn_size / 2.0);
  BOOST_TEST((tb.world().components.velocity[e] == Vector::zero()));
  BOOST_TEST(tb.world().components.mass[e] == Testbed::spawn_mass);
  // It takes part in the physics: registered with every declared system.
  BOOST_TEST(tb.world().bodies(SystemId::collision).size() == n + 1);
  BOOST_TEST(tb.world().bodies(SystemId::draw).size() == n + 1);
}

BOOST_AUTO_TEST_CASE(a_drag_flings_the_block_opposite_to_the_drag) {
  Testbed tb = on("bounce");
  const std::size_t n = tb.world().components.size();
  tb.handle(down(400, 200));
  tb.handle(move(350, 220));
  BOOST_TEST(tb.view(60, 0).sling.has_value());  // the slingshot is drawn while dragging
  tb.handle(up(300, 240));
  BOOST_TEST(!tb.view(60, 0).sling.has_value());
  const auto keys = Testbed::key_list(8);  // the H list says which way it flies
  BOOST_TEST(std::count(keys.begin(), keys.end(), "drag   slingshot: it flies opposite to the drag") == 1);
  const Vector v = tb.world().components.velocity[n];
  BOOST_TEST(v.x == 100 * Testbed::fling_scale);
  BOOST_TEST(v.y == -40 * Testbed::fling_scale);
  // A huge drag is capped so the block cannot tunnel through a wall.
  tb.handle(down(400, 300));
  tb.handle(up(-5000, 300));
  BOOST_TEST(Vector::norm(tb.world().components.velocity[n + 1]) <= Testbed::max_fling + 1e-12);
  BOOST_TEST(tb.world().components.velocity[n + 1].x > 0.0);
}

// Right drag: a ray from the press point to the mouse, with the first body
// it enters as ray_cast finds it; nothing is spawned.
BOOST_AUTO_TEST_CASE(a_right_drag_shows_a_ray_and_its_hit) {
  Testbed tb = on("bounce");
  const std::size_t n = tb.world().components.size();
  const InputEvent right_down{InputEvent::Kind::mouse_down, 0, 200, 100, 3};
  tb.handle(right_down);
  tb.handle(move(200, 590));
  const View v = tb.view(60, 0);
  BOOST_TEST(!v.sling.has_value());
  BOOST_TEST_REQUIRE(v.ray.has_value());
  BOOST_TEST((v.ray->from == Vector{200, 100}));
  BOOST_TEST((v.ray->to == Vector{200, 590}));
  BOOST_TEST_REQUIRE(v.ray->hit.has_value());
  const auto want = ray_cast(tb.world(), {200, 100}, {0, 490}, 490);
  BOOST_TEST_REQUIRE(want.has_value());
  BOOST_TEST(v.ray->hit->body == want->body);
  BOOST_TEST((v.ray->hit->point == want->point));
  BOOST_TEST(v.ray->hit->fraction == want->fraction);
  BOOST_TEST((v.ray->hit->point == Vector{200, 560}));  // the floor's top
  BOOST_TEST((v.ray->hit->normal == Vector{0, -1}));
  const auto ray_line = [](const std::string& l) { return l.starts_with("ray: body 1 at (200.0, 560.0)"); };
  BOOST_TEST(std::count_if(v.hud.begin(), v.hud.end(), ray_line) == 1);  // the HUD says what was hit
  // Short of the floor: the ray is drawn whole, with no hit.
  tb.handle(move(200, 300));
  BOOST_TEST_REQUIRE(tb.view(60, 0).ray.has_value());
  BOOST_TEST(!tb.view(60, 0).ray->hit.has_value());
  tb.handle(InputEvent{InputEvent::Kind::mouse_up, 0, 200, 300, 3});
  BOOST_TEST(!tb.view(60, 0).ray.has_value());
  BOOST_TEST(tb.world().components.size() == n);  // the right button spawns nothing
  const auto keys = Testbed::key_list(8);
  BOOST_TEST(std::count(keys.begin(), keys.end(), "right drag: ray, first body hit, normal") == 1);
}

BOOST_AUTO_TEST_CASE(no_block_is_spawned_in_a_wall) {
  Testbed tb = on("bounce");
  const std::size_t n = tb.world().components.size();
  tb.handle(down(20, 300));
  tb.handle(up(20, 300));
  BOOST_TEST(tb.world().components.size() == n);
  BOOST_TEST(!tb.message().empty());
  // Other buttons do nothing.
  tb.handle({InputEvent::Kind::mouse_down, 0, 400, 300, 3});
  tb.handle({InputEvent::Kind::mouse_up, 0, 400, 300, 3});
  BOOST_TEST(tb.world().components.size() == n);
}

// A click inside a body is refused like one on a wall; the message fades.
BOOST_AUTO_TEST_CASE(no_block_is_spawned_into_a_body_and_the_message_fades) {
  Testbed tb = on("stack");
  const Components& c = tb.world().components;
  const std::size_t n = c.size();
  EntityId inside = n;
  for (EntityId e = 0; e < n && inside == n; ++e)
    if (std::isfinite(c.mass[e])) inside = e;
  BOOST_REQUIRE(inside < n);
  const Vector at = c.position[inside] + Vector{c.box[inside].width / 2.0, c.box[inside].height / 2.0};
  const std::vector<Vector> before = c.position;
  BOOST_TEST(!tb.spawn(at, {}));
  BOOST_TEST(c.size() == n);
  BOOST_TEST((c.position == before));
  BOOST_TEST(tb.message() == "no room there: a block cannot overlap another body");
  BOOST_TEST(tb.view(60, 0).hud.back() == tb.message());
  tb.handle(press(key::space));  // fades in real time, paused or not
  tb.advance(Testbed::message_ms / 2);
  BOOST_TEST(!tb.message().empty());
  tb.advance(Testbed::message_ms / 2 + 1);
  BOOST_TEST(tb.message().empty());
  // Touching is no overlap: right on top of the first tower (its top at y = 360) is room.
  BOOST_TEST(tb.spawn({220, 360 - Testbed::spawn_size / 2.0}, {}));
}

BOOST_AUTO_TEST_CASE(overlay_keys_toggle_and_contacts_are_recorded) {
  Testbed tb = on("cradle");
  BOOST_TEST(!tb.overlays().aabb);
  tb.handle(press('a'));
  tb.handle(press('v'));
  tb.handle(press('c'));
  BOOST_TEST(tb.overlays().aabb);
  BOOST_TEST(tb.overlays().velocity);
  BOOST_TEST(tb.overlays().contacts);
  BOOST_TEST(tb.world().pass.record_contacts);
  // Run until the striker hits the row: the view carries those contacts.
  for (int i = 0; i < 60 && tb.view(60, 0).contacts.empty(); ++i) tb.step();
  const View v = tb.view(60, 0);
  BOOST_TEST_REQUIRE(!v.contacts.empty());
  BOOST_TEST(std::abs(v.contacts[0].normal.x) == 1.0);
  BOOST_TEST(v.contacts[0].normal.y == 0.0);
  // Each one drawn where its bodies meet now: on the edge they share.
  BOOST_TEST_REQUIRE(v.contact_regions.size() == v.contacts.size());
  const Components& c = tb.world().components;
  for (std::size_t i = 0; i < v.contacts.size(); ++i) {
    const ContactRegion r = v.contact_regions[i];
    for (const EntityId e : {v.contacts[i].c, v.contacts[i].b}) {
      BOOST_TEST(r.lo.x >= c.position[e].x);
      BOOST_TEST(r.hi.x <= c.position[e].x + c.box[e].width);
      BOOST_TEST(r.lo.y >= c.position[e].y);
      BOOST_TEST(r.hi.y <= c.position[e].y + c.box[e].height);
    }
    BOOST_TEST((r.lo.x == r.hi.x || r.lo.y == r.hi.y));  // touching: a segment
  }
  // A step without contacts shows none: nothing is left behind.
  for (int i = 0; i < 200 && !tb.view(60, 0).contacts.empty(); ++i) tb.step();
  BOOST_TEST(tb.view(60, 0).contacts.empty());
  BOOST_TEST(tb.view(60, 0).contact_regions.empty());
  tb.handle(press('C'));  // upper case works too
  BOOST_TEST(!tb.overlays().contacts);
  BOOST_TEST(tb.view(60, 0).contacts.empty());
}

BOOST_AUTO_TEST_CASE(a_non_finite_body_pauses_the_window_with_a_banner) {
  Testbed tb = on("many");
  tb.advance(3 * course_dt, 1000);
  tb.world().components.velocity[5] = {std::nan(""), 0.0};
  tb.advance(10 * course_dt, 1000);
  BOOST_TEST(tb.paused());
  const std::int64_t frame = tb.world().frame;
  const auto hud = tb.view(60, 0).hud;
  BOOST_TEST(hud.back().find("stopped: body 5 has a non-finite position") == 0u, hud.back());
  tb.handle(press(' '));  // resume: still stopped
  tb.advance(10 * course_dt, 1000);
  BOOST_TEST(tb.world().frame == frame);
  tb.handle(press('r'));  // a reset starts again
  BOOST_TEST(!tb.world().health.non_finite.has_value());
}

BOOST_AUTO_TEST_CASE(hud_help_and_slow_motion) {
  Testbed tb = on("many");
  BOOST_TEST(tb.view(60, 0).hud.size() == 3u);  // compact: no stage times before T
  tb.handle(press('t'));
  BOOST_TEST(tb.view(60, 0).hud.size() == 4u);
  const std::string times = tb.view(60, 0).hud[3];
  BOOST_TEST(times.find("collision") != std::string::npos);
  tb.handle(press('i'));
  BOOST_TEST(tb.view(60, 0).hud.empty());
  BOOST_TEST(tb.view(60, 0).help.empty());
  tb.handle(press('h'));
  const auto help = tb.view(60, 0).help;
  BOOST_TEST(help.size() == Testbed::key_list(8).size());
  tb.handle(press('s'));
  BOOST_TEST(tb.slow());
  BOOST_TEST(tb.advance(course_dt * 3) == 0);  // a quarter of the time passes
  BOOST_TEST(tb.advance(course_dt * 1.1) == 1);
}

// The HUD says how the world is solved and which overlays are on.
BOOST_AUTO_TEST_CASE(the_hud_shows_the_solver_substeps_ccd_and_overlays) {
  Testbed tb = on("many");
  BOOST_TEST(tb.view(60, 0).hud[2] == "solver course  substeps 1  CCD off  overlays: none (A, V, C)");
  tb.handle(press('a'));
  tb.handle(press('c'));
  BOOST_TEST(tb.view(60, 0).hud[2] == "solver course  substeps 1  CCD off  overlays: aabb (A), contacts (C)");
  Overrides o;
  o.world = {{"solver", "stable"}, {"iterations", "12"}, {"substeps", "4"}, {"ccd", "on"}};
  Testbed st(all_scenes(), 0, o, Overlays{.velocity = true, .times = true});
  BOOST_TEST(st.view(60, 0).hud[2] == "solver stable (12 it.)  substeps 4  CCD on  overlays: velocity (V)");
  // Every stage's time (the drawing wraps them to the window: hud_and_keys_stay_inside_the_window).
  std::string all;
  for (const std::string& line : st.view(60, 0).hud) all += line;
  for (const char* stage : {"relax", "positions", "ccd", "store", "draw"}) BOOST_TEST(all.find(stage) != std::string::npos);
}

BOOST_AUTO_TEST_CASE(the_hud_shows_no_time_for_a_left_out_system) {
  Testbed tb = on("drift");
  tb.step();
  tb.handle(press('t'));
  const std::string times = tb.view(60, 0).hud[3];
  BOOST_TEST(times.find("forces off") != std::string::npos, times);
  BOOST_TEST(times.find("collision off") != std::string::npos);
  BOOST_TEST(times.find("move off") == std::string::npos);
}

BOOST_AUTO_TEST_CASE(escape_q_and_closing_quit) {
  Testbed tb = on("many");
  BOOST_TEST((tb.handle(press(key::escape)) == Testbed::Action::quit));
  BOOST_TEST((tb.handle(press('q')) == Testbed::Action::quit));
  BOOST_TEST((tb.handle({InputEvent::Kind::quit}) == Testbed::Action::quit));
  BOOST_TEST((tb.handle(press('x')) == Testbed::Action::none));
}

BOOST_AUTO_TEST_CASE(steps_and_resets_reach_the_trace) {
  Testbed tb = on("bounce");
  std::vector<std::int64_t> frames;
  tb.on_step = [&](const World& w) { frames.push_back(w.frame); };
  tb.on_reset = [&](const World& w) { frames.push_back(-1 - w.frame); };
  tb.advance(course_dt * 2);
  tb.handle(press('r'));
  tb.handle(press('n'));
  const std::vector<std::int64_t> expected{1, 2, -1, 1};
  BOOST_TEST(frames == expected, boost::test_tools::per_element());
}

// The health check's note (a sinking tower in the course mode) is on the HUD,
// as in the headless summary; a world without one shows none.
BOOST_AUTO_TEST_CASE(the_hud_shows_the_health_note) {
  SceneSpec tower;
  tower.name = "tower";
  tower.params.gravity = {0, 0.001};
  tower.restitution = 0.0;
  GridSpec g;
  g.first.pos = {380, 160};
  g.first.width = g.first.height = 40;
  g.first.mass = 1.0;
  g.rows = 10;
  g.step = {0, 40};
  tower.blocks.push_back(g);
  Testbed tb({tower}, 0);
  const auto has_note = [&] {
    for (const std::string& line : tb.view(60, 0).hud)
      if (line.rfind("note: ", 0) == 0) return true;
    return false;
  };
  BOOST_TEST(!has_note());
  for (int i = 0; i < 600; ++i) tb.step();
  BOOST_TEST(has_note());
  std::string all;
  for (const std::string& line : tb.view(60, 0).hud) all += line + " ";
  BOOST_TEST(all.find("--solver stable") != std::string::npos, all);
}

BOOST_AUTO_TEST_SUITE_END()

namespace {

// What the overlay draws, without a window: every text (a 9 px monospace
// font, 17 px lines) and every filled or stroked box.
struct Recorder final : Painter {
  struct Text {
    std::string s;
    int x, y;
  };
  std::vector<Text> texts;
  std::vector<std::array<double, 4>> boxes;
  void fill_box(double x, double y, double w, double h, Color) override { boxes.push_back({x, y, w, h}); }
  void stroke_box(double x, double y, double w, double h, Color) override { boxes.push_back({x, y, w, h}); }
  void line(Vector, Vector, Color) override {}
  int text(const std::string& s, int x, int y, Color) override {
    texts.push_back({s, x, y});
    return line_height();
  }
  int line_height() const override { return 17; }
  double char_width() const override { return 9.0; }
};

SceneSpec big_world(int w, int h) {
  SceneSpec s;
  s.name = "big";
  s.width = w, s.height = h;
  return s;
}

bool near(Vector a, Vector b) { return std::abs(a.x - b.x) < 1e-9 && std::abs(a.y - b.y) < 1e-9; }

}  // namespace

BOOST_AUTO_TEST_SUITE(testbed_camera)

// A world that fits is the window itself: scale 1, no offset (the input
// logs' coordinates are window coordinates there, as before the camera).
BOOST_AUTO_TEST_CASE(a_world_that_fits_is_shown_at_scale_1) {
  const Camera c = Camera::fit({800, 600}, {800, 600});
  BOOST_TEST(c.scale == 1.0);
  BOOST_TEST((c.eye == Vector{0, 0}));
  BOOST_TEST((c.to_world({123, 456}) == Vector{123, 456}));
  // Smaller than its window: centred on whole pixels, at scale 1.
  const Camera small = Camera::fit({81, 81}, min_window);
  BOOST_TEST(small.scale == 1.0);
  BOOST_TEST((small.to_screen({0, 0}) == Vector{280, 200}));
}

BOOST_AUTO_TEST_CASE(a_large_world_is_scaled_to_fit_and_the_window_fits_the_screen) {
  const Vector view = window_size({3000, 2000}, {1280, 992});
  BOOST_TEST((view == Vector{1280, 992}));
  BOOST_TEST((window_size({800, 600}, {1280, 992}) == Vector{800, 600}));
  BOOST_TEST((window_size({81, 81}, {1280, 992}) == min_window));
  const Camera c = Camera::fit({3000, 2000}, view);
  BOOST_TEST(c.scale == 1280.0 / 3000.0);
  // The whole world inside the window, from its left edge to its right, centred vertically.
  const Vector lo = c.to_screen({0, 0}), hi = c.to_screen({3000, 2000});
  BOOST_TEST(near({lo.x, hi.x}, {0, 1280}));
  BOOST_TEST(std::abs(lo.y - (992 - hi.y)) <= 1.0);
  BOOST_TEST(near(c.to_world(c.to_screen({1234.5, 987.25})), {1234.5, 987.25}));
}

BOOST_AUTO_TEST_CASE(the_wheel_zooms_about_the_cursor) {
  Camera c = Camera::fit({3000, 2000}, {1280, 992});
  const Vector at{300, 500};
  const Vector under = c.to_world(at);
  c.zoom_about(at, 2.0);
  BOOST_TEST(c.scale == 2 * 1280.0 / 3000.0);
  BOOST_TEST(near(c.to_world(at), under));
  c.zoom_about(at, 1e6);  // clamped
  BOOST_TEST(c.scale == Camera::max_scale);
  c.zoom_about(at, 1e-6);
  BOOST_TEST(c.scale == c.min_scale());
  // A pan moves the world with the drag, and never past its edges.
  Camera p = Camera::on({1500, 1000}, {3000, 2000}, {1280, 992});
  const Vector e = p.eye;
  p.pan({-100, 40});
  BOOST_TEST(near(p.eye, e + Vector{100, -40}));
  p.pan({1e6, 1e6});
  BOOST_TEST((p.eye == Vector{0, 0}));
}

// Inside the dead zone the camera stays; beyond, it moves just enough; at
// the world's edges it stops.
BOOST_AUTO_TEST_CASE(the_camera_follows_with_a_dead_zone_clamped_to_the_world) {
  Camera c = Camera::on({1500, 1000}, {3000, 2000}, {1000, 800});
  BOOST_TEST((c.to_screen({1500, 1000}) == Vector{500, 400}));
  const Vector e = c.eye;
  c.follow({1500 + 0.1 * 1000, 1000});  // within 15 % of the centre
  BOOST_TEST((c.eye == e));
  c.follow({1500 + 400, 1000});
  BOOST_TEST(c.to_screen({1900, 1000}).x == 500 + Camera::dead_zone * 1000);
  c.follow({2990, 1990});
  BOOST_TEST((c.eye == Vector{2000, 1200}));  // the world's corner in the window's
}

// The mouse goes through the camera: a click spawns at the world point under
// it, and the log keeps that point, so a replay without the camera (headless)
// lands on it too.
BOOST_AUTO_TEST_CASE(a_click_lands_on_the_world_point_under_the_cursor_and_replays_there) {
  const SceneSpec s = big_world(3000, 2000);
  Testbed tb({s}, 0);
  tb.set_viewport({1000, 800});
  BOOST_TEST(tb.camera().scale == 1000.0 / 3000.0);
  InputLog log{"big", {}, 0};
  tb.record(&log);
  tb.live(down(500, 400));
  tb.live(up(500, 400));
  const EntityId spawned = static_cast<EntityId>(tb.world().components.size() - 1);
  const Vector centre = tb.world().components.position[spawned] + Vector{15, 15};
  const Vector w = tb.camera().to_world({500, 400});
  BOOST_TEST((centre == Vector{std::round(w.x), std::round(w.y)}));
  BOOST_TEST(log.events.front().event.x == static_cast<int>(std::round(w.x)));
  // The wheel and a middle drag change the picture only: nothing logged.
  tb.live({InputEvent::Kind::wheel, 2, 100, 100});
  tb.live({InputEvent::Kind::mouse_down, 0, 10, 10, 2});
  tb.live(move(60, 10));
  tb.live({InputEvent::Kind::mouse_up, 0, 60, 10, 2});
  BOOST_TEST(log.events.size() == 2u);
  BOOST_TEST(tb.camera().scale == 1000.0 / 3000.0 * 1.25 * 1.25);
  for (int i = 0; i < 5; ++i) tb.step();
  log.end = tb.ticks();
  Testbed again({s}, 0);
  again.replay(log);
  again.play();
  BOOST_TEST((again.world().components.position[spawned] == tb.world().components.position[spawned]));
}

BOOST_AUTO_TEST_CASE(shift_and_a_left_drag_pan_instead_of_spawning) {
  Testbed tb({big_world(3000, 2000)}, 0);
  tb.set_viewport({1000, 800});
  tb.live({InputEvent::Kind::wheel, 3, 500, 400});
  const Vector eye = tb.camera().eye;
  const std::size_t n = tb.world().components.size();
  tb.live(press(key::lshift));
  tb.live(down(500, 400));
  tb.live(move(400, 400));
  tb.live(up(400, 400));
  BOOST_TEST(tb.world().components.size() == n);
  BOOST_TEST(tb.camera().eye.x > eye.x);
  tb.live(press('f'));  // back to the whole world
  BOOST_TEST(tb.camera().scale == 1000.0 / 3000.0);
}

// The platformer's camera keeps its player in the dead zone as it runs.
BOOST_AUTO_TEST_CASE(the_platformer_follows_its_player) {
  Testbed tb({load_scene_file(test::scene_path("platformer"))}, 0);
  tb.set_viewport({400, 300});
  BOOST_TEST(tb.camera().scale == 1.0);
  tb.handle(press(key::right));
  const auto player_on_screen = [&] {
    const Vec2 f = *tb.level()->focus();
    return tb.camera().to_screen({f.x, f.y});
  };
  const double eye0 = tb.camera().eye.x;
  for (int i = 0; i < 90; ++i) tb.step();
  BOOST_TEST(tb.camera().eye.x > eye0);
  BOOST_TEST(std::abs(player_on_screen().x - 200) <= Camera::dead_zone * 400 + 1e-9);
}

// A plain click in the target game spends no shot; a drag does, and while
// it is held the view has the rubber band from the sling and the dots of
// the flight, falling under gravity.
BOOST_AUTO_TEST_CASE(a_click_spends_no_shot_and_a_drag_shows_its_flight) {
  Testbed tb({load_scene_file(test::scene_path("targets-1"))}, 0);
  const auto& game = dynamic_cast<const Targets&>(*tb.level());
  const int shots = game.shots_left();
  const std::size_t bodies = tb.world().components.size();
  tb.handle(down(300, 300));
  tb.handle(up(302, 301));
  BOOST_TEST(game.shots_left() == shots);
  BOOST_TEST(tb.world().components.size() == bodies);
  tb.handle(down(300, 300));
  BOOST_TEST(tb.view(60, 0).preview.empty());  // no pull yet
  tb.handle(move(100, 330));
  const View v = tb.view(60, 0);
  const Vec2 sling = *tb.level()->launch_point();
  BOOST_TEST((v.sling->first == Vector{sling.x, sling.y}));
  BOOST_TEST((v.sling->second == Vector{sling.x - 200, sling.y + 30}));
  BOOST_TEST(v.preview.size() >= 5u);
  BOOST_TEST(v.preview[0].x > sling.x);  // flung right, opposite to the pull
  // Under gravity the vertical speed grows: each gap's drop exceeds the last.
  for (std::size_t i = 2; i < v.preview.size(); ++i)
    BOOST_TEST(v.preview[i].y - v.preview[i - 1].y > v.preview[i - 1].y - v.preview[i - 2].y);
  tb.handle(up(100, 330));
  BOOST_TEST(game.shots_left() == shots - 1);
}

// The HUD and the key list stay inside the window, wrapped to its width,
// at 800 px with every stage time and in an 81 x 81 world's window.
BOOST_AUTO_TEST_CASE(hud_and_keys_stay_inside_the_window) {
  Overrides o;
  o.world = {{"solver", "stable"}};
  for (const Vector view : {Vector{800, 600}, min_window}) {
    const bool small = view == min_window;
    Testbed tb(small ? std::vector<SceneSpec>{big_world(81, 81)} : all_scenes(), 0, o,
               Overlays{.help = true, .times = true});
    tb.set_viewport(view);
    Recorder r;
    Overlay::over(tb.world(), tb.view(60, 0), r);
    BOOST_TEST(r.texts.size() >= Testbed::key_list(9).size() + 3);
    for (const Recorder::Text& t : r.texts) {
      BOOST_TEST(t.x >= 0);
      BOOST_TEST(t.x + 9.0 * t.s.size() <= view.x, t.s);
      BOOST_TEST(t.y + 17 <= view.y, t.s);
    }
    for (const auto& b : r.boxes) BOOST_TEST((b[0] >= 0 && b[0] + b[2] <= view.x && b[1] + b[3] <= view.y));
  }
}

// A HUD too long for the room the key list leaves (a long note, stage times,
// in the smallest window) is cut, its last line saying so: the key list stays
// whole and inside the window, below the HUD, neither panel over the other.
BOOST_AUTO_TEST_CASE(a_long_hud_is_cut_to_keep_the_key_list_whole_inside_the_window) {
  Testbed tb({big_world(81, 81)}, 0, {}, Overlays{.help = true, .times = true});
  tb.set_viewport(min_window);
  View v = tb.view(60, 0);
  for (int i = 0; i < 12; ++i) v.hud.push_back("note " + std::to_string(i) + ": " + std::string(100, 'x'));
  Recorder r;
  Overlay::over(tb.world(), v, r);
  const std::vector<std::string> keys = Testbed::key_list(1);
  std::size_t drawn = 0, hud_end = 0;
  for (std::size_t i = 0; i < r.texts.size(); ++i) {
    const Recorder::Text& t = r.texts[i];
    BOOST_TEST((t.x >= 0 && t.x + 9.0 * t.s.size() <= min_window.x), t.s);
    BOOST_TEST(t.y + 17 <= min_window.y, t.s);
    drawn += std::find(keys.begin(), keys.end(), t.s) != keys.end();
    if (t.s.starts_with("... ")) hud_end = i;
  }
  BOOST_TEST(drawn == keys.size());  // every key, whole
  BOOST_TEST_REQUIRE(hud_end > 0u);
  BOOST_TEST(r.texts[hud_end].s.ends_with("more lines (H hides the key list)"), r.texts[hud_end].s);
  BOOST_TEST(r.texts[hud_end].y + 17 <= r.texts[hud_end + 1].y);  // the keys below the HUD's last line
  for (const auto& b : r.boxes) BOOST_TEST((b[0] >= 0 && b[0] + b[2] <= min_window.x && b[1] + b[3] <= min_window.y));
  // Without the key list the HUD has the window's height.
  View alone = v;
  alone.help.clear();
  Recorder q;
  Overlay::over(tb.world(), alone, q);
  BOOST_TEST(q.texts.size() > r.texts.size() - keys.size());
  for (const Recorder::Text& t : q.texts) BOOST_TEST(t.y + 17 <= min_window.y, t.s);
}

BOOST_AUTO_TEST_CASE(wrap_breaks_at_spaces_and_indents) {
  const auto lines = Overlay::wrap("alpha beta gamma delta epsilon zeta eta theta", 20);
  BOOST_TEST(lines.size() == 3u);
  BOOST_TEST(lines[0] == "alpha beta gamma");
  BOOST_TEST(lines[1] == "  delta epsilon zeta");
  for (const std::string& l : lines) BOOST_TEST(l.size() <= 20u);
  BOOST_TEST(Overlay::wrap(std::string(50, 'x'), 20).size() == 3u);  // no space: cut
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace test_testbed
