// Q3-Q5: Move, the red block, Forces.
#include "helpers.hpp"

using namespace physics;

BOOST_AUTO_TEST_SUITE(q3_move)

BOOST_AUTO_TEST_CASE(move_adds_dt_times_velocity) {
  World w = test::physics_world();
  const auto b = Block::make(w, 100, 100, 40, 40, test::grey, 10.0);
  w.components.velocity[b.id] = {0.25, -0.5};
  Systems(w).move->update(w.components, course_dt);
  BOOST_TEST(w.components.position[b.id].x == 100 + course_dt * 0.25);
  BOOST_TEST(w.components.position[b.id].y == 100 + course_dt * -0.5);
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(q4_red_block)

BOOST_AUTO_TEST_CASE(the_red_block_drifts_through_the_walls_without_collision) {
  // Q4: with Draw+Move only, the red block (mass 10, velocity (0.25, 0.25)) is
  // not stopped by the walls.
  World w(SystemSet{false, false, true, false});
  Game::init_walls(w);
  const auto red = Game::red_block_with_velocity(w);
  BOOST_TEST(w.components.mass[red.id] == 10.0);
  BOOST_TEST((w.components.color[red.id] == Game::red));
  BOOST_TEST((w.components.velocity[red.id] == Vector{0.25, 0.25}));
  BOOST_TEST(w.bodies(SystemId::move).size() == 5u);  // Block::make registers it with Move
  for (int i = 0; i < 600; ++i) Game::step(w);  // 10 s: 2500 px
  BOOST_TEST(w.components.position[red.id].x > 800.0);
  BOOST_TEST(w.components.position[red.id].y > 600.0);
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(q5_forces)

BOOST_AUTO_TEST_CASE(forces_adds_dt_times_force_over_mass_then_resets) {
  World w = test::physics_world();
  const auto b = Block::make(w, 100, 100, 40, 40, test::grey, 10.0);
  w.components.velocity[b.id] = {1.0, 2.0};
  w.components.sum_forces[b.id] = {0.25, -0.75};
  Systems(w).forces->update(w.components, course_dt);
  BOOST_TEST(w.components.velocity[b.id].x == 1.0 + course_dt * (0.25 / 10.0));
  BOOST_TEST(w.components.velocity[b.id].y == 2.0 + course_dt * (-0.75 / 10.0));
  BOOST_TEST((w.components.sum_forces[b.id] == Vector::zero()));
  // Reset: a second update changes nothing.
  const Vector v = w.components.velocity[b.id];
  Systems(w).forces->update(w.components, course_dt);
  BOOST_TEST((w.components.velocity[b.id] == v));
}

BOOST_AUTO_TEST_CASE(infinite_mass_is_untouched) {
  World w = test::physics_world();
  const auto wall = Block::make(w, 0, 0, 40, 40, test::grey, infinity);
  w.components.sum_forces[wall.id] = {3.0, 4.0};
  Systems(w).forces->update(w.components, course_dt, Vector{0, 0.01});
  BOOST_TEST((w.components.velocity[wall.id] == Vector::zero()));
}

BOOST_AUTO_TEST_CASE(an_initial_force_gives_a_constant_velocity) {
  // Q5: force (0.25, 0.25) on the red block: one velocity change, then uniform motion.
  World w(SystemSet{false, true, true, false});
  const auto red = Block::make(w, 100, 100, 40, 40, Color{255, 0, 0, 255}, 10.0);
  w.components.sum_forces[red.id] = {0.25, 0.25};
  Game::step(w);
  const Vector v1 = w.components.velocity[red.id];
  BOOST_TEST(v1.x == course_dt * 0.025);
  const Vector p1 = w.components.position[red.id];
  for (int i = 0; i < 10; ++i) Game::step(w);
  BOOST_TEST((w.components.velocity[red.id] == v1));
  BOOST_TEST(w.components.position[red.id].x > p1.x + 9 * course_dt * v1.x);
}

BOOST_AUTO_TEST_CASE(the_red_block_set_going_by_a_force_moves_as_with_the_velocity) {
  // Q5: Game::red_block_with_force applies (0.25, 0.25) instead of the velocity.
  World w(SystemSet{false, true, true, false});
  const auto red = Game::red_block_with_force(w);
  BOOST_TEST((w.components.velocity[red.id] == Vector::zero()));
  BOOST_TEST((w.components.sum_forces[red.id] == Vector{0.25, 0.25}));
  Game::step(w);
  BOOST_TEST((w.components.velocity[red.id] == Vector{course_dt * 0.025, course_dt * 0.025}));
}

BOOST_AUTO_TEST_CASE(gravity_is_an_acceleration_on_finite_masses) {
  World w = test::physics_world(Params{course_dt, 1, {0.0, 0.001}});
  const auto light = Block::make(w, 100, 100, 10, 10, test::grey, 1.0);
  const auto heavy = Block::make(w, 300, 100, 10, 10, test::grey, 1000.0);
  Game::step(w);
  BOOST_TEST(w.components.velocity[light.id].y == course_dt * 0.001);
  BOOST_TEST(w.components.velocity[heavy.id].y == course_dt * 0.001);
}

BOOST_AUTO_TEST_SUITE_END()
