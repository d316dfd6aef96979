// The stable solver without ghost collisions (issue 23, item 3): a box
// sliding over touching boxes (a floor, a slot) moves as on one flat body,
// resting stacks hold when gravity's step g·h² exceeds a block's size, and a
// push into a wall leaves nothing inside the wall nor overlapping. Each case
// against its closed form or invariant, in the modes that claim resting
// contact (the stable solver alone, with CCD, and auto where it takes the solver).
#include <functional>

#include "helpers.hpp"
#include "numerics/scenes.hpp"

// The file's own names, apart from the other test files' with which it is
// compiled (Makefile, TEST_UNITY).
namespace test_seams {

using namespace physics;
using namespace physics::numerics;

namespace {

const Mode stable{"stable", 1, false, Solver::stable, 8};
const Mode stable_ccd{"stable+ccd", 1, true, Solver::stable, 8};
const Mode automatic{"auto", 1, false, Solver::automatic, 8};

constexpr double g = 0.001;

// A floor of 40 touching fixed 40x40 blocks whose top is at y = 200 (or one
// 1600 px wide block), and a 20x20 block resting on it at x = 0, sliding at
// 0.5 px/ms, with friction mu; `ceiling`: the blocks' bottom at y = 200 and
// the block under it, gravity up. Returns the slider's x after `frames`.
double slide(const Mode& m, bool touching, double mu, int frames, bool ceiling = false) {
  World w = make_world(m, {0, ceiling ? -g : g});
  const double rest = ceiling ? 200 : 180, surface = ceiling ? 160 : 200;
  const EntityId s = block(w, 0, rest, 20, 20, 1.0, {0.5, 0}, 0.0);
  if (touching)
    for (int i = 0; i < 40; ++i) block(w, 40.0 * i, surface, 40, 40, infinity, {}, 0.0);
  else
    block(w, 0, surface, 1600, 40, infinity, {}, 0.0);
  for (std::size_t e = 0; e < w.components.size(); ++e) w.components.friction[e] = mu;
  for (int f = 0; f < frames; ++f) Game::step(w);
  BOOST_TEST(std::abs(w.components.position[s].y - rest) < 0.05);  // neither sunk nor lifted
  return w.components.position[s].x;
}

// Steps w 63 frames and checks that block s fell freely from rest at y = 0
// (the sheet's symplectic Euler: y = g h² n(n+1)/2 after n steps) and kept x.
void expect_free_fall(World& w, EntityId s, double x) {
  const int n = 63;
  for (int f = 0; f < n; ++f) Game::step(w);
  const double h = course_dt;
  BOOST_TEST(std::abs(w.components.position[s].y - g * h * h * n * (n + 1) / 2) < 1e-9);
  BOOST_TEST(w.components.position[s].x == x);
}

// The deepest overlap over `frames` frames of the world `build` makes.
double deepest(World& w, int frames) {
  double out = 0.0;
  for (int f = 0; f < frames; ++f) Game::step(w), out = std::max(out, max_overlap(w));
  return out;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(seams)

// Frictionless: x = v0 t, 0.5 px/ms × 63 frames of 1000/60 ms = 525 px (the
// stable solver stopped at the first seam, x = 20).
BOOST_AUTO_TEST_CASE(a_frictionless_slide_over_touching_floor_blocks_keeps_its_speed) {
  for (const Mode& m : {stable, stable_ccd, automatic}) {
    BOOST_TEST_INFO(m.name);
    BOOST_TEST(std::abs(slide(m, true, 0.0, 63) - 525.0) < 1e-9);
  }
}

// Under a ceiling of touching blocks, gravity up, e = 0: auto took the
// course's pass there (no pair of finite bodies pressed together), which at
// a seam pushes the slider out sideways (the family's seam-slide seed 17 ended
// 734 px short); a seamed surface under gravity now puts it on the solver.
BOOST_AUTO_TEST_CASE(auto_slides_under_a_ceiling_of_touching_blocks_as_under_one) {
  for (const bool touching : {true, false}) {
    BOOST_TEST_INFO(touching);
    BOOST_TEST(std::abs(slide(automatic, touching, 0.0, 63, true) - 525.0) < 1e-9);
  }
}

// With friction 0.5 the slide stops after v0²/(2 mu g) = 250 px (within the
// matrix's 3 %: the error is v0·dt/2), the same as on one flat floor (it
// stopped after 20 px at the first seam). Auto takes the solver on a floor of
// touching blocks (a seamed surface) and the course's pass on one flat
// floor, so its slide over the seams is the solver's over one floor.
BOOST_AUTO_TEST_CASE(a_friction_slide_over_touching_floor_blocks_stops_where_it_does_on_one_floor) {
  for (const Mode& m : {stable, stable_ccd, automatic}) {
    BOOST_TEST_INFO(m.name);
    const Mode& on_one_floor = m.solver == Solver::automatic ? stable : m;
    const double seams = slide(m, true, 0.5, 120), flat = slide(on_one_floor, false, 0.5, 120);
    BOOST_TEST(std::abs(seams - 250.0) < 0.03 * 250.0);
    BOOST_TEST(std::abs(seams - flat) < 1e-9);
  }
}

// A 20x20 block falls from rest into a slot exactly 20 px wide between two
// columns of touching 20x20 fixed blocks: free fall, the sheet's symplectic
// Euler's y = g h² n(n+1)/2 after n steps (it stopped on the first wall
// block's top, 458 px short).
BOOST_AUTO_TEST_CASE(a_block_falls_freely_down_a_slot_of_touching_blocks_that_fits_exactly) {
  for (const Mode& m : {stable, stable_ccd, automatic}) {
    BOOST_TEST_INFO(m.name);
    World w = make_world(m, {0, g});
    const EntityId s = block(w, 100, 0, 20, 20, 1.0, {}, 0.0);
    for (int i = 0; i < 60; ++i) block(w, 80, 20.0 * i, 20, 20, infinity), block(w, 120, 20.0 * i, 20, 20, infinity);
    expect_free_fall(w, s, 100.0);
  }
}

// The same along a wall: a 20x20 block moving into a column of touching
// 20x20 fixed blocks at 0.2 px/ms, e = 0, falls along it freely (it stopped on
// the second wall block's corner: a vertical normal from the seam).
BOOST_AUTO_TEST_CASE(a_block_pressed_into_a_wall_of_touching_blocks_falls_freely_along_it) {
  for (const Mode& m : {stable, stable_ccd, automatic}) {
    BOOST_TEST_INFO(m.name);
    World w = make_world(m, {0, g});
    const EntityId s = block(w, 100, 0, 20, 20, 1.0, {0.2, 0}, 0.0);
    for (int i = 0; i < 60; ++i) block(w, 120, 20.0 * i, 20, 20, infinity, {}, 0.0);
    expect_free_fall(w, s, 100.0);
  }
}

// A floor at fractional coordinates (x = 0.1 + 40 i, top at 200.3), whose
// blocks overlap by rounding, under g = 0.01: a slide at 2 px/ms keeps its
// speed (it stopped at the first seam, with auto too).
BOOST_AUTO_TEST_CASE(a_slide_over_a_floor_at_fractional_coordinates_keeps_its_speed) {
  for (const Mode& m : {stable, stable_ccd, automatic}) {
    BOOST_TEST_INFO(m.name);
    World w = make_world(m, {0, 0.01});
    const EntityId s = block(w, 0.1, 180.3, 20, 20, 1.0, {2, 0}, 0.0);
    for (int i = 0; i < 99; ++i) block(w, 0.1 + 40 * i, 200.3, 40, 40, infinity, {}, 0.0);
    for (int f = 0; f < 100; ++f) Game::step(w);
    BOOST_TEST(std::abs(w.components.position[s].x - (0.1 + 2 * 100 * course_dt)) < 1e-9);
    BOOST_TEST(w.components.velocity[s].x == 2.0);
  }
}

// Three towers of five 40x40 blocks on the floor when gravity's step g·h²
// (1000 px at dt = 1000 ms; 278 px at g = 1 px/ms²) exceeds a block's size:
// no block moves by 1 px, nothing overlaps by 1 px (they burst sideways by
// 40-60 px within a step).
BOOST_AUTO_TEST_CASE(resting_stacks_hold_when_gravitys_step_exceeds_a_block) {
  for (Mode m : {stable, stable_ccd, automatic})
    for (const auto& [dt, gravity] : {std::pair{1000.0, g}, std::pair{course_dt, 1.0}}) {
      BOOST_TEST_INFO(m.name << ", dt = " << dt << " ms, g = " << gravity);
      m.dt = dt;
      World w = make_world(m, {0, gravity});
      walls(w);
      std::vector<std::pair<EntityId, Vector>> start;
      for (int row = 0; row < 5; ++row)
        for (int col = 0; col < 3; ++col) {
          const Vector p{200.0 + 180 * col, 520.0 - 40 * row};
          start.emplace_back(block(w, p.x, p.y, 40, 40, 1.0, {}, 0.0), p);
        }
      BOOST_TEST(deepest(w, 300) < 1.0);
      double moved = 0.0;
      for (const auto& [e, p] : start) moved = std::max(moved, Vector::norm(w.components.position[e] - p));
      BOOST_TEST(moved < 1.0);
    }
}

// A block of mass 1e6 at 0.5 px/ms pushes a light one (mass 1) into a fixed
// wall, e = 0: the light one never enters the wall, nothing overlaps by 1 px,
// and with the solver's impacts the pusher stops (a perfectly inelastic push
// against a wall; with CCD on, the impacts are CCD's). It ended 3.3 px inside
// the wall, 16.7 px into the pusher, the pusher still at 0.5.
BOOST_AUTO_TEST_CASE(a_heavy_pusher_drives_a_light_block_into_a_wall_without_entering_it) {
  for (const Mode& m : {stable, stable_ccd}) {
    BOOST_TEST_INFO(m.name);
    World w = make_world(m);
    const EntityId heavy = block(w, 100, 100, 40, 40, 1e6, {0.5, 0}, 0.0);
    const EntityId light = block(w, 200, 110, 20, 20, 1.0, {}, 0.0);
    block(w, 400, 0, 40, 400, infinity, {}, 0.0);
    BOOST_TEST(deepest(w, 60) < 1.0);
    BOOST_TEST(w.components.position[light].x + 20.0 <= 400.0 + 0.05);
    if (!m.ccd) BOOST_TEST(std::abs(w.components.velocity[heavy].x) < 1e-9);
  }
}

// A light block between a pusher and a wall, bouncing (the family's
// push-into-wall seed 18): the wall's impulse sends it back into the pusher
// it was leaving, a pair that had no contact at the substep's start, so it
// moved 8 px into the pusher and the position projection pushed it 3.35 px
// into the wall. With rounds (SolverSettings::rounds, 3 for the stable
// solver; turned_to_meet) the contacts are taken again after such a turn:
// never 1 px into the wall or into the pusher, order kept, energy never grows.
double push_into_wall() {
  World w = make_world(stable);
  walls(w);
  const double xl = 760 - 26 - 3.62;
  const EntityId light = block(w, xl, 300 - 13, 26, 26, 1.0, {}, 0.566);
  const EntityId pusher = block(w, xl - 164 - 30, 300 - 15, 30, 30, 14.6, {0.295, 0}, 0.566);
  const double e0 = w.kinetic_energy();
  double worst = 0.0;
  for (int f = 0; f < 214; ++f) {
    Game::step(w);
    const Components& k = w.components;
    worst = std::max({worst, k.position[light].x + 26 - 760, max_overlap(w)});
    BOOST_TEST_REQUIRE(k.position[pusher].x < k.position[light].x, "frame " << f);
    BOOST_TEST_REQUIRE(w.kinetic_energy() <= e0 * (1 + 1e-12), "frame " << f);
  }
  return worst;
}

BOOST_AUTO_TEST_CASE(a_light_block_turned_back_by_a_wall_meets_its_pusher) {
  BOOST_TEST(push_into_wall() < 1.0);  // one round: 3.35 px
}

// An infinite-mass pusher at 0.5 px/ms drives a row of 30 touching 10x10
// blocks: the row moves with it, nothing overlaps by 1 px (9.4 px before),
// from the start with the solver, after settling with auto (which starts on
// the course's pass).
BOOST_AUTO_TEST_CASE(an_infinite_mass_pusher_drives_a_row_without_overlaps) {
  for (const Mode& m : {stable, automatic}) {
    BOOST_TEST_INFO(m.name);
    World w = make_world(m);
    block(w, 0, 100, 40, 40, infinity, {0.5, 0}, 0.0);
    std::vector<EntityId> row;
    for (int i = 0; i < 30; ++i) row.push_back(block(w, 40.0 + 10 * i, 115, 10, 10, 1.0, {}, 0.0));
    const double settling = deepest(w, 30);
    if (m.solver == Solver::stable) BOOST_TEST(settling < 1.0);
    BOOST_TEST(deepest(w, 170) < 1.0);
    for (const EntityId e : row) BOOST_TEST(w.components.velocity[e].x == 0.5);
  }
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace test_seams
