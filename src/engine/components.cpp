#include "engine/components.hpp"

#include <stdexcept>

namespace physics {

EntityId Components::create() {
  if (position.size() >= std::numeric_limits<EntityId>::max())
    throw std::length_error("too many entities");
  const auto id = static_cast<EntityId>(position.size());
  position.push_back(component::position::def);
  box.push_back(component::box::def);
  color.push_back(component::color::def);
  mass.push_back(component::mass::def);
  velocity.push_back(component::velocity::def);
  sum_forces.push_back(component::sum_forces::def);
  restitution.push_back(component::restitution::def);
  friction.push_back(component::friction::def);
  rules_.emplace_back();
  return id;
}

void Components::reserve(std::size_t n) {
  position.reserve(n);
  box.reserve(n);
  color.reserve(n);
  mass.reserve(n);
  velocity.reserve(n);
  sum_forces.reserve(n);
  restitution.reserve(n);
  friction.reserve(n);
  rules_.reserve(n);
}

void Components::set_rules(EntityId e, const ContactRules& r) {
  ruled_ -= rules_[e].plain() ? 0 : 1;
  ruled_ += r.plain() ? 0 : 1;
  rules_[e] = r;
}

}  // namespace physics
