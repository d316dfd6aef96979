// Collision system (course: systems/collision.ml, questions 5-8).
#pragma once

#include <vector>

#include "component_defs.hpp"

namespace physics {

// One resolved contact, kept for the testbed's overlays and for tests.
struct Contact {
  EntityId c, b;
  Vector penetration;  // the shortest of the four vectors of figure 2 (moves c out of b)
  Vector normal;       // penetration, normalised
  bool approaching;    // whether an impulse was applied (v·n < 0)
};

class Collision : public System<component::position, component::box, component::mass,
                                component::velocity, component::restitution> {
 public:
  // Resolves every registered pair once, in registration order.
  void update(Components& c);

  // Resolves the pair (c, b) as the sheet's detailed algorithm does.
  // Returns whether the boxes overlapped.
  static bool resolve(Components& comps, EntityId c, EntityId b, Contact* out = nullptr);

  // The shortest of the four penetration vectors of s = b ⊖ c (figure 2).
  // Ties go to the first of (s.x, 0), (s.x + s.w, 0), (0, s.y), (0, s.y + s.h):
  // x before y, the negative side before the positive one.
  static Vector penetration(Vector s_pos, Rect s);

  bool record_contacts = false;
  const std::vector<Contact>& contacts() const { return contacts_; }
  std::size_t contact_count() const { return contact_count_; }

 private:
  std::vector<Contact> contacts_;
  std::size_t contact_count_ = 0;
};

}  // namespace physics
