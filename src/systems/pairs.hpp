// Candidate pairs for the numerics options (CCD, stable solver).
//
// This is the one place where the numerics code finds the pairs it looks at:
// every pair (i < j, in the Collision system's registration order) except two
// infinite masses, whose boxes, each grown by `reach` (px) on every side plus
// the distance it travels in `h` ms at its current velocity, overlap. It is a
// plain O(n^2) loop on purpose; a broadphase (sweep and prune, grid) can
// replace the body of candidate_pairs() without touching its callers, as long
// as it returns a superset of these pairs in the same order.
#pragma once

#include <span>
#include <vector>

#include "component_defs.hpp"

namespace physics {

struct BodyPair {
  EntityId c, b;  // c registered before b
};

void candidate_pairs(const Components& k, std::span<const EntityId> entities, double h, double reach,
                     std::vector<BodyPair>& out);

}  // namespace physics
