// The Minkowski sweep: when does the origin lie strictly inside a box that
// moves in a straight line? Shared by CCD (engine/ccd.cpp: the box is the
// Minkowski difference of two bodies, moving at their relative velocity) and
// the ray cast (engine/query.cpp: the difference of a body and a point, the
// ray's start, moving opposite to the ray), so that a ray and a body's sweep
// agree to the last bit on when a box is entered and by which face.
#pragma once

#include <algorithm>
#include <limits>

#include "course/utils/rect.hpp"
#include "course/utils/vect.hpp"

namespace physics {

// An open interval of times (empty when !(lo < hi)).
struct Interval {
  double lo, hi;
};

// Open interval of times at which s + d·t < 0 < s + size + d·t: the origin is
// strictly inside the moving Minkowski box along one axis.
inline Interval slab(double s, double size, double d) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  if (d == 0.0) return (s < 0.0 && 0.0 < s + size) ? Interval{-inf, inf} : Interval{inf, -inf};
  const double a = -s / d, b = -(s + size) / d;
  return d > 0.0 ? Interval{b, a} : Interval{a, b};
}

// Both axes of the box at s + d·t of the given size: the origin is strictly
// inside it during (enter, exit) when enter < exit, and enters it across an
// x face when along_x (x wins a tie, as in Collision::penetration).
struct Sweep {
  double enter, exit;
  bool along_x;
};

inline Sweep sweep(Vector s, Rect size, Vector d) {
  const Interval ix = slab(s.x, size.width, d.x);
  const Interval iy = slab(s.y, size.height, d.y);
  return {std::max(ix.lo, iy.lo), std::min(ix.hi, iy.hi), ix.lo >= iy.lo};
}

}  // namespace physics
