// Q2: components, Block::make, the systems' compile-time requirements.
#include <stdexcept>

#include "helpers.hpp"

using namespace physics;

// A system only accepts entities that have the components it requires: this
// is checked at compile time, so the checks are static_asserts.
template <class S, class E>
concept can_register = requires(S s, E e) { s.register_entity(e); };
using OnlyPosition = Entity<component::position>;
using PositionVelocity = Entity<component::position, component::velocity>;
static_assert(!can_register<Move, OnlyPosition>, "Move must reject an entity without velocity");
static_assert(can_register<Move, PositionVelocity>);
static_assert(!can_register<Forces, PositionVelocity>, "Forces needs mass and sum_forces");
static_assert(!can_register<Collision, PositionVelocity>);
static_assert(can_register<Collision, Block::t>);
static_assert(can_register<Draw, Block::t>);

BOOST_AUTO_TEST_SUITE(q2_components)

BOOST_AUTO_TEST_CASE(component_defaults) {
  Components c;
  const EntityId e = c.create();
  BOOST_TEST((c.velocity[e] == Vector::zero()));
  BOOST_TEST((c.sum_forces[e] == Vector::zero()));
  BOOST_TEST(c.mass[e] == 0.0);
  BOOST_TEST(c.restitution[e] == 1.0);
}

BOOST_AUTO_TEST_CASE(block_make_sets_its_components) {
  World w;
  const auto b = Block::make(w, 12.5, 30, 40, 20, Color{255, 0, 0, 255}, 10.0);
  const Components& c = w.components;
  BOOST_TEST((c.position[b.id] == Vector{12.5, 30}));
  BOOST_TEST((c.box[b.id] == Rect{40, 20}));
  BOOST_TEST((c.color[b.id] == Color{255, 0, 0, 255}));
  BOOST_TEST(c.mass[b.id] == 10.0);
  BOOST_TEST((c.velocity[b.id] == Vector::zero()));
  BOOST_TEST((c.sum_forces[b.id] == Vector::zero()));
}

BOOST_AUTO_TEST_CASE(walls_have_an_infinite_mass) {
  // The sheet's Q2 ends: "modifier Game.init_walls pour créer des murs de masse infinie".
  World w;
  Game::init_walls(w);
  BOOST_TEST_REQUIRE(w.components.size() == 4u);
  for (EntityId e = 0; e < 4; ++e) BOOST_TEST((w.components.mass[e] == infinity));
}

BOOST_AUTO_TEST_CASE(block_make_registers_only_with_declared_systems) {
  World w(SystemSet{true, false, true, false});
  Block::make(w, 0, 0, 10, 10, test::grey, 1.0);
  BOOST_TEST(w.bodies(SystemId::draw).size() == 1u);
  BOOST_TEST(w.bodies(SystemId::move).size() == 1u);
  BOOST_TEST(!w.declares(SystemId::forces));
  BOOST_TEST(!w.declares(SystemId::collision));
}

// Block::make asserts its input (a programming error); bad input from a
// scene is rejected by the scene validator: see scene_validation/* in
// test_scene.cpp.
BOOST_AUTO_TEST_CASE(block_make_accepts_a_fixed_block) {
  World w;
  BOOST_CHECK_NO_THROW(Block::make(w, 0, 0, 10, 10, test::grey, infinity));
  BOOST_TEST(w.components.mass[0] == infinity);
}

BOOST_AUTO_TEST_CASE(world_rejects_bad_parameters) {
  BOOST_CHECK_THROW(World(SystemSet{}, Params{0.0}), std::invalid_argument);
  BOOST_CHECK_THROW(World(SystemSet{}, Params{-1.0}), std::invalid_argument);
  BOOST_CHECK_THROW(World(SystemSet{}, Params{std::nan("")}), std::invalid_argument);
  BOOST_CHECK_THROW(World(SystemSet{}, Params{course_dt, 0}), std::invalid_argument);
  // The same limits as the scene validator (engine/limits.hpp).
  BOOST_CHECK_THROW(World(SystemSet{}, Params{course_dt, max_substeps + 1}), std::invalid_argument);
  BOOST_CHECK_THROW(World(SystemSet{}, Params{max_dt * 2}), std::invalid_argument);
  BOOST_CHECK_THROW(World(SystemSet{}, Params{course_dt, 1, Vector{0, max_motion * 2}}), std::invalid_argument);
  BOOST_CHECK_NO_THROW(World(SystemSet{}, Params{max_dt, max_substeps, Vector{max_motion, -max_motion}}));
}

BOOST_AUTO_TEST_CASE(unregister_keeps_order) {
  std::vector<EntityId> list;  // a world's Move list (World::stage)
  Move m(list);
  m.register_entity(Block::t{3});
  m.register_entity(Block::t{5});
  m.register_entity(Block::t{7});
  m.unregister(5);
  BOOST_TEST_REQUIRE(m.size() == 2u);
  BOOST_TEST(m.entities()[0] == 3u);
  BOOST_TEST(m.entities()[1] == 7u);
  BOOST_TEST((list == std::vector<EntityId>{3, 7}));  // the system registers into the list it views
}

BOOST_AUTO_TEST_SUITE_END()
