#include "games/platformer.hpp"

#include <algorithm>
#include <cmath>

namespace physics {

namespace {
double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
bool holds(const std::vector<BodyId>& v, BodyId b) { return std::find(v.begin(), v.end(), b) != v.end(); }
}  // namespace

Platformer::Platformer(const SceneSpec& s, WorldId w, std::span<const BlockRole> roles)
    : bottom_(s.height + 100.0), gravity_(world_def(w).gravity), dt_(world_def(w).dt),
      coins_(ids(tagged(w, roles, "coin"))), goals_(ids(tagged(w, roles, "goal"))) {
  const std::vector<BodyId> players = ids(tagged(w, roles, "player"));
  if (players.size() != 1)
    throw SceneError(s.name + ": a platformer needs exactly one block with \"tag\": \"player\" (found " +
                     std::to_string(players.size()) + ")");
  player_ = players.front();
  // A mover: fixed (the solvers never move it, move_and_slide places it); its velocity is the level's.
  velocity_ = velocity(player_);
  set_mass(player_, fixed_mass);
  set_restitution(player_, 0.0);
  set_velocity(player_, {});
  before_ = bounds(player_);
  stand(w);
  for (const Tagged& p : tagged(w, roles, "platform")) {
    const Vec2 v = velocity(p.body);
    const double speed = std::hypot(v.x, v.y);
    if (!(speed > 0.0 && std::isfinite(p.role->travel)))
      throw SceneError(s.name + ": a block tagged \"platform\" needs a \"velocity\" and a \"travel\" (body " +
                       std::to_string(p.index) + ")");
    // Where it starts and its direction: the scene's (scene.cpp resolves them; a saved level's platform on its
    // way keeps its own).
    const auto from = p.role->travel_from, dir = p.role->travel_dir;
    lifts_.push_back({p.body, {from.x, from.y}, {dir.x, dir.y}, p.role->travel});
  }
}

// What the player stands on at the start (a saved level's player on the
// moving platform rides it from the first step, as in the run saved): the
// first body but a sensor under its box, within a pixel. A player saved in
// the air starts from rest: the level's velocity is not saved.
void Platformer::stand(WorldId w) {
  const Aabb b = bounds(player_);
  for (const BodyId o : query_box(w, {{b.lower.x, b.upper.y}, {b.upper.x, b.upper.y + 1.0}}))
    if (!(o == player_) && !is_sensor(o)) {
      moved_.on_floor = true;
      moved_.floor = o;
      return;
    }
}

bool Platformer::key(int code, bool down) {
  switch (code) {
    case key::left: left_ = down; return true;
    case key::right: right_ = down; return true;
    case key::down: down_ = down; return true;
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
  for (const Lift& m : lifts_) {
    const Vec2 v = velocity(m.body);
    const double along = dot(position(m.body) - m.start, m.dir), ahead = dot(v, m.dir);
    if ((along >= m.travel && ahead > 0.0) || (along <= 0.0 && ahead < 0.0)) set_velocity(m.body, -1.0 * v);
  }
}

// Whether the player stands on a one-way block or a one-way tile.
bool Platformer::on_one_way() const {
  if (!moved_.on_floor || !is_valid(moved_.floor)) return false;
  if (!is_tile_layer(moved_.floor)) return one_way(moved_.floor) == OneWay::up;
  for (const MoverHit& h : moved_.hits)
    if (h.body == moved_.floor && h.normal.y < 0.0) return tile_at(h.body, h.column, h.row) == TileKind::one_way_up;
  return false;
}

// Running sets the speed (the mover adds its floor's motion); letting go
// stops it on a floor and keeps its momentum in the air. A jump needs a
// floor; Down with it on a one-way floor drops through instead.
void Platformer::before_step(WorldId) {
  move_platforms();
  const bool run_right = right_ && !left_, run_left = left_ && !right_;
  Vec2 v = velocity_;
  if (run_right || run_left) v.x = run_right ? run_speed : -run_speed;
  else if (moved_.on_floor) v.x = 0.0;
  if (jump_ && moved_.on_floor) {
    if (down_ && on_one_way()) dropping_ = drop_frames;
    else v.y = -jump_speed;
  }
  jump_ = false;
  v = v + dt_ * gravity_;  // the world's gravity acts on finite masses only: the mover adds its own
  mover_.pass_one_way = dropping_ > 0;
  dropping_ = std::max(0, dropping_ - 1);
  before_ = bounds(player_);
  moved_ = move_and_slide(player_, v, mover_, moved_);
  velocity_ = moved_.velocity;
}

// The coins and goals the player's box met on its way (the box around where
// it was and where it is: it passes through sensors).
void Platformer::meet(WorldId w, Aabb swept) {
  touching_goal_ = false;
  for (const BodyId b : query_box(w, swept)) {
    if (holds(coins_, b) && is_valid(b)) {
      destroy_body(b);
      ++collected_;
    }
    if (holds(goals_, b)) touching_goal_ = true;
  }
}

Level::Outcome Platformer::after_step(WorldId w) {
  const Aabb now = bounds(player_);
  meet(w, {{std::min(before_.lower.x, now.lower.x), std::min(before_.lower.y, now.lower.y)},
           {std::max(before_.upper.x, now.upper.x), std::max(before_.upper.y, now.upper.y)}});
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
  line += won_ ? "   GOAL! level won" : moved_.on_floor ? "   on ground" : "   in the air";
  if (at_goal_) line += "   the flag wants every coin first";
  return {line, "arrows: run   Space/Up: jump   Down+Space: drop through   R: restart"};
}

std::optional<Vec2> Platformer::focus() const {
  const Vec2 s = size(player_);
  return position(player_) + Vec2{s.x / 2.0, s.y / 2.0};
}

}  // namespace physics
