#include "api/view.hpp"

#include "api/convert.hpp"
#include "api/registry.hpp"

namespace physics::api {

namespace {
// The def a world runs, read back from its parameters and systems.
WorldDef def_of(const World& w) {
  WorldDef d;
  d.dt = w.params.dt;
  d.substeps = w.params.substeps;
  d.gravity = to_public(w.params.gravity);
  d.solver = to_public(w.params.solver);
  d.iterations = w.params.iterations;
  d.ccd = w.params.ccd;
  d.integrator = to_public(w.params.integrator);
  d.forces = w.declares(SystemId::forces);
  d.move = w.declares(SystemId::move);
  d.collision = w.declares(SystemId::collision);
  d.contact_events = w.events.enabled;
  d.threads = w.workers.threads();
  return d;
}
}  // namespace

View::View(World& w) {
  Live live;
  live.world = &w;
  live.table.def = def_of(w);
  id_ = add(std::move(live));
}

View::~View() {
  if (live(id_)) remove(id_);
}

void View::rebind(World& w) {
  Live& live = world(id_);
  // The table knows how many bodies the world had (the old place may be
  // moved from, and empty, by now).
  const std::size_t known = live.table.generation.size();
  if (known != 0 && w.components.size() != known)
    throw Error("View::rebind: not the same world moved (" + std::to_string(w.components.size()) + " bodies, not " +
                std::to_string(known) + ")");
  live.world = &w;
  live.table.def = def_of(w);
}

World& internal(WorldId id) { return *world(id).world; }

BodyId body_id(WorldId id, EntityId e) {
  Live& w = world(id);
  if (e >= w.table.generation.size()) throw Error("entity " + std::to_string(e) + " is not a body of " + describe(id));
  return id_of(id, w, e);
}

EntityId entity(BodyId b) { return body(b).entity; }

}  // namespace physics::api
