// Q8: the Collision system (the sheet's detailed algorithm).
#include "course/game.hpp"
#include "helpers.hpp"

using namespace physics;

namespace {

struct TwoBodies {
  World w = test::physics_world();
  EntityId c, b;
  TwoBodies(Vector pc, Rect rc, double mc, Vector vc, Vector pb, Rect rb, double mb, Vector vb) {
    c = Block::make(w, pc.x, pc.y, rc.width, rc.height, test::grey, mc).id;
    b = Block::make(w, pb.x, pb.y, rb.width, rb.height, test::grey, mb).id;
    w.components.velocity[c] = vc;
    w.components.velocity[b] = vb;
  }
  Components& k() { return w.components; }
};

double normal_speed(const Components& k, EntityId e, Vector n) { return Vector::dot(k.velocity[e], n); }

}  // namespace

BOOST_AUTO_TEST_SUITE(q8_collision)

BOOST_AUTO_TEST_CASE(penetration_is_the_shortest_of_the_four_vectors) {
  // s = (-10, -30) 60x60: candidates (-10,0), (50,0), (0,-30), (0,30).
  BOOST_TEST((Collision::penetration({-10, -30}, {60, 60}) == Vector{-10, 0}));
  BOOST_TEST((Collision::penetration({-50, -30}, {60, 60}) == Vector{10, 0}));
  BOOST_TEST((Collision::penetration({-30, -5}, {60, 60}) == Vector{0, -5}));
  BOOST_TEST((Collision::penetration({-30, -58}, {60, 60}) == Vector{0, 2}));
}

BOOST_AUTO_TEST_CASE(equal_masses_head_on_exchange_velocities) {
  TwoBodies p({100, 100}, {40, 40}, 5.0, {0.5, 0}, {139, 100}, {40, 40}, 5.0, {-0.25, 0});
  BOOST_TEST_REQUIRE(Collision::resolve(p.k(), p.c, p.b));
  BOOST_TEST((p.k().velocity[p.c] == Vector{-0.25, 0}));
  BOOST_TEST((p.k().velocity[p.b] == Vector{0.5, 0}));
}

BOOST_AUTO_TEST_CASE(a_block_hitting_a_wall_reverses_its_normal_velocity_exactly) {
  for (const double m : {1.0, 3.0, 7.3, 1e9}) {
    World w = test::physics_world();
    Game::init_walls(w);
    const auto b = Block::make(w, 725, 300, 40, 40, test::grey, m);  // 5 px into the right wall
    BOOST_TEST_REQUIRE(b.id == 4u);  // after the four walls
    w.components.velocity[b.id] = {0.3, 0.7};
    test::collide(w);
    BOOST_TEST(w.components.velocity[b.id].x == -0.3);
    BOOST_TEST(w.components.velocity[b.id].y == 0.7);
    BOOST_TEST(w.components.position[b.id].x == 720.0);  // the wall did not move; the block did, fully
    BOOST_TEST(w.components.position[3].x == 760.0);
  }
}

BOOST_AUTO_TEST_CASE(momentum_and_energy_conserved_at_e_1_energy_lost_below) {
  for (const double e : {1.0, 0.75, 0.5, 0.0}) {
    TwoBodies p({100, 100}, {40, 30}, 3.0, {0.7, 0.2}, {135, 110}, {20, 50}, 11.0, {-0.1, -0.4});
    p.k().restitution[p.c] = p.k().restitution[p.b] = e;
    const auto momentum = [&] { return 3.0 * p.k().velocity[p.c] + 11.0 * p.k().velocity[p.b]; };
    const auto energy = [&] {
      return 0.5 * 3.0 * Vector::dot(p.k().velocity[p.c], p.k().velocity[p.c]) +
             0.5 * 11.0 * Vector::dot(p.k().velocity[p.b], p.k().velocity[p.b]);
    };
    const Vector p0 = momentum();
    const double e0 = energy();
    BOOST_TEST_REQUIRE(Collision::resolve(p.k(), p.c, p.b));
    const Vector p1 = momentum();
    BOOST_TEST(std::abs(p1.x - p0.x) < 1e-14);
    BOOST_TEST(std::abs(p1.y - p0.y) < 1e-14);
    if (e == 1.0)
      BOOST_TEST(std::abs(energy() - e0) < 1e-14 * e0);
    else
      BOOST_TEST(energy() < e0 * (1 - 1e-3));
  }
}

