// The sheet's physics stages as the engine runs them: Forces (Q5), Move
// (Q3) and the Collision pass (Q8), over the bodies of a stage, in their
// registration order.
//
// The course's systems (course/systems/) are the student's answers, which
// the exercise mode replaces by stubs; the engine's own step (engine/step.cpp:
// the public API, the benchmark), which runs no course code, runs these. They are
// the course's formulas, operation for operation and in the same order, so
// a step through them gives the same bits as one through the course's
// systems: tests/test_geometry.cpp checks it on random worlds.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "engine/components.hpp"
#include "engine/contact.hpp"
#include "engine/pairs.hpp"
#include "engine/workers.hpp"

namespace physics {

// Forces: for each finite mass m, v += h·(Σf/m + gravity), then Σf = 0; an
// infinite mass is left as it is. `workers`: the threads of the loop over
// the bodies (each body its own: the same bits for any number); none: one.
void apply_forces(Components& c, std::span<const EntityId> bodies, double h, Vector gravity,
                  Workers* workers = nullptr);

// Move: x += h·v, infinite masses included (a moving platform). `workers`: as apply_forces'.
void move_bodies(Components& c, std::span<const EntityId> bodies, double h, Workers* workers = nullptr);

// The Collision pass's answer for the pair (c, b), Collision::resolve's:
// nothing for two infinite masses or boxes that do not overlap (false);
// otherwise the position correction shared by the speeds, the impulse
// along the normal if the pair approaches, friction, and the contact in
// *out if given (true).
bool resolve_pair(Components& k, EntityId c, EntityId b, Contact* out = nullptr);

// The pass over the broad phase's course pairs, Collision::update's: the
// number of pairs resolved; their contacts appended to *contacts if given.
std::size_t resolve_pairs(Components& k, BroadPhase::CoursePairs pairs, std::vector<Contact>* contacts = nullptr);

}  // namespace physics
