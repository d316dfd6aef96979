// The auto mode (--solver auto, engine/auto_mode.hpp): what it chooses and
// what that costs. Its pass/fail on every stiff and extreme case is in the
// stability matrix's auto column (tests/test_stability.cpp). Here:
//  - the cost rule on the cheap cases, where the course's pass passes: auto
//    must then be the course's pass and nothing more (no solver substep, no
//    swept body), which the results show bit for bit. Its only extra work is
//    its O(n) look at the bodies (untimed, see World::auto_before_move); wall times are measured
//    by `make stability`, not here;
//  - a pile takes the stable solver and gives its results bit for bit;
//  - only fast bodies are swept.
#include <functional>

#include "helpers.hpp"
#include "app/headless.hpp"
#include "course/utils/random.hpp"
#include "numerics/family.hpp"
#include "numerics/scenes.hpp"
#include "numerics/stability.hpp"

// The file's own names, apart from the other test files' with which it is
// compiled (Makefile, TEST_UNITY).
namespace test_auto {

using namespace physics;
using namespace physics::numerics;

namespace {

const Mode course_mode{"course", 1, false, Solver::course, 8};
const Mode automatic_mode{"auto", 1, false, Solver::automatic, 8};
const Mode stable_mode{"stable", 1, false, Solver::stable, 8};

bool same_state(const World& a, const World& b) {
  const Components &x = a.components, &y = b.components;
  if (x.size() != y.size()) return false;
  for (std::size_t e = 0; e < x.size(); ++e)
    if (x.position[e] != y.position[e] || x.velocity[e] != y.velocity[e]) return false;
  return true;
}

// The same scene built in two modes, run for `frames` frames.
std::pair<World, World> run_both(const Mode& a, const Mode& b, Vector gravity,
                                 const std::function<void(World&)>& build, int frames) {
  World wa = make_world(a, gravity), wb = make_world(b, gravity);
  build(wa);
  build(wb);
  for (int f = 0; f < frames; ++f) Game::step(wa), Game::step(wb);
  return {std::move(wa), std::move(wb)};
}

struct CheapCase {
  const char* name;
  std::function<void(World&)> build;
  int frames;
};

// The matrix's cases where the course passes (tools/numerics/stability.cpp),
// built the same way, and the sheet's question-9 scene.
std::vector<CheapCase> cheap_cases() {
  std::vector<CheapCase> out;
  for (const double ratio : {1e3, 1e12})
    out.push_back({"heavy hits light", [ratio](World& w) {
                     block(w, 100, 100, 40, 40, ratio, {0.5, 0});
                     block(w, 300, 110, 20, 20, 1.0);
                   }, 120});
  out.push_back({"25 % overlap", [](World& w) {
                   walls(w);
                   block(w, 380, 280, 40, 40, 1.0);
                   block(w, 410, 280, 40, 40, 1.0);
                 }, 30});
  out.push_back({"two co-located blocks", [](World& w) {
                   walls(w);
                   block(w, 380, 280, 40, 40, 1.0);
                   block(w, 380, 280, 40, 40, 1.0);
                 }, 30});
  out.push_back({"corner hits", [](World& w) {
                   walls(w);
                   const double v = 0.6, step = v * w.params.dt;
                   block(w, 720 - step + 5, 520 - step + 5, 40, 40, 1.0, {v, v});
                   block(w, 100, 100, 40, 40, 2.0, {0.3, 0.3});
                   block(w, 150, 150, 40, 40, 2.0, {-0.3, -0.3});
                 }, 600});
  out.push_back({"question 9, 1e7 px away", [](World& w) {
                   Game::init_scene(w);
                   for (auto& p : w.components.position) p = p + Vector{1e7, 1e7};
                 }, 3000});
  return out;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(auto_mode)

BOOST_AUTO_TEST_CASE(where_the_course_passes_auto_is_the_course_pass_bit_for_bit) {
  for (const CheapCase& c : cheap_cases()) {
    auto [course, automatic] = run_both(course_mode, automatic_mode, {}, c.build, c.frames);
    const AutoStats& s = automatic.automatic.stats;
    BOOST_TEST_INFO(c.name);
    BOOST_TEST(same_state(course, automatic));
    BOOST_TEST(s.solver_substeps == 0);
    BOOST_TEST(s.swept == 0);
    BOOST_TEST(s.course_substeps == c.frames);
  }
}

BOOST_AUTO_TEST_CASE(a_resting_stack_takes_the_stable_solver_bit_for_bit) {
  const auto build = [](World& w) {
    walls(w);
    for (int k = 0; k < 8; ++k) block(w, 390, 560.0 - 20 * (k + 1), 20, 20, 1.0, {}, 0.0);
  };
  auto [stable, automatic] = run_both(stable_mode, automatic_mode, {0, 0.001}, build, 600);
  BOOST_TEST(same_state(stable, automatic));
  BOOST_TEST(automatic.automatic.stats.solver_substeps == 600);
  BOOST_TEST(automatic.automatic.stats.course_substeps == 0);
}

BOOST_AUTO_TEST_CASE(a_pile_switches_to_the_solver_and_back_once_it_is_gone) {
  // No gravity: two blocks pushed against each other by a third pass, then
  // fly apart. The pressed pair switches auto to the solver; the solver is
  // held a while, then the course's pass resumes.
  World w = make_world(automatic_mode);
  walls(w);
  const EntityId a = block(w, 100, 280, 40, 40, 1e6, {0.1, 0});
  block(w, 200, 290, 20, 20, 1.0);
  block(w, 300, 280, 40, 40, 1e6, {-0.1, 0});
  for (int f = 0; f < 600; ++f) Game::step(w);
  const AutoStats& s = w.automatic.stats;
  BOOST_TEST(s.solver_substeps > 0);
  BOOST_TEST(s.course_substeps > 0);
  BOOST_TEST(w.components.velocity[a].x < 0.0);  // the heavy ones bounced apart
}

BOOST_AUTO_TEST_CASE(only_fast_bodies_are_swept_and_none_tunnels) {
  World w = make_world(automatic_mode);
  walls(w);
  for (int i = 0; i < 20; ++i) block(w, 100 + 30 * i, 100, 10, 10, 1.0, {0.01, 0.02});  // 0.37 px per frame
  const EntityId bullet = block(w, 400, 400, 4, 4, 1.0, {300.0, 0});   // 5000 px per frame
  for (int f = 0; f < 120; ++f) {
    Game::step(w);
    const Vector p = w.components.position[bullet];
    BOOST_TEST_REQUIRE((p.x > 40 && p.x < 756));  // inside the walls at every frame
  }
  BOOST_TEST(w.automatic.stats.swept == 120);  // the bullet, every substep; the slow ones never
  BOOST_TEST(w.ccd.stats.impacts > 120);        // several wall hits per frame, each swept
}

BOOST_AUTO_TEST_CASE(the_headless_summary_says_what_auto_used) {
  // One block on the floor: the first substep looks with the solver, finds
  // no pile, and the course's pass does the rest. Two stacked: a pile.
  World one = make_world(automatic_mode, {0, 0.001});
  walls(one);
  block(one, 390, 540, 20, 20, 1.0, {}, 0.0);
  Headless::run(one, 10);
  BOOST_TEST(Headless::auto_line(one) ==
             "course pass 9 substeps, stable solver 1 substeps (1 contacts iterated), CCD swept 0 bodies");
  World two = make_world(automatic_mode, {0, 0.001});
  walls(two);
  block(two, 390, 540, 20, 20, 1.0, {}, 0.0);
  block(two, 390, 520, 20, 20, 1.0, {}, 0.0);
  Headless::run(two, 10);
  BOOST_TEST(Headless::auto_line(two) ==
             "course pass 0 substeps, stable solver 10 substeps (20 contacts iterated), CCD swept 0 bodies");
}


// Closing speeds decide what is swept (the report): two 10 px blocks
// head on at 0.6 px/ms each (10 px a frame each, within their reach) close
// 20 px a frame, and the course's pass let them through each other.
BOOST_AUTO_TEST_CASE(bodies_closing_faster_than_their_reach_are_swept) {
  for (const double gap : {183.0, 185.0, 187.0}) {
    World w = make_world(automatic_mode);
    walls(w);
    const EntityId a = block(w, 300, 300, 10, 10, 1.0, {0.6, 0});
    const EntityId b = block(w, 310 + gap, 300, 10, 10, 1.0, {-0.6, 0});
    for (int f = 0; f < 600; ++f) {
      Game::step(w);
      BOOST_TEST_REQUIRE(w.components.position[a].x < w.components.position[b].x, "gap " << gap << ", frame " << f);
    }
    BOOST_TEST(w.automatic.stats.swept > 0);
  }
}

// A row of 30 blocks at +-0.55 px/ms, e = 1: in one dimension the order never
// changes (it did 8 545 times over 600 frames) and the energy is kept.
BOOST_AUTO_TEST_CASE(a_row_closing_in_keeps_its_order_and_energy) {
  World w = make_world(automatic_mode);
  walls(w);
  Random rng(1);
  std::vector<EntityId> row;
  for (int i = 0; i < 30; ++i) row.push_back(block(w, 50 + 23.0 * i, 300, 10, 10, 1.0, {rng.uniform(0, 1) < 0.5 ? 0.55 : -0.55, 0}));
  const double e0 = w.kinetic_energy();
  for (int f = 0; f < 600; ++f) {
    Game::step(w);
    for (std::size_t i = 1; i < row.size(); ++i)
      BOOST_TEST_REQUIRE(w.components.position[row[i - 1]].x < w.components.position[row[i]].x, "frame " << f);
  }
  BOOST_TEST(std::abs(w.kinetic_energy() - e0) < 1e-9 * e0);
}

// 200 blocks of 8 px at up to 2 px/ms in the walls, restitution e, under auto.
static World fast_gas(double e) {
  World w = make_world(automatic_mode);
  walls(w);
  Random rng(2);
  for (int i = 0; i < 200; ++i)
    block(w, 60 + 34.0 * (i % 20) + rng.uniform(0, 20), 60 + 48.0 * (i / 20) + rng.uniform(0, 30), 8, 8,
          rng.uniform(1, 3), {rng.uniform(-2, 2), rng.uniform(-2, 2)}, e);
  return w;
}

// A fast elastic gas: 200 blocks of 8 px at up to 2 px/ms, e = 1. On the
// solver's path it lost 60 % of its energy in 3000 frames (every body with two
// contacts in a substep had them solved together) and let bodies out through
// the walls; undoing such chains (roll_back) still lost 0.4 % in the family's
// gas draws. Elastic without gravity, auto's path is now ccd's: the course's
// pass with every body swept, no solver substep.
BOOST_AUTO_TEST_CASE(a_fast_elastic_gas_keeps_its_energy_and_its_walls) {
  World w = fast_gas(1.0);
  const double e0 = w.kinetic_energy();
  for (int f = 0; f < 600; ++f) Game::step(w);
  BOOST_TEST(std::abs(w.kinetic_energy() - e0) < 1e-9 * e0);
  BOOST_TEST(w.health.escaped == 0);
  BOOST_TEST(w.automatic.stats.solver_substeps == 0);
}

// The same gas with e = 0.9 takes the solver's path on trial: a substep's
// chains of impacts (a body with a bounce and another contact) are undone
// and swept, so no body leaves through the walls and the energy never grows.
BOOST_AUTO_TEST_CASE(a_fast_inelastic_gas_has_its_chains_undone_and_swept) {
  World w = fast_gas(0.9);
  double energy = w.kinetic_energy();
  for (int f = 0; f < 600; ++f) {
    Game::step(w);
    BOOST_TEST_REQUIRE(w.kinetic_energy() <= energy * (1 + 1e-12), "frame " << f);
    energy = w.kinetic_energy();
  }
  BOOST_TEST(w.health.escaped == 0);
  BOOST_TEST(w.automatic.stats.undone > 0);
}

// A light block squeezed between two heavy ones 4e11 times heavier needs
// about π·sqrt(4e11), two million, impacts: CCD runs out of budget and can
// only stop the bodies, losing their time. After one such substep auto
// hands the scene to the solver (AutoMode::after_sweep), which takes the
// jam whole: one capped substep in 120 frames (three before), the order and
// the momentum kept.
BOOST_AUTO_TEST_CASE(a_jam_goes_to_the_solver_after_one_capped_substep) {
  World w = make_world(automatic_mode);
  walls(w);
  const EntityId a = block(w, 100, 284, 32, 32, 4e11, {0.229, 0}, 0.0);
  const EntityId light = block(w, 182, 298, 3, 3, 1.0, {}, 0.0);
  const EntityId b = block(w, 313, 284, 32, 32, 4e11, {-0.284, 0}, 0.0);
  const Vector p0 = w.momentum();
  bool ordered = true;
  for (int f = 0; f < 120; ++f) {
    Game::step(w);
    const auto& x = w.components.position;
    ordered = ordered && x[a].x < x[light].x && x[light].x < x[b].x;
  }
  BOOST_TEST(ordered);
  BOOST_TEST(w.ccd.stats.capped_substeps == 1);
  BOOST_TEST(std::abs(w.momentum().x - p0.x) < 1e-9 * 4e11 * 0.5);
}

// Under gravity with every restitution 1, auto's solver path is
// stable+ccd's (AutoMode::sweep_all): a pile of light and heavy e = 1 blocks
// falling into the box keeps its step energy and nothing sinks or leaves.
// With the solver taking each substep's impacts together, the family's e = 1
// piles sank 2-10 px and threw light bodies out through the walls. With one
// block of e = 0.5 in the scene, the solver's path is the one it was.
BOOST_AUTO_TEST_CASE(an_elastic_pile_under_gravity_is_swept_whole) {
  const auto build = [](World& w, double last_e) {
    walls(w);
    Random rng(5);
    for (int i = 0; i < 60; ++i)
      block(w, 60 + 34.0 * (i % 20), 300 - 40.0 * (i / 20), 5 + (i * 7) % 25, 5 + (i * 11) % 25,
            i % 3 == 0 ? 500.0 : 1.0, {rng.uniform(-0.2, 0.2), 0}, i == 59 ? last_e : 1.0);
  };
  World w = make_world(automatic_mode, {0, 0.002});
  build(w, 1.0);
  const double e0 = step_energy(w);
  double worst_overlap = 0, most = e0;
  for (int f = 0; f < 900; ++f) {
    Game::step(w);
    BOOST_TEST_REQUIRE(w.automatic.sweep_all());
    most = std::max(most, step_energy(w));
    if (f >= 800) worst_overlap = std::max(worst_overlap, max_overlap(w));
  }
  BOOST_TEST(most - e0 < 1e-9 * criteria::energy_in_play(w));
  BOOST_TEST(worst_overlap < 1.0);
  BOOST_TEST(w.health.escaped == 0);
  World mixed = make_world(automatic_mode, {0, 0.002});
  build(mixed, 0.5);
  Game::step(mixed);
  BOOST_TEST(mixed.automatic.solver_path());
  BOOST_TEST(!mixed.automatic.sweep_all());
}

// A heavy block driving a light one into a wall without gravity: the course's
// pass takes (wall, light) and (light, pusher) one after the other and
// shares each correction by the bodies' speeds, so the fast light block took
// most of the pusher's and was left in the wall, 1.3-3.3 px deep by the time
// the pair had been pressed three substeps in a row (the family's
// push-into-wall, floating: seeds 23 and 18 here, towards each of the four
// walls, the pusher registered first on two of them). Auto now takes the
// solver once the pusher will close the light block's room to the wall
// within a substep (AutoMode::count_squeezed).
BOOST_AUTO_TEST_CASE(a_block_pushed_into_a_wall_without_gravity_stays_out_of_it) {
  struct Draw {
    double ratio, v, e, gap_wall, gap;
    int pusher, light;
  };
  for (const Draw d : {Draw{5.25e8, 0.412, 0.388, 41.2, 121, 35, 16}, Draw{14.6, 0.295, 0.566, 3.62, 164, 30, 26}})
    for (int side = 0; side < 4; ++side) {  // towards +x, -x, +y, -y
      World w = make_world(automatic_mode);
      walls(w);
      const bool x = side < 2, up = side % 2 == 0;
      const double face = up ? (x ? 760 : 560) : 40;  // the wall's face the light block is driven onto
      const double l = up ? face - d.light - d.gap_wall : face + d.gap_wall;
      const double p = up ? l - d.gap - d.pusher : l + d.light + d.gap;
      const auto make = [&](double at, int size, double mass, double v) {
        const double across = (x ? 300 : 400) - size / 2.0;
        const Vector vel = x ? Vector{up ? v : -v, 0} : Vector{0, up ? v : -v};
        return x ? block(w, at, across, size, size, mass, vel, d.e) : block(w, across, at, size, size, mass, vel, d.e);
      };
      if (!up) make(p, d.pusher, d.ratio, d.v);  // registered first: the pass takes (pusher, light) first
      const EntityId light = make(l, d.light, 1.0, 0.0);
      if (up) make(p, d.pusher, d.ratio, d.v);
      double deepest = 0, overlap = 0;
      for (int f = 0; f < 240; ++f) {
        Game::step(w);
        const double lo = x ? w.components.position[light].x : w.components.position[light].y;
        deepest = std::max(deepest, up ? lo + d.light - face : face - lo);
        overlap = std::max(overlap, max_overlap(w));
      }
      BOOST_TEST_INFO("mass " << d.ratio << ", towards side " << side);
      BOOST_TEST(deepest < 1.0);
      BOOST_TEST(overlap < 1.0);
      BOOST_TEST(w.automatic.stats.solver_substeps > 0);
    }
}

// Rounds after a turn start from where impact_time put each impacted body:
// the start of its new line, behind the face it bounced off. A 13 px block
// falling 42 px a substep that bounced at 12 of 16.7 ms lay 26 px into the
// floor there, and that round's contact, taking the shortest way out, sent
// it on down through the floor (the family's pile seeds 30 and 36: two and
// three blocks out). Auto's solver now takes such a pair's axis where the
// bodies really are (SolverSettings::physical_axes).
BOOST_AUTO_TEST_CASE(a_block_bouncing_late_in_a_substep_is_not_sent_through_the_floor) {
  const Family* pile = find_family("pile");
  BOOST_TEST_REQUIRE(pile != nullptr);
  for (const std::uint64_t seed : {30, 36}) {
    const Outcome o = pile->draw(seed).run(automatic_mode);
    BOOST_TEST(o.pass, "pile seed " << seed << ": " << o.figure);
  }
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace test_auto
