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

template <class... Required>
class System {
 public:
  // OCaml: `register`. Fails to compile if the entity lacks a required component.
  template <class... Has>
    requires(has_component<Required, Has...> && ...)
  void register_entity(Entity<Has...> e) {
    entities_.push_back(e.id);
  }

  // OCaml: `unregister`. Keeps the registration order, which fixes the order in
  // which pairs are resolved and therefore the result of a run.
  void unregister(EntityId id) { std::erase(entities_, id); }

  std::span<const EntityId> entities() const { return entities_; }
  std::size_t size() const { return entities_.size(); }

 protected:
  std::vector<EntityId> entities_;
};

}  // namespace physics
