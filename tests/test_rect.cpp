// Q6-Q7: Rect::mdiff and Rect::has_origin, and Vector.
#include "helpers.hpp"

using namespace physics;

BOOST_AUTO_TEST_SUITE(q6_mdiff)

BOOST_AUTO_TEST_CASE(mdiff_follows_the_sheets_formula) {
  // x = x2 - x1 - w1, y = y2 - y1 - h1, w = w2 + w1, h = h2 + h1
  const auto [p, r] = Rect::mdiff({10, 20}, {30, 40}, {100, 5}, {7, 9});
  BOOST_TEST(p.x == 100 - 10 - 30);
  BOOST_TEST(p.y == 5 - 20 - 40);
  BOOST_TEST(r.width == 37);
  BOOST_TEST(r.height == 49);
}

BOOST_AUTO_TEST_CASE(mdiff_of_overlapping_boxes_contains_the_origin) {
  // c at (0,0) 40x40, b at (30,10) 20x20: overlap of 10 px on x.
  const auto [p, r] = Rect::mdiff({0, 0}, {40, 40}, {30, 10}, {20, 20});
  BOOST_TEST(p.x == -10.0);
  BOOST_TEST(p.y == -30.0);
  BOOST_TEST(p.x < 0.0);  // the origin is inside: x < 0 < x + w, y < 0 < y + h
  BOOST_TEST(p.x + r.width > 0.0);
  BOOST_TEST(p.y < 0.0);
  BOOST_TEST(p.y + r.height > 0.0);
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(q7_has_origin)

BOOST_AUTO_TEST_CASE(inside_outside_and_border) {
  BOOST_TEST(Rect::has_origin({-1, -1}, {2, 2}));
  BOOST_TEST(Rect::has_origin({-0.5, -10}, {1, 20}));
  BOOST_TEST(!Rect::has_origin({1, -1}, {2, 2}));    // right of the origin
  BOOST_TEST(!Rect::has_origin({-3, -1}, {2, 2}));   // left
  BOOST_TEST(!Rect::has_origin({-1, 0.5}, {2, 2}));  // below
  // The border is outside: touching is not colliding.
  BOOST_TEST(!Rect::has_origin({0, -1}, {2, 2}));
  BOOST_TEST(!Rect::has_origin({-2, -1}, {2, 2}));
  BOOST_TEST(!Rect::has_origin({-1, 0}, {2, 2}));
  BOOST_TEST(!Rect::has_origin({-1, -2}, {2, 2}));
  BOOST_TEST(!Rect::has_origin({0, 0}, {2, 2}));
}

BOOST_AUTO_TEST_CASE(the_difference_of_overlapping_boxes_has_the_origin) {
  const auto [p, r] = Rect::mdiff({0, 0}, {40, 40}, {30, 10}, {20, 20});
  BOOST_TEST(Rect::has_origin(p, r));
  const auto [q, s] = Rect::mdiff({0, 0}, {40, 40}, {41, 10}, {20, 20});  // 1 px apart
  BOOST_TEST(!Rect::has_origin(q, s));
}

BOOST_AUTO_TEST_CASE(touching_boxes_do_not_collide) {
  World w = test::physics_world();
  const auto a = Block::make(w, 0, 0, 40, 40, test::grey, 1.0);
  const auto b = Block::make(w, 40, 0, 40, 40, test::grey, 1.0);
  w.components.velocity[a.id] = {-0.1, 0};  // separating
  BOOST_TEST(!test::overlaps(w.components, a.id, b.id));
  BOOST_TEST(!Collision::resolve(w.components, a.id, b.id));
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(vector_module)

BOOST_AUTO_TEST_CASE(vector_operations) {
  const Vector a{3, 4}, b{-1, 2};
  BOOST_TEST((Vector::add(a, b) == Vector{2, 6}));
  BOOST_TEST((Vector::sub(a, b) == Vector{4, 2}));
  BOOST_TEST((Vector::mult(2, a) == Vector{6, 8}));
  BOOST_TEST(Vector::dot(a, b) == 5.0);
  BOOST_TEST(Vector::norm(a) == 5.0);
  BOOST_TEST((Vector::normalize(a) == Vector{0.6, 0.8}));
  BOOST_TEST((Vector::normalize(Vector::zero()) == Vector::zero()));
  BOOST_TEST(Vector::is_zero(Vector::zero()));
  BOOST_TEST(!Vector::is_zero(b));
  BOOST_TEST(std::abs(Vector::norm({3e200, 4e200}) / 5e200 - 1) < 1e-15);  // no overflow to inf
}

BOOST_AUTO_TEST_SUITE_END()
