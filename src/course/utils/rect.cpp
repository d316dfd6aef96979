#include "course/utils/rect.hpp"

namespace physics {

std::pair<Vector, Rect> Rect::mdiff(Vector p1, Rect r1, Vector p2, Rect r2) {
  // Q6 begin
  // Q6 stub: // TODO Q6: the Minkowski difference of r1 placed at p1 and r2 placed at p2:
  // Q6 stub: //   x = x2 - x1 - w1,  y = y2 - y1 - h1,  w = w2 + w1,  h = h2 + h1.
  // Q6 stub: (void)p1, (void)r1, (void)p2, (void)r2;
  // Q6 stub: return {};
  const Vector p{p2.x - p1.x - r1.width, p2.y - p1.y - r1.height};
  // Sums of ints: the caller guarantees sizes well below INT_MAX / 2.
  const Rect r{r2.width + r1.width, r2.height + r1.height};
  return {p, r};
  // Q6 end
}

bool Rect::has_origin(Vector p, Rect r) {
  // Q7 begin
  // Q7 stub: // TODO Q7: true iff the point (0, 0) is inside the rectangle r placed at p
  // Q7 stub: // (border excluded: two boxes that merely touch do not collide).
  // Q7 stub: (void)p, (void)r;
  // Q7 stub: return false;
  return p.x < 0.0 && 0.0 < p.x + r.width && p.y < 0.0 && 0.0 < p.y + r.height;
  // Q7 end
}

}  // namespace physics
