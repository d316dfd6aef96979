#include "course/system_defs.hpp"

namespace physics {

Systems::Systems(SystemSet set) {
  if (set.draw) draw.emplace();
  if (set.forces) forces.emplace();
  if (set.move) move.emplace();
  if (set.collision) collision.emplace();
}

SystemSet Systems::declared() const {
  return {draw.has_value(), forces.has_value(), move.has_value(), collision.has_value()};
}

}  // namespace physics
