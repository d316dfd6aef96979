// The engine's own geometry (engine/geometry.hpp) against the course's
// answers it stands in for (Rect::mdiff, Rect::has_origin,
// Collision::penetration): the same bits on every input, random or chosen on
// an edge (touching boxes, ties between the four vectors, zero sizes, signed
// zeros, infinities and NaN), so that the engine's CCD, health check and
// queries behave exactly as they did when they called the course's.
#include <bit>
#include <cstdint>
#include <limits>
#include <random>

#include "engine/geometry.hpp"
#include "helpers.hpp"

using namespace physics;

namespace {

bool same(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }
bool same(Vector a, Vector b) { return same(a.x, b.x) && same(a.y, b.y); }

// Positions on the edges that matter: zeros of both signs, small integers
// (boxes that touch or tie), halves, non-finite values.
const double edge_values[] = {0.0,  -0.0, 1.0,  -1.0, 0.5, -0.5, 10.0, -10.0, 20.0, -20.0, 40.0, -40.0,
                              1e-300, -1e-300, 1e300, -1e300,
                              std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
                              std::numeric_limits<double>::quiet_NaN()};
const int edge_sizes[] = {0, 1, 2, 10, 20, 40, 80};

// Compares the three functions on one input, counting the disagreements.
int disagreements(Vector p1, Rect r1, Vector p2, Rect r2) {
  const auto [cp, cr] = Rect::mdiff(p1, r1, p2, r2);
  const auto [ep, er] = minkowski_difference(p1, r1, p2, r2);
  int bad = 0;
  if (!same(cp, ep) || !(cr == er)) ++bad;
  if (Rect::has_origin(cp, cr) != contains_origin(cp, cr)) ++bad;
  if (!same(Collision::penetration(cp, cr), penetration_vector(cp, cr))) ++bad;
  // The two other functions on the raw inputs too (not only on differences).
  if (Rect::has_origin(p1, r1) != contains_origin(p1, r1)) ++bad;
  if (!same(Collision::penetration(p1, r1), penetration_vector(p1, r1))) ++bad;
  return bad;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(engine_geometry)

BOOST_AUTO_TEST_CASE(agrees_with_the_course_on_edge_inputs) {
  int bad = 0, cases = 0;
  for (const double x : edge_values)
    for (const double y : edge_values)
      for (const int w : edge_sizes)
        for (const int h : edge_sizes) {
          bad += disagreements({0.0, 0.0}, Rect{w, h}, {x, y}, Rect{h, w});
          bad += disagreements({x, y}, Rect{w, h}, {0.0, 0.0}, Rect{}), cases += 2;
        }
  BOOST_TEST(bad == 0, bad << " disagreements in " << cases << " edge cases");
}

BOOST_AUTO_TEST_CASE(agrees_with_the_course_on_random_inputs) {
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> real(-200.0, 200.0);
  std::uniform_int_distribution<int> size(0, 120), grid(-20, 20), kind(0, 2);
  // Half-pixel grids make touching boxes and ties frequent; reals make the rest.
  auto coordinate = [&] { return kind(rng) == 0 ? real(rng) : grid(rng) * (kind(rng) == 0 ? 0.5 : 10.0); };
  int bad = 0;
  for (int i = 0; i < 200000; ++i)
    bad += disagreements({coordinate(), coordinate()}, Rect{size(rng), size(rng)}, {coordinate(), coordinate()},
                         Rect{size(rng), size(rng)});
  BOOST_TEST(bad == 0);
}

// The inputs above would agree trivially if both sides were stubs returning
// the same constant; these pin the engine's functions to the sheet's values.
BOOST_AUTO_TEST_CASE(gives_the_sheets_values_with_its_tie_rules) {
  const auto [p, r] = minkowski_difference({10, 20}, {30, 40}, {100, 5}, {7, 9});
  BOOST_TEST((p == Vector{60, -55}));
  BOOST_TEST((r == Rect{37, 49}));
  BOOST_TEST(contains_origin({-1, -1}, {2, 2}));
  BOOST_TEST(!contains_origin({0, -1}, {2, 2}));   // touching on the left edge
  BOOST_TEST(!contains_origin({-2, -1}, {2, 2}));  // touching on the right edge
  BOOST_TEST(!contains_origin({-1, -1}, {0, 2}));  // zero width
  BOOST_TEST((penetration_vector({-10, -30}, {60, 60}) == Vector{-10, 0}));
  BOOST_TEST((penetration_vector({-30, -5}, {60, 60}) == Vector{0, -5}));
  BOOST_TEST((penetration_vector({-30, -58}, {60, 60}) == Vector{0, 2}));
  // Ties: -x before +x, x before y.
  BOOST_TEST((penetration_vector({-30, -30}, {60, 60}) == Vector{-30, 0}));
  BOOST_TEST((penetration_vector({-40, -20}, {60, 60}) == Vector{20, 0}));
  BOOST_TEST((penetration_vector({-40, -40}, {60, 60}) == Vector{20, 0}));
}

BOOST_AUTO_TEST_SUITE_END()
