#include "utils/rect.hpp"

namespace physics {

std::pair<Vector, Rect> Rect::mdiff(Vector p1, Rect r1, Vector p2, Rect r2) {
  const Vector p{p2.x - p1.x - r1.width, p2.y - p1.y - r1.height};
  // Sums of ints: the caller guarantees sizes well below INT_MAX / 2.
  const Rect r{r2.width + r1.width, r2.height + r1.height};
  return {p, r};
}

bool Rect::has_origin(Vector p, Rect r) {
  return p.x < 0.0 && 0.0 < p.x + r.width && p.y < 0.0 && 0.0 < p.y + r.height;
}

}  // namespace physics
