// Shared by the test files: Boost.Test include and small world builders.
#pragma once
#define BOOST_TEST_DYN_LINK
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "entities/block.hpp"
#include "world.hpp"

namespace physics::test {

inline constexpr Color grey{128, 128, 128, 255};

// A world with only the physics systems (no Draw), as a headless run has.
inline World physics_world(Params p = {}) { return World(SystemSet{false, true, true, true}, p); }

inline bool overlaps(const Components& c, EntityId a, EntityId b) {
  const auto [p, r] = Rect::mdiff(c.position[a], c.box[a], c.position[b], c.box[b]);
  return Rect::has_origin(p, r);
}

}  // namespace physics::test
