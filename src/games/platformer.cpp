#include "games/platformer.hpp"

#include <algorithm>
#include <cmath>

namespace physics {

namespace {
double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
}  // namespace

Platformer::Platformer(const SceneSpec& s, WorldId w, std::span<const BlockRole> roles)
    : bottom_(s.height + 100.0), coins_(ids(tagged(w, roles, "coin"))), goals_(ids(tagged(w, roles, "goal"))) {
  const std::vector<BodyId> players = ids(tagged(w, roles, "player"));
  if (players.size() != 1)
    throw SceneError(s.name + ": a platformer needs exactly one block with \"tag\": \"player\" (found " +
                     std::to_string(players.size()) + ")");
  player_ = players.front();
  for (const Tagged& p : tagged(w, roles, "platform")) {
    const Vec2 v = velocity(p.body);
    const double speed = std::hypot(v.x, v.y);
    if (!(speed > 0.0 && std::isfinite(p.role->travel)))
      throw SceneError(s.name + ": a block tagged \"platform\" needs a \"velocity\" and a \"travel\" (body " +
                       std::to_string(p.index) + ")");
    // Where it starts and its direction: the scene's (scene.cpp resolves them; a saved level's platform on its
    // way keeps its own).
    const auto from = p.role->travel_from, dir = p.role->travel_dir;
    movers_.push_back({p.body, {from.x, from.y}, {dir.x, dir.y}, p.role->travel});
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
void Platformer::move_platforms() const {
  for (const Mover& m : movers_) {
    const Vec2 v = velocity(m.body);
    const double along = dot(position(m.body) - m.start, m.dir), ahead = dot(v, m.dir);
    if ((along >= m.travel && ahead > 0.0) || (along <= 0.0 && ahead < 0.0)) set_velocity(m.body, -1.0 * v);
  }
}

void Platformer::before_step(WorldId) {
  move_platforms();
  const Vec2 under = ground_ ? velocity(*ground_) : Vec2{};
  Vec2 v = velocity(player_);
  // Running sets the speed relative to the ground; letting go leaves the
  // player to friction (so a moving platform carries a player standing still).
  // Not into a wall: pressed against one, friction would hold the player up
  // on its side.
  const bool run_right = right_ && !left_ && !wall_right_, run_left = left_ && !right_ && !wall_left_;
  if (run_right || run_left) v.x = under.x + (run_right ? run_speed : -run_speed);
  if (jump_ && ground_) v.y = under.y - jump_speed;
  if (run_right || run_left || (jump_ && ground_)) set_velocity(player_, v);
  jump_ = false;
}

// The player stands on what touches it with a normal pushing it up (y grows
// downwards), and meets a wall where the normal pushes it sideways; sensors
// aside.
void Platformer::find_contacts(WorldId w) {
  ground_.reset();
  touching_goal_ = false;
  wall_left_ = wall_right_ = false;
  for (const Touching& t : touching(w)) {
    const bool a = t.a == player_, b = t.b == player_;
    if (!a && !b) continue;
    const BodyId other = a ? t.b : t.a;
    if (std::find(goals_.begin(), goals_.end(), other) != goals_.end()) touching_goal_ = true;
    if (is_sensor(other)) continue;
    const Vec2 push = a ? t.normal : -1.0 * t.normal;  // the normal pushes a away from b
    if (push.y < -0.5) ground_ = other;
    if (push.x > 0.5) wall_left_ = true;
    if (push.x < -0.5) wall_right_ = true;
  }
}

Level::Outcome Platformer::after_step(WorldId w) {
  find_contacts(w);
  for (const TouchEvent& e : contact_events(w)) {
    if (!e.begin || (!(e.a == player_) && !(e.b == player_))) continue;
    const BodyId other = e.a == player_ ? e.b : e.a;
    if (std::find(coins_.begin(), coins_.end(), other) != coins_.end() && is_valid(other)) {
      destroy_body(other);
      ++collected_;
    }
    if (std::find(goals_.begin(), goals_.end(), other) != goals_.end()) touching_goal_ = true;
  }
  // The flag wins once every coin is taken, whether the player reached it
  // last or takes the last coin while touching it.
  at_goal_ = touching_goal_ && collected_ < coins_total();
  if (touching_goal_ && !at_goal_) won_ = true;
  if (won_) return Outcome::won;
  const double y = position(player_).y;
  return std::isfinite(y) && y < bottom_ ? Outcome::playing : Outcome::lost;
}

std::vector<std::string> Platformer::hud() const {
  std::string line = "coins " + std::to_string(collected_) + "/" + std::to_string(coins_.size());
  line += won_ ? "   GOAL! level won" : ground_ ? "   on ground" : "   in the air";
  if (at_goal_) line += "   the flag wants every coin first";
  return {line, "arrows: run   Space/Up: jump   R: restart"};
}

std::optional<Vec2> Platformer::focus() const {
  const Vec2 s = size(player_);
  return position(player_) + Vec2{s.x / 2.0, s.y / 2.0};
}

}  // namespace physics
