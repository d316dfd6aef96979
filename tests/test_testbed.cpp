// The testbed's input handling without a window: events in, world changes out.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "scene/builtin_scenes.hpp"
#include "helpers.hpp"
#include "app/testbed.hpp"

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
  BOOST_TEST(tb.view(60, 0).hud.size() >= 4u);
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
  Testbed st(all_scenes(), 0, o, Overlays{.velocity = true});
  BOOST_TEST(st.view(60, 0).hud[2] == "solver stable (12 it.)  substeps 4  CCD on  overlays: velocity (V)");
  // Every stage's time, on lines that fit the 800 px window.
  std::string all;
  for (const std::string& line : st.view(60, 0).hud) {
    BOOST_TEST(line.size() <= 100u, line);
    all += line;
  }
  for (const char* stage : {"relax", "positions", "ccd", "store", "draw"}) BOOST_TEST(all.find(stage) != std::string::npos);
}

BOOST_AUTO_TEST_CASE(the_hud_shows_no_time_for_a_left_out_system) {
  Testbed tb = on("drift");
  tb.step();
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
  for (const std::string& line : tb.view(60, 0).hud) {
    all += line + " ";
    if (line.rfind("note: ", 0) == 0 || line.rfind("  ", 0) == 0) BOOST_TEST(line.size() <= 90u, line);  // fits 800 px
  }
  BOOST_TEST(all.find("--solver stable") != std::string::npos, all);
}

BOOST_AUTO_TEST_SUITE_END()
