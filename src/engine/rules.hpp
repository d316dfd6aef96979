// Contact rules (engine/components.hpp, ContactRules): which pairs the solvers
// see. The one place the broad phase asks, for every stage (the course pass,
// CCD, the stable solver), so a filtered pair, a sensor's pair or a body
// passing through a one-way platform never enters a solver's pair list.
#pragma once

#include <cstdint>

#include "engine/components.hpp"

namespace physics {

// Category and mask: each one's category shares a bit with the other's mask.
inline bool filters_meet(const ContactRules& a, const ContactRules& b) {
  return (a.category & b.mask) != 0 && (b.category & a.mask) != 0;
}

// px. How far a body may already be past a one-way face and still be
// stopped by it, beyond what its approach covered in the step.
inline constexpr double one_way_slop = 0.01;

// Whether the one-way platform p stops the body b now: b must be on the
// side of p's face, allowing for how far its approach towards the face
// (relative speed along the face's inward normal) carried it in h ms. A body
// coming from behind, or already part-way through, passes.
bool one_way_stops(const Components& k, EntityId p, EntityId b, double h);

// Whether the solvers see the pair (c, b) in a step of h ms: the filters
// meet, neither is a sensor, and each one-way platform of the pair stops
// the other.
bool solvable(const Components& k, EntityId c, EntityId b, double h);

// Whether contact events report the pair: the filters meet, and a solver
// sees it or one of the two is a sensor.
bool reported(const Components& k, EntityId c, EntityId b, double h);

// Which of the two a pair list keeps.
enum class PairRule : std::uint8_t { solvable, reported };
inline bool keeps(PairRule rule, const Components& k, EntityId c, EntityId b, double h) {
  return rule == PairRule::solvable ? solvable(k, c, b, h) : reported(k, c, b, h);
}

}  // namespace physics
