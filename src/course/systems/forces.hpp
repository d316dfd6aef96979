// Forces system (course: systems/forces.ml): turns the sum of the forces of
// the frame into a velocity change, then clears it.
#pragma once

#include "engine/components.hpp"

namespace physics {

class Forces : public System<component::sum_forces, component::mass, component::velocity> {
 public:
  using System::System;  // bound to a world's list (course/system_defs.hpp)
  // For each finite mass m: v += dt * (Σf / m + gravity); Σf = 0.
  // `gravity` is an acceleration (px/ms²) applied to every finite mass, the
  // "perpetual force" the sheet mentions; zero in the course's scenes.
  void update(Components& c, double dt, Vector gravity = Vector::zero()) const;
};

}  // namespace physics
