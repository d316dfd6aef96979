// --course: the sheet's scenes built by the course's own functions
// (app/course_world.cpp) are the worlds their descriptions make (the scene
// module, through the public API), to the bit, and stay so when stepped.
#include "app/course_world.hpp"
#include "course/game.hpp"
#include "helpers.hpp"
#include "scene/builtin_scenes.hpp"

// The file's own names, apart from the other test files' with which it is
// compiled (Makefile, TEST_UNITY).
namespace test_course_world {

using namespace physics;

namespace {

// Every component, contact rule, stage list and health watch of the two.
void expect_same(const World& a, const World& b, const std::string& what) {
  const Components &x = a.components, &y = b.components;
  BOOST_TEST_REQUIRE(x.size() == y.size(), what);
  BOOST_TEST((x.position == y.position), what);
  BOOST_TEST((x.box == y.box), what);
  BOOST_TEST((x.color == y.color), what);
  BOOST_TEST((x.mass == y.mass), what);
  BOOST_TEST((x.velocity == y.velocity), what);
  BOOST_TEST((x.sum_forces == y.sum_forces), what);
  BOOST_TEST((x.restitution == y.restitution), what);
  BOOST_TEST((x.friction == y.friction), what);
  for (EntityId e = 0; e < x.size(); ++e) BOOST_TEST((x.rules(e) == y.rules(e)), what << " body " << e);
  for (const SystemId s : {SystemId::draw, SystemId::forces, SystemId::move, SystemId::collision}) {
    BOOST_TEST(a.declares(s) == b.declares(s), what);
    if (a.declares(s) && b.declares(s)) BOOST_TEST((*a.stage(s) == *b.stage(s)), what);
  }
  BOOST_TEST(a.health.first_body == b.health.first_body, what);
  BOOST_TEST((a.health.x0 == b.health.x0 && a.health.y0 == b.health.y0 && a.health.x1 == b.health.x1 &&
              a.health.y1 == b.health.y1),
             what);
}

void expect_course_builds(const SceneSpec& s, const std::string& what) {
  const std::vector<Body> bodies = expand(s, what);
  World course = CourseWorld::make(s, bodies, true), scene = make_world(s, bodies, true);
  expect_same(course, scene, what + " at the start");
  for (int i = 0; i < 300; ++i) Game::step(course), Game::step(scene);
  expect_same(course, scene, what + " after 300 frames");
}

}  // namespace

BOOST_AUTO_TEST_SUITE(course_world)

BOOST_AUTO_TEST_CASE(the_course_builds_each_sheet_scene_as_its_description_does) {
  BOOST_TEST(CourseWorld::scenes().size() == 5u);
  for (const std::string_view name : CourseWorld::scenes()) {
    const SceneSpec* s = find_builtin(name);
    BOOST_TEST_REQUIRE(s != nullptr, name);
    BOOST_TEST(s->walls, name);
    expect_course_builds(*s, std::string(name));
  }
}

BOOST_AUTO_TEST_CASE(the_overrides_it_takes_reach_both_builds) {
  // The seed of many's squares, the walls' size and restitution (the scene's
  // wall_defs against the sheet's Game::init_walls), the world's parameters.
  SceneSpec many = *find_builtin("many");
  Overrides o;
  o.seed = 7;
  apply(many, o);
  many.params.gravity = {0.0, 0.001};
  expect_course_builds(many, "many, seed 7, gravity");
  SceneSpec walls = *find_builtin("walls");
  walls.width = 1000, walls.height = 700, walls.restitution = 0.3;
  expect_course_builds(walls, "walls of 1000x700, e = 0.3");
  SceneSpec bounce = *find_builtin("bounce");
  bounce.width = 900, bounce.height = 500;
  bounce.params.substeps = 3;
  expect_course_builds(bounce, "bounce in 900x500, 3 substeps");
}

BOOST_AUTO_TEST_CASE(another_scene_is_built_from_its_description) {
  BOOST_TEST(!CourseWorld::builds("cradle"));
  const SceneSpec& s = *find_builtin("cradle");
  const std::vector<Body> bodies = expand(s, "cradle");
  expect_same(CourseWorld::make(s, bodies, false), make_world(s, bodies, false), "cradle");
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace test_course_world
