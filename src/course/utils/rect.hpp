// The course's `Rect` module (the archive's src/utils/rect.ml): a rectangle of integer size.
// Its position lives in a separate `position` component, as in the course, so
// the functions below take a position and a Rect side by side.
#pragma once

#include <utility>

#include "course/utils/vect.hpp"

namespace physics {

struct Rect {
  int width = 0;
  int height = 0;

  // Minkowski difference of r1 placed at p1 and r2 placed at p2 (sheet, "mdiff"):
  //   x = x2 - x1 - w1,  y = y2 - y1 - h1,  w = w2 + w1,  h = h2 + h1.
  // mdiff(pc, c, pb, b) is s = b ⊖ c: the set of offsets pb - pc for which the
  // boxes overlap, so the origin lies in it exactly when c and b intersect.
  static std::pair<Vector, Rect> mdiff(Vector p1, Rect r1, Vector p2, Rect r2);

  // True iff (0, 0) is strictly inside the rectangle r placed at p.
  // The border does NOT count: two boxes that merely touch (share an edge after
  // a position correction) are separated, and must not collide again, otherwise
  // a block resting on the floor would be "hit" every frame.
  static bool has_origin(Vector p, Rect r);

  friend constexpr bool operator==(Rect a, Rect b) = default;
};

}  // namespace physics
