#include "engine/health.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

#include "engine/geometry.hpp"

namespace physics {

void Health::watch(double left, double top, double right, double bottom, EntityId first) {
  bounded = true;
  x0 = left, y0 = top, x1 = right, y1 = bottom;
  first_body = first;
}

namespace {
bool all_finite(Vector v) { return std::isfinite(v.x) && std::isfinite(v.y); }

// Whether any of the n doubles at d is inf or NaN. The exponent bits are all
// ones only for inf and NaN, and then adding one at the exponent's lowest bit
// carries into the sign bit, which no finite value reaches: OR-ing the sums
// needs only 64-bit AND, ADD and OR, which SSE2 has (a 64-bit max or compare
// it has not, and the loop stayed scalar). Four independent lanes of fixed
// count let -O2 vectorise it: 4x faster than the max over exponents.
bool any_non_finite(const double* d, std::size_t n) {
  constexpr std::uint64_t exponent = 0x7ff0000000000000u, carry = 0x0010000000000000u;
  std::uint64_t lane[4] = {};
  std::size_t i = 0;
  for (; i + 4 <= n; i += 4)
    for (std::size_t l = 0; l < 4; ++l) lane[l] |= (std::bit_cast<std::uint64_t>(d[i + l]) & exponent) + carry;
  std::uint64_t m = lane[0] | lane[1] | lane[2] | lane[3];
  for (; i < n; ++i) m |= (std::bit_cast<std::uint64_t>(d[i]) & exponent) + carry;
  return (m >> 63) != 0;
}
}  // namespace

void Health::check_bodies(const Components& c, std::int64_t frame, Workers* workers) {
  if (non_finite) return;
  const std::size_t n = c.size();
  static_assert(sizeof(Vector) == 2 * sizeof(double));
  // (n > 0: an empty world's data() is null, and ->x through it undefined)
  const bool bad = n > 0 && workers_or_one(workers).or_over_ranges(n, min_parallel_items, [&](int, std::size_t begin, std::size_t end) {
    const std::size_t count = 2 * (end - begin);
    return static_cast<std::uint8_t>(any_non_finite(&c.position[begin].x, count) ||
                                     any_non_finite(&c.velocity[begin].x, count));
  }) != 0;
  for (std::size_t e = 0; bad && e < n; ++e) {
    const Vector p = c.position[e], v = c.velocity[e];
    if (all_finite(p) && all_finite(v)) continue;
    const auto id = static_cast<EntityId>(e);
    non_finite = all_finite(p) ? NonFinite{id, true, v, frame} : NonFinite{id, false, p, frame};
    return;
  }
  if (bounded && frame % escape_period == 0) count_escapes(c, frame);
}

void Health::count_escapes(const Components& c, std::int64_t frame) {
  const std::size_t n = c.size();
  if (out_.size() < n) out_.resize(n, 0);
  // Locals: the rare store into out_ (bytes, which may alias anything) would
  // otherwise make the compiler reload the arrays and bounds for every body.
  const Vector* pos = c.position.data();
  const Rect* box = c.box.data();
  const double left = x0, top = y0, right = x1, bottom = y1;
  for (std::size_t e = first_body; e < n; ++e) {
    const double cx = pos[e].x + box[e].width * 0.5, cy = pos[e].y + box[e].height * 0.5;
    if (((cx < left) | (cx > right) | (cy < top) | (cy > bottom)) == 0 || out_[e]) continue;
    out_[e] = 1;
    if (escaped++ == 0) first_escape = Escape{static_cast<EntityId>(e), frame};
  }
}

double overlap_depth(const Components& k, EntityId c, EntityId b) {
  const auto [s_pos, s] = minkowski_difference(k.position[c], k.box[c], k.position[b], k.box[b]);
  if (!contains_origin(s_pos, s)) return 0.0;
  const Vector pen = penetration_vector(s_pos, s);
  return std::abs(pen.x) + std::abs(pen.y);  // one of them is 0
}

}  // namespace physics
