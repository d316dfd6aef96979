// Collision system (course: systems/collision.ml, questions 6-8).
#pragma once

#include <vector>

#include "engine/components.hpp"
#include "engine/contact.hpp"
#include "engine/pairs.hpp"
#include "engine/world.hpp"

namespace physics {

class Collision : public System<component::position, component::box, component::mass,
                                component::velocity, component::restitution> {
 public:
  // Bound to a world's Collision list and its pass's contacts (World::pass).
  Collision(std::vector<EntityId>& bodies, PassContacts& pass)
      : System(bodies), record_contacts(pass.record_contacts), contacts_(pass.contacts),
        contact_count_(pass.contact_count) {}

  // Q8. The sheet's loop: for each pair (c, b) of registered bodies, resolve
  // it. The engine's broad phase hands the pairs over in the sheet's order
  // (c registered before b, then by b), leaving out only pairs whose boxes
  // cannot touch; the result is bit for bit the one of looping over every
  // pair (tests/test_broadphase.cpp keeps that loop as the oracle).
  void update(Components& c, BroadPhase::CoursePairs pairs);

  // Q8. Resolves the pair (c, b) as the sheet's detailed algorithm does.
  // Returns whether the boxes overlapped.
  static bool resolve(Components& comps, EntityId c, EntityId b, Contact* out = nullptr);

  // Q8. The shortest of the four penetration vectors of s = b ⊖ c (figure 2).
  // Ties go to the first of (s.x, 0), (s.x + s.w, 0), (0, s.y), (0, s.y + s.h):
  // x before y, the negative side before the positive one.
  static Vector penetration(Vector s_pos, Rect s);

  // The contacts of the last update(), for the testbed's overlays and tests:
  // the world's (World::pass), which the engine's pass fills the same way.
  bool& record_contacts;
  const std::vector<Contact>& contacts() const { return contacts_; }
  std::size_t contact_count() const { return contact_count_; }

 private:
  std::vector<Contact>& contacts_;
  std::size_t& contact_count_;
};

}  // namespace physics
