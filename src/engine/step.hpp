// One frame of a world (the sheet's main loop: "call update in the main
// program"): for each substep, the Forces, Move and Collision stages in the
// sheet's order, with the engine's numerics stages between them, then the
// step's contact events and health checks.
//
// run_frame is that sequence, once, for whoever supplies the three stages:
// the engine's step runs it with the engine's own stages (engine/stages.hpp:
// the public API, the benchmark), the course's Game::step with the course's
// systems (course/systems/: the student's answers in the exercise mode). The
// two give the same bits (tests/test_geometry.cpp, tests/test_api.cpp).
#pragma once

#include "engine/world.hpp"

namespace physics {

// forces(h) and move(h) run a stage over the world's bodies of that stage for
// a substep of h ms; pass() runs the course pass over w.course_pairs() and
// leaves its contacts in w.pass. A stage the world did not declare is skipped.
template <class ForcesStage, class MoveStage, class PassStage>
void run_frame(World& w, ForcesStage&& forces, MoveStage&& move, PassStage&& pass) {
  const double h = w.params.substep();
  const bool has_forces = w.declares(SystemId::forces), has_move = w.declares(SystemId::move);
  const bool has_collision = w.declares(SystemId::collision);
  for (int k = 0; k < w.params.substeps; ++k) {
    w.before_forces();  // the exact integrator's start (docs/numerics.md); nothing by default
    if (has_forces) w.times.time(Stage::forces, [&] { forces(h); });
    w.before_move(h);  // the engine's numerics options (docs/numerics.md); nothing in the course mode
    if (has_move) w.times.time(Stage::move, [&] { move(h); });
    if (!has_collision) continue;
    if (w.solver_step()) {
      w.after_move();  // the stable solver projects overlaps apart instead of the course's pass
    } else {
      w.times.time(Stage::collision, [&] { pass(); });
      w.record_contacts();  // the pass's contacts, for contact events (engine/events.hpp) and the auto mode
    }
  }
  w.end_frame();
}

// The engine's frame: run_frame with the engine's stages. No course code.
void step(World& w);

}  // namespace physics
