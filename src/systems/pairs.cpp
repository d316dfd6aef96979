#include "systems/pairs.hpp"

#include <algorithm>
#include <cmath>

namespace physics {

namespace {
struct Bounds {
  double x0, y0, x1, y1;
};

// The box swept over [0, h] at constant velocity, grown by `reach`.
Bounds swept(const Components& k, EntityId e, double h, double reach) {
  const Vector p = k.position[e];
  const Vector q = p + h * k.velocity[e];
  const double w = k.box[e].width, hh = k.box[e].height;
  return {std::min(p.x, q.x) - reach, std::min(p.y, q.y) - reach, std::max(p.x, q.x) + w + reach,
          std::max(p.y, q.y) + hh + reach};
}
}  // namespace

void candidate_pairs(const Components& k, std::span<const EntityId> entities, double h, double reach,
                     std::vector<BodyPair>& out) {
  out.clear();
  const std::size_t n = entities.size();
  std::vector<Bounds> bounds(n);
  for (std::size_t i = 0; i < n; ++i) bounds[i] = swept(k, entities[i], h, reach);
  for (std::size_t i = 0; i < n; ++i) {
    const EntityId c = entities[i];
    const bool c_fixed = !std::isfinite(k.mass[c]);
    const Bounds bc = bounds[i];
    for (std::size_t j = i + 1; j < n; ++j) {
      const EntityId b = entities[j];
      if (c_fixed && !std::isfinite(k.mass[b])) continue;  // two walls never collide
      const Bounds bb = bounds[j];
      // Closed test: touching boxes are candidates (resting contact). A NaN
      // bound fails every comparison and drops the pair, which is the safe
      // side for a body that is already lost.
      if (bc.x0 <= bb.x1 && bb.x0 <= bc.x1 && bc.y0 <= bb.y1 && bb.y0 <= bc.y1) out.push_back({c, b});
    }
  }
}

}  // namespace physics
