// The event-driven reference simulator, checked against closed forms.
#include "helpers.hpp"
#include "reference/closed_forms.hpp"
#include "reference/event_sim.hpp"
#include "course/utils/random.hpp"

// The file's own names, apart from the other test files' with which it is
// compiled (Makefile, TEST_UNITY).
namespace test_reference {

using namespace physics;
using namespace physics::reference;
// The reference's bodies (the scenes' physics::Body, which another test file
// brings in, is not this).
using physics::reference::Body;

namespace {

constexpr double g = 0.001;  // px/ms²
const Body floor_body{{0, 500}, {}, 800, 40, infinity, 1.0};

bool close(double a, double b, double rel) { return std::abs(a - b) <= rel * std::max({std::abs(a), std::abs(b), 1.0}); }

}  // namespace

BOOST_AUTO_TEST_SUITE(reference_simulator)

BOOST_AUTO_TEST_CASE(free_flight_follows_the_parabola) {
  const Vector p0{100, 50}, v0{0.3, -0.4}, grav{0, g};
  EventSim sim({Body{p0, v0, 10, 10, 2.0, 1.0}}, grav, 5000);
  for (const double t : {0.5, 100.0, 1234.5, 5000.0}) {
    sim.advance_to(t);
    const Vector want = free_flight_position(p0, v0, grav, t);
    BOOST_TEST(close(sim.bodies()[0].p.x, want.x, 1e-12));
    BOOST_TEST(close(sim.bodies()[0].p.y, want.y, 1e-12));
    BOOST_TEST(close(sim.bodies()[0].v.y, free_flight_velocity(v0, grav, t).y, 1e-12));
  }
  BOOST_TEST(sim.events().empty());
}

BOOST_AUTO_TEST_CASE(a_projectile_lands_when_the_parabola_meets_the_floor) {
  // Bottom at y0 + 10 = 110, floor top at 500: 390 = v0y t + g t²/2.
  const double v0y = -0.2;
  EventSim sim({floor_body, Body{{100, 100}, {0.1, v0y}, 10, 10, 1.0, 0.0}}, {0, g}, 3000);
  sim.advance_to(3000);
  BOOST_TEST_REQUIRE(!sim.events().empty());
  const double t_land = (-v0y + std::sqrt(v0y * v0y + 2 * g * 390.0)) / g;
  BOOST_TEST(close(sim.events()[0].t, t_land, 1e-12));
  // e = 0: it stays on the floor, sliding at its horizontal speed.
  BOOST_TEST(sim.resting(1));
  BOOST_TEST(sim.bodies()[1].p.y == 490.0);
  BOOST_TEST(close(sim.bodies()[1].p.x, 100 + 0.1 * 3000, 1e-12));
}

BOOST_AUTO_TEST_CASE(bounce_apexes_are_h_e_to_the_2n_and_the_block_comes_to_rest) {
  for (const double e : {0.5, 0.8}) {
    const double h = 200.0;  // bottom 200 px above the floor
    const double t_rest = bounce_rest_time(h, g, e);
    EventSim sim({floor_body, Body{{300, 500 - h - 20}, {}, 20, 20, 3.0, e}}, {0, g}, 2 * t_rest);
    for (int n = 0; n < 6; ++n) {
      const double t_n = bounce_impact_time(h, g, e, n), t_next = bounce_impact_time(h, g, e, n + 1);
      sim.advance_to(0.5 * (t_n + t_next));  // the apex after the n-th impact (n+1-th bounce)
      BOOST_TEST_REQUIRE(sim.events().size() == static_cast<std::size_t>(n + 1));
      BOOST_TEST(close(sim.events()[n].t, t_n, 1e-12));
      BOOST_TEST(close(480.0 - sim.bodies()[1].p.y, bounce_apex(h, e, n + 1), 1e-9));
    }
    sim.advance_to(2 * t_rest);
    BOOST_TEST(sim.resting(1));
    BOOST_TEST(sim.bodies()[1].p.y == 480.0);
    BOOST_TEST(sim.bodies()[1].v.y == 0.0);
    // The last impact is the Zeno limit (up to the rest speed's cut-off).
    BOOST_TEST(close(sim.events().back().t, t_rest, 1e-6));
  }
}

BOOST_AUTO_TEST_CASE(two_body_collisions_give_the_closed_form_velocities) {
  for (const double e : {0.0, 0.5, 1.0})
    for (const auto& [m1, m2] : {std::pair{1.0, 1.0}, {2.0, 7.0}, {1e6, 1.0}}) {
      const double v1 = 0.4, v2 = -0.1;
      EventSim sim({Body{{0, 0}, {v1, 0}, 10, 10, m1, e}, Body{{50, 3}, {v2, 0}, 20, 10, m2, e}}, {}, 1000);
      sim.advance_to(1000);
      BOOST_TEST_REQUIRE(sim.events().size() == 1u);
      BOOST_TEST(close(sim.events()[0].t, 40.0 / 0.5, 1e-12));
      const auto [w1, w2] = two_body(m1, v1, m2, v2, e);
      BOOST_TEST(close(sim.bodies()[0].v.x, w1, 1e-12));
      BOOST_TEST(close(sim.bodies()[1].v.x, w2, 1e-12));
      BOOST_TEST(sim.bodies()[0].v.y == 0.0);
    }
}

BOOST_AUTO_TEST_CASE(newtons_cradle_passes_the_velocity_to_the_last_block) {
  const int n = 5;
  std::vector<Body> bodies{Body{{0, 0}, {0.5, 0}, 20, 20, 1.0, 1.0}};
  for (int k = 0; k < n - 1; ++k) bodies.push_back(Body{{100.0 + 20 * k, 0}, {}, 20, 20, 1.0, 1.0});
  EventSim sim(bodies, {}, 1000);
  sim.advance_to(1000);
  const auto want = cradle(n, 0.5);
  for (int k = 0; k < n; ++k) BOOST_TEST(sim.bodies()[k].v.x == want[k]);
  BOOST_TEST(sim.events().size() == static_cast<std::size_t>(n - 1));
  for (const auto& ev : sim.events()) BOOST_TEST(ev.t == 160.0);  // all at the first contact
}

BOOST_AUTO_TEST_CASE(an_elastic_gas_keeps_energy_and_momentum) {
  for (const bool walls : {false, true}) {
    Random rng(3);
    std::vector<Body> bodies;
    if (walls) {  // a closed 600 x 400 box
      bodies.push_back(Body{{-40, -40}, {}, 680, 40, infinity, 1.0});
      bodies.push_back(Body{{-40, 400}, {}, 680, 40, infinity, 1.0});
      bodies.push_back(Body{{-40, 0}, {}, 40, 400, infinity, 1.0});
      bodies.push_back(Body{{600, 0}, {}, 40, 400, infinity, 1.0});
    }
    for (int i = 0; i < 40; ++i)
      bodies.push_back(Body{{5 + 70.0 * (i % 8), 5 + 70.0 * (i / 8)}, {rng.uniform(-0.3, 0.3), rng.uniform(-0.3, 0.3)},
                            static_cast<double>(rng.uniform_int(5, 30)), static_cast<double>(rng.uniform_int(5, 30)),
                            rng.uniform(1, 10), 1.0});
    EventSim sim(bodies, {}, 20000);
    const double E0 = sim.energy();
    const Vector P0 = sim.momentum();
    sim.advance_to(20000);
    const double events = static_cast<double>(sim.events().size());
    BOOST_TEST(events > (walls ? 500.0 : 10.0));
    BOOST_TEST(std::abs(sim.energy() - E0) <= 1e-14 * E0 * events);
    if (!walls) {  // momentum: only without the walls' infinite masses
      const double scale = std::abs(P0.x) + std::abs(P0.y);
      BOOST_TEST(std::abs(sim.momentum().x - P0.x) <= 1e-14 * scale * events);
      BOOST_TEST(std::abs(sim.momentum().y - P0.y) <= 1e-14 * scale * events);
    }
    // No two boxes ever end up overlapping.
    for (std::size_t i = 0; i < bodies.size(); ++i)
      for (std::size_t j = i + 1; j < bodies.size(); ++j) {
        const Body &a = sim.bodies()[i], &b = sim.bodies()[j];
        const double ox = std::min(a.p.x + a.w, b.p.x + b.w) - std::max(a.p.x, b.p.x);
        const double oy = std::min(a.p.y + a.h, b.p.y + b.h) - std::max(a.p.y, b.p.y);
        BOOST_TEST(std::min(ox, oy) <= 1e-9);
      }
  }
}

BOOST_AUTO_TEST_CASE(a_stack_rests_and_a_dropped_box_settles_on_it) {
  std::vector<Body> bodies{floor_body};
  for (int k = 0; k < 5; ++k) bodies.push_back(Body{{300, 480.0 - 20 * k}, {}, 20, 20, 1.0, 0.5});
  bodies.push_back(Body{{302, 200}, {}, 20, 20, 1.0, 0.5});
  EventSim sim(bodies, {0, g}, 20000);
  sim.advance_to(20000);
  for (std::size_t k = 1; k <= 5; ++k) BOOST_TEST(std::abs(sim.bodies()[k].p.y - (480.0 - 20 * (k - 1))) < 1e-6);
  BOOST_TEST(std::abs(sim.bodies()[6].p.y - 380.0) < 1e-6);
  for (std::size_t k = 1; k <= 6; ++k) BOOST_TEST(sim.resting(k));
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace test_reference
