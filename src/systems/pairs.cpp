#include "systems/pairs.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

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
  // Sort the boxes by their left edge and only look at the ones that start
  // before a box ends (sweep and prune on x): the same pairs as the all-pairs
  // loop (brute_force_pairs), which the 10 000-body cases cannot afford.
  // A NaN bound sorts nowhere in particular and fails every comparison, so a
  // lost body simply has no pair.
  std::vector<std::uint32_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = static_cast<std::uint32_t>(i);
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    if (bounds[a].x0 != bounds[b].x0) return bounds[a].x0 < bounds[b].x0;
    return a < b;
  });
  std::vector<std::pair<std::uint32_t, std::uint32_t>> found;
  for (std::size_t oi = 0; oi < n; ++oi) {
    const std::uint32_t i = order[oi];
    const Bounds bi = bounds[i];
    const bool i_fixed = !std::isfinite(k.mass[entities[i]]);
    for (std::size_t oj = oi + 1; oj < n && bounds[order[oj]].x0 <= bi.x1; ++oj) {
      const std::uint32_t j = order[oj];
      const Bounds bj = bounds[j];
      if (i_fixed && !std::isfinite(k.mass[entities[j]])) continue;  // two walls never collide
      // Closed test: touching boxes are candidates (resting contact).
      if (bj.x1 >= bi.x0 && bi.y0 <= bj.y1 && bj.y0 <= bi.y1) found.emplace_back(std::min(i, j), std::max(i, j));
    }
  }
  // Registration order, as the all-pairs loop gives them.
  std::sort(found.begin(), found.end());
  out.reserve(found.size());
  for (const auto& [i, j] : found) out.push_back({entities[i], entities[j]});
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
