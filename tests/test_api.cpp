// The public API (include/physics/physics.hpp): ids with generations, checked
// values, the step the scenes run (bit for bit), save and restore, queries,
// events, contact rules and health.
#include <cstring>
#include <string>

#include "helpers.hpp"
#include "api/view.hpp"
#include "physics/physics.hpp"
#include "scene/builtin_scenes.hpp"
#include "scene/scene.hpp"

// For Boost.Test's messages.
namespace physics {
std::ostream& operator<<(std::ostream& o, WorldId w) { return o << "world(" << w.index1 << ", " << w.generation << ")"; }
std::ostream& operator<<(std::ostream& o, BodyId b) {
  return o << "body(" << b.index1 << ", " << b.generation << ", " << b.world << ")";
}
std::ostream& operator<<(std::ostream& o, Filter f) { return o << "filter(" << f.category << ", " << f.mask << ")"; }
}  // namespace physics

// The file's own names, apart from the other test files' with which it is
// compiled (Makefile, TEST_UNITY).
namespace test_api {

namespace {

using namespace physics;

// A stable-solver world with an 800 px floor at y = 560 and a 40 px box above it.
struct Falling {
  WorldId world;
  BodyId floor, box;
  explicit Falling(SolverKind solver = SolverKind::stable, bool events = false) {
    WorldDef def = default_world_def();
    def.gravity = {0.0, 0.001};
    def.solver = solver;
    def.contact_events = events;
    world = create_world(def);
    BodyDef f = default_body_def();
    f.position = {0, 560};
    f.size = {800, 40};
    f.mass = fixed_mass;
    floor = create_body(world, f);
    BodyDef b = default_body_def();
    b.position = {380, 100};
    b.size = {40, 40};
    b.restitution = 0.0;
    box = create_body(world, b);
  }
  ~Falling() {
    if (is_valid(world)) destroy_world(world);
  }
  void run(int frames) {
    for (int i = 0; i < frames; ++i) step(world);
  }
};

using physics::test::same_bits;

// The message of the Error that f throws, or "" if it throws none.
template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

using physics::test::has;

}  // namespace

BOOST_AUTO_TEST_SUITE(public_api)

BOOST_AUTO_TEST_CASE(a_box_falls_and_rests_on_the_floor) {
  Falling f;
  f.run(600);
  BOOST_TEST(std::abs(position(f.box).y - 520.0) < 0.5);  // on the floor's top, 560 - 40, within the slop
  BOOST_TEST(position(f.box).x == 380.0);
  BOOST_TEST(std::abs(velocity(f.box).y) < 1e-6);
  BOOST_TEST(frame(f.world) == 600);
}

BOOST_AUTO_TEST_CASE(a_destroyed_body_s_id_names_no_other_body) {
  Falling f;
  const BodyId old = f.box;
  destroy_body(old);
  BOOST_TEST(!is_valid(old));
  const BodyId next = create_body(f.world, default_body_def());
  BOOST_TEST(is_valid(next));
  BOOST_TEST(!(next == old));
  BOOST_TEST(has(error_of([&] { position(old); }), "stale"));
  BOOST_TEST(has(error_of([&] { destroy_body(old); }), "stale"));
  BOOST_TEST(body_count(f.world) == 2u);
  BOOST_TEST(has(error_of([&] { position(null_body); }), "null body id"));
}

BOOST_AUTO_TEST_CASE(a_destroyed_world_s_ids_name_nothing_even_when_its_slot_is_reused) {
  const WorldId first = create_world();
  const BodyId b = create_body(first);
  destroy_world(first);
  const WorldId second = create_world();  // the same slot, a new generation
  BOOST_TEST(second.index1 == first.index1);
  BOOST_TEST(second.generation != first.generation);
  BOOST_TEST(!is_valid(first));
  BOOST_TEST(!is_valid(b));
  BOOST_TEST(has(error_of([&] { step(first); }), "no such world"));
  BOOST_TEST(has(error_of([&] { position(b); }), "no such world"));
  BOOST_TEST(body_count(second) == 0u);
  destroy_world(second);
  BOOST_TEST(has(error_of([&] { destroy_world(second); }), "no such world"));
}

BOOST_AUTO_TEST_CASE(bad_values_throw_naming_the_value_and_change_nothing) {
  Falling f;
  BodyDef d = default_body_def();
  d.size = {0, 10};
  BOOST_TEST(has(error_of([&] { create_body(f.world, d); }), "size must be whole pixels"));
  d = default_body_def();
  d.size = {10.5, 10};
  BOOST_TEST(has(error_of([&] { create_body(f.world, d); }), "size"));
  d = default_body_def();
  d.mass = -1;
  BOOST_TEST(has(error_of([&] { create_body(f.world, d); }), "mass must be in [1e-300, 1e150] or fixed_mass"));
  // Beyond the scene files' bounds an energy or an impulse overflows: refused as there.
  for (const double m : {1e-320, 1e308}) {
    d.mass = m;
    BOOST_TEST(has(error_of([&] { create_body(f.world, d); }), "mass must be in [1e-300, 1e150]"), m);
  }
  d = default_body_def();
  d.position = {std::nan(""), 0};
  BOOST_TEST(has(error_of([&] { create_body(f.world, d); }), "position must be finite"));
  BOOST_TEST(body_count(f.world) == 2u);
  d = default_body_def();
  d.mass = 1e150;  // the bound itself is a mass
  BOOST_TEST(is_valid(create_body(f.world, d)));
  destroy_body(bodies(f.world).back());
  BOOST_TEST(has(error_of([&] { set_restitution(f.box, 2.0); }), "restitution must be in [0, 1]"));
  BOOST_TEST(restitution(f.box) == 0.0);
  BOOST_TEST(has(error_of([&] { set_velocity(f.box, {INFINITY, 0}); }), "velocity"));
  BOOST_TEST(has(error_of([&] { set_friction(f.box, -1); }), "friction"));
  WorldDef w = default_world_def();
  w.dt = 0;
  BOOST_TEST(has(error_of([&] { create_world(w); }), "bad WorldDef: dt must be"));
  w = default_world_def();
  w.substeps = 0;
  BOOST_TEST(has(error_of([&] { create_world(w); }), "substeps"));
  BOOST_TEST(has(error_of([&] { ray_cast(f.world, {NAN, 0}, {1, 0}, 10); }), "finite"));
}

// The API's world and a scene's world of the same bodies step the same bits:
// physics::step(WorldId) runs the engine's stages, Game::step the course's
// systems, in the one frame (engine/step.hpp, run_frame).
BOOST_AUTO_TEST_CASE(the_api_steps_the_built_in_scene_many_bit_for_bit_in_every_solver) {
  for (const SolverKind kind : {SolverKind::course, SolverKind::stable, SolverKind::automatic}) {
    SceneSpec spec = *find_builtin("many");
    spec.params.solver = kind == SolverKind::course ? Solver::course
                         : kind == SolverKind::stable ? Solver::stable : Solver::automatic;
    World scene = make_world(spec, false);
    WorldDef def = default_world_def();
    def.solver = kind;
    def.gravity = {scene.params.gravity.x, scene.params.gravity.y};
    const WorldId world = create_world(def);
    std::vector<BodyId> ids;
    const Components& c = scene.components;
    for (EntityId e = 0; e < c.size(); ++e) {
      BodyDef d = default_body_def();
      d.position = {c.position[e].x, c.position[e].y};
      d.size = {double(c.box[e].width), double(c.box[e].height)};
      d.mass = c.mass[e];
      d.velocity = {c.velocity[e].x, c.velocity[e].y};
      d.force = {c.sum_forces[e].x, c.sum_forces[e].y};
      d.restitution = c.restitution[e];
      d.friction = c.friction[e];
      ids.push_back(create_body(world, d));
    }
    for (int i = 0; i < 300; ++i) {
      Game::step(scene);
      step(world);
    }
    bool same = true;
    for (EntityId e = 0; e < c.size(); ++e)
      same = same && same_bits(position(ids[e]).x, c.position[e].x) && same_bits(position(ids[e]).y, c.position[e].y) &&
             same_bits(velocity(ids[e]).x, c.velocity[e].x) && same_bits(velocity(ids[e]).y, c.velocity[e].y);
    BOOST_TEST(same, "solver " << int(kind));
    destroy_world(world);
  }
}

BOOST_AUTO_TEST_CASE(a_restored_state_steps_on_bit_for_bit) {
  for (const SolverKind kind : {SolverKind::course, SolverKind::stable, SolverKind::automatic}) {
    Falling f(kind);
    f.run(20);  // in flight: the warm start and the auto mode's state matter below
    const WorldState saved = save_state(f.world);
    f.run(100);
    const Vec2 after = position(f.box), v = velocity(f.box);
    set_position(f.box, {0, 0});
    destroy_body(f.floor);
    restore_state(f.world, saved);
    BOOST_TEST(is_valid(f.floor));
    BOOST_TEST(frame(f.world) == 20);
    f.run(100);
    BOOST_TEST(same_bits(position(f.box).y, after.y));
    BOOST_TEST(same_bits(velocity(f.box).y, v.y));
  }
  const WorldId w = create_world();
  BOOST_TEST(has(error_of([&] { restore_state(w, WorldState{}); }), "empty"));
  destroy_world(w);
}

// After a restore, a body made since the save is gone: its id must not name
// the next body made in its slot, nor may a state go into another world.
BOOST_AUTO_TEST_CASE(ids_made_after_a_save_stay_stale_after_the_restore) {
  Falling f;
  const WorldState saved = save_state(f.world);
  BodyDef d = default_body_def();
  d.user_data = 7;
  const BodyId made_since = create_body(f.world, d);
  restore_state(f.world, saved);
  BOOST_TEST(!is_valid(made_since));
  d.user_data = 9;
  const BodyId next = create_body(f.world, d);  // the same slot
  BOOST_TEST(!(next == made_since));
  BOOST_TEST(!is_valid(made_since));
  BOOST_TEST(has(error_of([&] { user_data(made_since); }), "stale"));
  BOOST_TEST(user_data(next) == 9u);
  Falling other;
  BOOST_TEST(has(error_of([&] { restore_state(other.world, saved); }), "goes back into its own world"));
  BOOST_TEST(position(other.box).y == 100.0);
}

BOOST_AUTO_TEST_CASE(out_of_range_enums_and_runaway_impulses_are_refused) {
  WorldDef w = default_world_def();
  w.solver = static_cast<SolverKind>(7);
  BOOST_TEST(has(error_of([&] { create_world(w); }), "solver or integrator"));
  Falling f;
  BodyDef d = default_body_def();
  d.one_way = static_cast<OneWay>(9);
  BOOST_TEST(has(error_of([&] { create_body(f.world, d); }), "one_way"));
  BOOST_TEST(has(error_of([&] { set_one_way(f.box, static_cast<OneWay>(9)); }), "one_way"));
  set_mass(f.box, 1e-300);  // the smallest mass: an impulse of 1 would give 1e300 px/ms
  BOOST_TEST(has(error_of([&] { apply_impulse(f.box, {1.0, 0.0}); }), "the velocity an impulse gives"));
  BOOST_TEST(velocity(f.box).x == 0.0);
}

BOOST_AUTO_TEST_CASE(queries_name_the_bodies_they_hit) {
  Falling f;
  const auto hit = ray_cast(f.world, {10, 0}, {0, 1}, 1000);
  BOOST_TEST_REQUIRE(hit.has_value());
  BOOST_TEST(hit->body == f.floor);
  BOOST_TEST(hit->point.y == 560.0);
  BOOST_TEST(hit->normal.y == -1.0);
  BOOST_TEST(!ray_cast(f.world, {10, 0}, {0, -1}, 1000).has_value());
  const auto at = query_point(f.world, {400, 120});
  BOOST_TEST_REQUIRE(at.size() == 1u);
  BOOST_TEST(at[0] == f.box);
  BOOST_TEST(query_box(f.world, {{0, 0}, {800, 600}}).size() == 2u);
  BOOST_TEST(query_box(f.world, {{0, 0}, {800, 100}}).empty());  // touching the box's top is not overlapping
  destroy_body(f.box);
  BOOST_TEST(query_point(f.world, {400, 120}).empty());
}

BOOST_AUTO_TEST_CASE(contact_events_report_the_landing) {
  Falling f(SolverKind::stable, true);
  int begins = 0;
  for (int i = 0; i < 600; ++i) {
    step(f.world);
    for (const TouchEvent& e : contact_events(f.world)) {
      BOOST_TEST(e.a == f.floor);
      BOOST_TEST(e.b == f.box);
      begins += e.begin;
    }
  }
  BOOST_TEST(begins == 1);
}

BOOST_AUTO_TEST_CASE(sensors_filters_and_one_way_bodies_let_the_box_through) {
  for (int which = 0; which < 3; ++which) {
    Falling f;
    if (which == 0) set_sensor(f.floor, true);
    if (which == 1) set_filter(f.box, {1, 0});
    if (which == 2) set_one_way(f.floor, OneWay::down);  // stops only what comes from below
    f.run(300);
    BOOST_TEST(position(f.box).y > 600.0, "case " << which);
  }
  Falling f;
  set_one_way(f.floor, OneWay::up);
  f.run(300);
  BOOST_TEST(position(f.box).y < 521.0);
  BOOST_TEST(filter(f.box) == Filter{});
  BOOST_TEST(!is_sensor(f.floor));
}

BOOST_AUTO_TEST_CASE(forces_impulses_and_user_data) {
  WorldDef def = default_world_def();
  const WorldId w = create_world(def);
  BodyDef d = default_body_def();
  d.mass = 2.0;
  d.user_data = 42;
  const BodyId b = create_body(w, d);
  apply_impulse(b, {1.0, 0.0});
  BOOST_TEST(velocity(b).x == 0.5);
  apply_force(b, {0.0, 0.2});
  BOOST_TEST(force(b).y == 0.2);
  step(w);
  BOOST_TEST(force(b).y == 0.0);  // spent by the step
  BOOST_TEST(velocity(b).y == 0.2 / 2.0 * def.dt);
  BOOST_TEST(user_data(b) == 42u);
  set_mass(b, fixed_mass);
  apply_impulse(b, {1.0, 0.0});
  BOOST_TEST(velocity(b).x == 0.5);
  BOOST_TEST(world_of(b) == w);
  destroy_world(w);
}

BOOST_AUTO_TEST_CASE(health_counts_escapes_and_stops_a_non_finite_world) {
  WorldDef def = default_world_def();
  def.bounds = Aabb{{0, 0}, {100, 100}};
  const WorldId w = create_world(def);
  BodyDef d = default_body_def();
  d.velocity = {1.0, 0.0};
  const BodyId b = create_body(w, d);
  for (int i = 0; i < 20; ++i) step(w);
  const HealthReport h = health(w);
  BOOST_TEST(h.finite);
  BOOST_TEST(h.escaped == 1);
  BOOST_TEST_REQUIRE(h.first_escape.has_value());
  BOOST_TEST(*h.first_escape == b);
  bool named_stages = false;
  for (const StageTime& s : profile(w)) named_stages = named_stages || (s.stage == "move" && s.ms_per_step >= 0.0);
  BOOST_TEST(named_stages);
  destroy_world(w);
}

BOOST_AUTO_TEST_CASE(touching_lists_the_resting_pair_with_its_impulse) {
  Falling f(SolverKind::stable, true);
  f.run(300);
  const auto t = touching(f.world);
  BOOST_TEST_REQUIRE(t.size() == 1u);
  BOOST_TEST(t[0].a == f.floor);
  BOOST_TEST(t[0].b == f.box);
  BOOST_TEST(t[0].normal.y == 1.0);  // pushes the floor down, away from the box
  BOOST_TEST(t[0].normal_impulse > 0.0);  // holding the box up against gravity
}

// A View gives the public API a world its caller owns (the games on the testbed's).
BOOST_AUTO_TEST_CASE(a_view_names_a_world_made_elsewhere_and_goes_stale_with_its_view) {
  World scene = make_world(*find_builtin("bounce"), false);
  WorldId id;
  BodyId red;
  {
    const api::View view(scene);
    id = view.id();
    BOOST_TEST(body_count(id) == scene.components.size());
    red = api::body_id(id, Game::wall_count);  // the red block comes after the four walls
    BOOST_TEST(mass(red) == 10.0);
    set_velocity(red, {0.5, 0.0});
    BOOST_TEST(scene.components.velocity[Game::wall_count].x == 0.5);
    step(id);
    BOOST_TEST(scene.frame == 1);
    BOOST_TEST(world_def(id).dt == scene.params.dt);
    BOOST_TEST(has(error_of([&] { destroy_world(id); }), "does not own"));
    BOOST_TEST(&api::internal(id) == &scene);
  }
  BOOST_TEST(!is_valid(id));
  BOOST_TEST(!is_valid(red));
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace test_api
