// Scenes as data: the built-in scenes declare their systems, generators,
// command-line overrides, placement checks.
#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include "scene/builtin_scenes.hpp"
#include "app/dump.hpp"
#include "app/headless.hpp"
#include "helpers.hpp"
#include "app/offscreen.hpp"
#include "scene/scene.hpp"
#include "course/utils/random.hpp"

// The file's own names, apart from the other test files' with which it is
// compiled (Makefile, TEST_UNITY).
namespace test_scene {

using namespace physics;

namespace {

const SceneSpec& builtin(const char* name) {
  const SceneSpec* s = find_builtin(name);
  BOOST_TEST_REQUIRE(s != nullptr);
  return *s;
}

std::string state(const World& w) {
  std::ostringstream o;
  Dump::write_state(o, w);
  return o.str();
}

// Expects SceneError whose message contains every one of `parts`.
template <class F>
void expect_error(F&& f, std::initializer_list<std::string> parts) {
  try {
    f();
    BOOST_ERROR("no SceneError");
  } catch (const SceneError& e) {
    const std::string msg = e.what();
    for (const std::string& p : parts) BOOST_TEST(msg.find(p) != std::string::npos, "'" << p << "' in: " << msg);
    BOOST_TEST(msg.find('\n') == std::string::npos);
  }
}

// The question-9 scene as the foundation wrote it by hand (before scenes were
// data): the reference the `many` scene must reproduce bit for bit.
void reference_q9(World& w, std::uint64_t seed) {
  Game::init_walls(w, 800, 600);
  const auto red = Block::make(w, 100, 100, 40, 40, Color{255, 0, 0, 255}, 10.0);
  w.components.sum_forces[red.id] = {0.25, 0.25};
  Random rng(seed);
  for (int i = 0; i < 10; ++i) {
    const int side = rng.uniform_int(20, 40);
    const double mass = rng.uniform(1.0, 20.0);
    const Vector impulse{rng.uniform(0.0, 0.25), rng.uniform(0.0, 0.25)};
    const Color col{static_cast<std::uint8_t>(rng.uniform_int(40, 220)),
                    static_cast<std::uint8_t>(rng.uniform_int(40, 220)),
                    static_cast<std::uint8_t>(rng.uniform_int(40, 220)), 255};
    const double x = 180 + 110 * (i % 5) + rng.uniform(0, 50);
    const double y = 220 + 150 * (i / 5) + rng.uniform(0, 80);
    const auto b = Block::make(w, x, y, side, side, Game::away_from_walls(col), mass);
    w.components.sum_forces[b.id] = Vector::mult(1.0 / w.params.dt, impulse);
  }
}

}  // namespace

BOOST_AUTO_TEST_SUITE(scene_builtins)

BOOST_AUTO_TEST_CASE(the_issue_lists_these_scenes_in_this_order) {
  std::vector<std::string> names;
  for (const SceneSpec& s : builtin_scenes()) names.push_back(s.name);
  const std::vector<std::string> expected{"walls", "drift", "impulse", "bounce", "many", "cradle", "gas", "stack"};
  BOOST_TEST(names == expected, boost::test_tools::per_element());
  BOOST_TEST(find_builtin("nope") == nullptr);
  for (const SceneSpec& s : builtin_scenes()) {
    BOOST_TEST(!s.description.empty());
    BOOST_CHECK_NO_THROW(validate(s, s.name));
  }
}

BOOST_AUTO_TEST_CASE(each_step_of_the_sheet_declares_only_its_systems) {
  BOOST_TEST(builtin("walls").systems.to_string() == "draw");
  BOOST_TEST(builtin("drift").systems.to_string() == "draw,move");
  BOOST_TEST(builtin("impulse").systems.to_string() == "draw,forces,move");
  BOOST_TEST(builtin("bounce").systems.to_string() == "draw,forces,move,collision");
  // Only the declared systems exist in the world, and a headless world has no Draw.
  const World w = make_world(builtin("drift"), false);
  BOOST_TEST(!w.declares(SystemId::draw));
  BOOST_TEST(!w.declares(SystemId::forces));
  BOOST_TEST(w.declares(SystemId::move));
  BOOST_TEST(!w.declares(SystemId::collision));
  const World d = make_world(builtin("walls"), true);
  BOOST_TEST(d.declares(SystemId::draw));
  BOOST_TEST(d.bodies(SystemId::draw).size() == 4u);
  BOOST_TEST(!d.declares(SystemId::move));
}

BOOST_AUTO_TEST_CASE(a_left_out_system_has_no_time_in_the_summary) {
  World w = make_world(builtin("drift"), false);
  const auto s = Headless::run(w, 10);
  std::ostringstream out;
  Headless::print_summary(out, w, s, "test", "drift");
  const std::string text = out.str();
  BOOST_TEST(text.find("forces off") != std::string::npos);
  BOOST_TEST(text.find("collision off") != std::string::npos);
  BOOST_TEST(text.find("move off") == std::string::npos);
  BOOST_TEST(w.times.ns[static_cast<int>(Stage::forces)] == 0);
  BOOST_TEST(w.times.ns[static_cast<int>(Stage::collision)] == 0);
}

BOOST_AUTO_TEST_CASE(drift_passes_through_the_walls_and_bounce_does_not) {
  World drift = make_world(builtin("drift"), false);
  World bounce = make_world(builtin("bounce"), false);
  for (int i = 0; i < 600; ++i) Game::step(drift), Game::step(bounce);
  BOOST_TEST(drift.components.position[4].x > 800.0);  // 4 walls first, then the red block
  BOOST_TEST(bounce.components.position[4].x < 760.0);
  BOOST_TEST(bounce.components.position[4].x > 40.0);
}

BOOST_AUTO_TEST_CASE(impulse_starts_from_a_force_not_a_velocity) {
  World w = make_world(builtin("impulse"), false);
  BOOST_TEST((w.components.velocity[4] == Vector::zero()));
  BOOST_TEST((w.components.sum_forces[4] == Vector{0.25, 0.25}));
  Game::step(w);
  BOOST_TEST(w.components.velocity[4].x == course_dt * 0.025);
}

BOOST_AUTO_TEST_CASE(many_is_the_question_9_scene_bit_for_bit) {
  for (const std::uint64_t seed : {42ULL, 7ULL}) {
    World ref = test::physics_world(), scene = test::physics_world(), game = test::physics_world();
    reference_q9(ref, seed);
    Overrides o;
    o.seed = seed;
    SceneSpec s = builtin("many");
    apply(s, o);
    populate(scene, s);
    Game::init_scene(game, seed);
    BOOST_TEST(state(scene) == state(ref));
    BOOST_TEST(state(game) == state(ref));
    BOOST_TEST((scene.components.sum_forces == ref.components.sum_forces));
    BOOST_TEST((scene.components.color == ref.components.color));
    BOOST_TEST((game.components.sum_forces == ref.components.sum_forces));
    BOOST_TEST((game.components.color == ref.components.color));
    for (int i = 0; i < 200; ++i) Game::step(ref), Game::step(scene);
    BOOST_TEST(state(scene) == state(ref));
  }
}

BOOST_AUTO_TEST_CASE(drift_and_impulse_are_the_game_s_red_blocks_of_questions_4_and_5) {
  for (const char* name : {"drift", "impulse"}) {
    const SceneSpec s = builtin(name);
    World scene(s.systems, s.params);
    populate(scene, s);
    World game(s.systems, s.params);
    Game::init_walls(game);
    if (std::string(name) == "drift") Game::red_block_with_velocity(game);
    else Game::red_block_with_force(game);
    BOOST_TEST(state(game) == state(scene), name);
    BOOST_TEST((game.components.sum_forces == scene.components.sum_forces), name);
    BOOST_TEST((game.components.color == scene.components.color), name);
  }
}

BOOST_AUTO_TEST_CASE(cradle_hands_the_momentum_down_the_row) {
  World w = make_world(builtin("cradle"), false);
  BOOST_TEST(w.components.size() == 10u);
  const Vector p0 = w.momentum();
  // Before the striker arrives the row is still; once it has hit, the striker stops.
  for (int i = 0; i < 60; ++i) Game::step(w);
  BOOST_TEST(w.components.velocity[4].x == 0.0);
  BOOST_TEST(w.components.velocity[9].x == 0.3);  // the far end carries it all
  BOOST_TEST(w.momentum().x == p0.x);
}

BOOST_AUTO_TEST_CASE(gas_has_hundreds_of_small_blocks_and_keeps_its_energy) {
  const SceneSpec& s = builtin("gas");
  BOOST_TEST(s.params.gravity.x == 0.0);
  BOOST_TEST(s.params.gravity.y == 0.0);
  World w = make_world(s, false);
  BOOST_TEST(w.finite_bodies() >= 200u);
  for (std::size_t e = 4; e < w.components.size(); ++e) {
    BOOST_TEST(w.components.box[e].width <= 10);
    BOOST_TEST(w.components.restitution[e] == 1.0);
  }
  for (EntityId a = 4; a < w.components.size(); ++a)
    for (EntityId b = a + 1; b < w.components.size(); ++b) BOOST_TEST_REQUIRE(!test::overlaps(w.components, a, b));
  const double ke = w.kinetic_energy();
  BOOST_TEST(ke > 0.0);
  std::size_t contacts = 0;
  for (int i = 0; i < 300; ++i) {
    Game::step(w);
    contacts += w.pass.contact_count;
  }
  BOOST_TEST(contacts > 100u);
  BOOST_TEST(std::abs(w.kinetic_energy() - ke) <= 1e-9 * ke);
}

BOOST_AUTO_TEST_CASE(stack_stands_on_the_floor_under_gravity) {
  const SceneSpec& s = builtin("stack");
  BOOST_TEST(s.params.gravity.y > 0.0);
  World w = make_world(s, false);
  // At start every block rests on the floor or on the block below: touching, not overlapping.
  std::set<double> bottoms;
  for (std::size_t e = 4; e < w.components.size(); ++e)
    bottoms.insert(w.components.position[e].y + w.components.box[e].height);
  BOOST_TEST(*bottoms.rbegin() == 560.0);  // the floor's top
  for (EntityId a = 0; a < w.components.size(); ++a)
    for (EntityId b = a + 1; b < w.components.size(); ++b) BOOST_TEST(!test::overlaps(w.components, a, b));
  for (int i = 0; i < 600; ++i) Game::step(w);
  // The towers stand: no block fell through the floor or off its tower.
  for (std::size_t e = 4; e < w.components.size(); ++e) {
    BOOST_TEST(w.components.position[e].y + 40 <= 560.0 + 1e-9);
    BOOST_TEST(w.components.position[e].y > 300.0);
    BOOST_TEST(w.components.velocity[e].x == 0.0);
  }
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(scene_generators)

BOOST_AUTO_TEST_CASE(a_grid_places_columns_then_rows) {
  SceneSpec s;
  GridSpec g;
  g.first.pos = {100, 100};
  g.first.width = 10;
  g.first.height = 20;
  g.first.mass = 2.0;
  g.columns = 3;
  g.rows = 2;
  g.step = {15, 25};
  s.blocks.push_back(g);
  const auto bodies = expand(s, "t");
  BOOST_TEST_REQUIRE(bodies.size() == 6u);
  BOOST_TEST(bodies[1].pos.x == 115.0);
  BOOST_TEST(bodies[3].pos.x == 100.0);
  BOOST_TEST(bodies[3].pos.y == 125.0);
  BOOST_TEST(bodies[5].mass == 2.0);
  BOOST_TEST(bodies[5].index == 5);
}

BOOST_AUTO_TEST_CASE(ten_thousand_bodies_in_one_entry) {
  SceneSpec s;
  GridSpec g;
  g.first.pos = {50, 50};
  g.first.width = g.first.height = 4;
  g.first.mass = 1.0;
  g.columns = 100;
  g.rows = 100;
  g.step = {5, 5};
  s.blocks.push_back(g);
  const World w = make_world(s, false);
  BOOST_TEST(w.components.size() == 10'004u);
}

BOOST_AUTO_TEST_CASE(random_draws_only_what_is_a_range_and_depends_on_the_seed) {
  RandomSpec r;
  r.count = 50;
  r.width = r.height = IntSpec::fixed(10);
  r.mass = RealSpec::uniform(1, 2);
  r.use_cells = false;
  r.origin = {40, 40};
  r.extent = {720, 520};
  SceneSpec s;
  s.blocks.push_back(r);
  const auto a = expand(s, "t");
  std::get<RandomSpec>(s.blocks[0]).seed = 43;
  const auto b = expand(s, "t");
  BOOST_TEST(a[0].mass != b[0].mass);
  for (const Body& x : a) {
    BOOST_TEST(x.width == 10);
    BOOST_TEST(x.mass >= 1.0);
    BOOST_TEST(x.mass < 2.0);
    BOOST_TEST(x.pos.x >= 40.0);
    BOOST_TEST(x.pos.x + 10 <= 760.0);
    BOOST_TEST(x.pos.y + 10 <= 560.0);
    BOOST_TEST((x.velocity == Vector::zero()));
  }
  // The first draws: mass, colour (r, g, b), then the position.
  Random rng(42);
  BOOST_TEST(a[0].mass == rng.uniform(1, 2));
  Color col{};
  for (std::uint8_t* ch : {&col.r, &col.g, &col.b}) *ch = static_cast<std::uint8_t>(rng.uniform_int(40, 220));
  col.a = a[0].color.a;
  BOOST_TEST((a[0].color == Game::away_from_walls(col)));
}

BOOST_AUTO_TEST_CASE(overrides_replace_the_scenes_values) {
  SceneSpec s = builtin("bounce");
  Overrides o;
  o.world = {{"dt", "5"},     {"substeps", "4"},      {"gravity", "0,0.002"}, {"restitution", "0.5"},
             {"ccd", "on"},   {"solver", "stable"},   {"iterations", "3"}};
  apply(s, o);
  BOOST_TEST(s.params.dt == 5.0);
  BOOST_TEST(s.params.substeps == 4);
  BOOST_TEST(s.params.gravity.y == 0.002);
  BOOST_TEST(s.params.ccd);
  BOOST_TEST((s.params.solver == Solver::stable));
  BOOST_TEST(s.params.iterations == 3);
  const World w = make_world(s, false);
  // --restitution is every body's, walls included, even one that gave its own.
  for (std::size_t e = 0; e < w.components.size(); ++e) BOOST_TEST(w.components.restitution[e] == 0.5);
  BOOST_TEST(w.params.dt == 5.0);
  BOOST_TEST(w.params.ccd);
}

BOOST_AUTO_TEST_CASE(seed_override_gives_each_generator_its_own_seed) {
  SceneSpec s;
  RandomSpec r;
  r.count = 1;
  r.side = IntSpec::fixed(10);
  r.mass = RealSpec::uniform(1, 2);
  s.blocks = {r, r};
  Overrides o;
  o.seed = 9;
  apply(s, o);
  BOOST_TEST(std::get<RandomSpec>(s.blocks[0]).seed == 9u);
  BOOST_TEST(std::get<RandomSpec>(s.blocks[1]).seed == 10u);
}

BOOST_AUTO_TEST_CASE(an_impulse_becomes_the_velocity_change_impulse_over_mass) {
  SceneSpec s;
  s.systems = {false, true, true, false};
  BlockSpec b;
  b.pos = {100, 100};
  b.width = b.height = 10;
  b.mass = 4.0;
  b.impulse = {1.0, -2.0};
  s.blocks.push_back(b);
  World w = make_world(s, false);
  Game::step(w);
  BOOST_TEST(w.components.velocity[4].x == 0.25, boost::test_tools::tolerance(1e-15));
  BOOST_TEST(w.components.velocity[4].y == -0.5, boost::test_tools::tolerance(1e-15));
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(scene_placement)

BOOST_AUTO_TEST_CASE(a_block_overlapping_a_wall_is_an_error_naming_it) {
  SceneSpec s;
  BlockSpec b;
  b.pos = {20, 100};
  b.width = b.height = 40;
  b.mass = 1;
  s.blocks.push_back(b);
  expect_error([&] { validate(s, "x"), expand(s, "x"); }, {"x: blocks[0]", "left wall"});
  std::get<BlockSpec>(s.blocks[0]).pos = {100, 540};
  expect_error([&] { expand(s, "x"); }, {"blocks[0]", "bottom wall"});
  // Touching a wall is fine: touching boxes do not collide.
  std::get<BlockSpec>(s.blocks[0]).pos = {40, 520};
  BOOST_CHECK_NO_THROW(expand(s, "x"));
}

BOOST_AUTO_TEST_CASE(a_block_outside_the_world_is_an_error) {
  SceneSpec s;
  s.walls = false;
  BlockSpec b;
  b.pos = {790, 100};
  b.width = b.height = 40;
  b.mass = 1;
  s.blocks.push_back(b);
  expect_error([&] { expand(s, "x"); }, {"blocks[0]", "outside the 800x600 world"});
  std::get<BlockSpec>(s.blocks[0]).pos = {0, 0};  // no walls: the corner is free
  BOOST_CHECK_NO_THROW(expand(s, "x"));
}

BOOST_AUTO_TEST_CASE(a_generated_body_in_a_wall_names_its_entry_and_index) {
  SceneSpec s = builtin("cradle");
  std::get<GridSpec>(s.blocks[1]).columns = 20;  // runs into the right wall
  expect_error([&] { expand(s, "x"); }, {"blocks[1] (grid body 9)", "right wall"});
}

BOOST_AUTO_TEST_CASE(invalid_values_are_errors_with_their_key_path) {
  const auto bad = [](auto change, std::initializer_list<std::string> parts) {
    SceneSpec s = builtin("bounce");
    change(s);
    expect_error([&] { validate(s, "f"); }, parts);
  };
  bad([](SceneSpec& s) { s.params.dt = 0; }, {"f: world.dt", "> 0"});
  bad([](SceneSpec& s) { s.params.dt = std::nan(""); }, {"world.dt"});
  bad([](SceneSpec& s) { s.params.substeps = 0; }, {"world.substeps"});
  bad([](SceneSpec& s) { s.params.iterations = 0; }, {"world.iterations"});
  bad([](SceneSpec& s) { s.params.gravity = {infinity, 0}; }, {"world.gravity", "finite"});
  bad([](SceneSpec& s) { s.restitution = 1.5; }, {"world.restitution", "[0, 1]"});
  bad([](SceneSpec& s) { s.width = 60; }, {"world.walls"});
  bad([](SceneSpec& s) { std::get<BlockSpec>(s.blocks[0]).mass = 0; }, {"blocks[0].mass", "\"inf\""});
  bad([](SceneSpec& s) { std::get<BlockSpec>(s.blocks[0]).mass = -infinity; }, {"blocks[0].mass"});
  bad([](SceneSpec& s) { std::get<BlockSpec>(s.blocks[1]).width = 0; }, {"blocks[1].size", "> 0"});
  bad([](SceneSpec& s) { std::get<BlockSpec>(s.blocks[0]).restitution = -0.1; }, {"blocks[0].restitution"});
  bad([](SceneSpec& s) { std::get<BlockSpec>(s.blocks[0]).velocity = {std::nan(""), 0}; }, {"blocks[0].velocity"});
}

BOOST_AUTO_TEST_CASE(too_many_bodies_is_an_error_before_anything_is_allocated) {
  SceneSpec s;
  GridSpec g;
  g.first.pos = {50, 50};
  g.first.width = g.first.height = 1;
  g.first.mass = 1;
  g.columns = 1'000'000;
  g.rows = 1'000'000;
  s.blocks.push_back(g);
  expect_error([&] { expand(s, "x"); }, {"x: blocks", "too many bodies"});
}

BOOST_AUTO_TEST_SUITE_END()

// What Block::make used to throw on is the validator's now: each bad block
// is a SceneError naming the key, before any body is made.
BOOST_AUTO_TEST_SUITE(scene_validation)

BOOST_AUTO_TEST_CASE(bad_blocks_are_rejected_by_the_validator) {
  const auto with = [](auto change) {
    SceneSpec s;
    BlockSpec b;
    b.pos = {100, 100};
    b.width = b.height = 10;
    b.mass = 1.0;
    change(b);
    s.blocks.push_back(b);
    return s;
  };
  const auto rejects = [](const SceneSpec& s, std::initializer_list<std::string> parts) {
    expect_error([&] { make_world(s, false, "v"); }, parts);
    expect_error([&] { expand(s, "v"); }, parts);
  };
  rejects(with([](BlockSpec& b) { b.width = 0; }), {"v: blocks[0].size: must be > 0 (got 0)"});
  rejects(with([](BlockSpec& b) { b.height = -1; }), {"v: blocks[0].size: must be > 0 (got -1)"});
  rejects(with([](BlockSpec& b) { b.width = max_block_size + 1; }), {"blocks[0].size: must be <= 1048576"});
  rejects(with([](BlockSpec& b) { b.mass = 0.0; }), {"v: blocks[0].mass: must be > 0 or \"inf\" (got 0)"});
  rejects(with([](BlockSpec& b) { b.mass = -2.0; }), {"blocks[0].mass: must be > 0 or \"inf\" (got -2)"});
  rejects(with([](BlockSpec& b) { b.mass = std::nan(""); }), {"blocks[0].mass: must be > 0"});
  rejects(with([](BlockSpec& b) { b.pos.x = std::nan(""); }), {"blocks[0].pos: must be finite"});
  rejects(with([](BlockSpec& b) { b.restitution = 1.5; }), {"blocks[0].restitution: must be in [0, 1] (got 1.5)"});
  const World w = make_world(with([](BlockSpec& b) { b.mass = infinity; }), false);
  BOOST_TEST(w.components.mass.back() == infinity);
}

// A load validates once: make_world expands (validates) the scene once, and
// building from the bodies of an expand does not validate again.
BOOST_AUTO_TEST_CASE(a_scene_is_validated_once_per_build) {
  const SceneSpec s = builtin("many");
  std::int64_t before = validation_count();
  const World a = make_world(s, false);
  BOOST_TEST(validation_count() - before == 1);
  before = validation_count();
  const std::vector<Body> bodies = expand(s, "many");
  const World b = make_world(s, bodies, false);
  BOOST_TEST(validation_count() - before == 1);
  BOOST_TEST(a.components.position == b.components.position);
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(scene_offscreen)

BOOST_AUTO_TEST_CASE(the_offscreen_picture_paints_the_drawn_blocks) {
  const World w = make_world(builtin("bounce"), true);
  const auto rgb = Offscreen::render(w, 800, 600);
  const auto px = [&](int x, int y) {
    const std::size_t i = (static_cast<std::size_t>(y) * 800 + x) * 3;
    return Color{rgb[i], rgb[i + 1], rgb[i + 2], 255};
  };
  BOOST_TEST((px(400, 10) == Game::wall_blue));
  BOOST_TEST((px(10, 300) == Game::wall_black));
  BOOST_TEST((px(120, 120) == Color{255, 0, 0, 255}));       // the red block
  BOOST_TEST((px(340, 310) == default_block_color));         // the platform
  BOOST_TEST((px(400, 200) == Color{255, 255, 255, 255}));   // background
  // Each block has a darker 1 px outline inside its box: touching blocks of
  // one colour read as separate blocks.
  const Components& c = w.components;
  for (EntityId e = 4; e < c.size(); ++e) {
    const int x = static_cast<int>(std::lround(c.position[e].x)), y = static_cast<int>(std::lround(c.position[e].y));
    BOOST_TEST((px(x, y) == outline_color(c.color[e])));
    BOOST_TEST((px(x + c.box[e].width - 1, y + c.box[e].height / 2) == outline_color(c.color[e])));
    BOOST_TEST((px(x + 1, y + 1) == c.color[e]));
  }
  BOOST_TEST((outline_color(Color{255, 0, 0, 255}) == Color{140, 0, 0, 255}));
  // Without Draw (a headless world) nothing is drawn.
  const World h = make_world(builtin("bounce"), false);
  const auto blank = Offscreen::render(h, 800, 600);
  BOOST_TEST(std::all_of(blank.begin(), blank.end(), [](std::uint8_t b) { return b == 255; }));
}

BOOST_AUTO_TEST_SUITE_END()

// Overlapping starts are warned about, not refused: the first pair found
// equals the all-pairs answer (whether any pair overlaps), in O(n log n).
BOOST_AUTO_TEST_SUITE(scene_overlaps)

namespace {
Body box(double x, double y, int w, int h) {
  Body b;
  b.pos = {x, y};
  b.width = w;
  b.height = h;
  return b;
}
bool overlap(const Body& a, const Body& b) {
  return a.pos.x < b.pos.x + b.width && b.pos.x < a.pos.x + a.width && a.pos.y < b.pos.y + b.height &&
         b.pos.y < a.pos.y + a.height;
}
}  // namespace

BOOST_AUTO_TEST_CASE(touching_is_no_overlap) {
  BOOST_TEST(!first_overlap({box(0, 0, 10, 10), box(10, 0, 10, 10), box(0, 10, 10, 10), box(10, 10, 5, 5)}));
  const auto o = first_overlap({box(0, 0, 10, 10), box(50, 0, 10, 10), box(9, 9, 2, 2)});
  BOOST_REQUIRE(o.has_value());
  BOOST_TEST(o->first == 0u);
  BOOST_TEST(o->second == 2u);
  BOOST_TEST(first_overlap({box(0, 0, 10, 10), box(0, 0, 10, 10)}).has_value());  // the same box twice
}

BOOST_AUTO_TEST_CASE(the_broad_phase_agrees_with_all_pairs) {
  Random rng(7);
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<Body> bodies;
    const int n = rng.uniform_int(0, 12);
    for (int i = 0; i < n; ++i)
      bodies.push_back(box(rng.uniform_int(0, 60), rng.uniform_int(0, 60), rng.uniform_int(1, 12), rng.uniform_int(1, 12)));
    bool any = false;
    for (std::size_t i = 0; i < bodies.size(); ++i)
      for (std::size_t j = i + 1; j < bodies.size(); ++j) any = any || overlap(bodies[i], bodies[j]);
    const auto o = first_overlap(bodies);
    BOOST_TEST(o.has_value() == any, "trial " << trial);
    if (o) BOOST_TEST((o->first < o->second && overlap(bodies[o->first], bodies[o->second])));
  }
}

BOOST_AUTO_TEST_CASE(a_100000_body_grid_is_checked_quickly) {
  std::vector<Body> bodies;
  for (int i = 0; i < 100000; ++i) bodies.push_back(box(i % 316 * 4.0, i / 316 * 4.0, 4, 4));  // touching
  BOOST_TEST(!first_overlap(bodies));  // quadratic would be 5e9 checks
  bodies.push_back(box(2, 2, 4, 4));
  BOOST_TEST(first_overlap(bodies).has_value());
}

BOOST_AUTO_TEST_CASE(the_warning_names_the_two_blocks) {
  SceneSpec s;
  BlockSpec a;
  a.pos = {100, 100};
  a.width = a.height = 20;
  a.mass = 1;
  BlockSpec b = a;
  b.pos = {300, 300};
  BlockSpec c = a;
  c.pos = {110, 110};
  s.blocks = {a, b, c};
  BOOST_TEST(overlap_warning(s, expand(s, "x.json"), "x.json") ==
             "warning: x.json: blocks[0] and blocks[2] overlap at the start");
  s.blocks.pop_back();
  BOOST_TEST(overlap_warning(s, expand(s, "x.json"), "x.json").empty());
}

BOOST_AUTO_TEST_SUITE_END()

// Random colours keep away from the walls' blue and black (a square of
// `many` used to come out wall-blue, another near-black).
BOOST_AUTO_TEST_CASE(random_colours_keep_away_from_the_walls) {
  const auto dist2 = [](Color a, Color b) {
    const auto d = [](int x, int y) { return (x - y) * (x - y); };
    return d(a.r, b.r) + d(a.g, b.g) + d(a.b, b.b);
  };
  std::size_t checked = 0;
  for (const char* name : {"many", "gas"})
    for (std::uint64_t seed = 0; seed < 40; ++seed) {
      SceneSpec s = builtin(name);
      Overrides o;
      o.seed = seed;
      apply(s, o);
      for (const Body& b : expand(s, name)) {
        BOOST_TEST(dist2(b.color, Game::wall_blue) >= Game::min_wall_color_distance * Game::min_wall_color_distance);
        BOOST_TEST(dist2(b.color, Game::wall_black) >= Game::min_wall_color_distance * Game::min_wall_color_distance);
        ++checked;
      }
    }
  BOOST_TEST(checked > 10000u);
}

}  // namespace test_scene
