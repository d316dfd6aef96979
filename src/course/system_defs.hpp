// The systems of a world (course: system_defs.ml instantiates Draw, Move,
// Forces and Collision). A scene declares which ones it uses (SystemSet,
// engine/system_set.hpp); the others are never created, so nothing registers
// with them and nothing updates them.
//
// The world holds each declared system's bodies (World::stage) and the
// Collision pass's contacts (World::pass); Systems(w) binds the course's
// systems to them, so that registering with a system adds the body to the
// world's list, which the engine's own stages read too. Bind them where they
// are used (Systems s(w);): they are views of w and cannot outlive it.
#pragma once

#include <optional>

#include "course/systems/collision.hpp"
#include "course/systems/draw.hpp"
#include "course/systems/forces.hpp"
#include "course/systems/move.hpp"
#include "engine/world.hpp"

namespace physics {

struct Systems {
  std::optional<Draw> draw;
  std::optional<Forces> forces;
  std::optional<Move> move;
  std::optional<Collision> collision;

  explicit Systems(World& w);
};

}  // namespace physics
