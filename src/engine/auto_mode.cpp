#include "engine/auto_mode.hpp"

#include <algorithm>
#include <cmath>

#include "engine/pairs.hpp"

namespace physics {

bool AutoMode::plan(const Components& k, std::span<const EntityId> bodies, double h, Vector gravity) {
  // A scene under gravity starts on the solver: its bodies may be resting
  // on each other already, and three course passes would let a pile sink.
  if (stats.course_substeps + stats.solver_substeps == 0 && !Vector::is_zero(gravity)) hold_left_ = hold + 1;
  if (hold_left_ > 0) --hold_left_;
  const std::size_t n = k.size();
  reach_.resize(n);
  start_.assign(n, 0.0);
  // Half of a body's thinnest side plus the world's thinnest: an overlap up
  // to that is pushed out on the side it came from.
  const auto side = [&](EntityId e) { return static_cast<double>(std::min(k.box[e].width, k.box[e].height)); };
  double thinnest = infinity;
  for (const EntityId e : bodies) thinnest = std::min(thinnest, side(e));
  for (const EntityId e : bodies) reach_[e] = 0.5 * (side(e) + thinnest);
  mark_fast(k, bodies, h);
  // Under gravity, the solver too when bodies bounce (the course's pass
  // reflects the whole substep's kick: the e = 1 long run's energy creeps
  // up) or when a body is fast: what it lands on may be a pile, and CCD
  // alone would carry it down the pile one impact at a time, without end.
  bool bouncy = false;
  if (!Vector::is_zero(gravity))
    for (const EntityId e : bodies)
      if (std::isfinite(k.mass[e]) && k.restitution[e] > 0.0) {
        bouncy = true;
        break;
      }
  solver_path_ = hold_left_ > 0 || (!Vector::is_zero(gravity) && (bouncy || fast_count_ > 0));
  ++(solver_path_ ? stats.solver_substeps : stats.course_substeps);
  return solver_path_;
}

// Fast: Move's displacement, h·|v| (the velocity after Forces), exceeds the
// body's reach.
void AutoMode::mark_fast(const Components& k, std::span<const EntityId> bodies, double h) {
  fast_.resize(k.size());
  fast_count_ = 0;
  for (const EntityId e : bodies) {
    const Vector d = h * k.velocity[e];
    const bool fast = Vector::dot(d, d) > reach_[e] * reach_[e];  // squared: no root per body
    fast_[e] = fast;
    fast_count_ += fast;
  }
}

void AutoMode::after_solver(const Components& k, std::span<const EntityId> bodies,
                            std::span<const ContactConstraint> contacts, double h) {
  stats.contacts += static_cast<std::int64_t>(contacts.size());
  pressed_.clear();
  for (const ContactConstraint& ct : contacts)
    if (ct.wc > 0.0 && ct.wb > 0.0 && ct.lambda + ct.lambda2 > 0.0) pressed_.push_back(Pair{ct.c, ct.b}.key());
  count_pressed();
  // The bodies still fast after the solver's impulses are swept from their
  // impact time on: the solver's impact_time shifted each body hit before
  // touching so that its line from then on is its motion (the earliest of
  // its impacts, as there).
  mark_fast(k, bodies, h);
  if (fast_count_ == 0) return;
  for (const ContactConstraint& ct : contacts) {
    if (ct.resting || !(ct.toi > 0.0)) continue;
    for (const EntityId e : {ct.c, ct.b})
      if (std::isfinite(k.mass[e])) start_[e] = start_[e] == 0.0 ? ct.toi : std::min(start_[e], ct.toi);
  }
}

void AutoMode::after_course_pass(const Components& k, std::span<const Contact> contacts) {
  pressed_.clear();
  for (const Contact& c : contacts)
    if (std::isfinite(k.mass[c.c]) && std::isfinite(k.mass[c.b]))
      pressed_.push_back(Pair{c.c, c.b}.key());
  count_pressed();
}

// Each pair of finite bodies pressed together this substep, with the number
// of substeps in a row it has been (pressed_ in, runs_ kept): `persist` in a
// row holds the solver.
void AutoMode::count_pressed() {
  // Mostly in order already (pairs come in registration order).
  if (!std::is_sorted(pressed_.begin(), pressed_.end())) std::sort(pressed_.begin(), pressed_.end());
  next_runs_.clear();
  auto old = runs_.begin();
  for (const std::uint64_t key : pressed_) {
    while (old != runs_.end() && old->first < key) ++old;
    const int run = old != runs_.end() && old->first == key ? old->second + 1 : 1;
    next_runs_.emplace_back(key, run);
    if (run >= persist) hold_left_ = hold;
  }
  std::swap(runs_, next_runs_);
}

}  // namespace physics
