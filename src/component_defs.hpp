// Components (course: component_defs.ml).
//
// Each component is a tag naming one property and its default value, as in
//   class velocity = object val velocity = Component.def Vector.zero ... end
// The values are stored in Components, one dense array per component, indexed
// by entity id: the "object" of the OCaml code is spread across these arrays.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "ecs.hpp"
#include "utils/rect.hpp"
#include "utils/vect.hpp"

namespace physics {

struct Color {
  std::uint8_t r = 0, g = 0, b = 0, a = 255;
  friend constexpr bool operator==(Color, Color) = default;
};

inline constexpr double infinity = std::numeric_limits<double>::infinity();

namespace component {
// Top-left corner, in px; y grows downwards (SDL).
struct position { static constexpr Vector def{}; };
struct box { static constexpr Rect def{}; };
struct color { static constexpr Color def{}; };
// Q2. mass in arbitrary units; `infinity` for fixed bodies (walls, platforms).
// The course's default is 0.0; every body created by Block::make sets its own.
struct mass { static constexpr double def = 0.0; };
// Q2. px/ms; starts at zero.
struct velocity { static constexpr Vector def{}; };
// Q2. Sum of the forces applied during this frame; Forces turns it into a
// velocity change and resets it to zero.
struct sum_forces { static constexpr Vector def{}; };
// Coefficient of restitution of the body's material, in [0, 1]. A pair uses
// the smaller of its two values (see Collision).
struct restitution { static constexpr double def = 1.0; };
}  // namespace component

// Dense storage: one array per component, all of the same length (one slot per
// entity ever created). An entity without some component simply never has that
// slot read, because no system requiring it accepts the entity.
struct Components {
  std::vector<Vector> position;
  std::vector<Rect> box;
  std::vector<Color> color;
  std::vector<double> mass;
  std::vector<Vector> velocity;
  std::vector<Vector> sum_forces;
  std::vector<double> restitution;

  // A new entity id with every component at its default value.
  EntityId create();
  std::size_t size() const { return position.size(); }
  void reserve(std::size_t n);
};

}  // namespace physics
