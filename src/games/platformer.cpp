#include "games/platformer.hpp"

#include <algorithm>
#include <cmath>

namespace physics {

Platformer::Platformer(const SceneSpec& s, World& w, std::span<const BlockRole> roles)
    : bottom_(s.height + 100.0), coins_(tagged(roles, "coin")), goals_(tagged(roles, "goal")) {
  const std::vector<EntityId> players = tagged(roles, "player");
  if (players.size() != 1)
    throw SceneError(s.name + ": a platformer needs exactly one block with \"tag\": \"player\" (found " +
                     std::to_string(players.size()) + ")");
  player_ = players.front();
  for (const EntityId e : tagged(roles, "platform")) {
    const Vector v = w.components.velocity[e];
    const double speed = Vector::norm(v);
    if (!(speed > 0.0 && std::isfinite(roles[e].travel)))
      throw SceneError(s.name + ": a block tagged \"platform\" needs a \"velocity\" and a \"travel\" (body " +
                       std::to_string(e) + ")");
    movers_.push_back({e, roles[e].travel_from, roles[e].travel_dir, roles[e].travel});  // scene.cpp resolves them
  }
}

bool Platformer::key(int code, bool down) {
  switch (code) {
    case key::left: left_ = down; return true;
    case key::right: right_ = down; return true;
    case key::up:
    case key::space:
      if (down) jump_ = true;  // a press, consumed by the next step
      return true;
    default: return false;
  }
}

// A platform goes back and forth between its start and `travel` px along
// its first velocity: its velocity flips at either end.
void Platformer::move_platforms(World& w) const {
  Components& k = w.components;
  for (const Mover& m : movers_) {
    const Vector v = k.velocity[m.body];
    const double along = Vector::dot(k.position[m.body] - m.start, m.dir), ahead = Vector::dot(v, m.dir);
    if ((along >= m.travel && ahead > 0.0) || (along <= 0.0 && ahead < 0.0)) k.velocity[m.body] = -1.0 * v;
  }
}

void Platformer::before_step(World& w) {
  move_platforms(w);
  Components& k = w.components;
  const Vector under = ground_ ? k.velocity[*ground_] : Vector{};
  Vector& v = k.velocity[player_];
  // Running sets the speed relative to the ground; letting go leaves the
  // player to friction (so a moving platform carries a player standing still).
  // Not into a wall: pressed against one, friction would hold the player up
  // on its side.
  const bool run_right = right_ && !left_ && !wall_right_, run_left = left_ && !right_ && !wall_left_;
  if (run_right || run_left) v.x = under.x + (run_right ? run_speed : -run_speed);
  if (jump_ && ground_) v.y = under.y - jump_speed;
  jump_ = false;
}

// The player stands on what touches it with a normal pushing it up (y grows
// downwards), and meets a wall where the normal pushes it sideways; sensors
// aside.
void Platformer::find_contacts(const World& w) {
  ground_.reset();
  wall_left_ = wall_right_ = false;
  for (const ContactEvents::Touch& t : w.events.touching()) {
    const bool a = t.pair.c == player_, b = t.pair.b == player_;
    if (!a && !b) continue;
    const EntityId other = a ? t.pair.b : t.pair.c;
    if (w.components.any_rules() && w.components.rules(other).sensor) continue;
    const Vector push = a ? t.normal : -1.0 * t.normal;  // the normal pushes a away from b
    if (push.y < -0.5) ground_ = other;
    if (push.x > 0.5) wall_left_ = true;
    if (push.x < -0.5) wall_right_ = true;
  }
}

Level::Outcome Platformer::after_step(World& w) {
  find_contacts(w);
  for (const ContactEvent& e : w.events.events()) {
    if (e.kind != EventKind::begin || (e.a != player_ && e.b != player_)) continue;
    const EntityId other = e.a == player_ ? e.b : e.a;
    if (std::find(coins_.begin(), coins_.end(), other) != coins_.end() && w.alive(other)) {
      w.destroy(other);
      ++collected_;
    }
    if (std::find(goals_.begin(), goals_.end(), other) != goals_.end()) won_ = true;
  }
  if (won_) return Outcome::won;
  const double y = w.components.position[player_].y;
  return std::isfinite(y) && y < bottom_ ? Outcome::playing : Outcome::lost;
}

std::vector<std::string> Platformer::hud() const {
  std::string line = "coins " + std::to_string(collected_) + "/" + std::to_string(coins_.size());
  line += won_ ? "   GOAL! level won" : ground_ ? "   on ground" : "   in the air";
  return {line, "arrows: run   Space/Up: jump   R: restart"};
}

}  // namespace physics
