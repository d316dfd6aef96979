// The exact integrator (--integrator exact, engine/integrator.hpp): free
// flight under gravity is the closed form to rounding in every solver mode,
// at every dt and substep count; contacts stay as they were.
#include <algorithm>
#include <cmath>

#include "course/entities/block.hpp"
#include "helpers.hpp"

// The file's own names, apart from the other test files' with which it is
// compiled (Makefile, TEST_UNITY).
namespace test_integrator {

using namespace physics;
using namespace physics::test;

namespace {

constexpr Vector g{0.0, 0.001};  // px/ms², the report's gravity
constexpr Vector x0{100.0, 300.0}, v0{0.3, -0.5};
constexpr double t_end = 600.0;  // ms: the top of the arc is y = 175, far from every wall

struct Mode {
  const char* name;
  Solver solver;
  bool ccd;
};
constexpr Mode modes[] = {{"course", Solver::course, false},
                          {"stable", Solver::stable, false},
                          {"ccd", Solver::course, true},
                          {"stable+ccd", Solver::stable, true}};

// The course's walls under gravity g, in a mode, with an integrator.
World walled(const Mode& m, Integrator integrator, double dt = course_dt, int substeps = 1) {
  Params p;
  p.dt = dt;
  p.substeps = substeps;
  p.gravity = g;
  p.solver = m.solver;
  p.ccd = m.ccd;
  p.integrator = integrator;
  World w = physics_world(p);
  Game::init_walls(w);
  return w;
}

// A block thrown inside the course's walls (so that the solver and CCD have
// pairs to look at), run to t_end; returns the world.
World thrown(const Mode& m, Integrator integrator, double dt, int substeps) {
  World w = walled(m, integrator, dt, substeps);
  const EntityId b = Block::make(w, x0.x, x0.y, 10, 10, grey, 1.0).id;
  w.components.velocity[b] = v0;
  const auto frames = std::lround(t_end / dt);
  for (long f = 0; f < frames; ++f) Game::step(w);
  return w;
}

constexpr EntityId thrown_block = Game::wall_count;

Vector closed_form(double t) { return x0 + t * v0 + (0.5 * t * t) * g; }

// Largest of the two axes' errors relative to the closed form's coordinates.
double relative_error(Vector got, Vector want) {
  return std::max(std::abs(got.x - want.x) / std::abs(want.x), std::abs(got.y - want.y) / std::abs(want.y));
}

}  // namespace

BOOST_AUTO_TEST_SUITE(exact_integrator)

BOOST_AUTO_TEST_CASE(free_flight_is_the_closed_form_to_rounding_in_every_mode) {
  for (const Mode& m : modes)
    for (const double hz : {60.0, 100.0, 240.0})
      for (const int substeps : {1, 3, 8}) {
        BOOST_TEST_CONTEXT(m.name << ", dt = 1000/" << hz << ", " << substeps << " substep(s)") {
          const double dt = 1000.0 / hz;
          const World w = thrown(m, Integrator::exact, dt, substeps);
          const double t = static_cast<double>(std::lround(t_end / dt)) * dt;
          BOOST_TEST(relative_error(w.components.position[thrown_block], closed_form(t)) < 1e-12);
          BOOST_TEST(relative_error(w.components.velocity[thrown_block], v0 + t * g) < 1e-12);
          BOOST_TEST(w.ccd.stats.impacts == 0);  // free flight indeed
        }
      }
}

// What the test above would catch: the sheet's symplectic Euler lands
// g·t·h/2 below the closed form (1.25 px at dt = 1000/240 after 600 ms, 5 px
// at 1000/60), in every mode.
BOOST_AUTO_TEST_CASE(the_course_integrator_is_off_by_g_t_h_over_2) {
  for (const Mode& m : modes) {
    BOOST_TEST_CONTEXT(m.name) {
      const double dt = 1000.0 / 60.0;
      const World w = thrown(m, Integrator::course, dt, 1);
      const double t = static_cast<double>(std::lround(t_end / dt)) * dt;
      const double dy = w.components.position[thrown_block].y - closed_form(t).y;
      BOOST_TEST(std::abs(dy - 0.5 * g.y * t * dt) < 1e-9);
    }
  }
}

// Harmless at contacts: a block resting on the floor stays on it with the
// stable solver and CCD (no hovering a·h²/2 above it), and every mode keeps
// it on the floor, out of it, at rest.
BOOST_AUTO_TEST_CASE(a_block_resting_on_the_floor_stays_there) {
  for (const Mode& m : modes)
    for (const Integrator integrator : {Integrator::course, Integrator::exact}) {
      BOOST_TEST_CONTEXT(m.name << ", integrator " << name(integrator)) {
        World w = walled(m, integrator);
        const EntityId b = Block::make(w, 380, 540, 20, 20, grey, 1.0, 0.0).id;
        for (int f = 0; f < 300; ++f) Game::step(w);
        const double y = w.components.position[b].y;
        BOOST_TEST(std::abs(y - 540.0) < 0.2);  // the course pass leaves g·dt² at most
        BOOST_TEST(std::abs(w.components.velocity[b].y) < 0.02);
        // Shifted although the solver or CCD stopped it, it would hover 0.139 px up.
        if (m.solver == Solver::stable || m.ccd) BOOST_TEST(std::abs(y - 540.0) < 0.02);
      }
    }
}

// A bouncing block (e = 1) stays within the walls in every mode, and with
// the stable solver or CCD, which decide the motion at an impact, its energy
// does not grow (over these 20 s it lost 11 times |E0| with the course
// integrator, 0.2 times with the exact one). Not with the course pass: it pushes
// a body out to the surface, which gains g·d for a penetration d; the
// course integrator's own error, a loss of about as much, hid that
// (docs/numerics.md).
BOOST_AUTO_TEST_CASE(bounces_stay_inside_the_walls_without_gaining_energy) {
  for (const Mode& m : modes) {
    BOOST_TEST_CONTEXT(m.name) {
      World w = walled(m, Integrator::exact);
      const EntityId b = Block::make(w, 100, 100, 20, 20, grey, 1.0, 1.0).id;
      w.components.velocity[b] = {0.4, 0.1};
      const auto energy = [&] {
        const Vector v = w.components.velocity[b];
        return 0.5 * Vector::dot(v, v) - Vector::dot(g, w.components.position[b]);
      };
      const double e0 = energy();
      for (int f = 0; f < 1200; ++f) {
        Game::step(w);
        const Vector x = w.components.position[b];
        BOOST_TEST_REQUIRE((x.x > 39.0 && x.x < 741.0 && x.y > 39.0 && x.y < 541.0), "frame " << f);
      }
      if (m.solver == Solver::stable || m.ccd) BOOST_TEST(energy() < e0 + 0.01 * std::abs(e0));
    }
  }
}

BOOST_AUTO_TEST_CASE(the_names_are_course_and_exact) {
  BOOST_TEST(name(Integrator::course) == "course");
  BOOST_TEST(name(Integrator::exact) == "exact");
  BOOST_TEST((integrator_from_name("exact") == Integrator::exact));
  BOOST_TEST((integrator_from_name("course") == Integrator::course));
  BOOST_TEST(!integrator_from_name("Exact"));
  BOOST_TEST(!integrator_from_name(""));
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace test_integrator
