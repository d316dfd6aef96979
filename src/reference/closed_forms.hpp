// Closed forms the event-driven reference is checked against (tests/test_reference.cpp)
// and that the report compares the engine with where they exist.
#pragma once

#include <utility>
#include <vector>

#include "course/utils/vect.hpp"

namespace physics::reference {

// Free flight under a constant acceleration g: p0 + v0·t + g·t²/2.
constexpr Vector free_flight_position(Vector p0, Vector v0, Vector g, double t) {
  return {p0.x + v0.x * t + 0.5 * g.x * t * t, p0.y + v0.y * t + 0.5 * g.y * t * t};
}
constexpr Vector free_flight_velocity(Vector v0, Vector g, double t) { return {v0.x + g.x * t, v0.y + g.y * t}; }

// A block dropped from rest with its bottom `h` px above a fixed floor, under
// gravity g (px/ms², > 0), restitution e: the apex after the n-th bounce is
// h·e^(2n) above the floor; the n-th impact happens at
//   t_n = t_0 (1 + 2e + 2e² + ... + 2e^n) (n = 0: the first), t_0 = sqrt(2h/g),
// and the bounces end (Zeno) at t_∞ = t_0 (1 + e) / (1 - e) for e < 1.
double bounce_apex(double h, double e, int n);
double bounce_impact_time(double h, double g, double e, int n);
double bounce_rest_time(double h, double g, double e);

// Head-on collision of two bodies along a line, restitution e:
// returns the velocities after the impact.
std::pair<double, double> two_body(double m1, double v1, double m2, double v2, double e);

// Newton's cradle: n equal touching blocks, the first arriving at speed v
// (e = 1): each impact exchanges the velocities, so the last one leaves at v
// and the others stop. Returns the final velocities, first to last.
std::vector<double> cradle(int n, double v);

}  // namespace physics::reference
