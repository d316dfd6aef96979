// The systems of a world (course: system_defs.ml instantiates Draw, Move,
// Forces and Collision). A scene declares which ones it uses (SystemSet,
// engine/system_set.hpp); the others are never created, so nothing registers
// with them and nothing updates them.
#pragma once

#include <optional>

#include "course/systems/collision.hpp"
#include "course/systems/draw.hpp"
#include "course/systems/forces.hpp"
#include "course/systems/move.hpp"
#include "engine/system_set.hpp"

namespace physics {

struct Systems {
  std::optional<Draw> draw;
  std::optional<Forces> forces;
  std::optional<Move> move;
  std::optional<Collision> collision;

  explicit Systems(SystemSet set = {});
  SystemSet declared() const;
};

}  // namespace physics
