// The engine's own geometry (engine/geometry.hpp) and stages
// (engine/stages.hpp) against the course's answers they stand in for
// (Rect::mdiff, Rect::has_origin, Collision::penetration; Forces, Move,
// Collision::resolve and its pass): the same bits on every input, random or
// chosen on an edge (touching boxes, ties between the four vectors, zero
// sizes, signed zeros, infinities and NaN; fixed bodies, bodies at rest,
// friction), so that the engine behaves exactly as it did when it called the
// course's.
#include <cstdint>
#include <limits>
#include <random>

#include "engine/geometry.hpp"
#include "engine/stages.hpp"
#include "engine/step.hpp"
#include "helpers.hpp"
#include "scene/builtin_scenes.hpp"
#include "scene/scene.hpp"

// The file's own names, apart from the other test files' with which it is
// compiled (Makefile, TEST_UNITY).
namespace test_geometry {

using namespace physics;

namespace {

// Bit for bit (tests/helpers.hpp): -0 is not +0, a NaN equals itself.
using physics::test::same_bits;

// Positions on the edges that matter: zeros of both signs, small integers
// (boxes that touch or tie), halves, non-finite values.
const double edge_values[] = {0.0,  -0.0, 1.0,  -1.0, 0.5, -0.5, 10.0, -10.0, 20.0, -20.0, 40.0, -40.0,
                              1e-300, -1e-300, 1e300, -1e300,
                              std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                              std::numeric_limits<double>::quiet_NaN()};
const int edge_sizes[] = {0, 1, 2, 10, 20, 40, 80};

// Compares the three functions on one input, counting the disagreements.
int disagreements(Vector p1, Rect r1, Vector p2, Rect r2) {
  const auto [cp, cr] = Rect::mdiff(p1, r1, p2, r2);
  const auto [ep, er] = minkowski_difference(p1, r1, p2, r2);
  int bad = 0;
  if (!same_bits(cp, ep) || !(cr == er)) ++bad;
  if (Rect::has_origin(cp, cr) != contains_origin(cp, cr)) ++bad;
  if (!same_bits(Collision::penetration(cp, cr), penetration_vector(cp, cr))) ++bad;
  // The two other functions on the raw inputs too (not only on differences).
  if (Rect::has_origin(p1, r1) != contains_origin(p1, r1)) ++bad;
  if (!same_bits(Collision::penetration(p1, r1), penetration_vector(p1, r1))) ++bad;
  return bad;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(engine_geometry)

BOOST_AUTO_TEST_CASE(agrees_with_the_course_on_edge_inputs) {
  int bad = 0, cases = 0;
  for (const double x : edge_values)
    for (const double y : edge_values)
      for (const int w : edge_sizes)
        for (const int h : edge_sizes) {
          bad += disagreements({0.0, 0.0}, Rect{w, h}, {x, y}, Rect{h, w});
          bad += disagreements({x, y}, Rect{w, h}, {0.0, 0.0}, Rect{}), cases += 2;
        }
  BOOST_TEST(bad == 0, bad << " disagreements in " << cases << " edge cases");
}

BOOST_AUTO_TEST_CASE(agrees_with_the_course_on_random_inputs) {
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> real(-200.0, 200.0);
  std::uniform_int_distribution<int> size(0, 120), grid(-20, 20), kind(0, 2);
  // Half-pixel grids make touching boxes and ties frequent; reals make the rest.
  auto coordinate = [&] { return kind(rng) == 0 ? real(rng) : grid(rng) * (kind(rng) == 0 ? 0.5 : 10.0); };
  int bad = 0;
  for (int i = 0; i < 200000; ++i)
    bad += disagreements({coordinate(), coordinate()}, Rect{size(rng), size(rng)}, {coordinate(), coordinate()},
                         Rect{size(rng), size(rng)});
  BOOST_TEST(bad == 0);
}

// The inputs above would agree trivially if both sides were stubs returning
// the same constant; these pin the engine's functions to the sheet's values.
BOOST_AUTO_TEST_CASE(gives_the_sheets_values_with_its_tie_rules) {
  const auto [p, r] = minkowski_difference({10, 20}, {30, 40}, {100, 5}, {7, 9});
  BOOST_TEST((p == Vector{60, -55}));
  BOOST_TEST((r == Rect{37, 49}));
  BOOST_TEST(contains_origin({-1, -1}, {2, 2}));
  BOOST_TEST(!contains_origin({0, -1}, {2, 2}));   // touching on the left edge
  BOOST_TEST(!contains_origin({-2, -1}, {2, 2}));  // touching on the right edge
  BOOST_TEST(!contains_origin({-1, -1}, {0, 2}));  // zero width
  BOOST_TEST((penetration_vector({-10, -30}, {60, 60}) == Vector{-10, 0}));
  BOOST_TEST((penetration_vector({-30, -5}, {60, 60}) == Vector{0, -5}));
  BOOST_TEST((penetration_vector({-30, -58}, {60, 60}) == Vector{0, 2}));
  // Ties: -x before +x, x before y.
  BOOST_TEST((penetration_vector({-30, -30}, {60, 60}) == Vector{-30, 0}));
  BOOST_TEST((penetration_vector({-40, -20}, {60, 60}) == Vector{20, 0}));
  BOOST_TEST((penetration_vector({-40, -40}, {60, 60}) == Vector{20, 0}));
}

BOOST_AUTO_TEST_SUITE_END()

namespace {

// n bodies on a tight grid (most neighbours overlap, some touch), with
// fixed bodies, bodies at rest, zero sizes, friction and pending forces.
Components random_bodies(std::mt19937_64& rng, int n) {
  std::uniform_real_distribution<double> unit(0.0, 1.0), speed(-0.5, 0.5);
  std::uniform_int_distribution<int> size(0, 40), cell(0, 7), kind(0, 7);
  Components k;
  for (int i = 0; i < n; ++i) {
    const EntityId e = k.create();
    const bool on_grid = kind(rng) < 4;  // integer positions: touching boxes and ties
    k.position[e] = {cell(rng) * 20.0 + (on_grid ? 0.0 : unit(rng) * 20.0),
                     cell(rng) * 20.0 + (on_grid ? 0.0 : unit(rng) * 20.0)};
    k.box[e] = Rect{size(rng), size(rng)};
    k.mass[e] = kind(rng) == 0 ? infinity : 0.5 + 20.0 * unit(rng);
    if (kind(rng) > 1) k.velocity[e] = {speed(rng), speed(rng)};
    k.sum_forces[e] = {speed(rng), speed(rng)};
    k.restitution[e] = unit(rng);
    if (kind(rng) < 4) k.friction[e] = unit(rng);
  }
  return k;
}

std::vector<EntityId> all_ids(const Components& k) {
  std::vector<EntityId> ids(k.size());
  for (EntityId e = 0; e < ids.size(); ++e) ids[e] = e;
  return ids;
}

// Bit for bit, every array the stages write.
bool same(const Components& a, const Components& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t e = 0; e < a.size(); ++e)
    if (!same_bits(a.position[e], b.position[e]) || !same_bits(a.velocity[e], b.velocity[e]) ||
        !same_bits(a.sum_forces[e], b.sum_forces[e]))
      return false;
  return true;
}

bool same(const Contact& a, const Contact& b) {
  return a.c == b.c && a.b == b.b && same_bits(a.penetration, b.penetration) && same_bits(a.normal, b.normal) &&
         a.approaching == b.approaching && same_bits(a.jn, b.jn) && same_bits(a.jt, b.jt);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(engine_stages)

BOOST_AUTO_TEST_CASE(forces_and_move_agree_with_the_course_systems) {
  std::mt19937_64 rng(3);
  for (int world = 0; world < 50; ++world) {
    Components course = random_bodies(rng, 40);
    Components engine = course;
    std::vector<EntityId> forces_list, move_list;  // a world's lists, without the world
    Forces forces(forces_list);
    Move move(move_list);
    for (EntityId e = 0; e < course.size(); ++e) {
      forces.register_entity(Entity<component::sum_forces, component::mass, component::velocity>{e});
      move.register_entity(Entity<component::position, component::velocity>{e});
    }
    const Vector gravity{0.0, world % 2 ? 0.001 : 0.0};
    forces.update(course, course_dt / 3, gravity);
    move.update(course, course_dt / 3);
    apply_forces(engine, all_ids(engine), course_dt / 3, gravity);
    move_bodies(engine, all_ids(engine), course_dt / 3);
    BOOST_TEST_REQUIRE(same(course, engine), "world " << world);
    BOOST_TEST(!same(course, random_bodies(rng, 40)));  // the comparison can fail
  }
}

BOOST_AUTO_TEST_CASE(resolving_a_pair_agrees_with_the_course_collision) {
  std::mt19937_64 rng(8);
  int resolved = 0, approaching = 0;
  for (int world = 0; world < 20; ++world) {
    Components course = random_bodies(rng, 30);
    Components engine = course;
    // Every pair, in the sheet's order, each one after the corrections of the last.
    for (EntityId c = 0; c < course.size(); ++c)
      for (EntityId b = c + 1; b < course.size(); ++b) {
        Contact from_course, from_engine;
        const bool hit = Collision::resolve(course, c, b, &from_course);
        BOOST_TEST_REQUIRE(hit == resolve_pair(engine, c, b, &from_engine));
        if (hit) {
          BOOST_TEST_REQUIRE(same(from_course, from_engine), "world " << world << " pair " << c << ", " << b);
          ++resolved;
          approaching += from_course.approaching;
        }
        BOOST_TEST_REQUIRE(same(course, engine), "world " << world << " pair " << c << ", " << b);
      }
  }
  // The worlds exercise the algorithm: many contacts, impulses among them.
  BOOST_TEST(resolved > 200);
  BOOST_TEST(approaching > 100);
}

BOOST_AUTO_TEST_CASE(the_pass_over_the_broad_phase_agrees_with_the_course_collision) {
  std::mt19937_64 rng(13);
  for (int world = 0; world < 20; ++world) {
    Components course = random_bodies(rng, 60);
    Components engine = course;
    const Components before = course;
    std::vector<EntityId> list;
    PassContacts pass;
    Collision collision(list, pass);
    collision.record_contacts = true;
    for (EntityId e = 0; e < course.size(); ++e)
      collision.register_entity(Entity<component::position, component::box, component::mass, component::velocity,
                                       component::restitution>{e});
    BroadPhase for_course, for_engine;
    collision.update(course, for_course.course_pairs(course, collision.entities(), course_dt));
    std::vector<Contact> contacts;
    const std::vector<EntityId> ids = all_ids(engine);
    const std::size_t count = resolve_pairs(engine, for_engine.course_pairs(engine, ids, course_dt), &contacts);
    BOOST_TEST_REQUIRE(count == collision.contact_count());
    BOOST_TEST_REQUIRE(count > 0u);
    BOOST_TEST_REQUIRE(contacts.size() == collision.contacts().size());
    for (std::size_t i = 0; i < contacts.size(); ++i) BOOST_TEST_REQUIRE(same(contacts[i], collision.contacts()[i]));
    BOOST_TEST_REQUIRE(same(course, engine), "world " << world);
    // Without a contact list, the same pass.
    Components again = before;
    BroadPhase for_again;
    BOOST_TEST(resolve_pairs(again, for_again.course_pairs(again, ids, course_dt)) == count);
    BOOST_TEST(same(again, engine));
  }
}

// The one frame (engine/step.hpp, run_frame) with either set of stages: the
// engine's step (the public API's) and the course's Game::step give the same
// bits on every built-in scene, in every solver, with and without CCD, the
// exact integrator and substeps, contact events and the pass's contacts too.
BOOST_AUTO_TEST_CASE(the_engine_step_and_the_course_step_agree_on_every_built_in_scene) {
  struct Mode {
    Solver solver;
    bool ccd;
    Integrator integrator;
    int substeps;
  };
  const Mode modes[] = {{Solver::course, false, Integrator::course, 1}, {Solver::stable, false, Integrator::course, 1},
                        {Solver::automatic, false, Integrator::course, 1}, {Solver::course, true, Integrator::exact, 3},
                        {Solver::stable, true, Integrator::exact, 2}};
  int scenes = 0, contacts = 0;
  for (const SceneSpec& builtin : builtin_scenes())
    for (const Mode& m : modes) {
      SceneSpec spec = builtin;
      spec.params.solver = m.solver;
      spec.params.ccd = m.ccd;
      spec.params.integrator = m.integrator;
      spec.params.substeps = m.substeps;
      World engine = make_world(spec, false), course = make_world(spec, false);
      engine.enable_events();
      course.enable_events();
      bool events_agree = true;
      for (int frame = 0; frame < 120; ++frame) {
        physics::step(engine);
        Game::step(course);
        const auto a = engine.events.events(), b = course.events.events();
        events_agree = events_agree && a.size() == b.size() && engine.pass.contact_count == course.pass.contact_count;
        for (std::size_t i = 0; events_agree && i < a.size(); ++i)
          events_agree = a[i].a == b[i].a && a[i].b == b[i].b && a[i].kind == b[i].kind && same_bits(a[i].jn, b[i].jn);
        contacts += static_cast<int>(engine.pass.contact_count);
      }
      BOOST_TEST_REQUIRE(same(engine.components, course.components), spec.name << " solver " << name(m.solver));
      BOOST_TEST_REQUIRE(events_agree, spec.name << " solver " << name(m.solver));
      ++scenes;
    }
  BOOST_TEST(scenes >= 40);
  BOOST_TEST(contacts > 1000);  // the course passes resolved contacts: the comparison covers them
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace test_geometry
