// Q1: init_walls.
#include "course/game.hpp"
#include "helpers.hpp"

using namespace physics;

BOOST_AUTO_TEST_SUITE(q1_init_walls)

BOOST_AUTO_TEST_CASE(four_walls_with_the_sheets_geometry_and_colours) {
  World w;
  Game::init_walls(w);
  const Components& c = w.components;
  BOOST_TEST_REQUIRE(c.size() == 4u);
  int horizontal = 0, vertical = 0;
  for (EntityId e = 0; e < 4; ++e) {
    const Rect r = c.box[e];
    BOOST_TEST(std::min(r.width, r.height) == Game::wall_thickness);
    if (r.width > r.height) {  // horizontal: blue, full width
      ++horizontal;
      BOOST_TEST((c.color[e] == Game::wall_blue));
      BOOST_TEST(r.width == Game::width);
      BOOST_TEST(c.position[e].x == 0.0);
      BOOST_TEST((c.position[e].y == 0.0 || c.position[e].y == Game::height - 40.0));
    } else {  // vertical: black, the whole height left between the other two
      ++vertical;
      BOOST_TEST((c.color[e] == Game::wall_black));
      BOOST_TEST(r.height == Game::height - 80);
      BOOST_TEST(c.position[e].y == 40.0);
      BOOST_TEST((c.position[e].x == 0.0 || c.position[e].x == Game::width - 40.0));
    }
    // Inside the window.
    BOOST_TEST(c.position[e].x >= 0.0);
    BOOST_TEST(c.position[e].y >= 0.0);
    BOOST_TEST(c.position[e].x + r.width <= Game::width);
    BOOST_TEST(c.position[e].y + r.height <= Game::height);
  }
  BOOST_TEST(horizontal == 2);
  BOOST_TEST(vertical == 2);
}

BOOST_AUTO_TEST_CASE(walls_do_not_overlap_and_close_the_screen) {
  World w;
  Game::init_walls(w);
  BOOST_TEST_REQUIRE(w.components.size() == 4u);
  for (EntityId a = 0; a < 4; ++a)
    for (EntityId b = a + 1; b < 4; ++b) BOOST_TEST(!test::overlaps(w.components, a, b));
  // Total wall area = screen area minus the inside: the four cover the border exactly.
  double area = 0;
  for (EntityId e = 0; e < 4; ++e) area += double(w.components.box[e].width) * w.components.box[e].height;
  BOOST_TEST(area == double(Game::width) * Game::height - double(Game::width - 80) * (Game::height - 80));
}

BOOST_AUTO_TEST_CASE(walls_are_registered_with_every_declared_system) {
  World w;
  Game::init_walls(w);
  BOOST_TEST(w.bodies(SystemId::draw).size() == 4u);
  BOOST_TEST(w.bodies(SystemId::move).size() == 4u);
  BOOST_TEST(w.bodies(SystemId::forces).size() == 4u);
  BOOST_TEST(w.bodies(SystemId::collision).size() == 4u);
}

BOOST_AUTO_TEST_CASE(walls_never_move_under_collision_or_forces) {
  World w = test::physics_world();
  Game::init_walls(w);
  for (EntityId e = 0; e < 4; ++e) w.components.sum_forces[e] = {5.0, 5.0};
  const auto before = w.components.position;
  for (int i = 0; i < 10; ++i) Game::step(w);
  BOOST_TEST((w.components.position == before));
  for (EntityId e = 0; e < 4; ++e) BOOST_TEST((w.components.velocity[e] == Vector::zero()));
}

BOOST_AUTO_TEST_SUITE_END()
