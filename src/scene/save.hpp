// --save: a world's state as a scene file, to be loaded and run on.
//
// The scene it writes holds the world's parameters, its bodies as they are
// now (position, velocity, pending force, mass, colour, restitution,
// friction and contact rules; the walls of question 1 as the "walls" key
// they came from) and a "state" key with the frame and whatever the next
// step reads beyond the bodies: the stable solver's warm-start impulses.
// Loading it and running k frames gives, bit for bit, the dump of running
// on k frames without stopping, in every mode (tests/test_save.cpp).
// Destroyed bodies are left out: the others' ids close up, in order.
#pragma once

#include "scene/scene.hpp"
#include "engine/world.hpp"

namespace physics::Save {

// `from`: the scene `w` was made from (after the command line's overrides).
SceneSpec scene_of(const World& w, const SceneSpec& from);

}  // namespace physics::Save
