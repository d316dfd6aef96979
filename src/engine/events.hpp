// Contact events (beyond the sheet; docs/game-physics.md): after each step,
// the pairs that started touching (`begin`) and stopped touching (`end`).
//
// A pair touches in a step if a solver exchanged an impulse or a correction
// between its bodies during the step (a contact of the course pass, of the
// stable solver or of CCD: an impact can leave the pair apart by the end of
// the step), or if their boxes overlap or lie within `gap` px of each other
// when the step ends (resting contact, and the overlaps of sensors, which no
// solver sees). Pairs the contact rules filter out never touch.
//
// Events come in increasing pair order (c, then b, as the pair lists), so a
// run's events are the same on every machine. Off by default: a world that
// does not ask for events pays nothing.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "engine/components.hpp"
#include "engine/pairs.hpp"

namespace physics {

enum class EventKind : std::uint8_t { begin, end };

struct ContactEvent {
  std::int64_t frame;  // the step after which it happened (World::frame)
  EventKind kind;
  EntityId a, b;       // a registered before b
  Vector normal;       // unit, pushes a away from b
  double depth;        // px, >= 0: the boxes' overlap at the end of the step
  double jn, jt;       // normal and tangential impulses exchanged during the step
};

class ContactEvents {
 public:
  static constexpr double gap = 0.5;  // px: boxes this close still touch (the stable solver's margin)

  bool enabled = false;
  // By entity id, the body an event names for it (TileSet::owners: a tile
  // strip's proxy is named as its layer); empty, or past its end: itself.
  std::vector<EntityId> owner;

  // A solver's contact during the step; the impulses of one pair add up.
  void touch(EntityId c, EntityId b, Vector normal, double jn, double jt) {
    if (!enabled) return;
    if (owner.empty()) step_.push_back({{c, b}, normal, 0.0, jn, jt});
    else step_.push_back(named({{c, b}, normal, 0.0, jn, jt}));
  }
  // After the step: this step's events from the touches and the boxes.
  void finish(const Components& k, std::span<const EntityId> bodies, std::int64_t frame);

  // The last step's events.
  std::span<const ContactEvent> events() const { return events_; }
  // The pairs touching after the last step, in pair order.
  struct Touch {
    Pair pair;
    Vector normal;
    double depth = 0.0, jn = 0.0, jt = 0.0;
  };
  std::span<const Touch> touching() const { return current_; }

 private:
  void add_resting(const Components& k, std::span<const EntityId> bodies);
  // t with its bodies named through `owner`, the earlier one first.
  Touch named(Touch t) const;
  std::vector<Touch> merged();

  std::vector<Touch> step_;     // this step's touches, in the order found
  std::vector<Touch> current_;  // after the last step, sorted by pair
  std::vector<ContactEvent> events_;
  BroadPhase broadphase_;       // its own: the world's keeps its fat grid for the solvers
  std::vector<Pair> pairs_;
};

}  // namespace physics
