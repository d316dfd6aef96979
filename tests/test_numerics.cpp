// The numerics options: swept collision (CCD), the stable contact solver, and
// the course mode left as it was. The stiff/extreme matrix is test_stability.cpp.
#include <algorithm>
#include <bit>
#include <cstdint>
#include <functional>
#include <vector>

#include "course/game.hpp"
#include "helpers.hpp"
#include "numerics/report.hpp"
#include "numerics/scenes.hpp"
#include "course/utils/random.hpp"

// The file's own names, apart from the other test files' with which it is
// compiled (Makefile, TEST_UNITY).
namespace test_numerics {

using namespace physics;
using namespace physics::numerics;

BOOST_AUTO_TEST_SUITE(numerics_ccd)

// A walled box of `count` random blocks (sides 1-30 px, masses 1-5), each
// with a random velocity of at most `speed` px/ms per axis.
World random_blocks(Random& rng, int count, double speed) {
  World w = test::physics_world();
  Game::init_walls(w);
  for (int i = 0; i < count; ++i) {
    const auto b = Block::make(w, rng.uniform(0, 780), rng.uniform(0, 580), rng.uniform_int(1, 30),
                               rng.uniform_int(1, 30), test::grey, rng.uniform(1, 5));
    w.components.velocity[b.id] = {rng.uniform(-speed, speed), rng.uniform(-speed, speed)};
  }
  return w;
}

BOOST_AUTO_TEST_CASE(candidate_pairs_are_the_all_pairs_ones_in_registration_order) {
  Random rng(9);
  World w = random_blocks(rng, 400, 2.0);
  Block::make(w, 100, 100, 20, 20, test::grey, 1.0);  // two exactly touching boxes
  Block::make(w, 120, 100, 20, 20, test::grey, 1.0);
  for (const double h : {0.0, 16.0})
    for (const double reach : {0.0, 0.5}) {
      std::vector<Pair> fast, slow;
      candidate_pairs(w.components, w.bodies(SystemId::collision), h, reach, fast);
      brute_force_pairs(w.components, w.bodies(SystemId::collision), h, reach, slow);
      BOOST_TEST_REQUIRE(fast.size() == slow.size());
      BOOST_TEST(fast.size() > 100u);
      for (std::size_t i = 0; i < fast.size(); ++i) {
        BOOST_TEST(fast[i].c == slow[i].c);
        BOOST_TEST(fast[i].b == slow[i].b);
      }
    }
}

// One broad phase asked again and again, as the world asks it: it keeps its
// grid while the bodies stay in their fat boxes, and its last pairs while
// every swept box keeps its bits. Moves far smaller than the fat margin must
// still make and break pairs (two boxes 0.25 px apart, then touching).
BOOST_AUTO_TEST_CASE(a_kept_broad_phase_sees_every_small_change) {
  Random rng(21);
  World w = random_blocks(rng, 300, 0.01);
  const EntityId left = Block::make(w, 100, 100, 20, 20, test::grey, 1.0).id;
  const EntityId right = Block::make(w, 120, 100, 20, 20, test::grey, 1.0).id;
  w.components.velocity[left] = w.components.velocity[right] = {0.0, 0.0};
  BroadPhase bp;
  const auto ids = w.bodies(SystemId::collision);
  const auto has = [](const std::vector<Pair>& pairs, EntityId a, EntityId b) {
    return std::find(pairs.begin(), pairs.end(), Pair{std::min(a, b), std::max(a, b)}) != pairs.end();
  };
  std::vector<Pair> found, expected;
  const auto check = [&](double h, double reach) {
    bp.find(w.components, ids, h, reach, found);
    brute_force_pairs(w.components, ids, h, reach, expected);
    BOOST_TEST_REQUIRE((found == expected));
  };
  for (int round = 0; round < 40; ++round) {
    check(16.0, 0.0);
    check(16.0, 0.0);  // nothing changed: the kept pairs
    BOOST_TEST(has(found, left, right) == (round % 2 == 0));
    // Apart by a quarter pixel on odd rounds, touching again on even ones.
    w.components.position[right].x = round % 2 == 0 ? 120.25 : 120.0;
    // A body's velocity or size, far within its fat box.
    const EntityId e = ids[rng.uniform_int(0, static_cast<int>(ids.size()) - 1)];
    if (round % 3 == 0) w.components.velocity[e].x = -w.components.velocity[e].x;
    if (round % 3 == 1 && e != left && e != right) w.components.box[e].width += 1;
    if (round % 5 == 4) check(0.0, 0.5);  // another reach, then back
  }
}

// Asked again after a few bodies' velocities changed (the solver turned
// them), as the solver asks: the bodies whose swept box shrank keep a subset
// of their pairs, and the few whose box left its last one (within the grid's
// fat box) are looked up alone. Block a, sped up, reaches block b 2 px
// ahead on even rounds: a pair found only that way.
BOOST_AUTO_TEST_CASE(a_kept_broad_phase_finds_the_pairs_of_the_few_boxes_that_grew) {
  Random rng(33);
  World w = random_blocks(rng, 400, 0.01);
  const EntityId a = Block::make(w, 100, 100, 20, 20, test::grey, 1.0).id;
  const EntityId b = Block::make(w, 122, 100, 20, 20, test::grey, 1.0).id;
  w.components.velocity[a] = {0.05, 0.0};
  w.components.velocity[b] = {0.0, 0.0};
  BroadPhase bp;
  const auto ids = w.bodies(SystemId::collision);
  std::vector<Pair> found, expected;
  const auto check = [&] {
    bp.find(w.components, ids, 16.0, 0.5, found);
    brute_force_pairs(w.components, ids, 16.0, 0.5, expected);
    BOOST_TEST_REQUIRE((found == expected));
  };
  // Asked by find_again with the changed bodies but every third round (the
  // solver's turned velocities): the others' boxes are not made again.
  std::vector<EntityId> changed;
  for (int round = 0; round < 30; ++round) {
    check();
    changed.clear();
    w.components.velocity[a].x = round % 2 == 0 ? 0.125 : 0.05;
    // A few others a little faster, or slower (their boxes shrink).
    for (int i = 0; i < 4; ++i) {
      const EntityId e = ids[rng.uniform_int(0, static_cast<int>(ids.size()) - 1)];
      w.components.velocity[e] = (i % 2 == 0 ? 1.5 : 0.5) * w.components.velocity[e];
      changed.push_back(e);
    }
    changed.push_back(a);
    if (round % 3 == 2) {
      check();
    } else {
      bp.find_again(w.components, ids, changed, 16.0, 0.5, found);
      brute_force_pairs(w.components, ids, 16.0, 0.5, expected);
      BOOST_TEST_REQUIRE((found == expected));
    }
    const bool touching = std::find(found.begin(), found.end(), Pair{a, b}) != found.end();
    BOOST_TEST(touching == (round % 2 == 0));
  }
  // Another h than the last call's: every box is made again.
  w.components.velocity[a].x = 0.125;
  bp.find_again(w.components, ids, {}, 0.0, 0.5, found);
  brute_force_pairs(w.components, ids, 0.0, 0.5, expected);
  BOOST_TEST((found == expected));
}

// A few bodies thrown out of their fat boxes, onto others, call after call
// (bodies bouncing off a pile): they take new boxes in the kept grid, whose
// pairs must then include theirs at the new places, by find() and by
// find_again(), whether looked up alone or among the grid's candidates; a
// body turned to an infinite mass as it lands on a wall
// (a pair the grid must not list) needs a grid built again, and so do more
// moved bodies than the grid keeps count of.
BOOST_AUTO_TEST_CASE(a_kept_grid_takes_the_few_bodies_that_left_their_fat_boxes) {
  Random rng(57);
  World w = random_blocks(rng, 400, 0.01);
  BroadPhase bp;
  const auto ids = w.bodies(SystemId::collision);
  std::vector<Pair> found, expected;
  bp.find(w.components, ids, 16.0, 0.5, found);
  const std::uint64_t builds = bp.builds();
  std::vector<EntityId> changed;
  std::size_t new_pairs = 0;
  const int half = static_cast<int>(ids.size()) / 2;
  const auto throw_onto_another = [&](EntityId e) {
    const EntityId onto = ids[rng.uniform_int(0, static_cast<int>(ids.size()) - 1)];
    w.components.position[e] = w.components.position[onto] + Vector{3.0, 2.0};  // overlapping it
    w.components.velocity[e] = {rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5)};
    changed.push_back(e);
  };
  for (int round = 0; round < 8; ++round) {
    changed.clear();
    for (int i = 0; i < 3; ++i) throw_onto_another(ids[rng.uniform_int(0, half - 1)]);
    // Half the rounds, more bodies leave their last boxes (within their fat
    // ones: bodies never thrown) than are looked up alone: the grid's
    // candidates are tested.
    for (int i = 0; round % 4 >= 2 && i < 20; ++i) {
      const EntityId turned = ids[rng.uniform_int(half, static_cast<int>(ids.size()) - 1)];
      w.components.velocity[turned] = -w.components.velocity[turned];
      changed.push_back(turned);
    }
    const std::vector<Pair> before = found;
    if (round % 2 == 0)
      bp.find(w.components, ids, 16.0, 0.5, found);
    else
      bp.find_again(w.components, ids, changed, 16.0, 0.5, found);
    brute_force_pairs(w.components, ids, 16.0, 0.5, expected);
    BOOST_TEST_REQUIRE((found == expected));
    for (const Pair p : found) new_pairs += std::find(before.begin(), before.end(), p) == before.end();
  }
  BOOST_TEST(new_pairs >= 8u);  // (each thrown body overlaps the one it was thrown onto)
  BOOST_TEST(bp.builds() == builds);  // 24 bodies of 404: within what the grid keeps count of (404 / 16)
  // A body thrown onto the left wall as it becomes a wall too: no pair of two walls.
  changed.clear();
  const EntityId e = ids[5];
  w.components.mass[e] = infinity;
  w.components.position[e] = {2.0, 300.0};
  bp.find(w.components, ids, 16.0, 0.5, found);
  brute_force_pairs(w.components, ids, 16.0, 0.5, expected);
  BOOST_TEST((found == expected));
  BOOST_TEST(bp.builds() == builds + 1);
  // Many bodies thrown, call after call: a build once more than one body in 16 moved since the last.
  for (int round = 0; round < 4; ++round) {
    for (int i = 0; i < 10; ++i) throw_onto_another(ids[rng.uniform_int(0, half - 1)]);
    bp.find(w.components, ids, 16.0, 0.5, found);
    brute_force_pairs(w.components, ids, 16.0, 0.5, expected);
    BOOST_TEST_REQUIRE((found == expected));
  }
  BOOST_TEST(bp.builds() == builds + 2);
}

