// The public API's small value types: a 2D vector, an axis-aligned box and a
// colour. Units are the engine's: px for lengths, ms for time; y grows
// downwards (screen coordinates); a body's position is its top-left corner.
// Only standard headers: a game includes this without the engine's sources.
#pragma once

#include <cstdint>

namespace physics {

// A 2D vector of doubles (px, px/ms, px/ms^2 or a force, by context).
struct Vec2 {
  double x = 0.0;
  double y = 0.0;

  friend constexpr Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
  friend constexpr Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
  friend constexpr Vec2 operator-(Vec2 a) { return {-a.x, -a.y}; }
  friend constexpr Vec2 operator*(double k, Vec2 v) { return {k * v.x, k * v.y}; }
  friend constexpr bool operator==(Vec2, Vec2) = default;
};

// An axis-aligned box from `lower` (top-left, smallest x and y) to `upper`.
struct Aabb {
  Vec2 lower;
  Vec2 upper;

  constexpr Vec2 size() const { return upper - lower; }
  friend constexpr bool operator==(const Aabb&, const Aabb&) = default;
};

// An RGBA colour, 8 bits a channel; the engine only stores it for drawing.
struct Color {
  std::uint8_t r = 0, g = 0, b = 0, a = 255;
  friend constexpr bool operator==(Color, Color) = default;
};

}  // namespace physics
