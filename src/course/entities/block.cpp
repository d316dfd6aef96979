#include "course/entities/block.hpp"

#include "course/systems/collision.hpp"
#include "course/systems/draw.hpp"
#include "course/systems/forces.hpp"
#include "course/systems/move.hpp"

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

  // Registered with each system the world declared, each bound to its list
  // in the world as Systems(w) binds them (course/system_defs.hpp, which an
  // entity does not include: it sits above the entities); each checks at
  // compile time that a block has the components it needs.
  if (auto* l = w.stage(SystemId::draw)) Draw(*l).register_entity(e);
  if (auto* l = w.stage(SystemId::move)) Move(*l).register_entity(e);
  if (auto* l = w.stage(SystemId::forces)) Forces(*l).register_entity(e);
  if (auto* l = w.stage(SystemId::collision)) Collision(*l, w.pass).register_entity(e);
  return e;
}

}  // namespace physics::Block
