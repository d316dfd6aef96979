// The platformer (scene key "game": {"kind": "platformer"}, docs/games.md):
// the block tagged "player" runs with the arrow keys and jumps with Space
// (or Up) only while it stands on something, which the world's contact
// events tell (a touching pair whose normal pushes the player up). Blocks
// tagged "coin" (sensors) are collected when the player's contact with them
// begins, then removed; touching a block tagged "goal" once every coin is
// collected wins the level (before, the HUD says what is missing);
// falling below the world loses it (the testbed restarts it). A block tagged
// "platform" moves with its velocity and turns back after "travel" px, and
// carries the player by friction.
#pragma once

#include <optional>

#include "games/level.hpp"

namespace physics {

class Platformer final : public Level {
 public:
  static constexpr double run_speed = 0.25;   // px/ms, relative to what the player stands on
  static constexpr double jump_speed = 0.7;   // px/ms, upwards

  Platformer(const SceneSpec& s, WorldId w, std::span<const BlockRole> roles);

  bool key(int code, bool down) override;
  bool launch(WorldId, Vec2, Vec2) override { return true; }  // no slingshot here
  void before_step(WorldId w) override;
  Outcome after_step(WorldId w) override;
  std::vector<std::string> hud() const override;
  std::optional<Vec2> focus() const override;  // the player's centre

  BodyId player() const { return player_; }
  int coins() const { return collected_; }
  int coins_total() const { return static_cast<int>(coins_.size()); }
  bool grounded() const { return ground_.has_value(); }

 private:
  struct Mover {
    BodyId body;
    Vec2 start;
    Vec2 dir;       // unit: its first velocity's direction
    double travel;  // px from start along dir before it turns back
  };
  void move_platforms() const;
  void find_contacts(WorldId w);

  BodyId player_;
  double bottom_;  // px: below this the player has fallen off the world
  std::vector<BodyId> coins_, goals_;
  std::vector<Mover> movers_;
  bool left_ = false, right_ = false, jump_ = false;
  std::optional<BodyId> ground_;  // what the player stands on
  bool wall_left_ = false, wall_right_ = false;  // a solid side face touches the player there
  int collected_ = 0;
  bool won_ = false, at_goal_ = false, touching_goal_ = false;  // at_goal_: touching a goal, coins still missing
};

}  // namespace physics
