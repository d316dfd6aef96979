#include "engine/events.hpp"

#include <algorithm>

#include "engine/contact.hpp"

namespace physics {

// The pairs whose boxes overlap or lie within `gap` at the end of the step,
// with their normal and depth (engine/contact.hpp's best_axis).
void ContactEvents::add_resting(const Components& k, std::span<const EntityId> bodies) {
  broadphase_.find(k, bodies, 0.0, gap / 2, pairs_, PairRule::reported);
  for (const Pair p : pairs_) {
    const auto [axis, separation] = best_axis(k, p.c, p.b);
    if (separation > gap) continue;
    const Touch t{p, axis_normal[axis], separation < 0.0 ? -separation : 0.0, 0.0, 0.0};
    step_.push_back(owner.empty() ? t : named(t));
  }
}

ContactEvents::Touch ContactEvents::named(Touch t) const {
  const auto name = [&](EntityId e) { return e < owner.size() ? owner[e] : e; };
  t.pair = {name(t.pair.c), name(t.pair.b)};
  if (t.pair.b < t.pair.c) std::swap(t.pair.c, t.pair.b), t.normal = -t.normal;
  return t;
}

// This step's touches, one per pair, in pair order: impulses summed, the
// normal and depth of the end of the step when the boxes still touch, else
// of the solver's last contact.
std::vector<ContactEvents::Touch> ContactEvents::merged() {
  // Stable: the resting entries (added last) come after a pair's solver entries.
  std::stable_sort(step_.begin(), step_.end(), [](const Touch& x, const Touch& y) { return x.pair.key() < y.pair.key(); });
  std::vector<Touch> out;
  for (const Touch& t : step_) {
    if (out.empty() || !(out.back().pair == t.pair)) {
      out.push_back(t);
      continue;
    }
    Touch& m = out.back();
    m.jn += t.jn, m.jt += t.jt;
    m.normal = t.normal, m.depth = t.depth;
  }
  step_.clear();
  return out;
}

void ContactEvents::finish(const Components& k, std::span<const EntityId> bodies, std::int64_t frame) {
  events_.clear();
  if (!enabled) return;
  add_resting(k, bodies);
  std::vector<Touch> now = merged();
  // Both lists are in pair order: a merge gives begins and ends in pair order.
  const auto event = [&](EventKind kind, const Touch& t) {
    events_.push_back({frame, kind, t.pair.c, t.pair.b, t.normal, t.depth, t.jn, t.jt});
  };
  std::size_t i = 0, j = 0;
  while (i < current_.size() || j < now.size()) {
    if (j == now.size() || (i < current_.size() && current_[i].pair.key() < now[j].pair.key())) {
      Touch ended = current_[i++];
      ended.depth = 0.0, ended.jn = 0.0, ended.jt = 0.0;  // nothing exchanged this step
      event(EventKind::end, ended);
    } else if (i == current_.size() || now[j].pair.key() < current_[i].pair.key()) {
      event(EventKind::begin, now[j++]);
    } else {
      ++i, ++j;
    }
  }
  current_ = std::move(now);
}

}  // namespace physics
