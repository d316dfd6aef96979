#include "course/utils/vect.hpp"

#include <cmath>

namespace physics {

// hypot avoids overflow for huge coordinates (1e200 squared is inf) at a small cost.
double Vector::norm(Vector v) { return std::hypot(v.x, v.y); }

Vector Vector::normalize(Vector v) {
  const double n = norm(v);
  if (n == 0.0) return zero();
  return {v.x / n, v.y / n};
}

}  // namespace physics
