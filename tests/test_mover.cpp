// The box mover (include/physics/mover.hpp; docs/api.md, "Movers"): it never
// tunnels (a thin wall, a tile floor, at any speed), never jitters in a
// corner (of blocks, of tiles), slides over seams between blocks, rides
// moving platforms, lands on one-way bodies and tiles from above and passes
// them from below and sideways (and drops through them when told), pushes
// crates that the solver then rests against a wall, and refuses bad input.
#include <cmath>
#include <string>

#include "helpers.hpp"
#include "physics/mover.hpp"
#include "physics/physics.hpp"

// The file's own names, apart from the other test files' with which it is
// compiled (Makefile, TEST_UNITY).
namespace test_mover {

using namespace physics;

namespace {

constexpr double dt = 1000.0 / 60.0;
constexpr double g = 0.001;

// A world with gravity (the stable solver, for the crates) and helpers to add fixed blocks and tiles.
struct Scene {
  WorldId world;
  explicit Scene(Vec2 gravity = {0.0, g}) {
    WorldDef def = default_world_def();
    def.gravity = gravity;
    def.solver = SolverKind::stable;
    world = create_world(def);
  }
  ~Scene() { destroy_world(world); }
  BodyId block(Vec2 p, Vec2 s, double mass = fixed_mass, OneWay face = OneWay::none) const {
    BodyDef d = default_body_def();
    d.position = p, d.size = s, d.mass = mass, d.restitution = 0.0, d.one_way = face;
    return create_body(world, d);
  }
  // Rows like "..#=": '#' solid, '=' one-way up, '.' empty; cells of 16 px from p.
  BodyId tiles(Vec2 p, std::initializer_list<std::string> rows) const {
    TileLayerDef t;
    t.position = p, t.cell_size = 16, t.restitution = 0.0;
    t.columns = static_cast<int>(rows.begin()->size()), t.rows = static_cast<int>(rows.size());
    for (const std::string& r : rows)
      for (const char c : r) t.cells.push_back(c == '#' ? TileKind::solid : c == '=' ? TileKind::one_way_up : TileKind::empty);
    return create_tile_layer(world, t);
  }
};

// A 20 x 30 mover driven as a game drives it: gravity into its velocity,
// then move_and_slide, then the world's step.
struct Player {
  BodyId body;
  MoverDef def = default_mover_def();
  MoverResult last;
  Vec2 v;
  Player(const Scene& s, Vec2 p) : body(s.block(p, {20, 30})) {}
  // One frame with the run speed `run` along x (nullopt: keep v.x).
  void frame(WorldId w, std::optional<double> run = std::nullopt, bool gravity = true) {
    if (run) v.x = *run;
    if (gravity) v.y += g * dt;
    last = move_and_slide(body, v, def, last);
    v = last.velocity;
    step(w);
  }
  Vec2 at() const { return position(body); }
};

// A player at (80, 0) pressing at 0.2 px/ms against a wall whose left face
// is at x = 100 falls as in free flight for `frames` frames, x unchanged
// (and reported on the wall if `on_wall`).
void falls_freely_against_the_wall(const Scene& s, int frames, bool on_wall) {
  Player q(s, {80, 0});
  double vy = 0.0, y = 0.0;
  for (int f = 0; f < frames; ++f) {
    q.frame(s.world, 0.2);
    vy += g * dt, y += vy * dt;
    BOOST_TEST_REQUIRE(std::abs(q.at().y - y) < 1e-9);
    BOOST_TEST_REQUIRE(q.at().x == 80.0);
    if (on_wall) BOOST_TEST_REQUIRE(q.last.on_wall);
  }
}

double overlap(BodyId a, BodyId b) {
  const Aabb x = bounds(a), y = bounds(b);
  const double ox = std::min(x.upper.x, y.upper.x) - std::max(x.lower.x, y.lower.x);
  const double oy = std::min(x.upper.y, y.upper.y) - std::max(x.lower.y, y.lower.y);
  return ox > 0.0 && oy > 0.0 ? std::min(ox, oy) : 0.0;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mover)

// 600 px a frame at a 1 px wall: it stops on the wall's face, on_wall, the wall named.
BOOST_AUTO_TEST_CASE(fast_motion_stops_at_a_thin_wall) {
  Scene s({0.0, 0.0});
  const BodyId wall = s.block({300, 0}, {1, 200});
  Player p(s, {0, 100});
  p.def.motion_mode = MotionMode::floating;
  const MoverResult r = move_and_slide(p.body, {36.0, 0.0}, p.def);  // 600 px in one step
  BOOST_TEST(p.at().x == 280.0);
  BOOST_TEST(p.at().y == 100.0);
  BOOST_TEST(r.on_wall);
  BOOST_TEST(!r.on_floor);
  BOOST_REQUIRE_EQUAL(r.hits.size(), 1u);
  BOOST_TEST((r.hits[0].body == wall));
  BOOST_TEST(r.hits[0].normal.x == -1.0);
  BOOST_TEST(r.velocity.x == 0.0);
  // And back the other way, from beyond it.
  set_position(p.body, {600, 100});
  move_and_slide(p.body, {-36.0, 0.0}, p.def);
  BOOST_TEST(p.at().x == 301.0);
}

// Falling at 1000 px a frame onto a floor one tile thick: it lands on the
// tiles' top and names the cell under its middle.
BOOST_AUTO_TEST_CASE(fast_fall_stops_on_a_tile_floor) {
  Scene s;
  const BodyId layer = s.tiles({0, 400}, {"################"});
  Player p(s, {37, -600});
  const MoverResult r = move_and_slide(p.body, {0.0, 60.0}, p.def);
  BOOST_TEST(p.at().y == 370.0);
  BOOST_TEST(p.at().x == 37.0);
  BOOST_TEST(r.on_floor);
  BOOST_TEST((r.floor == layer));
  BOOST_REQUIRE_EQUAL(r.hits.size(), 1u);
  BOOST_TEST(r.hits[0].column == 2);  // x 37 to 57: the middle, 47, in cell 2
  BOOST_TEST(r.hits[0].row == 0);
  BOOST_TEST(r.hits[0].normal.y == -1.0);
  BOOST_TEST(r.velocity.y == 0.0);
}

// Pushed right into the corner of a floor and a wall, with gravity, for 600
// frames: after landing, the position is the same to 1e-9 px every frame.
void corner_holds(const Scene& s, Player& p, Vec2 corner) {
  for (int f = 0; f < 30; ++f) p.frame(s.world, 0.3);
  const Vec2 rest = p.at();
  BOOST_TEST(rest.x == corner.x - 20.0);
  BOOST_TEST(rest.y == corner.y - 30.0);
  double worst = 0.0;
  for (int f = 0; f < 600; ++f) {
    p.frame(s.world, 0.3);
    worst = std::max({worst, std::abs(p.at().x - rest.x), std::abs(p.at().y - rest.y)});
    BOOST_TEST_REQUIRE(p.last.on_floor);
    BOOST_TEST_REQUIRE(p.last.on_wall);
  }
  BOOST_TEST(worst <= 1e-9);
}

BOOST_AUTO_TEST_CASE(no_jitter_in_a_corner_of_blocks) {
  Scene s;
  s.block({0, 400}, {400, 40});
  s.block({200, 300}, {40, 100});
  Player p(s, {150, 360});
  corner_holds(s, p, {200, 400});
}

BOOST_AUTO_TEST_CASE(no_jitter_in_a_corner_of_tiles) {
  Scene s;
  s.tiles({0, 320}, {"..........#", "..........#", "..........#", "..........#", "###########"});
  Player p(s, {100, 350});
  corner_holds(s, p, {160, 384});
}

// Running over a floor of 16 px blocks side by side and down a wall of
// stacked blocks: no seam stops it, x advances by v·dt every frame.
BOOST_AUTO_TEST_CASE(slides_over_seams_between_blocks) {
  Scene s;
  for (int i = 0; i < 60; ++i) s.block({16.0 * i, 400}, {16, 16});
  Player p(s, {3, 370});
  for (int f = 0; f < 5; ++f) p.frame(s.world, 0.0);
  for (int f = 0; f < 100; ++f) {
    const double x0 = p.at().x;
    p.frame(s.world, 0.5);
    BOOST_TEST_REQUIRE(!p.last.on_wall);
    BOOST_TEST_REQUIRE(p.last.on_floor);
    BOOST_TEST_REQUIRE(std::abs(p.at().x - x0 - 0.5 * dt) < 1e-9);
    BOOST_TEST_REQUIRE(p.at().y == 370.0);
  }
  // Falling while pressed against a wall of stacked 16 px blocks: it falls freely.
  Scene t;
  for (int i = 0; i < 40; ++i) t.block({100, 16.0 * i}, {16, 16});
  falls_freely_against_the_wall(t, 40, true);
}

// The same over a floor of 200 tiles at 0.05 to 5 px/ms (up to 5 cells a
// frame), and up a wall of tiles: no stop, no bump, x exact every frame.
BOOST_AUTO_TEST_CASE(slides_over_tile_seams_at_every_speed) {
  for (const double run : {0.05, 0.5, 5.0}) {
    Scene s;
    s.tiles({0, 400}, {std::string(200, '#'), std::string(200, '#')});
    Player p(s, {3, 370});
    p.frame(s.world, 0.0);
    double x = p.at().x;
    for (int f = 0; f < 30; ++f) {
      p.frame(s.world, run);
      x += run * dt;
      BOOST_TEST_REQUIRE(!p.last.on_wall);
      BOOST_TEST_REQUIRE(p.last.on_floor);
      BOOST_TEST_REQUIRE(std::abs(p.at().x - x) < 1e-9);
      BOOST_TEST_REQUIRE(p.at().y == 370.0);
    }
  }
  Scene t;
  t.tiles({100, 0}, std::initializer_list<std::string>{"#", "#", "#", "#", "#", "#", "#", "#", "#", "#", "#", "#"});
  falls_freely_against_the_wall(t, 25, false);
}

// Standing on a fixed platform moving right, then down, then up: carried by
// it, its bottom on the platform's top after every step.
BOOST_AUTO_TEST_CASE(rides_a_moving_platform) {
  for (const Vec2 pv : {Vec2{0.1, 0.0}, Vec2{0.0, 0.05}, Vec2{0.0, -0.05}, Vec2{-0.07, 0.03}}) {
    Scene s;
    const BodyId plat = s.block({100, 300}, {80, 10});
    set_velocity(plat, pv);
    Player p(s, {120, 270});
    // It lands within a few frames (the platform moves on under it meanwhile).
    for (int f = 0; f < 10 && !p.last.on_floor; ++f) p.frame(s.world, 0.0);
    BOOST_TEST_REQUIRE(p.last.on_floor);
    const double dx = p.at().x - position(plat).x;
    for (int f = 0; f < 120; ++f) {
      p.frame(s.world, 0.0);
      BOOST_TEST_REQUIRE(p.last.on_floor);
      BOOST_TEST_REQUIRE((p.last.floor == plat));
      BOOST_TEST_REQUIRE(std::abs(p.at().y + 30.0 - position(plat).y) < 1e-9);
      BOOST_TEST_REQUIRE(std::abs(p.at().x - position(plat).x - dx) < 1e-9);
    }
    BOOST_TEST(p.last.floor_velocity.x == pv.x);
    BOOST_TEST(p.last.floor_velocity.y == pv.y);
  }
}

// platform_on_leave: jumping off a platform moving right keeps its velocity
// (add_velocity), or not (do_nothing).
BOOST_AUTO_TEST_CASE(platform_on_leave_keeps_the_platforms_velocity_or_not) {
  for (const PlatformOnLeave mode : {PlatformOnLeave::add_velocity, PlatformOnLeave::do_nothing}) {
    Scene s;
    const BodyId plat = s.block({100, 300}, {80, 10});
    set_velocity(plat, {0.1, 0.0});
    Player p(s, {120, 270});
    p.def.platform_on_leave = mode;
    for (int f = 0; f < 10; ++f) p.frame(s.world, 0.0);
    p.v.y = -0.5;  // jump
    p.frame(s.world);
    BOOST_TEST(!p.last.on_floor);
    BOOST_TEST(p.v.x == (mode == PlatformOnLeave::add_velocity ? 0.1 : 0.0));
  }
}

// One-way: a block and a row of tiles. From below it jumps through, from the
// side it walks through, from above it lands; with pass_one_way it drops through.
void one_way_cases(const Scene& s, double top) {
  Player below(s, {60, top + 40});
  below.v.y = -0.6;
  double highest = 1e9;
  for (int f = 0; f < 80; ++f) below.frame(s.world), highest = std::min(highest, below.at().y);
  BOOST_TEST(highest + 30.0 < top);  // it went through, all of it above the top
  BOOST_TEST(below.last.on_floor);   // and came down on it
  BOOST_TEST(below.at().y + 30.0 == top);
  // Dropping through: pass_one_way for a few frames.
  below.def.pass_one_way = true;
  for (int f = 0; f < 5; ++f) below.frame(s.world, 0.0);
  below.def.pass_one_way = false;
  for (int f = 0; f < 20; ++f) below.frame(s.world, 0.0);
  BOOST_TEST(below.at().y > top + 40.0);
  BOOST_TEST(!below.last.on_floor);
  destroy_body(below.body);
  // Sideways, its feet below the top: it walks through.
  Player side(s, {0, top - 20});
  for (int f = 0; f < 10; ++f) side.frame(s.world, 0.6, false);
  BOOST_TEST(std::abs(side.at().x - 0.6 * dt * 10) < 1e-9);
  BOOST_TEST(!side.last.on_wall);
}

BOOST_AUTO_TEST_CASE(one_way_block_from_above_below_and_the_side) {
  Scene s;
  s.block({40, 200}, {96, 16}, fixed_mass, OneWay::up);
  one_way_cases(s, 200);
}

BOOST_AUTO_TEST_CASE(one_way_tiles_from_above_below_and_the_side) {
  Scene s;
  s.tiles({40, 200}, {"======"});
  one_way_cases(s, 200);
}

// Pushing crate A (mass 1) right into crate B, itself against a wall: the
// solver stacks them; they end at rest, each overlap under 1 px, and the mover stops behind A.
BOOST_AUTO_TEST_CASE(pushes_crates_that_the_solver_stacks_against_a_wall) {
  Scene s;
  s.block({0, 400}, {600, 40});
  const BodyId wall = s.block({400, 200}, {40, 200});
  const BodyId a = s.block({100, 380}, {20, 20}, 1.0);
  const BodyId b = s.block({200, 380}, {20, 20}, 1.0);
  Player p(s, {40, 370});
  bool pushed = false;
  for (int f = 0; f < 600; ++f) {
    p.frame(s.world, 0.2);
    for (const MoverHit& h : p.last.hits) pushed = pushed || (h.body == a && h.impulse > 0.0);
  }
  BOOST_TEST(pushed);
  BOOST_TEST(position(b).x > 370.0);  // pushed all the way
  BOOST_TEST(overlap(a, b) < 1.0);
  BOOST_TEST(overlap(b, wall) < 1.0);
  BOOST_TEST(overlap(p.body, a) < 1.0);
  BOOST_TEST(std::abs(velocity(a).x) < 1e-3);
  BOOST_TEST(std::abs(velocity(b).x) < 1e-3);
  BOOST_TEST(p.last.on_wall);
  BOOST_TEST(p.at().x + 20.0 <= position(a).x + 1.0);
}

// max_push_impulse bounds the push; push_layers 0 pushes nothing.
BOOST_AUTO_TEST_CASE(push_is_bounded_and_filtered) {
  Scene s({0.0, 0.0});
  const BodyId crate = s.block({100, 0}, {20, 20}, 2.0);
  Player p(s, {80, 0});
  p.def.motion_mode = MotionMode::floating;
  p.def.max_push_impulse = 0.1;
  const MoverResult r = move_and_slide(p.body, {0.5, 0.0}, p.def);
  BOOST_REQUIRE_EQUAL(r.hits.size(), 1u);
  BOOST_TEST(r.hits[0].impulse == 0.1);
  BOOST_TEST(velocity(crate).x == 0.05);
  set_velocity(crate, {});
  p.def.push_layers = 0;
  move_and_slide(p.body, {0.5, 0.0}, p.def);
  BOOST_TEST(velocity(crate).x == 0.0);
}

// Floor snap: walking off a 2 px step with a 4 px snap follows it down at
// once; with no snap, it falls; jumping never snaps.
BOOST_AUTO_TEST_CASE(floor_snap_follows_a_step_down_unless_moving_up) {
  for (const double snap_length : {4.0, 0.0}) {
    Scene s({0.0, 0.0});
    s.block({0, 400}, {100, 20});
    s.block({100, 402}, {100, 20});
    Player p(s, {70, 370});
    p.def.floor_snap_length = snap_length;
    p.last.on_floor = true;
    for (int f = 0; f < 10; ++f) p.frame(s.world, 0.3, false);
    BOOST_TEST(p.at().y == (snap_length > 0.0 ? 372.0 : 370.0));
    BOOST_TEST(p.last.on_floor == (snap_length > 0.0));
  }
}

BOOST_AUTO_TEST_CASE(bad_input_is_an_error) {
  Scene s;
  const BodyId crate = s.block({0, 0}, {10, 10}, 1.0);
  BOOST_CHECK_THROW(move_and_slide(crate, {1, 0}), Error);
  const BodyId fixed = s.block({50, 0}, {10, 10});
  MoverDef d = default_mover_def();
  d.up_direction = {0.6, -0.8};
  BOOST_CHECK_THROW(move_and_slide(fixed, {1, 0}, d), Error);
  d = default_mover_def();
  d.max_slides = 0;
  BOOST_CHECK_THROW(move_and_slide(fixed, {1, 0}, d), Error);
  BOOST_CHECK_THROW(move_and_slide(fixed, {NAN, 0}), Error);
  const BodyId layer = s.tiles({0, 100}, {"##"});
  BOOST_CHECK_THROW(move_and_slide(layer, {1, 0}), Error);
  try {
    move_and_slide(crate, {1, 0});
  } catch (const Error& e) {
    BOOST_TEST(std::string(e.what()).find("not fixed") != std::string::npos);
  }
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace test_mover
