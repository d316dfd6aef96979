// Islands of bodies joined by contacts: a union-find by entity id, with path
// halving. The stable solver's energy guard, its exact solve of small free
// islands (engine/island_solve.hpp) and auto's roll-back (engine/auto_mode.hpp)
// each join their own contacts with it.
#pragma once

#include <cstddef>
#include <vector>

#include "engine/ecs.hpp"

namespace physics {

class UnionFind {
 public:
  // Room for ids below n; an id is its own island once add()ed.
  void resize(std::size_t n) { parent_.resize(n); }
  void add(EntityId e) { parent_[e] = e; }
  EntityId find(EntityId e) {
    while (parent_[e] != e) e = parent_[e] = parent_[parent_[e]];
    return e;
  }
  // a's island into b's: b's root stays the root.
  void join(EntityId a, EntityId b) { parent_[find(a)] = find(b); }

 private:
  std::vector<EntityId> parent_;
};

}  // namespace physics
