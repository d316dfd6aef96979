#include "engine/step.hpp"

#include "engine/stages.hpp"

namespace physics {

void step(World& w) {
  Components& c = w.components;
  run_frame(
      w, [&](double h) { apply_forces(c, w.bodies(SystemId::forces), h, w.params.gravity, &w.workers); },
      [&](double h) { move_bodies(c, w.bodies(SystemId::move), h, &w.workers); },
      [&] {
        // As Collision::update: the last pass's count, and its contacts if recorded.
        PassContacts& p = w.pass;
        p.contacts.clear();
        p.contact_count = resolve_pairs(c, w.course_pairs(), p.record_contacts ? &p.contacts : nullptr);
      });
}

}  // namespace physics
