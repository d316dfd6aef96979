#include "course/entities/block.hpp"

#include <cassert>
#include <cmath>

namespace physics::Block {

t make(World& w, double x, double y, int width, int height, Color color, double mass,
       double restitution) {
  // The caller gives a valid block: the scene validator (scene/scene.cpp)
  // rejects bad input with a message; these only catch a programming error.
  assert(width > 0 && height > 0 && width <= max_block_size && height <= max_block_size);
  assert(mass > 0.0);  // or infinity (a fixed block); false for NaN
  assert(std::isfinite(x) && std::isfinite(y));
  assert(restitution >= 0.0 && restitution <= 1.0);

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