BOOST_AUTO_TEST_CASE(time_of_impact_is_where_the_relative_motion_enters_the_minkowski_box) {
  World w = test::physics_world();
  const auto a = Block::make(w, 100, 100, 20, 20, test::grey, 1.0).id;
  const auto wall = Block::make(w, 220, 50, 40, 200, test::grey, infinity).id;
  w.components.velocity[a] = {2.0, 0.0};
  const auto hit = Ccd::time_of_impact(w.components, a, wall, 0.0, 100.0);
  BOOST_TEST_REQUIRE(hit.has_value());
  BOOST_TEST(hit->t == 50.0);  // 100 px of gap at 2 px/ms
  BOOST_TEST((hit->n == Vector{-1, 0}));
  BOOST_TEST(!Ccd::time_of_impact(w.components, a, wall, 0.0, 49.0).has_value());
  // Moving away, or sliding past above it: no impact.
  w.components.velocity[a] = {-2.0, 0.0};
  BOOST_TEST(!Ccd::time_of_impact(w.components, a, wall, 0.0, 1e9).has_value());
  w.components.position[a] = {100, 0};
  w.components.velocity[a] = {2.0, 0.0};
  BOOST_TEST(!Ccd::time_of_impact(w.components, a, wall, 0.0, 1e9).has_value());
}

