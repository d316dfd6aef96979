// The games the engine ships (docs/games.md), by the name of the scene key
// "game.kind". The one file that knows every game: the interface
// (games/level.hpp) knows none, each game knows only the interface, and the
// testbed asks here for a scene's level. Adding a game: its files, and one
// line in registry.cpp.
#pragma once

#include <memory>
#include <span>

#include "games/level.hpp"

namespace physics {

// The level of a scene with a game (s.game.kind "platformer" or "targets")
// on the world `w` (the testbed's, through api::View), whose bodies have
// `roles` (by creation order). Enables the world's contact events. Throws SceneError naming the scene when the kind
// is unknown or the level lacks what its game needs (a platformer without a
// block tagged "player").
std::unique_ptr<Level> make_level(const SceneSpec& s, WorldId w, std::span<const BlockRole> roles);

}  // namespace physics
