// Shared by the test files: Boost.Test include and small world builders.
#pragma once
#define BOOST_TEST_DYN_LINK
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "course/game.hpp"
#include "course/system_defs.hpp"

namespace physics::test {

inline constexpr Color grey{128, 128, 128, 255};

// A world with only the physics systems (no Draw), as a headless run has.
inline World physics_world(Params p = {}) { return World(SystemSet{false, true, true, true}, p); }

// The same bits (-0 is not +0; a NaN is itself), not only the same value.
inline bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }
inline bool same_bits(Vector a, Vector b) { return same_bits(a.x, b.x) && same_bits(a.y, b.y); }

// Whether `part` occurs in the text `s` (a message, an output).
inline bool has(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

inline bool overlaps(const Components& c, EntityId a, EntityId b) {
  const auto [p, r] = Rect::mdiff(c.position[a], c.box[a], c.position[b], c.box[b]);
  return Rect::has_origin(p, r);
}

// The Collision system's pass, on the pairs of the world's broad phase.
inline void collide(World& w) { Systems(w).collision->update(w.components, w.course_pairs()); }

// The pairs the broad phase hands the course's pass, with boxes grown by
// `margin` (nothing resolved, so nothing moves and no pair is added).
inline std::vector<Pair> course_candidates(World& w, double margin) {
  w.broadphase.course_margin = margin;
  std::vector<Pair> out;
  for (const Pair p : w.course_pairs()) out.push_back(p);
  return out;
}

// The sheet's loop over every pair of the Collision system's bodies, O(n²):
// the oracle of Collision::update.
struct AllPairs {
  std::vector<Contact> contacts;
  std::size_t count = 0;
};
inline AllPairs update_all_pairs(World& w) {
  AllPairs out;
  const auto ids = w.bodies(SystemId::collision);
  for (std::size_t i = 0; i < ids.size(); ++i)
    for (std::size_t j = i + 1; j < ids.size(); ++j) {
      if (!solvable(w.components, ids[i], ids[j], w.params.substep())) continue;
      Contact contact;
      if (!Collision::resolve(w.components, ids[i], ids[j], &contact)) continue;
      ++out.count;
      out.contacts.push_back(contact);
    }
  return out;
}

}  // namespace physics::test
