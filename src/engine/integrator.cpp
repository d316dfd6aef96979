#include "engine/integrator.hpp"

namespace physics {

void ExactIntegrator::start(const Components& k, std::span<const EntityId> bodies) {
  // Sized to the arrays, which grow when bodies are added between steps.
  kick_.resize(k.size());
  v_forces_.resize(k.size());
  for (const EntityId e : bodies) kick_[e] = k.velocity[e];
}

void ExactIntegrator::after_forces(const Components& k, std::span<const EntityId> bodies) {
  for (const EntityId e : bodies) {
    kick_[e] = k.velocity[e] - kick_[e];
    v_forces_[e] = k.velocity[e];
  }
}

void ExactIntegrator::shift(Components& k, std::span<const EntityId> bodies, double h) const {
  const double half = 0.5 * h;
  for (const EntityId e : bodies) {
    // Untouched since Forces: free motion during the substep (see the header).
    if (k.velocity[e] != v_forces_[e] || kick_[e] == Vector::zero()) continue;
    k.position[e] = k.position[e] - half * kick_[e];
  }
}

}  // namespace physics
