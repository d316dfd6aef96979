// The small ECS the course builds on, in C++ (the archive's "small ECS
// library", given with the sheet, not written by the student). The engine
// owns it, below the course's systems and entities, which build on it;
// course/ecs.hpp names it in the course tree.
//
// OCaml: a component is a class holding one mutable value, an entity is an
// object inheriting the component classes it has, and a system is a functor
// over a class type listing the components it needs. A system's `register`
// then only type-checks for entities that have those components.
//
// Here the same check happens at compile time with typed handles: an
// Entity<position, velocity, ...> names the components its entity has, and
// System<Required...>::register_entity is constrained to entities that have
// each required one: registering any other fails to compile, naming the
// component in the unsatisfied constraint. The component *values* do not live in the entity but in dense
// arrays indexed by the entity id (engine/components.hpp), so the systems' loops
// walk contiguous memory even for 100 000 bodies.
#pragma once

#include <algorithm>
#include <cassert>
#include <cstdint>
#include <span>
#include <type_traits>
#include <vector>

namespace physics {

using EntityId = std::uint32_t;

template <class... Components>
struct Entity {
  EntityId id;
};

template <class C, class... Cs>
inline constexpr bool has_component = (std::is_same_v<C, Cs> || ...);

// A system is a view of one stage's body list, which the world holds
// (World::stage, engine/world.hpp): registering with it adds the body to the
// world's list, so that the engine's stages and the course's systems run over
// the same bodies in the same order. Bound to a const list it only reads
// (an update); registering then is a programming error (asserted).
template <class... Required>
class System {
 public:
  explicit System(std::vector<EntityId>& bodies) : entities_(bodies), list_(&bodies) {}
  explicit System(const std::vector<EntityId>& bodies) : entities_(bodies) {}

  // OCaml: `register`. Fails to compile if the entity lacks a required component.
  template <class... Has>
    requires(has_component<Required, Has...> && ...)
  void register_entity(Entity<Has...> e) {
    assert(list_);
    list_->push_back(e.id);
  }

  // OCaml: `unregister`. Keeps the registration order, which fixes the order in
  // which pairs are resolved and therefore the result of a run.
  void unregister(EntityId id) {
    assert(list_);
    std::erase(*list_, id);
  }

  std::span<const EntityId> entities() const { return entities_; }
  std::size_t size() const { return entities_.size(); }

 protected:
  const std::vector<EntityId>& entities_;  // the world's list for this stage

 private:
  std::vector<EntityId>* list_ = nullptr;  // the same list, to register with; null if bound read-only
};

}  // namespace physics
