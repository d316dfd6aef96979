// The engine's own box geometry: the Minkowski difference of two boxes, the
// strict origin test and the penetration vector. They are the sheet's
// Rect::mdiff (Q6), Rect::has_origin (Q7) and Collision::penetration (Q8),
// which the exercise mode asks the student to write: the engine's CCD, health
// check and queries must not run the student's answers (nor stop working
// while they are stubs), so they call these. The formulas and their order are
// the course's, operation for operation, so both give the same bits;
// tests/test_geometry.cpp checks that they agree on random and edge inputs
// (touching boxes, ties, zero sizes).
#pragma once

#include <cmath>
#include <utility>

#include "course/utils/rect.hpp"
#include "course/utils/vect.hpp"

namespace physics {

// s = r2 ⊖ r1, r1 placed at p1 and r2 at p2 (the sheet's mdiff):
//   x = x2 - x1 - w1,  y = y2 - y1 - h1,  w = w2 + w1,  h = h2 + h1.
// The origin lies in it exactly when the boxes overlap.
inline std::pair<Vector, Rect> minkowski_difference(Vector p1, Rect r1, Vector p2, Rect r2) {
  const Vector p{p2.x - p1.x - r1.width, p2.y - p1.y - r1.height};
  // Sums of ints: sizes are bounded far below INT_MAX / 2 (engine/limits.hpp).
  const Rect r{r2.width + r1.width, r2.height + r1.height};
  return {p, r};
}

// Whether (0, 0) lies strictly inside r placed at p: the border does not
// count, so boxes that merely touch do not overlap.
inline bool contains_origin(Vector p, Rect r) {
  return p.x < 0.0 && 0.0 < p.x + r.width && p.y < 0.0 && 0.0 < p.y + r.height;
}

// The shortest of the four vectors from the origin to the edges of s placed
// at p: (p.x, 0), (p.x + s.w, 0), (0, p.y), (0, p.y + s.h). A tie goes to
// the first of them: x before y, the negative side before the positive one.
inline Vector penetration_vector(Vector p, Rect s) {
  const Vector candidates[4] = {{p.x, 0.0}, {p.x + s.width, 0.0}, {0.0, p.y}, {0.0, p.y + s.height}};
  Vector best = candidates[0];
  double best_len = std::abs(p.x);
  for (int i = 1; i < 4; ++i) {
    const double len = std::abs(candidates[i].x) + std::abs(candidates[i].y);  // one is 0
    if (len < best_len) {
      best = candidates[i];
      best_len = len;
    }
  }
  return best;
}

}  // namespace physics
