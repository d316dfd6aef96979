// A game on the engine: the rules that turn a scene into a level (scene key
// "game", docs/games.md). The testbed owns the world and the input; a Level
// says what the game's keys do, what a slingshot launch does, what happens
// before and after each physics step (a player's run and jump, a coin
// collected, a target broken), whether the level is won or lost, and what
// the HUD says. Everything a Level decides depends only on the world and
// the keys it was given, so a replayed input gives the same game.
//
// A game uses the world through the public API (include/physics/physics.hpp)
// alone, as a game maker's program would: the testbed hands it the WorldId of
// its world (api::View). Its bodies' tags come from the scene (BlockRole).
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "input/keys.hpp"
#include "physics/physics.hpp"
#include "scene/scene.hpp"

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
  virtual bool launch(WorldId w, Vec2 from, Vec2 v) = 0;
  // Around the step: the controls' effect before, the rules after.
  virtual void before_step(WorldId w) = 0;
  virtual Outcome after_step(WorldId w) = 0;
  // The game's HUD lines (score, what is left, the keys).
  virtual std::vector<std::string> hud() const = 0;
  // A body the game made (launch), for the testbed's list of roles.
  virtual BlockRole role_of_new_body() const { return {}; }
  // Where its launches leave from, if not from the press point (the
  // testbed draws the drag from there).
  virtual std::optional<Vec2> launch_point() const { return std::nullopt; }
  // What the testbed's camera follows in a world larger than the window
  // (the player), if anything.
  virtual std::optional<Vec2> focus() const { return std::nullopt; }
};

// A body of the scene's and its role; `index` is its place in creation order.
struct Tagged {
  BodyId body;
  const BlockRole* role;
  std::size_t index;
};
// The bodies of `w` tagged `tag`, in creation order; `roles` are the scene's,
// one per body of the freshly made world but its tile layers, which come last
// and have none (SceneError if they do not match).
std::vector<Tagged> tagged(WorldId w, std::span<const BlockRole> roles, const std::string& tag);
std::vector<BodyId> ids(const std::vector<Tagged>& t);

}  // namespace physics
