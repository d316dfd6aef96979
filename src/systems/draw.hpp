// Draw system (course: systems/draw.ml): fills each block's box in its colour.
// Registering with Draw needs no SDL; only update() (draw.cpp) does, and it is
// built into the game program alone, never into the physics library.
#pragma once

#include "component_defs.hpp"

struct SDL_Renderer;

namespace physics {

class Draw : public System<component::position, component::box, component::color> {
 public:
  void update(const Components& c, SDL_Renderer* renderer) const;
};

}  // namespace physics
