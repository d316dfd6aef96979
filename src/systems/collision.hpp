// Collision system (course: systems/collision.ml, questions 5-8).
#pragma once

#include <utility>
#include <vector>

#include "component_defs.hpp"
#include "systems/broadphase.hpp"

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
  // Resolves every registered pair once, in registration order: the pairs
  // (entities()[i], entities()[j]), i < j, for i then j increasing, each with
  // the positions and velocities the earlier pairs left. Only the pairs the
  // broadphase finds are tested; the result is bit for bit the one of
  // update_all_pairs (tests/test_broadphase.cpp checks it).
  void update(Components& c);

  // The sheet's loop over every pair, O(n²). Kept as the oracle of update().
  void update_all_pairs(Components& c);

  // The pairs (c, b) of registered bodies whose boxes, grown by `margin` px
  // on every side, overlap or touch, in the order update() visits pairs
  // (c registered before b; pairs sorted by c's then b's registration rank).
  // Pairs of two infinite masses are never listed. For other solvers (CCD,
  // the stable solver) that need the same pairs; O(n + pairs).
  std::vector<std::pair<EntityId, EntityId>> candidate_pairs(const Components& c, double margin);

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

  // How far (px) a body may be pushed by the corrections of a pass before its
  // pairs are looked up again. Any value >= 0 gives the same result; this
  // one was the fastest on the bench scenes (fewer look-ups against more
  // candidate pairs).
  double margin = 1.0;

  // What the last update() did, for the benchmark.
  struct Stats {
    std::size_t candidates = 0;  // pairs found when the pass began
    std::size_t requeries = 0;   // bodies pushed out of their box during the pass
    std::size_t rebuilds = 0;    // broadphase rebuilt during the pass (many bodies pushed out)
  };
  const Stats& stats() const { return stats_; }
  const UniformGrid& grid() const { return grid_; }

 private:
  void build_broadphase(const Components& k, double grow);
  bool refresh(const Components& k, std::uint32_t i, PairKey current);
  void resolve_pair(Components& k, EntityId c, EntityId b);

  std::vector<Contact> contacts_;
  std::size_t contact_count_ = 0;

  // Broadphase state of the current pass, indexed by registration rank.
  std::vector<Aabb> boxes_;          // each body's box grown by `margin`; always contains the body
  std::vector<std::uint8_t> fixed_;  // infinite mass
  UniformGrid grid_;
  std::vector<PairKey> found_late_;  // min-heap: pairs found after a body left its box
  Stats stats_;
};

}  // namespace physics
