#include "course/systems/move.hpp"

namespace physics {

void Move::update(Components& c, double dt) const {
  // Q3 begin
  // Q3 stub: // TODO Q3: move every registered entity: its new position is the old one plus
  // Q3 stub: // dt x v, where v is its velocity (dt = 1000 / 60 ms in the course).
  // Q3 stub: (void)c, (void)dt;
  // Infinite masses move too: a fixed body is one that no force or impulse can
  // change, not one that cannot have a velocity (a moving platform).
  for (const EntityId e : entities_) c.position[e] = c.position[e] + dt * c.velocity[e];
  // Q3 end
}

}  // namespace physics
