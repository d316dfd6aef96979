// Building blocks of the numerics tools (make report, make stability) and of
// their tests: modes, scene builders and measures on a World.
#pragma once

#include <string>
#include <vector>

#include "course/game.hpp"
#include "engine/world.hpp"

namespace physics::numerics {

// A named setting of the step: the course mode, substeps, CCD, the stable solver.
struct Mode {
  std::string name;
  int substeps = 1;
  bool ccd = false;
  Solver solver = Solver::course;
  int iterations = 8;
  double dt = course_dt;
  // How long to run, not how to step: end a stability run as soon as CCD has
  // run out of budget in more than 1 % of the substeps the run would take, the
  // point from which its cell fails whatever follows. The tests set it (two
  // CCD cells spent 52 s of `make test` confirming a failure decided in the
  // first 1 %); `make stability` runs every cell out, to report the full count.
  bool stop_when_lost = false;
  // Set after the others (the modes above are written positionally).
  Integrator integrator = Integrator::course;

  Params params(Vector gravity = {}) const;
};

// The modes of the stability matrix, in column order.
std::vector<Mode> stability_modes();

// A world with the physics systems only (no Draw) in the given mode.
World make_world(const Mode& m, Vector gravity = {});

// The course's four walls (800 x 600, 40 px thick), shifted by `offset`.
void walls(World& w, Vector offset = {});

inline constexpr Color grey{128, 128, 128, 255};
EntityId block(World& w, double x, double y, int width, int height, double mass, Vector v = {}, double e = 1.0);

// Measures.
bool all_finite(const World& w);
// Deepest overlap (the shortest way out) over all pairs of registered bodies
// except two fixed ones, in px; 0 when nothing overlaps.
double max_overlap(const World& w);
// Finite bodies whose centre left the box [x0, x1] x [y0, y1].
int outside(const World& w, double x0, double y0, double x1, double y1);
// The energy the time stepping (symplectic Euler with step h = dt/substeps)
// keeps exactly in free flight: Σ m (|v|²/2 - g·x + h g·v/2), without the
// last term with the exact integrator (World::exact_motion). With g = 0 it
// is the kinetic energy. A collision law that never adds energy never makes
// it grow.
double step_energy(const World& w);
Vector momentum(const World& w);

}  // namespace physics::numerics
