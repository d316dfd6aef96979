// Move system (course: systems/move.ml): x += dt * v.
#pragma once

#include "engine/components.hpp"

namespace physics {

class Move : public System<component::position, component::velocity> {
 public:
  using System::System;  // bound to a world's list (course/system_defs.hpp)
  // dt in ms (the course's 1000/60); velocities are px/ms.
  void update(Components& c, double dt) const;
};

}  // namespace physics
