// Game physics beyond the sheet (docs/game-physics.md): friction, contact
// events, filtering and sensors, one-way platforms, removing bodies, and
// saving a world to run it on. Closed forms where there are some; bit for
// bit comparisons where a feature must change nothing else.
#include <cmath>
#include <map>
#include <sstream>

#include "app/dump.hpp"
#include "scene/save.hpp"
#include "scene/scene_json.hpp"
#include "course/entities/block.hpp"
#include "helpers.hpp"
#include "numerics/friction.hpp"

// The file's own names, apart from the other test files' with which it is
// compiled (Makefile, TEST_UNITY).
namespace test_game_physics {

using namespace physics;

namespace {

constexpr double g = 0.001;  // px/ms²

// The floor scene of these tests: walls (the bottom one's top at y = 560),
// gravity g, e = 0, friction `mu` on the walls and every block.
SceneSpec floor_scene(Solver solver, double mu) {
  SceneSpec s;
  s.name = "floor";
  s.params.gravity = {0, g};
  s.params.solver = solver;
  s.restitution = 0.0;
  s.friction = mu;
  return s;
}

BlockSpec block(Vector pos, int w, int h, double mass, Vector v = {}) {
  BlockSpec b;
  b.pos = pos, b.width = w, b.height = h, b.mass = mass, b.velocity = v;
  return b;
}

void run(World& w, int frames) {
  for (int i = 0; i < frames; ++i) Game::step(w);
}

std::string dump(const World& w) {
  std::ostringstream o;
  Dump::write_state(o, w);
  return o.str();
}

// Two equal blocks meeting head on, far from everything else.
SceneSpec head_on(Solver solver = Solver::course, bool ccd = false) {
  SceneSpec s;
  s.name = "two";
  s.walls = false;
  s.params.solver = solver;
  s.params.ccd = ccd;
  s.blocks.push_back(block({100, 100}, 40, 40, 1.0, {0.3, 0}));
  s.blocks.push_back(block({300, 100}, 40, 40, 1.0, {-0.3, 0}));
  return s;
}

// Distance a block launched at v0 along the floor slides before it stops.
double stop_distance(Solver solver, bool ccd, double mu, double v0) {
  SceneSpec s = floor_scene(solver, mu);
  s.params.ccd = ccd;
  s.blocks.push_back(block({100, 520}, 40, 40, 1.0, {v0, 0}));
  World w = make_world(s, false);
  for (int i = 0; i < 2000 && w.components.velocity[4].x != 0.0; ++i) Game::step(w);
  BOOST_TEST(w.components.velocity[4].x == 0.0);  // it stopped (sticking friction stops it exactly)
  return w.components.position[4].x - 100.0;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(friction)

// v0²/(2 mu g): 250 px for v0 = 0.5 px/ms, mu = 0.5. The symplectic step
// stops about v0·dt/2 early (CCD, whose impacts apply friction before Move)
// or late (the course pass, which applies it after Move): 1.7 % either way
// at the sheet's dt. The stable solver moves a slider on the trapezoid of
// its velocity (engine/slide.hpp): exact but for rounding here.
BOOST_AUTO_TEST_CASE(a_block_launched_along_the_floor_stops_after_v0_squared_over_2_mu_g) {
  const double v0 = 0.5, mu = 0.5, exact = v0 * v0 / (2 * mu * g);
  for (const auto& [solver, ccd] : {std::pair{Solver::stable, false}, {Solver::course, false}, {Solver::course, true},
                                    {Solver::stable, true}}) {
    const double d = stop_distance(solver, ccd, mu, v0);
    BOOST_TEST_CONTEXT("solver " << (solver == Solver::stable ? "stable" : "course") << ", ccd " << ccd) {
      BOOST_TEST(std::abs(d - exact) / exact < 0.03, "stopped after " << d << " px, exact " << exact);
    }
  }
}

// The report's friction table (make report): the stop distance's error is
// first order in dt for the course pass, CCD and auto (which takes this
// slide with the course pass), so it shrinks as dt does; the stable solver's
// is within the last substep's mu·g·h²/2 at every dt (the trapezoid).
BOOST_AUTO_TEST_CASE(the_stop_distance_error_falls_with_dt_in_every_solver) {
  std::map<std::string, std::vector<double>> errors;
  std::map<std::string, std::vector<double>> last_step;  // mu g h² / 2 over the exact stop
  for (const auto& setting : numerics::friction_settings()) {
    const numerics::Slide slide;
    const auto r = numerics::run_slide(setting.mode, slide);
    BOOST_TEST(r.stopped);
    errors[setting.family].push_back(std::abs(r.error));
    const double h = setting.mode.dt;
    last_step[setting.family].push_back(slide.mu * slide.g * h * h / 2 / slide.exact());
  }
  for (const auto& [family, e] : errors) {
    BOOST_TEST_REQUIRE(e.size() == 4u);
    BOOST_TEST(e[0] < 0.03, family);  // the sheet's dt: within 3 %
    if (family == "stable") {
      for (std::size_t i = 0; i < e.size(); ++i) BOOST_TEST(e[i] <= last_step[family][i], family << " " << i);
      BOOST_TEST(e[0] < 1e-3, family);  // symplectic Euler's v0·h/2 was 1.7 %
    } else {
      BOOST_TEST(e[3] < e[0] / 4, family);  // 8 times smaller dt: at least 4 times smaller error
    }
  }
}

BOOST_AUTO_TEST_CASE(without_friction_it_slides_on) {
  SceneSpec s = floor_scene(Solver::stable, 0.0);
  s.blocks.push_back(block({100, 520}, 40, 40, 1.0, {0.05, 0}));
  World w = make_world(s, false);
  run(w, 600);
  BOOST_TEST(w.components.velocity[4].x == 0.05);
}

BOOST_AUTO_TEST_CASE(a_frictionless_body_slides_on_anything) {
  // sqrt(mu_a mu_b): one frictionless body makes the pair frictionless.
  BOOST_TEST(pair_friction(0.0, 1.0) == 0.0);
  BOOST_TEST(pair_friction(0.25, 1.0) == 0.5);
  SceneSpec s = floor_scene(Solver::stable, 0.8);
  BlockSpec b = block({100, 520}, 40, 40, 1.0, {0.05, 0});
  b.contact.friction = 0.0;
  s.blocks.push_back(b);
  World w = make_world(s, false);
  run(w, 300);
  BOOST_TEST(w.components.velocity[4].x == 0.05);
}

// A constant sideways force below mu·m·g: static friction holds the block
// (the stable solver; see below for the course's); above it, it slides with
// acceleration F/m - mu·g.
BOOST_AUTO_TEST_CASE(a_sideways_force_below_mu_m_g_does_not_move_a_resting_block) {
  for (const Solver solver : {Solver::stable, Solver::course}) {
    for (const double share : {0.5, 0.9, 1.5}) {
      SceneSpec s = floor_scene(solver, 0.5);
      s.blocks.push_back(block({100, 520}, 40, 40, 2.0));
      World w = make_world(s, false);
      const double f = share * 0.5 * 2.0 * g;
      const int frames = 60;
      for (int i = 0; i < frames; ++i) {
        w.components.sum_forces[4] = {f, 0};
        Game::step(w);
      }
      const double moved = w.components.position[4].x - 100.0;
      BOOST_TEST_CONTEXT("solver " << (solver == Solver::stable ? "stable" : "course") << ", F = " << share
                                   << " mu m g") {
        if (share < 1.0 && solver == Solver::stable) {
          BOOST_TEST(moved == 0.0);
        } else if (share < 1.0) {
          // The course's frame moves before it collides: each frame the block
          // creeps (F/m)·dt² before friction stops it (docs/game-physics.md).
          const double creep = frames * f / 2.0 * course_dt * course_dt;
          BOOST_TEST(std::abs(moved - creep) < 1e-9 * creep, "moved " << moved << ", creep " << creep);
        } else {
          // Sliding at (F/m - mu g): within 3 % (stable), within the creep
          // above plus 3 % (course).
          const double t = frames * course_dt, a = f / 2.0 - 0.5 * g, exact = a * t * t / 2;
          const double creep = solver == Solver::course ? frames * f / 2.0 * course_dt * course_dt : 0.0;
          BOOST_TEST(std::abs(moved - exact) < creep + 0.03 * exact, "moved " << moved << ", exact " << exact);
        }
      }
    }
  }
}

// A platform of infinite mass moving sideways carries a block resting on it:
// friction brings the block to the platform's speed v at mu·g, so it lags
// behind by v²/(2 mu g), then moves with it.
BOOST_AUTO_TEST_CASE(a_block_on_a_moving_platform_is_carried_along) {
  for (const Solver solver : {Solver::stable, Solver::course}) {
    SceneSpec s = floor_scene(solver, 0.6);
    s.walls = false;
    s.params.gravity = {0, g};
    s.blocks.push_back(block({100, 400}, 200, 20, infinity, {0.1, 0}));  // the platform
    s.blocks.push_back(block({180, 360}, 40, 40, 1.0));                 // resting on it
    World w = make_world(s, false);
    run(w, 120);
    const double carried = w.components.position[1].x - 180.0;
    const double platform = w.components.position[0].x - 100.0;
    const double lag = 0.1 * 0.1 / (2 * 0.6 * g);
    BOOST_TEST_CONTEXT("solver " << (solver == Solver::stable ? "stable" : "course")) {
      BOOST_TEST(std::abs(platform - carried - lag) < 1.5, "block " << carried << " px, platform " << platform << " px");
      BOOST_TEST(std::abs(w.components.velocity[1].x - 0.1) < 1e-9);
      BOOST_TEST(w.components.position[1].y + 40 <= 400.0 + 1.0);  // still on top
    }
  }
}

BOOST_AUTO_TEST_SUITE_END()

// The stable solver keeps the classification and the contact of a pair
// whose bodies kept their state (ContactSolver::classify): what it keeps
// must include every input of the contact, or an edit of a resting body
// would not reach its contacts.
BOOST_AUTO_TEST_SUITE(kept_contacts)

// The impulses a frame's contacts carry, summed (the events' touching list).
double carried(World& w) {
  Game::step(w);
  double jn = 0.0;
  for (const auto& t : w.events.touching()) jn += t.jn;
  return jn;
}

// A stack of two at rest; the lower block made four times heavier carries
// what a stack built that heavy carries (with the old inverse mass kept,
// its floor contact would go on carrying the old weight).
BOOST_AUTO_TEST_CASE(a_mass_changed_at_rest_reaches_the_contacts) {
  const auto stack = [](double lower) {
    SceneSpec s = floor_scene(Solver::stable, 0.0);
    s.blocks.push_back(block({100, 520}, 40, 40, lower));
    s.blocks.push_back(block({100, 480}, 40, 40, 1.0));
    World w = make_world(s, false);
    w.enable_events();
    return w;
  };
  World edited = stack(1.0), built = stack(4.0);
  run(edited, 120);
  run(built, 180);
  const double before = carried(edited);
  edited.components.mass[4] = 4.0;
  run(edited, 59);
  const double after = carried(edited), expected = carried(built);
  BOOST_TEST(after > 1.5 * before);
  BOOST_TEST(std::abs(after - expected) < 1e-9 * expected, "carried " << after << ", a stack built so " << expected);
}

// A resting pile keeps its contacts, their rows and its broad phase's pairs
// from substep to substep; a body changed at rest must reach all of them at
// once: the edited world runs on as a world loaded from a save made right
// after the edit, which starts with nothing kept (with or without friction:
// the rows by axis and the friction rows), to the bits of its impulses.
BOOST_AUTO_TEST_CASE(a_body_changed_at_rest_runs_on_as_a_fresh_world) {
  for (const double mu : {0.0, 0.6}) {
    SceneSpec s = floor_scene(Solver::stable, mu);
    for (int row = 0; row < 5; ++row)  // a pyramid: each block on two, masses 1 to 3
      for (int i = 0; i < 6 - row; ++i)
        s.blocks.push_back(block({100.0 + 40 * i + 20 * row, 520.0 - 40 * row}, 40, 40, 1.0 + (i + row) % 3));
    World edited = make_world(s, false);
    run(edited, 150);
    edited.components.mass[6] = 7.3;
    const SceneSpec saved = read_scene(to_json(Save::scene_of(edited, s)), "saved.json");
    World fresh = make_world(saved, false);
    run(edited, 2);
    run(fresh, 2);
    BOOST_TEST(dump(edited) == dump(fresh), "mu " << mu);
    // The impulses too (shock propagation leaves a pile's velocities the same for many of them).
    BOOST_TEST(to_json(Save::scene_of(edited, s)) == to_json(Save::scene_of(fresh, s)), "mu " << mu);
  }
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(contact_events)

BOOST_AUTO_TEST_CASE(two_blocks_that_collide_once_give_one_begin_and_one_end) {
  for (const auto& [solver, ccd] : {std::pair{Solver::course, false}, {Solver::stable, false}, {Solver::course, true},
                                    {Solver::stable, true}}) {
    World w = make_world(head_on(solver, ccd), false);
    w.enable_events();
    std::vector<ContactEvent> all;
    double jn = 0.0;
    for (int i = 0; i < 120; ++i) {
      Game::step(w);
      for (const ContactEvent& e : w.events.events()) all.push_back(e);
      for (const auto& t : w.events.touching()) jn += t.jn;
    }
    BOOST_TEST_CONTEXT("solver " << (solver == Solver::stable ? "stable" : "course") << ", ccd " << ccd) {
      BOOST_TEST_REQUIRE(all.size() == 2u);
      BOOST_TEST((all[0].kind == EventKind::begin && all[1].kind == EventKind::end));
      BOOST_TEST((all[0].a == 0u && all[0].b == 1u && all[1].a == 0u && all[1].b == 1u));
      BOOST_TEST(all[0].frame < all[1].frame);
      BOOST_TEST((all[0].normal == Vector{-1, 0}));  // pushes block 0 (on the left) away from 1
      // The impulse that swapped their velocities, m·2v = 0.6, reported once.
      BOOST_TEST(std::abs(jn - 0.6) < 1e-12);
    }
  }
}

BOOST_AUTO_TEST_CASE(events_change_nothing_and_cost_nothing_when_off) {
  World a = make_world(head_on(Solver::course, false), false);
  World b = make_world(head_on(Solver::course, false), false);
  b.enable_events();
  run(a, 120);
  run(b, 120);
  BOOST_TEST(dump(a) == dump(b));
  BOOST_TEST(a.events.events().empty());
  BOOST_TEST(a.events.touching().empty());
}

BOOST_AUTO_TEST_CASE(a_resting_stack_keeps_its_contacts_without_new_events) {
  SceneSpec s = floor_scene(Solver::stable, 0.0);
  for (int i = 0; i < 3; ++i) s.blocks.push_back(block({300, 520.0 - 40 * i}, 40, 40, 1.0));
  World w = make_world(s, false);
  w.enable_events();
  Game::step(w);
  BOOST_TEST(w.events.events().size() == 3u);  // floor-0, 0-1, 1-2
  for (int i = 0; i < 200; ++i) {
    Game::step(w);
    BOOST_TEST_REQUIRE(w.events.events().empty());
  }
  BOOST_TEST(w.events.touching().size() == 3u);
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(filters_and_sensors)

namespace {
// The head-on pair with contact rules.
SceneSpec crossing(ContactRules left, ContactRules right) {
  SceneSpec s = head_on();
  std::get<BlockSpec>(s.blocks[0]).contact.rules = left;
  std::get<BlockSpec>(s.blocks[1]).contact.rules = right;
  return s;
}
}  // namespace

BOOST_AUTO_TEST_CASE(a_pair_interacts_only_if_each_category_meets_the_others_mask) {
  const ContactRules plain;
  ContactRules cat2;
  cat2.category = 2;
  ContactRules not2;
  not2.mask = ~2u;
  // (category 2 vs default mask: meet; category 2 vs a mask without bit 2: filtered)
  for (const auto& [l, r, collide] : {std::tuple{plain, plain, true}, {cat2, plain, true}, {cat2, not2, false},
                                      {not2, cat2, false}, {plain, not2, true}}) {
    for (const Solver solver : {Solver::course, Solver::stable}) {
      SceneSpec s = crossing(l, r);
      s.params.solver = solver;
      World w = make_world(s, false);
      run(w, 60);
      // Colliding, they swap velocities; filtered, they pass through each other.
      BOOST_TEST((w.components.velocity[0].x < 0) == collide);
    }
  }
}

BOOST_AUTO_TEST_CASE(filtered_pairs_never_enter_a_pair_list) {
  ContactRules cat2;
  cat2.category = 2;
  ContactRules not2;
  not2.mask = ~2u;
  SceneSpec s = crossing(cat2, not2);
  s.blocks[1] = block({110, 100}, 40, 40, 1.0);  // overlapping block 0
  std::get<BlockSpec>(s.blocks[1]).contact.rules = not2;
  World w = make_world(s, false);
  BOOST_TEST(test::course_candidates(w, 1.0).empty());
  std::vector<Pair> pairs;
  w.broadphase.find(w.components, w.bodies(SystemId::collision), course_dt, 1.0, pairs);
  BOOST_TEST(pairs.empty());
  brute_force_pairs(w.components, w.bodies(SystemId::collision), course_dt, 1.0, pairs);
  BOOST_TEST(pairs.empty());
}

// A sensor changes nothing in how the others move, in every mode: the
// scene with it dumps exactly as the scene without it (its own row aside).
BOOST_AUTO_TEST_CASE(everything_moves_exactly_as_if_the_sensor_were_not_there) {
  for (const auto& [solver, ccd] : {std::pair{Solver::course, false}, {Solver::stable, false}, {Solver::course, true},
                                    {Solver::stable, true}}) {
    SceneSpec without = floor_scene(solver, 0.3);
    without.params.ccd = ccd;
    without.restitution = 0.5;
    for (int i = 0; i < 6; ++i) without.blocks.push_back(block({200.0 + 50 * i, 100.0 + 60 * i}, 30, 30, 1.0 + i));
    SceneSpec with = without;
    BlockSpec zone = block({150, 300}, 500, 100, infinity);  // a trigger zone every block falls through
    zone.contact.rules.sensor = true;
    BlockSpec falling = block({420, 60}, 200, 30, 3.0, {0.02, 0});  // a moving sensor
    falling.contact.rules.sensor = true;
    with.blocks.push_back(zone);  // last: the others keep their ids
    with.blocks.push_back(falling);
    World a = make_world(without, false), b = make_world(with, false);
    b.enable_events();
    int begins = 0;
    for (int i = 0; i < 400; ++i) {
      Game::step(a);
      Game::step(b);
      for (const ContactEvent& e : b.events.events()) begins += e.kind == EventKind::begin && e.b == 10u;
    }
    std::string da = dump(a), db = dump(b);
    db.erase(db.rfind("\n10,") + 1);  // the sensors' rows, the last two
    BOOST_TEST_CONTEXT("solver " << (solver == Solver::stable ? "stable" : "course") << ", ccd " << ccd) {
      BOOST_TEST(da == db);
      BOOST_TEST(begins >= 6);  // every falling block went through it
    }
  }
}

// A body inside a sensor, or two filtered bodies on top of each other, are
// meant to overlap: the health check's persistent-overlap note ignores them.
BOOST_AUTO_TEST_CASE(meant_overlaps_are_not_reported_as_persistent) {
  SceneSpec s = floor_scene(Solver::course, 0.0);
  BlockSpec zone = block({200, 400}, 200, 160, infinity);
  zone.contact.rules.sensor = true;
  s.blocks.push_back(zone);
  s.blocks.push_back(block({250, 500}, 40, 60, 1.0));  // resting on the floor, inside the zone
  BlockSpec ghost = block({255, 505}, 30, 30, 1.0);     // inside that block, filtered from it
  ghost.contact.rules.category = 2;
  ghost.contact.rules.mask = ~2u;
  s.blocks.push_back(ghost);
  std::get<BlockSpec>(s.blocks[1]).contact.rules.mask = ~2u;
  World w = make_world(s, false);
  run(w, 300);
  BOOST_TEST(!w.health.deep.has_value());
  BOOST_TEST(w.health.escaped == 0);
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(one_way_platforms)

namespace {
// An "up" platform of infinite mass at y = 300, and a block at `y`, moving at vy.
World platform_world(Solver solver, double y, double vy, Face face = Face::up) {
  SceneSpec s = floor_scene(solver, 0.0);
  BlockSpec p = block({200, 300}, 200, 20, infinity);
  p.contact.rules.one_way = face;
  s.blocks.push_back(p);
  s.blocks.push_back(block({280, y}, 40, 40, 1.0, {0, vy}));
  return make_world(s, false);
}
}  // namespace

BOOST_AUTO_TEST_CASE(a_block_falling_onto_an_up_platform_rests_on_it) {
  for (const Solver solver : {Solver::course, Solver::stable}) {
    World w = platform_world(solver, 150, 0.0);
    run(w, 300);
    BOOST_TEST(std::abs(w.components.position[5].y - 260.0) < 0.5, "y = " << w.components.position[5].y);
  }
}

BOOST_AUTO_TEST_CASE(a_block_thrown_up_from_below_passes_through_then_lands_on_it) {
  for (const Solver solver : {Solver::course, Solver::stable}) {
    World w = platform_world(solver, 400, -0.8);  // rises about 320 px: well above the platform
    double highest = 400;
    for (int i = 0; i < 400; ++i) {
      Game::step(w);
      highest = std::min(highest, w.components.position[5].y);
    }
    BOOST_TEST(highest < 200.0);  // it went through
    BOOST_TEST(std::abs(w.components.position[5].y - 260.0) < 0.5, "y = " << w.components.position[5].y);
  }
}

BOOST_AUTO_TEST_CASE(a_down_platform_lets_a_falling_block_through) {
  World w = platform_world(Solver::course, 150, 0.0, Face::down);
  run(w, 300);
  BOOST_TEST(std::abs(w.components.position[5].y - 520.0) < 0.5);  // on the floor
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(removing_bodies)

BOOST_AUTO_TEST_CASE(a_destroyed_body_leaves_every_system_and_its_id_is_not_reused) {
  SceneSpec s = floor_scene(Solver::course, 0.0);
  for (int i = 0; i < 3; ++i) s.blocks.push_back(block({100.0 + 100 * i, 100}, 40, 40, 1.0));
  World w = make_world(s, true);
  w.destroy(5);
  BOOST_TEST(!w.alive(5));
  BOOST_TEST(w.alive(4));
  for (const auto ids : {w.bodies(SystemId::draw), w.bodies(SystemId::move), w.bodies(SystemId::forces),
                         w.bodies(SystemId::collision)})
    BOOST_TEST((std::find(ids.begin(), ids.end(), 5u) == ids.end()));
  const Vector before = w.components.position[5];
  run(w, 60);
  BOOST_TEST((w.components.position[5] == before));  // nothing moves it
  const EntityId next = w.components.create();
  BOOST_TEST(next == 7u);  // a new id, not 5
  // The dump keeps the others' ids, in order, and leaves 5 out.
  const std::string d = dump(w);
  BOOST_TEST(d.find("\n5,") == std::string::npos);
  BOOST_TEST(d.find("\n4,") < d.find("\n6,"));
  BOOST_TEST(w.finite_bodies() == 3u);  // 4, 6 and the new 7 (mass 0, the course's default: finite)
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(save_and_restore)

namespace {
// 600 frames in one go against 300, save, load, 300: the same dump.
void check_continues(SceneSpec s) {
  World whole = make_world(s, false);
  run(whole, 600);
  World first = make_world(s, false);
  run(first, 300);
  const SceneSpec saved = read_scene(to_json(Save::scene_of(first, s)), "saved.json");
  World rest = make_world(saved, false);
  BOOST_TEST(rest.frame == 300);
  run(rest, 300);
  BOOST_TEST(dump(rest) == dump(whole));
}

SceneSpec pile(Solver solver, bool ccd, double mu) {
  SceneSpec s = floor_scene(solver, mu);
  s.params.ccd = ccd;
  s.restitution = 0.3;
  for (int i = 0; i < 12; ++i)
    s.blocks.push_back(block({150.0 + 37 * (i % 4), 200.0 + 45 * (i / 4) - 3 * i}, 30, 30, 1.0 + i % 3, {0.05 * (i % 3), 0}));
  return s;
}
}  // namespace

BOOST_AUTO_TEST_CASE(a_saved_world_runs_on_bit_for_bit) {
  check_continues(pile(Solver::course, false, 0.0));
  check_continues(pile(Solver::stable, false, 0.6));
  check_continues(pile(Solver::course, true, 0.0));
  check_continues(pile(Solver::stable, true, 0.4));
  check_continues(pile(Solver::automatic, false, 0.4));  // its choices' state (hold, pressed pairs) too
  // The exact integrator keeps nothing from one step to the next: a save loses nothing.
  for (const bool ccd : {false, true}) {
    SceneSpec s = pile(Solver::stable, ccd, 0.4);
    s.params.integrator = Integrator::exact;
    check_continues(s);
  }
}

// The warm-start impulses are part of the state: without them the stable
// solver's run differs (so the test above does test them).
BOOST_AUTO_TEST_CASE(the_stable_solvers_warm_start_is_saved) {
  const SceneSpec s = pile(Solver::stable, false, 0.6);
  World whole = make_world(s, false);
  run(whole, 600);
  World first = make_world(s, false);
  run(first, 300);
  SceneSpec saved = Save::scene_of(first, s);
  BOOST_TEST(!saved.state->warm_start.empty());
  saved.state->warm_start.clear();
  World rest = make_world(saved, false);
  run(rest, 300);
  BOOST_TEST(dump(rest) != dump(whole));
}

// The auto mode's choice depends on the pairs pressed in the substeps before
// and on its hold: both go into the file and come back as they were.
BOOST_AUTO_TEST_CASE(the_auto_modes_state_is_saved) {
  const SceneSpec s = pile(Solver::automatic, false, 0.6);
  World first = make_world(s, false);
  run(first, 300);
  const AutoState before = first.automatic.state();
  BOOST_TEST(before.hold > 0);
  BOOST_TEST(!before.pressed.empty());
  const SceneSpec saved = read_scene(to_json(Save::scene_of(first, s)), "saved.json");
  BOOST_TEST_REQUIRE(saved.state->automatic.has_value());
  BOOST_TEST((*saved.state->automatic == before));  // no body destroyed: the same ids
  World rest = make_world(saved, false);
  BOOST_TEST((rest.automatic.state() == before));
}

BOOST_AUTO_TEST_CASE(destroyed_bodies_are_left_out_and_the_others_keep_their_order) {
  const SceneSpec s = pile(Solver::stable, false, 0.6);
  World w = make_world(s, false);
  run(w, 100);
  w.destroy(6);
  const SceneSpec saved = Save::scene_of(w, s);
  BOOST_TEST(saved.blocks.size() == 11u);
  BOOST_TEST((std::get<BlockSpec>(saved.blocks[2]).pos == w.components.position[7]));
  for (const WarmImpulse& imp : saved.state->warm_start) BOOST_TEST(imp.pair.b < 15u);
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(game_physics_keys)

namespace {
std::string error_of(const std::string& text) {
  try {
    expand(read_scene(text, "bad.json"), "bad.json");
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}
std::string with_block(const std::string& keys) {
  return R"({"blocks": [{"pos": [100, 100], "size": [20, 20], "mass": 1, )" + keys + "}]}";
}
}  // namespace

BOOST_AUTO_TEST_CASE(the_keys_are_read_written_and_read_again_unchanged) {
  const std::string text = R"({"world": {"friction": 0.25}, "blocks": [
    {"pos": [100, 100], "size": [20, 20], "mass": 1, "friction": 0.5, "category": 6, "mask": 3, "sensor": true},
    {"pos": [200, 100], "size": [60, 10], "mass": "inf", "one_way": "up"},
    {"grid": {"pos": [100, 300], "size": [10, 10], "mass": 1, "count": [3, 2], "friction": 0.1, "one_way": "left"}},
    {"random": {"count": 3, "side": 10, "mass": 1, "cells": {"pos": [300, 300], "columns": 3, "step": [20, 20]},
                "mask": 1}, "seed": 3}]})";
  const SceneSpec s = read_scene(text, "keys.json");
  BOOST_TEST(s.friction == 0.25);
  const auto& b = std::get<BlockSpec>(s.blocks[0]);
  BOOST_TEST(*b.contact.friction == 0.5);
  BOOST_TEST(b.contact.rules.category == 6u);
  BOOST_TEST(b.contact.rules.mask == 3u);
  BOOST_TEST(b.contact.rules.sensor);
  BOOST_TEST((std::get<BlockSpec>(s.blocks[1]).contact.rules.one_way == Face::up));
  BOOST_TEST((std::get<GridSpec>(s.blocks[2]).first.contact.rules.one_way == Face::left));
  BOOST_TEST(std::get<RandomSpec>(s.blocks[3]).contact.rules.mask == 1u);
  const SceneSpec again = read_scene(to_json(s), "again.json");
  BOOST_TEST(to_json(again) == to_json(s));
  // And the world gets them: the walls and the unset blocks the world's friction.
  World w = make_world(s, false);
  BOOST_TEST(w.components.friction[0] == 0.25);
  BOOST_TEST(w.components.friction[4] == 0.5);
  BOOST_TEST(w.components.friction[5] == 0.25);
  BOOST_TEST(w.components.rules(4).sensor);
  BOOST_TEST((w.components.rules(5).one_way == Face::up));
  BOOST_TEST(w.components.any_rules());
}

BOOST_AUTO_TEST_CASE(bad_values_are_named) {
  BOOST_TEST(error_of(with_block(R"("friction": -1)")) == "bad.json: blocks[0].friction: must be in [0, 1000] (got -1)");
  BOOST_TEST(error_of(with_block(R"("one_way": "diagonal")")) ==
             R"(bad.json: blocks[0].one_way: must be "up", "down", "left" or "right" (got the string "diagonal"))");
  BOOST_TEST(error_of(with_block(R"("category": 8589934592)")) ==
             "bad.json: blocks[0].category: must be an integer in [0, 4294967295] (got 8589934592)");
  BOOST_TEST(error_of(with_block(R"("sensor": "yes")")) == R"(bad.json: blocks[0].sensor: must be true or false (got the string "yes"))");
  BOOST_TEST(error_of(R"({"world": {"friction": 2000}})") == "bad.json: world.friction: must be in [0, 1000] (got 2000)");
  BOOST_TEST(error_of(R"({"state": {"warm_start": [[3, 2, 0, 1, 0]]}})") ==
             "bad.json: state.warm_start[0]: must name two bodies c < b < 4 (got 3, 2)");
}

BOOST_AUTO_TEST_CASE(a_bad_auto_state_is_named) {
  BOOST_TEST(error_of(R"({"world": {"solver": "auto"}, "state": {"auto": {"hold": 99}}})") ==
             "bad.json: state.auto.hold: must be an integer in [0, 8] (got 99)");
  BOOST_TEST(error_of(R"({"world": {"solver": "auto"}, "state": {"auto": {"pressed": [[2, 1, 3]]}}})") ==
             "bad.json: state.auto.pressed[0]: must name two bodies c < b < 4 (got 2, 1)");
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(game_physics_drawing)

namespace {
// Records what the Draw system fills.
struct Recorder : Canvas {
  struct Fill {
    Vector p;
    Rect r;
    Color c;
  };
  std::vector<Fill> fills;
  void fill_rect(Vector p, Rect r, Color c) override { fills.push_back({p, r, c}); }
  // Whether some fill covers the pixel (x, y).
  bool covers(double x, double y) const {
    for (const Fill& f : fills)
      if (x >= f.p.x && x < f.p.x + f.r.width && y >= f.p.y && y < f.p.y + f.r.height) return true;
    return false;
  }
};
}  // namespace

BOOST_AUTO_TEST_CASE(a_sensor_is_drawn_as_its_outline_and_a_platform_with_a_thick_solid_face) {
  World w(SystemSet{true, false, false, false});
  const auto sensor = Block::make(w, 100, 100, 60, 40, Color{200, 0, 0, 255}, 1.0);
  ContactRules r;
  r.sensor = true;
  w.components.set_rules(sensor.id, r);
  Recorder canvas;
  Game::draw(w, canvas);
  BOOST_TEST(canvas.covers(100, 100));   // the outline
  BOOST_TEST(canvas.covers(159, 139));
  BOOST_TEST(!canvas.covers(130, 120));  // not the inside
  for (const auto& f : canvas.fills) BOOST_TEST((f.c == Color{200, 0, 0, 255}));

  World p(SystemSet{true, false, false, false});
  const auto platform = Block::make(p, 100, 100, 60, 20, Color{100, 100, 100, 255}, infinity);
  ContactRules up;
  up.one_way = Face::up;
  p.components.set_rules(platform.id, up);
  Recorder drawn;
  Game::draw(p, drawn);
  // The last fill is the solid face: the top band, solid_face px thick, in the outline's shade.
  const auto& face = drawn.fills.back();
  BOOST_TEST((face.p == Vector{100, 100}));
  BOOST_TEST(face.r.width == 60);
  BOOST_TEST(face.r.height == solid_face);
  BOOST_TEST((face.c == outline_color(Color{100, 100, 100, 255})));
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace test_game_physics
