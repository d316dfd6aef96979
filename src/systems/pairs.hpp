// Candidate pairs for the numerics options (CCD, stable solver).
//
// This is the one place where the numerics code finds the pairs it looks at:
// every pair (i < j, in the Collision system's registration order) except two
// infinite masses, whose boxes, each grown by `reach` (px) on every side plus
// the distance it travels in `h` ms at its current velocity, overlap (touching
// counts). It is a sort-and-sweep on x, kept here so that the project's
// broadphase can replace the body of candidate_pairs() without touching its
// callers (Ccd, ContactSolver), as long as it returns a superset of these pairs
// in registration order. brute_force_pairs() is the all-pairs definition,
// for the tests.
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
void brute_force_pairs(const Components& k, std::span<const EntityId> entities, double h, double reach,
                       std::vector<BodyPair>& out);

}  // namespace physics
