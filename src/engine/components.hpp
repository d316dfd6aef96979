// Components (course: component_defs.ml), stored by the engine.
//
// The engine owns the component storage, so that it depends on no course
// code but the value types of course/utils: its stages, the course's systems
// (course/systems/) and entities (course/entities/) all read and write these
// arrays. course/component_defs.hpp names them in the course tree.
//
// Each component is a tag naming one property and its default value, as in
//   class velocity = object val velocity = Component.def Vector.zero ... end
// The values are stored in Components, one dense array per component, indexed
// by entity id: the "object" of the OCaml code is spread across these arrays.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "engine/ecs.hpp"
#include "physics/math.hpp"
#include "course/utils/rect.hpp"
#include "course/utils/vect.hpp"

namespace physics {

// Color (r, g, b, a: 8 bits each) is the public API's (include/physics/math.hpp).

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

// Beyond the sheet (docs/game-physics.md): the engine's game physics. Every
// default leaves the sheet's physics exactly as it is.
// Coulomb friction coefficient, >= 0. A pair uses sqrt(mu_a mu_b) (Box2D's
// rule: one frictionless material makes the pair frictionless).
struct friction { static constexpr double def = 0.0; };
}  // namespace component

// The face of a one-way platform that stops bodies (`none`: every face).
enum class Face : std::uint8_t { none, up, down, left, right };

// Which pairs a body takes part in (docs/game-physics.md):
//  - category/mask: a pair interacts only if each one's category shares a
//    bit with the other's mask; filtered pairs never enter a pair list;
//  - sensor: its overlaps give contact events, never a correction or an impulse;
//  - one_way: it stops bodies only on that face.
struct ContactRules {
  std::uint32_t category = 1;
  std::uint32_t mask = 0xFFFFFFFFu;
  bool sensor = false;
  Face one_way = Face::none;
  // The defaults: the body meets every other body on every face.
  bool plain() const { return category == 1 && mask == 0xFFFFFFFFu && !sensor && one_way == Face::none; }
  friend bool operator==(const ContactRules&, const ContactRules&) = default;
};

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
  std::vector<double> friction;

  // A new entity id with every component at its default value.
  EntityId create();
  std::size_t size() const { return position.size(); }
  void reserve(std::size_t n);

  // Contact rules are set through set_rules, which counts the bodies whose
  // rules are not plain: while there are none (every scene of the sheet),
  // the broad phase skips the rules' test altogether.
  const ContactRules& rules(EntityId e) const { return rules_[e]; }
  void set_rules(EntityId e, const ContactRules& r);
  bool any_rules() const { return ruled_ != 0; }

 private:
  std::vector<ContactRules> rules_;
  std::size_t ruled_ = 0;  // bodies whose rules are not plain()
};

}  // namespace physics
