#include "systems/draw.hpp"

#include <cmath>

namespace physics {

void Draw::update(const Components& c, Canvas& canvas) const {
  for (const EntityId e : entities_) {
    const Vector p = c.position[e];
    // Skip what cannot be drawn (NaN, or far outside int range) rather than
    // hand the canvas an undefined conversion.
    if (!(std::abs(p.x) < 1e9 && std::abs(p.y) < 1e9)) continue;
    canvas.fill_rect(p, c.box[e], c.color[e]);
  }
}

}  // namespace physics
