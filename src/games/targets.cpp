#include "games/targets.hpp"

#include <algorithm>

namespace physics {

Targets::Targets(const SceneSpec& s, WorldId w, std::span<const BlockRole> roles)
    : shots_(s.game.shots), shots_left_(s.game.shots), restitution_(s.restitution) {
  const std::vector<BodyId> slings = ids(tagged(w, roles, "sling"));
  if (slings.size() != 1)
    throw SceneError(s.name + ": a target game needs exactly one block with \"tag\": \"sling\" (found " +
                     std::to_string(slings.size()) + ")");
  for (const Tagged& t : tagged(w, roles, "target")) {
    targets_.push_back(t.body);
    strength_.push_back(t.role->strength);
  }
  if (targets_.empty()) throw SceneError(s.name + ": a target game needs at least one block with \"tag\": \"target\"");
  const Vec2 size = physics::size(slings.front());
  sling_ = position(slings.front()) + Vec2{size.x / 2.0, size.y / 2.0};
}

// The shot leaves from the sling whatever the press point: the drag only
// aims (its velocity is the testbed's slingshot's). A click (no drag, no
// velocity) aims nowhere and spends nothing.
bool Targets::launch(WorldId w, Vec2, Vec2 v) {
  if (shots_left_ == 0 || (v.x == 0.0 && v.y == 0.0)) return true;
  const double half = shot_size / 2.0;
  BodyDef shot = default_body_def();
  shot.position = {sling_.x - half, sling_.y - half};
  shot.size = {shot_size, shot_size};
  shot.color = {60, 60, 70, 255};
  shot.mass = shot_mass;
  shot.restitution = restitution_;
  shot.velocity = v;
  shot.friction = 0.5;
  create_body(w, shot);
  --shots_left_;
  since_last_shot_ = 0;
  return true;
}

// A target breaks on the impulse of one step, whatever hit it (the shot, a
// falling crate, the ground under a toppled tower).
Level::Outcome Targets::after_step(WorldId w) {
  ++since_last_shot_;
  for (const Touching& t : touching(w))
    for (std::size_t i = 0; i < targets_.size(); ++i) {
      const BodyId e = targets_[i];
      if ((t.a == e || t.b == e) && is_valid(e) && t.normal_impulse > strength_[i]) {
        destroy_body(e);
        ++broken_;
      }
    }
  if (targets_left() == 0) return Outcome::won;
  if (shots_left_ == 0 && since_last_shot_ > settle_frames) return Outcome::lost;
  return Outcome::playing;
}

std::vector<std::string> Targets::hud() const {
  std::string line = "targets left " + std::to_string(targets_left()) + "   shots " + std::to_string(shots_left_) + "/" +
                     std::to_string(shots_) + "   score " + std::to_string(score());
  if (targets_left() == 0) line += "   ALL DOWN! level won";
  return {line, "left drag: aim and shoot from the sling   R: restart"};
}

}  // namespace physics
