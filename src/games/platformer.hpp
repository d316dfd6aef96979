// The platformer (scene key "game": {"kind": "platformer"}, docs/games.md):
// the block tagged "player" is a box mover (physics/mover.hpp): the level
// makes it fixed and moves it with move_and_slide before each step, running
// with the arrow keys and jumping with Space (or Up) only while it stands on
// a floor; Down with Space on a one-way floor (a block or a tile) drops
// through it. Blocks tagged "coin" (sensors) are collected when the player's
// box meets them, then removed; meeting a block tagged "goal" once every
// coin is collected wins the level (before, the HUD says what is missing);
// falling below the world loses it (the testbed restarts it). A block tagged
// "platform" moves with its velocity and turns back after "travel" px; the
// mover rides it.
#pragma once

#include <optional>

#include "games/level.hpp"
#include "physics/mover.hpp"

namespace physics {

class Platformer final : public Level {
 public:
  static constexpr double run_speed = 0.25;   // px/ms, relative to what the player stands on
  static constexpr double jump_speed = 0.7;   // px/ms, upwards
  static constexpr int drop_frames = 6;       // frames one-way faces let the player through after Down + Space

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
  bool grounded() const { return moved_.on_floor; }
  Vec2 player_velocity() const { return velocity_; }  // the mover's (its body's is 0: the mover places it)
  const MoverResult& moved() const { return moved_; }  // the last move_and_slide's

 private:
  struct Lift {
    BodyId body;
    Vec2 start;
    Vec2 dir;       // unit: its first velocity's direction
    double travel;  // px from start along dir before it turns back
  };
  void stand(WorldId w);
  void move_platforms() const;
  bool on_one_way() const;
  void meet(WorldId w, Aabb swept);

  BodyId player_;
  double bottom_;  // px: below this the player has fallen off the world
  Vec2 gravity_;
  double dt_;
  std::vector<BodyId> coins_, goals_;
  std::vector<Lift> lifts_;
  MoverDef mover_ = default_mover_def();
  MoverResult moved_;
  Vec2 velocity_;
  Aabb before_{};  // the player's box before the last move
  bool left_ = false, right_ = false, down_ = false, jump_ = false;
  int dropping_ = 0;  // frames left with pass_one_way
  int collected_ = 0;
  bool won_ = false, at_goal_ = false, touching_goal_ = false;  // at_goal_: touching a goal, coins still missing
};

}  // namespace physics
