#include "entities/block.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace physics::Block {

t make(World& w, double x, double y, int width, int height, Color color, double mass,
       double restitution) {
  if (width <= 0 || height <= 0)
    throw std::invalid_argument("block size must be > 0 (got " + std::to_string(width) + "x" +
                                std::to_string(height) + ")");
  // Sizes are summed in Rect::mdiff; keep them far from int overflow.
  if (width > (1 << 28) || height > (1 << 28))
    throw std::invalid_argument("block size too large (max 2^28 px)");
  if (std::isnan(mass) || mass <= 0.0)
    throw std::invalid_argument("block mass must be > 0 or infinity (got " + std::to_string(mass) + ")");
  if (!std::isfinite(x) || !std::isfinite(y))
    throw std::invalid_argument("block position must be finite");
  if (!(restitution >= 0.0 && restitution <= 1.0))
    throw std::invalid_argument("restitution must be in [0, 1] (got " + std::to_string(restitution) + ")");

  Components& c = w.components;
  const t e{c.create()};
  c.position[e.id] = {x, y};
  c.box[e.id] = {width, height};
  c.color[e.id] = color;
  // Q2 begin
  // Q2 stub: // TODO Q2: store the block's mass in its component `mass` (velocity and
  // Q2 stub: // sum_forces keep their default: the zero vector).
  // Q2 stub: (void)mass;
  c.mass[e.id] = mass;
  // Q2 end
  c.restitution[e.id] = restitution;
  // velocity and sum_forces keep their defaults: zero (Q2).

  Systems& s = w.systems;
  if (s.draw) s.draw->register_entity(e);
  if (s.move) s.move->register_entity(e);
  if (s.forces) s.forces->register_entity(e);
  if (s.collision) s.collision->register_entity(e);
  return e;
}

}  // namespace physics::Block
