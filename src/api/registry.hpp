// The public API's table of worlds (include/physics/physics.hpp): each slot
// holds an engine World (its own, or one it views: api/view.hpp) and what the
// API adds to it (the def, the bodies' generations and user data). Ids are
// checked here, once, for every call: a null, stale or never-made id throws
// physics::Error naming it.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "engine/world.hpp"
#include "physics/physics.hpp"

namespace physics::api {

// What the API keeps beside a World's own state; saved and restored with it.
struct Table {
  WorldDef def;
  std::vector<std::uint16_t> generation;  // by entity id: the id's generation
  std::vector<std::uint64_t> user_data;   // by entity id
};

struct Live {
  std::unique_ptr<World> owned;  // null for a view
  World* world = nullptr;        // owned.get(), or the viewed world
  Table table;
  // By entity id, the last generation ever handed out: never rolled back by
  // restore_state, so that a body made after a restore never gets the
  // generation of one made, since the save, in the same slot.
  std::vector<std::uint16_t> issued;
  std::uint16_t issue(EntityId e);  // the next generation of slot e
  // Bodies made outside the API (a scene's, the testbed's) get generation 1
  // the first time the API looks: their ids are valid from then on.
  void sync();
};

// The live world an id names, or throws Error.
Live& world(WorldId id);
// The world and entity a body id names, or throws Error.
struct Named {
  Live& live;
  EntityId entity;
};
Named body(BodyId id);

WorldId add(Live live);     // a free slot, or a new one
void remove(WorldId id);    // throws Error if not live
bool live(WorldId id);
bool live(BodyId id);

BodyId id_of(WorldId world, const Live& w, EntityId e);
std::string describe(WorldId id);
std::string describe(BodyId id);

}  // namespace physics::api
