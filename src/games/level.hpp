// A game on the engine: the rules that turn a scene into a level (scene key
// "game", docs/games.md). The testbed owns the world and the input; a Level
// says what the game's keys do, what a slingshot launch does, what happens
// before and after each physics step (a player's run and jump, a coin
// collected, a target broken), whether the level is won or lost, and what
// the HUD says. Everything a Level decides depends only on the world and
// the keys it was given, so a replayed input gives the same game.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "input/keys.hpp"
#include "scene/scene.hpp"
#include "engine/world.hpp"

namespace physics {

class Level {
 public:
  enum class Outcome { playing, won, lost };

  virtual ~Level() = default;
  // A key pressed (down) or released; true if the game used it (then the
  // testbed does not).
  virtual bool key(int code, bool down) = 0;
  // The testbed's slingshot: a launch from `from` at velocity v. True if the
  // game took it (and then made its own body, if any).
  virtual bool launch(World& w, Vector from, Vector v) = 0;
  // Around Game::step: the controls' effect before, the rules after.
  virtual void before_step(World& w) = 0;
  virtual Outcome after_step(World& w) = 0;
  // The game's HUD lines (score, what is left, the keys).
  virtual std::vector<std::string> hud() const = 0;
  // A body the game made (launch), for the testbed's list of roles.
  virtual BlockRole role_of_new_body() const { return {}; }
  // Where its launches leave from, if not from the press point (the
  // testbed draws the drag from there).
  virtual std::optional<Vector> launch_point() const { return std::nullopt; }
};

// The ids of the bodies tagged `tag`, in id order.
std::vector<EntityId> tagged(std::span<const BlockRole> roles, const std::string& tag);

}  // namespace physics
