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

// Holds the grid between calls. The grid is built on each body's box grown
// by `fat_margin`, and kept while every body's box stays inside its fat one:
// any pair overlapping now then overlapped at the build, so filtering the
// grid's pairs by the exact boxes gives exactly a fresh search's list. Bodies
// at rest (a pile, a pyramid) thus cost a filter per call, not a grid; the
// stable solver's two searches per substep (swept boxes before Move, boxes
// after it) mostly share one grid.
class PairFinder {
 public:
  void find(const Components& k, std::span<const EntityId> entities, double h, double reach,
            std::vector<BodyPair>& out);
  // A body's box in double, [x0, x1] x [y0, y1].
  struct Bounds {
    double x0, y0, x1, y1;
  };

  // px. Larger keeps a grid longer but lists more candidates to filter;
  // 2 px is a fifth of the bench's blocks and above a resting body's drift.
  double fat_margin = 2.0;

 private:
  void rebuild(const Components& k, std::span<const EntityId> entities);

  std::vector<Bounds> current_;  // this call's exact boxes
  std::vector<Bounds> fat_;      // the boxes the grid was built on (grown by fat_margin)
  std::vector<Aabb> boxes_;      // fat_ rounded outwards to float
  std::vector<std::uint8_t> fixed_;
  std::vector<EntityId> entities_;
  UniformGrid grid_;
  bool built_ = false;
};

// One-off versions (a fresh PairFinder each call).
void candidate_pairs(const Components& k, std::span<const EntityId> entities, double h, double reach,
                     std::vector<BodyPair>& out);
void brute_force_pairs(const Components& k, std::span<const EntityId> entities, double h, double reach,
                       std::vector<BodyPair>& out);

}  // namespace physics
