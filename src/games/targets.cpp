#include "games/targets.hpp"

#include <algorithm>

#include "course/entities/block.hpp"

namespace physics {

Targets::Targets(const SceneSpec& s, World& w, std::span<const BlockRole> roles)
    : targets_(tagged(roles, "target")), shots_(s.game.shots), shots_left_(s.game.shots), restitution_(s.restitution) {
  const std::vector<EntityId> slings = tagged(roles, "sling");
  if (slings.size() != 1)
    throw SceneError(s.name + ": a target game needs exactly one block with \"tag\": \"sling\" (found " +
                     std::to_string(slings.size()) + ")");
  if (targets_.empty()) throw SceneError(s.name + ": a target game needs at least one block with \"tag\": \"target\"");
  const Components& k = w.components;
  const EntityId e = slings.front();
  sling_ = k.position[e] + Vector{k.box[e].width / 2.0, k.box[e].height / 2.0};
  for (const EntityId t : targets_) strength_.push_back(roles[t].strength);
}

// The shot leaves from the sling whatever the press point: the drag only
// aims (its velocity is the testbed's slingshot's).
bool Targets::launch(World& w, Vector, Vector v) {
  if (shots_left_ == 0) return true;
  const double half = shot_size / 2.0;
  const auto shot = Block::make(w, sling_.x - half, sling_.y - half, shot_size, shot_size, Color{60, 60, 70, 255},
                                shot_mass, restitution_);
  w.components.velocity[shot.id] = v;
  w.components.friction[shot.id] = 0.5;
  --shots_left_;
  since_last_shot_ = 0;
  return true;
}

// A target breaks on the impulse of one step, whatever hit it (the shot, a
// falling crate, the ground under a toppled tower).
Level::Outcome Targets::after_step(World& w) {
  ++since_last_shot_;
  for (const ContactEvents::Touch& t : w.events.touching())
    for (std::size_t i = 0; i < targets_.size(); ++i) {
      const EntityId e = targets_[i];
      if ((t.pair.c == e || t.pair.b == e) && w.alive(e) && t.jn > strength_[i]) {
        w.destroy(e);
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
