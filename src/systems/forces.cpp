#include "systems/forces.hpp"

#include <cmath>

namespace physics {

void Forces::update(Components& c, double dt, Vector gravity) const {
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
}

}  // namespace physics
