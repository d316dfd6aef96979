// The public API's save and restore: a WorldState is a copy of the engine's
// World and of the API's table for it, so restoring it and stepping repeats
// the saved run bit for bit (the warm-start impulses, the auto mode's state
// and the broad phase's grid come along).
#include "api/registry.hpp"

namespace physics {

struct WorldState::Data {
  WorldId from;  // a state goes back into its own world only: another's ids would name its bodies
  World world;
  api::Table table;
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
  const api::Live& w = api::world(world);
  s.data_ = std::make_unique<WorldState::Data>(WorldState::Data{world, *w.world, w.table});
  return s;
}

void restore_state(WorldId world, const WorldState& state) {
  api::Live& w = api::world(world);
  if (!state.data_) throw Error("restore_state: the state is empty (not made by save_state)");
  if (!(state.data_->from == world))
    throw Error("restore_state: the state was saved from " + api::describe(state.data_->from) + ", not from " +
                api::describe(world) + " (a state goes back into its own world)");
  *w.world = state.data_->world;
  w.table = state.data_->table;
}

}  // namespace physics
