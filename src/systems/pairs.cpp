#include "systems/pairs.hpp"

#include <algorithm>
#include <cmath>

namespace physics {

namespace {
using Bounds = PairFinder::Bounds;

// The box swept over [0, h] at constant velocity, grown by `reach`.
Bounds swept(const Components& k, EntityId e, double h, double reach) {
  const Vector p = k.position[e];
  const Vector q = p + h * k.velocity[e];
  const double w = k.box[e].width, hh = k.box[e].height;
  return {std::min(p.x, q.x) - reach, std::min(p.y, q.y) - reach, std::max(p.x, q.x) + w + reach,
          std::max(p.y, q.y) + hh + reach};
}
}  // namespace

void PairFinder::find(const Components& k, std::span<const EntityId> entities, double h, double reach,
                      std::vector<BodyPair>& out) {
  const std::size_t n = entities.size();
  current_.resize(n);
  bool reuse = built_ && n == entities_.size() && std::equal(entities.begin(), entities.end(), entities_.begin());
  for (std::size_t i = 0; i < n; ++i) {
    const Bounds s = current_[i] = swept(k, entities[i], h, reach);
    // (A NaN fails the test: a rebuild, which handles it.)
    if (!reuse) continue;  // (reuse implies fat_ holds the same n bodies)
    const Bounds& f = fat_[i];
    reuse = f.x0 <= s.x0 && f.y0 <= s.y0 && s.x1 <= f.x1 && s.y1 <= f.y1 &&
            fixed_[i] == !std::isfinite(k.mass[entities[i]]);
  }
  if (!reuse) rebuild(k, entities);
  out.clear();
  out.reserve(grid_.pairs().size());
  for (const PairKey key : grid_.pairs()) {
    const std::uint32_t i = pair_first(key), j = pair_second(key);
    const Bounds& a = current_[i];
    const Bounds& b = current_[j];
    // Closed test: touching boxes are candidates (resting contact). A NaN
    // bound fails it, so a lost body has no pair.
    if (a.x0 <= b.x1 && b.x0 <= a.x1 && a.y0 <= b.y1 && b.y0 <= a.y1) out.push_back({entities[i], entities[j]});
  }
}

void PairFinder::rebuild(const Components& k, std::span<const EntityId> entities) {
  const std::size_t n = entities.size();
  fat_.resize(n);
  boxes_.resize(n);
  fixed_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Bounds& c = current_[i];
    fat_[i] = {c.x0 - fat_margin, c.y0 - fat_margin, c.x1 + fat_margin, c.y1 + fat_margin};
    // Rounded outwards to float: the grid's boxes contain the exact ones, so
    // it finds a superset of the pairs, which the exact test trims.
    boxes_[i] = Aabb::outward(fat_[i].x0, fat_[i].y0, fat_[i].x1, fat_[i].y1);
    fixed_[i] = !std::isfinite(k.mass[entities[i]]);
  }
  grid_.build(boxes_, fixed_);
  entities_.assign(entities.begin(), entities.end());
  built_ = true;
}

void candidate_pairs(const Components& k, std::span<const EntityId> entities, double h, double reach,
                     std::vector<BodyPair>& out) {
  PairFinder().find(k, entities, h, reach, out);
}

void brute_force_pairs(const Components& k, std::span<const EntityId> entities, double h, double reach,
                       std::vector<BodyPair>& out) {
  out.clear();
  const std::size_t n = entities.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Bounds bi = swept(k, entities[i], h, reach);
    for (std::size_t j = i + 1; j < n; ++j) {
      if (!std::isfinite(k.mass[entities[i]]) && !std::isfinite(k.mass[entities[j]])) continue;
      const Bounds bj = swept(k, entities[j], h, reach);
      if (bi.x0 <= bj.x1 && bj.x0 <= bi.x1 && bi.y0 <= bj.y1 && bj.y0 <= bi.y1) out.push_back({entities[i], entities[j]});
    }
  }
}

}  // namespace physics
