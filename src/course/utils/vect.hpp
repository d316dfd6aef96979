// The course's `Vector` module (the archive's src/utils/vect.ml): a 2D vector of doubles.
// Kept a plain value type; the OCaml functions are static members so the sheet's
// `Vector.add a b` reads `Vector::add(a, b)` here. Operators are thin aliases.
#pragma once

namespace physics {

struct Vector {
  double x = 0.0;
  double y = 0.0;

  static constexpr Vector zero() { return {0.0, 0.0}; }
  static constexpr Vector add(Vector a, Vector b) { return {a.x + b.x, a.y + b.y}; }
  static constexpr Vector sub(Vector a, Vector b) { return {a.x - b.x, a.y - b.y}; }
  static constexpr Vector mult(double k, Vector v) { return {k * v.x, k * v.y}; }
  static constexpr double dot(Vector a, Vector b) { return a.x * b.x + a.y * b.y; }
  static double norm(Vector v);
  // Unit vector in the direction of v; the zero vector stays zero (no NaN).
  static Vector normalize(Vector v);
  static constexpr bool is_zero(Vector v) { return v.x == 0.0 && v.y == 0.0; }

  friend constexpr Vector operator+(Vector a, Vector b) { return add(a, b); }
  friend constexpr Vector operator-(Vector a, Vector b) { return sub(a, b); }
  friend constexpr Vector operator-(Vector a) { return {-a.x, -a.y}; }
  friend constexpr Vector operator*(double k, Vector v) { return mult(k, v); }
  friend constexpr bool operator==(Vector a, Vector b) = default;
};

}  // namespace physics