BOOST_AUTO_TEST_CASE(e_0_leaves_equal_normal_velocities) {
  TwoBodies p({100, 100}, {40, 40}, 2.0, {0.6, 0.1}, {138, 120}, {40, 40}, 9.0, {-0.2, 0.3});
  p.k().restitution[p.c] = 0.0;
  Contact contact;
  BOOST_TEST_REQUIRE(Collision::resolve(p.k(), p.c, p.b, &contact));
  const Vector n = contact.normal;
  BOOST_TEST((n == Vector{-1, 0}));
  BOOST_TEST(std::abs(normal_speed(p.k(), p.c, n) - normal_speed(p.k(), p.b, n)) < 1e-15);
  // Tangential velocities are untouched.
  BOOST_TEST(p.k().velocity[p.c].y == 0.1);
  BOOST_TEST(p.k().velocity[p.b].y == 0.3);
}

BOOST_AUTO_TEST_CASE(restitution_of_a_pair_is_the_smaller_one) {
  World w = test::physics_world();
  Game::init_walls(w);
  const auto b = Block::make(w, 725, 300, 40, 40, test::grey, 2.0, 0.5);
  w.components.velocity[b.id] = {0.5, 0};
  test::collide(w);
  BOOST_TEST(w.components.velocity[b.id].x == -0.25);  // -e·v with e = min(0.5, 1)
}

BOOST_AUTO_TEST_CASE(a_block_pressed_between_two_others_gets_both_impulses_once) {
  // A -> B <- C, equal masses, B touching both in the same frame. Sequential
  // resolution on current velocities: A|B exchange (A 0, B +1), then B|C
  // exchange (B -1, C +1). Summing both impulses computed from the initial
  // velocities instead would stop all three and lose all the energy.
  World w = test::physics_world();
  const auto a = Block::make(w, 100, 100, 40, 40, test::grey, 1.0);
  const auto b = Block::make(w, 139, 100, 40, 40, test::grey, 1.0);
  const auto c = Block::make(w, 178, 100, 40, 40, test::grey, 1.0);
  w.components.velocity[a.id] = {1.0, 0};
  w.components.velocity[c.id] = {-1.0, 0};
  test::collide(w);
  BOOST_TEST(w.pass.contact_count == 2u);
  BOOST_TEST(w.components.velocity[a.id].x == 0.0);
  BOOST_TEST(w.components.velocity[b.id].x == -1.0);
  BOOST_TEST(w.components.velocity[c.id].x == 1.0);
  BOOST_TEST(w.kinetic_energy() == 1.0);
}

BOOST_AUTO_TEST_CASE(position_correction_leaves_no_overlap) {
  // Moving pairs share the correction by speed; a wall takes none of it.
  TwoBodies moving({100, 100}, {40, 40}, 1.0, {0.5, 0}, {130, 90}, {40, 40}, 4.0, {-0.5, 0});
  BOOST_TEST_REQUIRE(Collision::resolve(moving.k(), moving.c, moving.b));
  BOOST_TEST(!test::overlaps(moving.k(), moving.c, moving.b));
  BOOST_TEST(moving.k().position[moving.c].x == 95.0);   // half of the 10 px
  BOOST_TEST(moving.k().position[moving.b].x == 135.0);

  TwoBodies slow_fast({100, 100}, {40, 40}, 1.0, {0.75, 0}, {132, 100}, {40, 40}, 1.0, {-0.25, 0});
  BOOST_TEST_REQUIRE(Collision::resolve(slow_fast.k(), slow_fast.c, slow_fast.b));
  BOOST_TEST(!test::overlaps(slow_fast.k(), slow_fast.c, slow_fast.b));
  BOOST_TEST(slow_fast.k().position[slow_fast.c].x == 94.0);  // N_c = 3/4 of 8 px
  BOOST_TEST(slow_fast.k().position[slow_fast.b].x == 134.0);
}

