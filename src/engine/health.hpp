// Physics health: after every step (Game::step, timed as Stage::health), an
// O(n) pass checks that every position and velocity is finite, so a run stops
// on the very frame a value goes bad. The rest is looked at less often, which
// keeps the whole check under 1 % of a step of scenes/gas10k.json (measured:
// docs/numerics.md, "The health check and its cost"): every `escape_period`
// frames, the bodies that left the world are counted; every `overlap_period`
// frames, the course solver's one known failure is looked for: an overlap
// deeper than `deep_overlap` px that is still there a period later (a stack
// sinking, bodies pressed into walls).
// The application reports what it finds (app/headless.cpp, app/testbed.cpp,
// app/cli.cpp: exit code 3); the check itself changes nothing in the world.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "engine/components.hpp"
#include "engine/workers.hpp"

namespace physics {

struct NonFinite {
  EntityId id = 0;
  bool velocity = false;  // else the position
  Vector value{};
  std::int64_t frame = 0;  // after which it was found (1 = the first frame)
};

struct Escape {
  EntityId id = 0;
  std::int64_t frame = 0;
};

struct DeepOverlap {
  EntityId c = 0, b = 0;
  double depth = 0.0;  // px, |penetration| at the second look
  std::int64_t frame = 0;
};

struct Health {
  // Frames between two looks. An escape is counted at the first look that
  // finds the body's centre outside (at most escape_period - 1 frames late; a
  // headless run also counts at its last frame) and reported "by frame N", N
  // the look's. A body pushed into a wall and back between two looks is not
  // seen: the count samples such excursions (gas10k.json: 6 bodies seen at
  // this period, 34 looking every frame, none outside at the end). A count
  // costs ~3 ns a body (the int sizes converted, four compares).
  static constexpr std::int64_t escape_period = 4;
  // A look walks the pairs the step's last course pass began with
  // (BroadPhase::each_course_candidate): no grid of its own.
  static constexpr std::int64_t overlap_period = 60;
  static constexpr double deep_overlap = 1.0;         // px

  // The inside of the world (the walls' inside, else the scene's bounds),
  // set by populate(); bodies from `first_body` on are watched (not the walls).
  bool bounded = false;
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  EntityId first_body = 0;

  std::optional<NonFinite> non_finite;  // the first; the world is not to be stepped again
  std::int64_t escaped = 0;             // bodies whose centre left the inside, each counted once
  std::optional<Escape> first_escape;
  std::optional<DeepOverlap> deep;                // persistent deep overlap, the first seen
  std::optional<std::pair<EntityId, EntityId>> suspect;  // deepest overlap of the last look

  bool finite() const { return !non_finite; }
  void watch(double left, double top, double right, double bottom, EntityId first);

  // The O(n) pass over the components after frame `frame`: the first
  // non-finite body (then nothing else is checked), and new escapes.
  // `workers`: the threads of the look for a non-finite value; none: one.
  void check_bodies(const Components& c, std::int64_t frame, Workers* workers = nullptr);
  // Counts the bodies newly outside (check_bodies does every escape_period).
  void count_escapes(const Components& c, std::int64_t frame);
  // Never counted as escaped: a tile layer's body and its strips' proxies
  // (fixed geometry, which may cover the walls), not bodies that move.
  void ignore(EntityId e) {
    if (out_.size() <= e) out_.resize(static_cast<std::size_t>(e) + 1, 0);
    out_[e] = 1;
  }

 private:
  std::vector<std::uint8_t> out_;  // per body: already counted as escaped
};

// |penetration| of the boxes of c and b (the course's shortest vector), 0 if
// they do not overlap.
double overlap_depth(const Components& k, EntityId c, EntityId b);

}  // namespace physics
