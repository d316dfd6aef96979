#include "systems/move.hpp"

namespace physics {

void Move::update(Components& c, double dt) const {
  // Infinite masses move too: a fixed body is one that no force or impulse can
  // change, not one that cannot have a velocity (a moving platform).
  for (const EntityId e : entities_) c.position[e] = c.position[e] + dt * c.velocity[e];
}

}  // namespace physics
