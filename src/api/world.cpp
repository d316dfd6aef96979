// The public API's worlds: create, destroy, step, and what a world reports.
#include <cmath>
#include <stdexcept>

#include "api/convert.hpp"
#include "api/registry.hpp"
#include "engine/step.hpp"

namespace physics {

namespace {
Params params_of(const WorldDef& d) {
  Params p;
  p.dt = d.dt;
  p.substeps = d.substeps;
  p.gravity = api::to_engine(d.gravity);
  p.ccd = d.ccd;
  p.solver = api::to_engine(d.solver);
  p.iterations = d.iterations;
  p.integrator = api::to_engine(d.integrator);
  return p;
}

SystemSet systems_of(const WorldDef& d) {
  SystemSet s;
  s.draw = false;  // the API's worlds are drawn by the game, from their bodies
  s.forces = d.forces;
  s.move = d.move;
  s.collision = d.collision;
  return s;
}

api::Live make(const WorldDef& d) {
  if (d.solver > SolverKind::automatic || d.integrator > IntegratorKind::exact)
    throw Error("bad WorldDef: solver or integrator is not one of the enum's values");
  Params p;
  try {
    p = params_of(d);
    validate(p);
  } catch (const std::invalid_argument& e) {
    throw Error(std::string("bad WorldDef: ") + e.what());
  }
  api::Live w;
  w.owned = std::make_unique<World>(systems_of(d), p);
  w.world = w.owned.get();
  try {
    w.world->workers = Workers(d.threads);
  } catch (const std::invalid_argument& e) {
    throw Error(std::string("bad WorldDef: ") + e.what());
  }
  w.table.def = d;
  if (d.bounds) {
    const Aabb& b = *d.bounds;
    api::check_finite(b.lower, "WorldDef::bounds.lower");
    api::check_finite(b.upper, "WorldDef::bounds.upper");
    api::require(b.lower.x <= b.upper.x && b.lower.y <= b.upper.y, "WorldDef::bounds.upper", ">= lower", b.upper);
    w.world->health.watch(b.lower.x, b.lower.y, b.upper.x, b.upper.y, 0);
  }
  if (d.contact_events) w.world->enable_events();
  return w;
}
}  // namespace

WorldDef default_world_def() { return WorldDef{}; }

WorldId create_world(const WorldDef& def) { return api::add(make(def)); }

void destroy_world(WorldId world) {
  if (!api::world(world).owned) throw Error(api::describe(world) + " views a world it does not own: its owner ends it");
  api::remove(world);
}

bool is_valid(WorldId world) { return api::live(world); }

void step(WorldId world) {
  World& w = *api::world(world).world;
  if (!w.health.finite()) throw Error(api::describe(world) + " holds a non-finite position or velocity: see health()");
  step(w);
}

std::int64_t frame(WorldId world) { return api::world(world).world->frame; }

std::vector<BodyId> bodies(WorldId world) {
  const api::Live& w = api::world(world);
  std::vector<BodyId> out;
  for (EntityId e = 0; e < w.table.generation.size(); ++e)
    if (w.world->alive(e)) out.push_back(api::id_of(world, w, e));
  return out;
}

std::size_t body_count(WorldId world) { return bodies(world).size(); }

WorldDef world_def(WorldId world) { return api::world(world).table.def; }

void set_gravity(WorldId world, Vec2 gravity) {
  api::Live& w = api::world(world);
  api::check_motion(gravity, "gravity");
  w.table.def.gravity = gravity;
  w.world->params.gravity = api::to_engine(gravity);
}

double kinetic_energy(WorldId world) { return api::world(world).world->kinetic_energy(); }

Vec2 momentum(WorldId world) { return api::to_public(api::world(world).world->momentum()); }

std::vector<StageTime> profile(WorldId world) {
  const StageTimes& t = api::world(world).world->times;
  std::vector<StageTime> out;
  for (std::size_t s = 0; s < stage_count; ++s) out.push_back({name(static_cast<Stage>(s)), t.ms_per_step(static_cast<Stage>(s))});
  return out;
}

HealthReport health(WorldId world) {
  const api::Live& w = api::world(world);
  const Health& h = w.world->health;
  HealthReport r;
  r.finite = h.finite();
  if (h.non_finite) r.non_finite = api::id_of(world, w, h.non_finite->id);
  r.escaped = h.escaped;
  if (h.first_escape) r.first_escape = api::id_of(world, w, h.first_escape->id);
  if (h.deep) r.deepest_overlap = h.deep->depth;
  return r;
}

std::vector<TouchEvent> contact_events(WorldId world) {
  const api::Live& w = api::world(world);
  std::vector<TouchEvent> out;
  for (const ContactEvent& e : w.world->events.events())
    out.push_back({e.kind == EventKind::begin, api::id_of(world, w, e.a), api::id_of(world, w, e.b),
                   api::to_public(e.normal), e.depth, e.jn, e.jt, e.frame});
  return out;
}

void enable_contact_events(WorldId world) {
  api::Live& w = api::world(world);
  w.world->enable_events();
  w.table.def.contact_events = true;
}

std::vector<Touching> touching(WorldId world) {
  const api::Live& w = api::world(world);
  std::vector<Touching> out;
  for (const ContactEvents::Touch& t : w.world->events.touching())
    out.push_back({api::id_of(world, w, t.pair.c), api::id_of(world, w, t.pair.b), api::to_public(t.normal), t.depth,
                   t.jn, t.jt});
  return out;
}

}  // namespace physics
