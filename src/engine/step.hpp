// One frame of a world (the sheet's main loop: "call update in the main
// program"): for each substep, the Forces, Move and Collision systems in the
// sheet's order, with the engine's numerics stages between them, then the
// step's contact events and health checks. The course's Game::step and the
// public API's physics::step(WorldId) both run this one function.
#pragma once

#include "engine/world.hpp"

namespace physics {

void step(World& w);

}  // namespace physics
