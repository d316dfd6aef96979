#include "engine/step.hpp"

namespace physics {

void step(World& w) {
  Systems& s = w.systems;
  const double h = w.params.substep();
  for (int k = 0; k < w.params.substeps; ++k) {
    w.before_forces();  // the exact integrator's start (docs/numerics.md); nothing by default
    if (s.forces) w.times.time(Stage::forces, [&] { s.forces->update(w.components, h, w.params.gravity); });
    w.before_move(h);  // the engine's numerics options (docs/numerics.md); nothing in the course mode
    if (s.move) w.times.time(Stage::move, [&] { s.move->update(w.components, h); });
    if (!s.collision) continue;
    if (w.solver_step()) {
      w.after_move();  // the stable solver projects overlaps apart instead of the course's pass
    } else {
      w.times.time(Stage::collision, [&] { s.collision->update(w.components, w.course_pairs()); });
      w.record_contacts();  // the pass's contacts, for contact events (engine/events.hpp) and the auto mode
    }
  }
  ++w.times.steps;
  ++w.frame;
  // Not part of the sheet: the contact events of the step, and the engine's
  // look at the state it left (engine/health.hpp).
  w.finish_events();
  w.times.time(Stage::health, [&] { w.check_health(); });
}

}  // namespace physics
