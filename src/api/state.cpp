// The public API's save and restore: a WorldState is a copy of the engine's
// World and of the API's table for it, so restoring it and stepping repeats
// the saved run bit for bit (the warm-start impulses, the auto mode's state
// and the broad phase's grid come along).
#include "api/registry.hpp"

namespace physics {

struct WorldState::Data {
  api::WorldCopy copy;
};

WorldState::WorldState() = default;
WorldState::~WorldState() = default;
WorldState::WorldState(const WorldState& o) : data_(o.data_ ? std::make_unique<Data>(*o.data_) : nullptr) {}
WorldState& WorldState::operator=(const WorldState& o) {
  if (this != &o) data_ = o.data_ ? std::make_unique<Data>(*o.data_) : nullptr;
  return *this;
}
WorldState::WorldState(WorldState&&) noexcept = default;
WorldState& WorldState::operator=(WorldState&&) noexcept = default;

WorldState save_state(WorldId world) {
  WorldState s;
  s.data_ = std::make_unique<WorldState::Data>(WorldState::Data{api::world(world)});
  return s;
}

void restore_state(WorldId world, const WorldState& state) {
  api::WorldCopy& w = api::world(world);
  if (!state.data_) throw Error("restore_state: the state is empty (not made by save_state)");
  w = state.data_->copy;
}

}  // namespace physics
