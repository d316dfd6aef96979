// The target game (scene key "game": {"kind": "targets", "shots": N},
// docs/games.md): the testbed's slingshot (left drag) launches a heavy block
// from the block tagged "sling" at towers of blocks standing on the ground.
// A block tagged "target" breaks, and is removed, when a contact's normal
// impulse in one step exceeds its "strength"; the level is won when no
// target is left, lost when the shots are spent and the last one has had
// `settle_frames` frames to do its work.
#pragma once

#include "games/level.hpp"

namespace physics {

class Targets final : public Level {
 public:
  static constexpr int shot_size = 30;          // px, square
  static constexpr double shot_mass = 20.0;     // a crate is 1 to 2
  static constexpr int points = 100;            // per target
  static constexpr int settle_frames = 240;     // after the last shot before the level is lost

  Targets(const SceneSpec& s, WorldId w, std::span<const BlockRole> roles);

  bool key(int, bool) override { return false; }
  bool launch(WorldId w, Vec2 from, Vec2 v) override;
  void before_step(WorldId) override {}
  Outcome after_step(WorldId w) override;
  std::vector<std::string> hud() const override;
  BlockRole role_of_new_body() const override { return {"shot"}; }
  std::optional<Vec2> launch_point() const override { return sling_; }

  int targets_left() const { return static_cast<int>(targets_.size()) - broken_; }
  int shots_left() const { return shots_left_; }
  int score() const { return broken_ * points; }

 private:
  Vec2 sling_;  // centre of the launch point
  std::vector<BodyId> targets_;
  std::vector<double> strength_;  // by target
  int shots_, shots_left_, broken_ = 0;
  std::int64_t since_last_shot_ = 0;
  double restitution_;
};

}  // namespace physics