BOOST_AUTO_TEST_CASE(both_at_rest_the_heavier_ejects_the_lighter) {
  TwoBodies heavy_c({100, 100}, {40, 40}, 10.0, {}, {130, 100}, {40, 40}, 1.0, {});
  Collision::resolve(heavy_c.k(), heavy_c.c, heavy_c.b);
  BOOST_TEST(heavy_c.k().position[heavy_c.c].x == 100.0);
  BOOST_TEST(heavy_c.k().position[heavy_c.b].x == 140.0);

  TwoBodies heavy_b({100, 100}, {40, 40}, 1.0, {}, {130, 100}, {40, 40}, 10.0, {});
  Collision::resolve(heavy_b.k(), heavy_b.c, heavy_b.b);
  BOOST_TEST(heavy_b.k().position[heavy_b.c].x == 90.0);
  BOOST_TEST(heavy_b.k().position[heavy_b.b].x == 130.0);
}

BOOST_AUTO_TEST_CASE(two_infinite_masses_never_collide) {
  TwoBodies p({100, 100}, {40, 40}, infinity, {0.1, 0}, {120, 100}, {40, 40}, infinity, {});
  BOOST_TEST(!Collision::resolve(p.k(), p.c, p.b));
  BOOST_TEST(p.k().position[p.c].x == 100.0);
  BOOST_TEST((p.k().velocity[p.c] == Vector{0.1, 0}));
}

BOOST_AUTO_TEST_CASE(a_separating_pair_gets_the_position_correction_alone) {
  TwoBodies p({100, 100}, {40, 40}, 1.0, {-0.5, 0}, {130, 100}, {40, 40}, 1.0, {0.5, 0});
  Contact contact;
  BOOST_TEST_REQUIRE(Collision::resolve(p.k(), p.c, p.b, &contact));
  BOOST_TEST(!contact.approaching);
  BOOST_TEST((p.k().velocity[p.c] == Vector{-0.5, 0}));
  BOOST_TEST((p.k().velocity[p.b] == Vector{0.5, 0}));
  BOOST_TEST(!test::overlaps(p.k(), p.c, p.b));
}

BOOST_AUTO_TEST_CASE(corner_ties_resolve_along_x_deterministically) {
  // Equal penetration on both axes: x wins, the negative side first.
  TwoBodies p({0, 0}, {40, 40}, 1.0, {0.5, 0.5}, {30, 30}, {40, 40}, 1.0, {});
  Contact contact;
  BOOST_TEST_REQUIRE(Collision::resolve(p.k(), p.c, p.b, &contact));
  BOOST_TEST((contact.penetration == Vector{-10, 0}));
  BOOST_TEST((p.k().position[p.c] == Vector{-10, 0}));
  BOOST_TEST((p.k().velocity[p.c] == Vector{0, 0.5}));
  BOOST_TEST((p.k().velocity[p.b] == Vector{0.5, 0}));
}

BOOST_AUTO_TEST_CASE(co_located_identical_blocks_separate_deterministically) {
  for (int run = 0; run < 2; ++run) {
    TwoBodies p({200, 200}, {30, 30}, 2.0, {}, {200, 200}, {30, 30}, 2.0, {});
    Contact contact;
    BOOST_TEST_REQUIRE(Collision::resolve(p.k(), p.c, p.b, &contact));
    BOOST_TEST((contact.penetration == Vector{-30, 0}));
    // Equal masses at rest: b is ejected (the sheet's "sinon" branch).
    BOOST_TEST((p.k().position[p.c] == Vector{200, 200}));
    BOOST_TEST((p.k().position[p.b] == Vector{230, 200}));
    BOOST_TEST(!test::overlaps(p.k(), p.c, p.b));
  }
}

BOOST_AUTO_TEST_SUITE_END()
