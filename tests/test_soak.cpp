// Soak, the short version of `make soak`: 10^5 steps of the gas and stack
// scenes, checked every 10^4 steps.
#include "scene/builtin_scenes.hpp"
#include "helpers.hpp"
#include "app/soak.hpp"

// The file's own names, apart from the other test files' with which it is
// compiled (Makefile, TEST_UNITY).
namespace test_soak {

using namespace physics;

namespace {

SoakResult soak_scene(const char* name, std::int64_t steps, Solver solver = Solver::course) {
  SceneSpec spec = *find_builtin(name);
  spec.params.solver = solver;
  World w = make_world(spec, false, name);
  return soak(w, steps, 10'000, soak_limits(spec, w));
}

}  // namespace

BOOST_AUTO_TEST_SUITE(soak_runs)

BOOST_AUTO_TEST_CASE(gas_keeps_its_energy_and_its_bodies_for_1e5_steps) {
  const SoakResult r = soak_scene("gas", 100'000);
  BOOST_TEST(r.ok, r.failure);
  BOOST_TEST(r.checks == 10);
  BOOST_TEST(r.energy_max - r.energy_min <= 1e-9 * r.energy_start);
}

BOOST_AUTO_TEST_CASE(stack_stays_finite_inside_and_bounded_for_1e5_steps) {
  const SoakResult r = soak_scene("stack", 100'000);
  BOOST_TEST(r.ok, r.failure);
  BOOST_TEST(r.steps == 100'000);
}

BOOST_AUTO_TEST_CASE(stack_with_the_stable_solver_never_gains_energy_for_1e5_steps) {
  const SoakResult r = soak_scene("stack", 100'000, Solver::stable);
  BOOST_TEST(r.ok, r.failure);
  BOOST_TEST(r.energy_max <= r.energy_start + 1e-9 * std::abs(r.energy_start) + 15 * 0.001);
}

BOOST_AUTO_TEST_CASE(the_checks_catch_a_broken_state) {
  // The soak must be able to fail: a NaN, an escaped body, and energy pumped in.
  const SceneSpec& spec = *find_builtin("gas");
  {
    World w = make_world(spec, false, "gas");
    const SoakLimits lim = soak_limits(spec, w);
    w.components.velocity[10] = {std::nan(""), 0.0};
    const SoakResult r = soak(w, 10, 10, lim);
    BOOST_TEST(!r.ok);
    BOOST_TEST(r.failure.find("not finite") != std::string::npos);
  }
  {
    World w = make_world(spec, false, "gas");
    const SoakLimits lim = soak_limits(spec, w);
    w.components.position[10] = {-500.0, 100.0};
    const SoakResult r = soak(w, 1, 1, lim);
    BOOST_TEST(!r.ok);
    BOOST_TEST(r.failure.find("left the walls") != std::string::npos);
  }
  {
    World w = make_world(spec, false, "gas");
    const SoakLimits lim = soak_limits(spec, w);
    for (double& e : w.components.restitution) e = 1.01;  // every collision pumps energy in
    const SoakResult r = soak(w, 1000, 1, lim);
    BOOST_TEST(!r.ok);
    BOOST_TEST(r.failure.find("energy") != std::string::npos, r.failure);
  }
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace test_soak