BOOST_AUTO_TEST_CASE(a_bullet_at_1000_px_per_ms_never_leaves_the_walls) {
  for (const Solver solver : {Solver::course, Solver::stable}) {
    Params p;
    p.ccd = true;
    p.solver = solver;
    World w = test::physics_world(p);
    Game::init_walls(w);
    const auto b = Block::make(w, 400, 295, 10, 10, test::grey, 1.0).id;
    w.components.velocity[b] = {1000.0, 3.0};
    for (int f = 0; f < 120; ++f) {
      Game::step(w);
      const Vector q = w.components.position[b];
      BOOST_TEST_REQUIRE(q.x >= 40.0);
      BOOST_TEST_REQUIRE(q.x + 10 <= 760.0);
      BOOST_TEST_REQUIRE(q.y >= 40.0);
      BOOST_TEST_REQUIRE(q.y + 10 <= 560.0);
    }
    BOOST_TEST(w.ccd.stats.impacts > 1000);  // ~ 16 wall hits per frame
    BOOST_TEST(w.kinetic_energy() == 0.5 * (1000.0 * 1000.0 + 9.0));  // wall reversals are exact
  }
}

BOOST_AUTO_TEST_CASE(without_gravity_ccd_matches_the_exact_reference) {
  // Straight lines between impacts: CCD is event-driven simulation itself.
  for (const Scenario& s : report_scenarios()) {
    if (s.gravity.y != 0.0) continue;
    for (const Mode& m : {Mode{"ccd", 1, true}, Mode{"stable+ccd", 1, true, Solver::stable}}) {
      const Errors e = measure(s, m);
      BOOST_TEST_INFO(s.name << " / " << m.name);
      BOOST_TEST(e.pos_rms < 1e-9);
      BOOST_TEST(e.tunnelled == 0);
      BOOST_TEST(e.max_penetration < 1e-9);
    }
  }
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(numerics_stable_solver)

// The stable solver under a light gravity, within the course's walls.
World stable_walled_world() {
  Params p;
  p.solver = Solver::stable;
  p.gravity = {0, 0.001};
  World w = test::physics_world(p);
  Game::init_walls(w);
  return w;
}

BOOST_AUTO_TEST_CASE(a_block_on_the_floor_rests_exactly_still) {
  World w = stable_walled_world();
  const auto b = Block::make(w, 300, 520, 40, 40, test::grey, 5.0, 0.5).id;
  for (int f = 0; f < 600; ++f) Game::step(w);
  BOOST_TEST(w.components.position[b].y == 520.0);
  BOOST_TEST(w.components.velocity[b].y == 0.0);
  // The course mode sinks it by g·dt² every frame and pushes it back out.
  World c = test::physics_world(Params{.gravity = {0, 0.001}});
  Game::init_walls(c);
  const auto cb = Block::make(c, 300, 520, 40, 40, test::grey, 5.0, 0.5).id;
  Game::step(c);
  BOOST_TEST(c.components.velocity[cb].y != 0.0);
}

BOOST_AUTO_TEST_CASE(a_heavy_block_on_a_light_one_rests_at_ratio_1e12) {
  World w = stable_walled_world();
  const auto light = Block::make(w, 390, 540, 20, 20, test::grey, 1.0).id;
  const auto heavy = Block::make(w, 380, 500, 40, 40, test::grey, 1e12).id;
  for (int f = 0; f < 600; ++f) {
    Game::step(w);
    BOOST_TEST_REQUIRE(max_overlap(w) < 0.05);
  }
  BOOST_TEST(w.components.position[light].y == 540.0);
  BOOST_TEST(std::abs(w.components.position[heavy].y - 500.0) < 0.05);
}

// A block moved into another at rest (a game's set_position) overlaps it
// while neither moves: the position stage must see the overlap that the
// new classification found (ContactSolver::any_overlap asks once per
// classification whether a classified pair overlaps, again after the axes
// are written) and push the two apart.
BOOST_AUTO_TEST_CASE(a_block_moved_into_a_resting_one_is_pushed_out) {
  World w = stable_walled_world();
  Block::make(w, 300, 520, 40, 40, test::grey, 1.0);
  const auto b = Block::make(w, 400, 520, 40, 40, test::grey, 1.0).id;
  for (int f = 0; f < 60; ++f) Game::step(w);  // at rest: a kept classification, no classified overlap
  BOOST_TEST_REQUIRE(max_overlap(w) == 0.0);
  w.components.position[b].x = 330.0;  // 10 px into the other
  BOOST_TEST_REQUIRE(max_overlap(w) > 9.0);
  for (int f = 0; f < 30; ++f) Game::step(w);
  BOOST_TEST(max_overlap(w) < 0.05);
}

BOOST_AUTO_TEST_CASE(poisson_restitution_never_adds_energy_in_a_squeeze) {
  // A light block between two heavy ones closing in: simultaneous contacts,
  // unconverged iterations; the energy guard must hold.
  Params p;
  p.solver = Solver::stable;
  p.iterations = 2;
  World w = test::physics_world(p);
  const auto a = Block::make(w, 100, 100, 40, 40, test::grey, 1e3).id;
  Block::make(w, 141, 110, 20, 20, test::grey, 1.0);
  const auto b = Block::make(w, 162, 100, 40, 40, test::grey, 1e3).id;
  w.components.velocity[a] = {0.1, 0};
  w.components.velocity[b] = {-0.1, 0};
  const double E0 = w.kinetic_energy();
  const Vector P0 = w.momentum();
  for (int f = 0; f < 100; ++f) {
    Game::step(w);
    BOOST_TEST_REQUIRE(w.kinetic_energy() <= E0 * (1 + 1e-12));
  }
  BOOST_TEST(std::abs(w.momentum().x - P0.x) < 1e-12 * 200);
}

BOOST_AUTO_TEST_CASE(a_bounce_keeps_e_squared_of_the_height) {
  Params p;
  p.solver = Solver::stable;
  p.gravity = {0, 0.001};
  p.substeps = 8;
  World w = test::physics_world(p);
  Game::init_walls(w);
  const auto b = Block::make(w, 390, 140, 20, 20, test::grey, 1.0, 0.5).id;  // 400 px above the floor
  double apex = 1e9;
  bool bounced = false;
  for (int f = 0; f < 120; ++f) {
    Game::step(w);
    if (w.components.velocity[b].y < 0) bounced = true;
    if (bounced) apex = std::min(apex, w.components.position[b].y);
  }
  BOOST_TEST_REQUIRE(bounced);
  const double height = 540.0 - apex;
  BOOST_TEST(std::abs(height - 0.25 * 400.0) < 5.0);  // h·e², to within the time step
}

// Without friction anywhere, the iterations run the x rows and the y rows
// apart, with their normals turned to +x and +y, two rows side by side where
// they share no body (ContactSolver::sweep_axis, sweep_two); with friction on
// any pair, every row takes the loop that reads friction. For rows of mu = 0
// both must give the same bits. `build` makes the scene's bodies (the ones
// compared); a far stack of two blocks follows, with friction between them
// or not.
std::vector<std::uint64_t> solve_bits(bool far_friction, const std::function<std::vector<EntityId>(World&)>& build) {
  Params p;
  p.solver = Solver::stable;
  p.gravity = {0, 0.001};
  World w = test::physics_world(p);
  const std::vector<EntityId> ids = build(w);
  const auto low = Block::make(w, 700, 540, 20, 20, test::grey, 1.0).id;
  const auto high = Block::make(w, 705, 520, 20, 20, test::grey, 1.0).id;
  if (far_friction) w.components.friction[low] = w.components.friction[high] = 0.5;
  std::vector<std::uint64_t> out;
  const auto add = [&] {
    for (const EntityId e : ids)
      for (const double x : {w.components.position[e].x, w.components.position[e].y, w.components.velocity[e].x,
                             w.components.velocity[e].y})
        out.push_back(std::bit_cast<std::uint64_t>(x));
  };
  add();
  for (int f = 0; f < 150; ++f) Game::step(w);
  add();
  return out;
}

void check_same_bits(const std::function<std::vector<EntityId>(World&)>& build) {
  const auto plain = solve_bits(false, build);
  BOOST_TEST(plain == solve_bits(true, build));
  // Something happened.
  const auto half = static_cast<std::ptrdiff_t>(plain.size() / 2);
  BOOST_TEST(!std::equal(plain.begin(), plain.begin() + half, plain.begin() + half));
}

// Within the walls, a pyramid of `base` blocks at its foot and `drops` smaller
// blocks falling on it: their ids.
std::vector<EntityId> pyramid_under_rain(World& w, int base, int drops) {
  Game::init_walls(w);
  std::vector<EntityId> ids;
  for (int r = 0; r < base; ++r)
    for (int i = 0; i < base - r; ++i)
      ids.push_back(Block::make(w, 60 + 10 * r + 20 * i, 540 - 20 * r, 20, 20, test::grey, 1.0).id);
  for (int i = 0; i < drops; ++i) {
    ids.push_back(Block::make(w, 40 + 22 * i, 200 - 15 * (i % 3), 12, 12, test::grey, 0.5 + 0.25 * (i % 4), 0.5).id);
    w.components.velocity[ids.back()] = {0.02 * ((i % 5) - 2), 0.1};
  }
  return ids;
}

BOOST_AUTO_TEST_CASE(rows_without_friction_give_the_friction_loops_bits) {
  check_same_bits([](World& w) { return pyramid_under_rain(w, 10, 12); });
  // The last x row and the first y row of the same level (the x contact is
  // the first of both its blocks, the walls come after them): not side by
  // side, each is solved along its own axis.
  check_same_bits([](World& w) {
    const auto a = Block::make(w, 100, 540, 20, 20, test::grey, 1.0).id;
    const auto b = Block::make(w, 120, 540, 20, 20, test::grey, 1.0).id;
    const auto c = Block::make(w, 300, 540, 20, 20, test::grey, 1.0).id;
    Game::init_walls(w);
    w.components.velocity[a] = {0.05, 0};
    w.components.velocity[c] = {0.03, 0};  // sliding: its row along x would change its impulse
    return std::vector<EntityId>{a, b, c};
  });
}

// With friction on every pair, the friction sweep solves four rows of a
// level side by side with AVX2 where the processor has it
// (ContactSolver::friction_four), else two with SSE2 (friction_two): the same
// bits. A pyramid with rain falling on it, both ways.
BOOST_AUTO_TEST_CASE(four_friction_rows_side_by_side_give_the_bits_of_two) {
  BOOST_TEST_MESSAGE("four rows with AVX2 on this processor: " << (ContactSolver::has_wide_rows() ? "yes" : "no"));
  const auto run = [](bool wide) {
    Params p;
    p.solver = Solver::stable;
    p.gravity = {0, 0.001};
    World w = test::physics_world(p);
    BOOST_TEST(w.contact_solver.wide_rows == ContactSolver::has_wide_rows());
    w.contact_solver.wide_rows = wide && ContactSolver::has_wide_rows();
    const std::vector<EntityId> ids = pyramid_under_rain(w, 14, 16);
    for (EntityId e = 0; e < w.components.size(); ++e) w.components.friction[e] = 0.3 + 0.1 * (e % 4);
    std::vector<std::uint64_t> out;
    for (int f = 0; f < 150; ++f) {
      Game::step(w);
      for (const EntityId e : ids)
        for (const double x : {w.components.position[e].x, w.components.position[e].y, w.components.velocity[e].x,
                               w.components.velocity[e].y})
          out.push_back(std::bit_cast<std::uint64_t>(x));
    }
    return out;
  };
  const auto two = run(false);
  BOOST_TEST(two == run(true));
  // Something happened: the last raindrop moved from the first frame to the last.
  const std::size_t frame = two.size() / 150;
  BOOST_TEST(!std::equal(two.begin() + static_cast<std::ptrdiff_t>(frame - 4),
                         two.begin() + static_cast<std::ptrdiff_t>(frame), two.end() - 4));
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(numerics_course_mode)

BOOST_AUTO_TEST_CASE(the_course_mode_never_runs_the_numerics_code) {
  World w = test::physics_world();
  Game::init_scene(w);
  for (int f = 0; f < 600; ++f) Game::step(w);
  BOOST_TEST(w.ccd.stats.impacts == 0);
  BOOST_TEST(w.contact_solver.stats.contacts == 0);
  BOOST_TEST(w.pass.contact_count + 1 > 0u);
}

BOOST_AUTO_TEST_CASE(the_course_error_shrinks_with_dt_as_first_order) {
  const Scenario projectile = report_scenarios().front();
  BOOST_TEST_REQUIRE(projectile.name == "projectile");
  double last = 1e300;
  std::vector<double> err;
  for (const double hz : {60.0, 120.0, 240.0, 480.0}) {
    const double e = measure(projectile, Mode{"course", 1, false, Solver::course, 8, 1000.0 / hz}).pos_rms;
    BOOST_TEST(e < last);
    last = e;
    err.push_back(e);
  }
  // Eight times smaller dt: between 5x and 16x smaller error (order ~1).
  BOOST_TEST(err.front() / err.back() > 5.0);
  BOOST_TEST(err.front() / err.back() < 16.0);
}

// The report's exact families: in free flight against the event reference,
// rounding at every dt, where the course integrator is first order.
BOOST_AUTO_TEST_CASE(the_exact_integrator_is_exact_in_the_reports_free_flight) {
  const auto scenarios = report_scenarios();
  const auto flight = std::find_if(scenarios.begin(), scenarios.end(), [](const Scenario& s) { return s.name == "free flight"; });
  BOOST_TEST_REQUIRE((flight != scenarios.end()));
  int exact = 0;
  for (const Setting& st : report_settings()) {
    BOOST_TEST_CONTEXT(st.family << " " << st.label) {
      const Errors e = measure(*flight, st.mode);
      if (st.mode.integrator == Integrator::exact) {
        ++exact;
        BOOST_TEST(e.pos_rms < 1e-10);
        BOOST_TEST(e.energy < 1e-12);
      } else {
        BOOST_TEST(e.pos_rms > 0.1);
      }
    }
  }
  BOOST_TEST(exact == 8);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace test_numerics
