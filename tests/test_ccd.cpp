// Swept collision at its limits (engine/ccd.hpp): out of impact budget, the
// scene's time keeps going and nothing gains energy; fast bodies crossing a
// sensor within a substep are seen.
#include <cmath>
#include <sstream>

#include "helpers.hpp"
#include "app/headless.hpp"
#include "numerics/scenes.hpp"

// The file's own names, apart from the other test files' with which it is
// compiled (Makefile, TEST_UNITY).
namespace test_ccd {

using namespace physics;
using namespace physics::numerics;

namespace {

const Mode ccd_mode{"ccd", 1, true, Solver::course, 8};
const Mode automatic_mode{"auto", 1, false, Solver::automatic, 8};
constexpr double g = 0.001;

// Kinetic and potential energy of the bodies from `first` on (y grows downwards).
double energy(const World& w, EntityId first) {
  double e = 0;
  for (EntityId b = first; b < w.components.size(); ++b) {
    const double m = w.components.mass[b];
    const Vector v = w.components.velocity[b];
    e += 0.5 * m * Vector::dot(v, v) - m * g * w.components.position[b].y;
  }
  return e;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(ccd_limits)

// A light block under a heavy one (1e6 times heavier, e = 0) on the floor
// runs CCD out of budget every substep (an inelastic collapse: impacts
// without end at one instant). Five
// e = 1 blocks bounce beside them: they used to stop with every body at the
// budget's moment while gravity kept adding to their speed, and their energy
// grew 3 677 times in 3000 frames. Now only the bodies still to meet
// something stop; the bouncers move on, their step energy (½v² - g·x +
// ½h g·v, which symplectic Euler and an e = 1 bounce keep) kept.
BOOST_AUTO_TEST_CASE(out_of_budget_time_goes_on_and_no_energy_is_gained) {
  World w = make_world(ccd_mode, {0, g});
  walls(w);
  block(w, 390, 540, 20, 20, 1.0, {}, 0.0);
  block(w, 380, 500, 40, 40, 1e6, {}, 0.0);
  const EntityId first = static_cast<EntityId>(w.components.size());
  for (int i = 0; i < 5; ++i) block(w, 100 + 60 * i, 200, 20, 20, 1.0);
  const double h = w.params.substep();
  const auto step_energy = [&] {
    double e = energy(w, first);
    for (EntityId b = first; b < w.components.size(); ++b) e += 0.5 * h * g * w.components.velocity[b].y;
    return e;
  };
  const double e0 = step_energy();
  double most = e0, lowest = 0;
  const Headless::Summary s = Headless::run(w, 3000, [&](const World& at) {
    most = std::max(most, step_energy());
    lowest = std::max(lowest, at.components.position[first].y);
  });
  BOOST_TEST(most <= e0 + 1e-9 * std::abs(e0));
  BOOST_TEST(w.ccd.stats.capped_substeps > 2900);
  // They fell to the floor and bounced on: time went on for them.
  BOOST_TEST(lowest > 530.0);
  BOOST_TEST(w.components.velocity[first].y != 0.0);
  std::ostringstream out;
  Headless::print_summary(out, w, s, "");
  BOOST_TEST(out.str().find("ccd:             " + std::to_string(w.ccd.stats.capped_substeps) + " substeps over budget") !=
             std::string::npos, out.str());
}

// An e = 1 block dropped on the floor comes back to where it fell from, in
// every mode that times its impacts within the substep (CCD, the stable
// solver's impact_time, auto). Taking back (1+e)(a·n)(h - t) of the gravity
// kick at the impact lost m g h |v| a bounce: it came back 15 px lower each
// time (contact.hpp, gravity_after_impact).
BOOST_AUTO_TEST_CASE(an_elastic_bounce_on_the_floor_comes_back_to_its_height) {
  for (const Mode& m : {ccd_mode, Mode{"stable", 1, false, Solver::stable, 8}, Mode{"stable+ccd", 1, true, Solver::stable, 8},
                        automatic_mode}) {
    World w = make_world(m, {0, g});
    walls(w);
    const EntityId b = block(w, 400, 100, 10, 10, 1.0, {}, 1.0);
    const double e0 = energy(w, b);
    double highest_after = 1e9, lowest_energy = e0;
    int bounces = 0;
    for (int f = 0; f < 1000; ++f) {
      const double before = w.components.velocity[b].y;
      Game::step(w);
      if (before > 0 && w.components.velocity[b].y < 0) ++bounces;
      if (bounces > 0) highest_after = std::min(highest_after, w.components.position[b].y);
      lowest_energy = std::min(lowest_energy, energy(w, b));
    }
    BOOST_TEST(bounces >= 8, m.name);
    // Within a frame's travel at the apex (the frames sample the path) of
    // y = 100 after eight bounces; the course's 15 px a bounce would be 120 px.
    BOOST_TEST(highest_after < 100.5, m.name << ": highest point after the bounces " << highest_after);
    // The energy at the frames' ends: the kinetic + potential of a body in
    // flight under symplectic Euler is off by at most m g h |v| / 2.
    BOOST_TEST(lowest_energy > e0 - 0.02, m.name << ": energy fell from " << e0 << " to " << lowest_energy);
  }
}

// A bullet at 20 000 px/ms in the walled box bounces about 900 times a frame
// off the walls: impacts spread over the substep, not a jam at one instant.
// The budget counts impacts per 1/64 of the substep, so the bullet is never
// capped and follows the lossless bounce (it used to freeze at the first
// substep's budget, 208 impacts).
BOOST_AUTO_TEST_CASE(a_bullet_bouncing_hundreds_of_times_a_frame_is_not_capped) {
  World w = make_world(ccd_mode);
  walls(w);
  const Vector v{20000 * std::cos(0.3), 20000 * std::sin(0.3)};
  const EntityId b = block(w, 395, 295, 10, 10, 1.0, v, 1.0);
  for (int f = 0; f < 60; ++f) Game::step(w);
  BOOST_TEST(w.ccd.stats.capped_substeps == 0);
  BOOST_TEST(w.ccd.stats.impacts > 60 * 500);
  BOOST_TEST(std::abs(Vector::norm(w.components.velocity[b]) - 20000.0) < 1e-6);
  BOOST_TEST(w.health.escaped == 0);
}

// A bullet at 20 px/ms (333 px a frame) between the walls crosses a 5 px
// sensor about once every two frames; the end-of-step overlaps saw a few of
// the crossings. Every frame whose path crosses the sensor is a touch: a
// begin event for each run of such frames, counted here from the closed form.
BOOST_AUTO_TEST_CASE(a_fast_body_crossing_a_sensor_is_seen_every_time) {
  for (const Mode& m : {ccd_mode, automatic_mode}) {
    World w = make_world(m);
    walls(w);
    const EntityId sensor = block(w, 400, 200, 5, 200, 1.0);
    ContactRules r;
    r.sensor = true;
    w.components.set_rules(sensor, r);
    const double v = 20.0, x0 = 100.0;
    block(w, x0, 300, 4, 4, 1.0, {v, 0});
    w.enable_events();
    // Unfolded, the bullet's left edge moves at v; folded between 40 and 756.
    const double lo = 40, hi = 756, period = 2 * (hi - lo);
    const auto inside = [&](double u) {
      const double a = std::fmod(u - lo, period), x = lo + (a <= hi - lo ? a : period - a);
      return x > 400 - 4 && x < 405;
    };
    int begins = 0, runs = 0;
    bool was = false;
    for (int f = 0; f < 600; ++f) {
      Game::step(w);
      for (const ContactEvent& e : w.events.events())
        begins += e.kind == EventKind::begin && (e.a == sensor || e.b == sensor);
      // This frame's path touches the sensor: sampled finely (0.1 px).
      bool touched = false;
      const double dt = w.params.dt;
      for (double t = 0; t <= dt && !touched; t += 0.1 / v) touched = inside(x0 + v * (f * dt + t));
      runs += touched && !was;
      was = touched;
    }
    BOOST_TEST_INFO(m.name);
    BOOST_TEST(runs > 200);
    BOOST_TEST(std::abs(begins - runs) <= 2, begins << " begins, " << runs << " runs of touching frames");
  }
}

// A light block squeezed between two heavy ones (e = 1, no gravity) runs
// CCD out of budget: the bodies that meet then stop where they meet, and a
// body that runs into a stopped one stops too. Stopping each at its own next
// impact as predicted before let a heavy block, chasing the light one, run
// into it once it had stopped: the light block ended on the far side of the
// heavy one and 99 % of the energy was gone. The blocks have friction, which
// a head-on squeeze never uses (no sliding) but which makes the impacts count
// against the budget that runs out: without it they are lossless, and CCD's
// budget for those takes the whole squeeze
// (stiff_family/ccd_takes_an_elastic_squeeze_to_its_end_without_gravity).
BOOST_AUTO_TEST_CASE(a_squeeze_out_of_budget_keeps_the_order_and_the_energy) {
  for (const Mode& m : {ccd_mode, automatic_mode}) {
    World w = make_world(m);
    walls(w);
    const EntityId a = block(w, 100, 280, 40, 40, 1e6, {0.1, 0});
    const EntityId light = block(w, 200, 290, 20, 20, 1.0);
    const EntityId b = block(w, 300, 280, 40, 40, 1e6, {-0.1, 0});
    for (const EntityId e : {a, light, b}) w.components.friction[e] = 0.5;
    // No gravity here: the kinetic energy is all of it.
    const auto kinetic = [&] { return w.kinetic_energy(); };
    const double e0 = kinetic();
    bool ordered = true;
    for (int f = 0; f < 600; ++f) {
      Game::step(w);
      const auto& x = w.components.position;
      ordered = ordered && x[a].x < x[light].x && x[light].x < x[b].x;
    }
    // The case this is about, with CCD alone. Auto's solver takes the light
    // block's first impact, and the rest, spread over the substep, fits the
    // budget (it is counted per stretch of time).
    if (!m.ccd) BOOST_TEST(w.ccd.stats.capped_substeps == 0, m.name);
    if (m.ccd) BOOST_TEST(w.ccd.stats.capped_substeps > 0, m.name);
    BOOST_TEST(ordered, m.name);
    BOOST_TEST(kinetic() <= e0 * (1 + 1e-9), m.name);
    BOOST_TEST(kinetic() > 0.99 * e0, m.name);
  }
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace test_ccd
