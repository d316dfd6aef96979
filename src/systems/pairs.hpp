// Candidate pairs for the numerics options (CCD, stable solver).
//
// Every pair (i < j, in the Collision system's registration order) except two
// infinite masses, whose boxes, each grown by `reach` (px) on every side plus
// the distance it travels in `h` ms at its current velocity, overlap (touching
// counts). They come from the same uniform grid as Collision's own pairs
// (systems/broadphase.hpp), then each is checked again on the exact double
// boxes, so the list is exactly brute_force_pairs()'s, the all-pairs
// definition kept for the tests.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "component_defs.hpp"
#include "systems/broadphase.hpp"

namespace physics {

struct BodyPair {
  EntityId c, b;  // c registered before b
};

// Holds the grid and its scratch arrays between calls, so that a solver
// calling it every substep allocates nothing once warmed up.
class PairFinder {
 public:
  void find(const Components& k, std::span<const EntityId> entities, double h, double reach,
            std::vector<BodyPair>& out);

  // find(k, entities, 0, reach, out), the same pairs, but when every body's
  // box grown by `reach` still lies inside the box it had at the last find(),
  // the last grid's pairs are filtered instead of building a new grid: any
  // pair overlapping now overlapped then. (The stable solver finds pairs
  // before Move with boxes swept over the substep, then again after it: the
  // second search is mostly a filter.)
  void find_again(const Components& k, std::span<const EntityId> entities, double reach,
                  std::vector<BodyPair>& out);

 private:
  struct Bounds {
    double x0, y0, x1, y1;
  };
  std::vector<Bounds> bounds_;   // at the last find(): each body's exact box
  std::vector<Bounds> current_;  // find_again's boxes
  std::vector<EntityId> entities_;
  std::vector<Aabb> boxes_;
  std::vector<std::uint8_t> fixed_;
  UniformGrid grid_;
};

// One-off versions (a fresh PairFinder each call).
void candidate_pairs(const Components& k, std::span<const EntityId> entities, double h, double reach,
                     std::vector<BodyPair>& out);
void brute_force_pairs(const Components& k, std::span<const EntityId> entities, double h, double reach,
                       std::vector<BodyPair>& out);

}  // namespace physics
