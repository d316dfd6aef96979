// The public API's table of worlds (include/physics/physics.hpp): each slot
// holds an engine World and what the API adds to it (the def, the bodies'
// generations and user data). Ids are checked here, once, for every call:
// a null, stale or never-made id throws physics::Error naming it.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "engine/world.hpp"
#include "physics/physics.hpp"

namespace physics::api {

// Everything restore_state puts back: WorldState::Data is this.
struct WorldCopy {
  World world;
  WorldDef def;
  std::vector<std::uint16_t> generation;  // by entity id; 0: never a body of this API
  std::vector<std::uint64_t> user_data;   // by entity id
};

struct Slot {
  std::unique_ptr<WorldCopy> live;  // null while the slot is free
  std::uint16_t generation = 0;     // bumped when the slot is freed
};

// The live world an id names, or throws Error.
WorldCopy& world(WorldId id);
// The world and entity a body id names, or throws Error.
struct Named {
  WorldCopy& world;
  EntityId entity;
};
Named body(BodyId id);

WorldId add(std::unique_ptr<WorldCopy> w);  // a free slot, or a new one
void remove(WorldId id);                    // throws Error if not live
bool live(WorldId id);
bool live(BodyId id);

BodyId id_of(WorldId world, const WorldCopy& w, EntityId e);
std::string describe(WorldId id);
std::string describe(BodyId id);

}  // namespace physics::api
