#include "course/systems/forces.hpp"

#include <cmath>

namespace physics {

void Forces::update(Components& c, double dt, Vector gravity) const {
  // Q5 begin
  // Q5 stub: // TODO Q5: for every registered entity of finite mass m (std::isfinite), turn the
  // Q5 stub: // sum of the forces into an acceleration a = sum_forces / m (plus `gravity`, an
  // Q5 stub: // acceleration applied to every finite mass), add dt x a to the velocity, then
  // Q5 stub: // reset sum_forces to the zero vector. An infinite mass: do nothing.
  // Q5 stub: (void)c, (void)dt, (void)gravity;
  for (const EntityId e : entities_) {
    const double m = c.mass[e];
    // Fixed bodies ignore forces; their sum_forces is left as it is, which is
    // never read (the sheet: "si cette dernière est infinie, ne rien faire").
    if (!std::isfinite(m)) continue;
    const Vector f = c.sum_forces[e];
    const Vector a = Vector{f.x / m, f.y / m} + gravity;  // Σf = m·a
    c.velocity[e] = c.velocity[e] + dt * a;
    c.sum_forces[e] = Vector::zero();
  }
  // Q5 end
}

}  // namespace physics
