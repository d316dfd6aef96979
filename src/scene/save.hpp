// --save: a world's state as a scene file, to be loaded and run on.
//
// The scene it writes holds the world's parameters, its bodies as they are
// now (position, velocity, pending force, mass, colour, restitution,
// friction and contact rules; the walls of question 1 as the "walls" key
// they came from), every other key of the scene it came from (name, style,
// systems, game), each body's part in a game (tag, strength, a platform's
// travel, with where it started and its direction, so that it turns back
// where it would have) and a "state" key with the frame and whatever the
// next step reads beyond the bodies: the stable solver's warm-start impulses
// and, after the first frame, the auto mode's choice state.
// Loading it and running k frames gives, bit for bit, the dump of running
// on k frames without stopping, in every mode (tests/test_save.cpp).
// Destroyed bodies are left out: the others' ids close up, in order.
// What a game's level keeps beyond its bodies (coins collected, shots left,
// the keys held) is not saved: a saved level starts again from its bodies.
#pragma once

#include <span>
#include <string>

#include "scene/scene.hpp"
#include "engine/world.hpp"

namespace physics::Save {

// `from`: the scene `w` was made from (after the command line's overrides);
// `roles`: its bodies' parts in the game, by entity id (a body past its end
// has none); `file`: where the scene will be written, so that a relative
// game.next names the same file from there ("": game.next as it was).
SceneSpec scene_of(const World& w, const SceneSpec& from, std::span<const BlockRole> roles,
                   const std::string& file = "");
// The same with the roles of the scene's own bodies (expanded again).
SceneSpec scene_of(const World& w, const SceneSpec& from);

// game.next as a path from the folder of `file`: the next level of `from`
// (read from its file: next_path), named so that it resolves from there.
std::string next_from(const GameSpec& from, const std::string& file);

}  // namespace physics::Save
