// The public API's bodies: create, destroy, and each property's getter and
// setter. Every setter checks its value as create_body does.
#include <cmath>

#include "api/convert.hpp"
#include "api/registry.hpp"

namespace physics {

namespace {
// The components a body has (a course Block's), each set below.
using Body = Entity<component::position, component::box, component::color, component::mass,
                    component::velocity, component::sum_forces, component::restitution>;

void check(const BodyDef& d) {
  api::check_finite(d.position, "a body's position");
  api::check_size(d.size);
  api::check_mass(d.mass);
  api::check_motion(d.velocity, "a body's velocity");
  api::check_motion(d.force, "a body's force");
  api::check_restitution(d.restitution);
  api::check_friction(d.friction);
  if (d.one_way > OneWay::right) throw Error("a body's one_way must be one of OneWay's values");
}

// The body's own components, for a getter or a setter.
struct Own {
  api::Live& w;
  EntityId e;
  Components& c() { return w.world->components; }
};
Own own(BodyId id) {
  const api::Named n = api::body(id);
  return {n.live, n.entity};
}

void set_rules(BodyId id, Filter f, bool sensor, OneWay face) {
  Own o = own(id);
  o.c().set_rules(o.e, api::rules_of(f, sensor, face));
}
}  // namespace

BodyDef default_body_def() { return BodyDef{}; }

BodyId create_body(WorldId world, const BodyDef& d) {
  api::Live& w = api::world(world);
  check(d);
  Components& c = w.world->components;
  const Body b{c.create()};
  c.position[b.id] = api::to_engine(d.position);
  c.box[b.id] = api::to_rect(d.size);
  c.color[b.id] = d.color;
  c.mass[b.id] = d.mass;
  c.velocity[b.id] = api::to_engine(d.velocity);
  c.sum_forces[b.id] = api::to_engine(d.force);
  c.restitution[b.id] = d.restitution;
  c.friction[b.id] = d.friction;
  const ContactRules rules = api::rules_of(d.filter, d.sensor, d.one_way);
  if (!rules.plain()) c.set_rules(b.id, rules);
  // The stages the world runs; Draw too in a world that draws (the testbed's, through api::View).
  for (const SystemId s : {SystemId::draw, SystemId::forces, SystemId::move, SystemId::collision})
    if (w.world->declares(s)) w.world->add(s, b.id);
  w.table.generation.resize(c.size(), 0);
  w.table.user_data.resize(c.size(), 0);
  w.table.generation[b.id] = w.issue(b.id);
  w.table.user_data[b.id] = d.user_data;
  return api::id_of(world, w, b.id);
}

void destroy_body(BodyId id) {
  Own o = own(id);
  o.w.world->destroy(o.e);
  o.w.table.generation[o.e] = o.w.issue(o.e);  // a generation no id holds: the id goes stale
}

bool is_valid(BodyId id) { return api::live(id); }
WorldId world_of(BodyId id) { return own(id), id.world; }

Vec2 position(BodyId id) { Own o = own(id); return api::to_public(o.c().position[o.e]); }
void set_position(BodyId id, Vec2 p) {
  Own o = own(id);
  api::check_finite(p, "a body's position");
  o.c().position[o.e] = api::to_engine(p);
}
Vec2 size(BodyId id) {
  Own o = own(id);
  return {static_cast<double>(o.c().box[o.e].width), static_cast<double>(o.c().box[o.e].height)};
}
void set_size(BodyId id, Vec2 s) {
  Own o = own(id);
  api::check_size(s);
  if (o.w.world->tiles.part_of_tiles(o.e))
    throw Error(api::describe(id) + " is a tile layer: its size is its grid's (set_size does not resize it)");
  o.c().box[o.e] = api::to_rect(s);
}
Aabb bounds(BodyId id) { const Vec2 p = position(id); return {p, p + size(id)}; }
Vec2 velocity(BodyId id) { Own o = own(id); return api::to_public(o.c().velocity[o.e]); }
void set_velocity(BodyId id, Vec2 v) {
  Own o = own(id);
  api::check_motion(v, "a body's velocity");
  o.c().velocity[o.e] = api::to_engine(v);
}
Vec2 force(BodyId id) { Own o = own(id); return api::to_public(o.c().sum_forces[o.e]); }
void apply_force(BodyId id, Vec2 f) {
  Own o = own(id);
  api::check_motion(f, "a force");
  o.c().sum_forces[o.e] = o.c().sum_forces[o.e] + api::to_engine(f);
}
void apply_impulse(BodyId id, Vec2 j) {
  Own o = own(id);
  api::check_motion(j, "an impulse");
  const double m = o.c().mass[o.e];
  if (!std::isfinite(m)) return;
  const Vector v = o.c().velocity[o.e] + Vector::mult(1.0 / m, api::to_engine(j));
  api::check_motion(api::to_public(v), "the velocity an impulse gives");  // a tiny mass: refused, not inf
  o.c().velocity[o.e] = v;
}
double mass(BodyId id) { Own o = own(id); return o.c().mass[o.e]; }
void set_mass(BodyId id, double m) { Own o = own(id); api::check_mass(m); o.c().mass[o.e] = m; }
double restitution(BodyId id) { Own o = own(id); return o.c().restitution[o.e]; }
void set_restitution(BodyId id, double e) { Own o = own(id); api::check_restitution(e); o.c().restitution[o.e] = e; }
double friction(BodyId id) { Own o = own(id); return o.c().friction[o.e]; }
void set_friction(BodyId id, double mu) { Own o = own(id); api::check_friction(mu); o.c().friction[o.e] = mu; }

Filter filter(BodyId id) { Own o = own(id); const ContactRules& r = o.c().rules(o.e); return {r.category, r.mask}; }
void set_filter(BodyId id, Filter f) { set_rules(id, f, is_sensor(id), one_way(id)); }
bool is_sensor(BodyId id) { Own o = own(id); return o.c().rules(o.e).sensor; }
void set_sensor(BodyId id, bool sensor) { set_rules(id, filter(id), sensor, one_way(id)); }
OneWay one_way(BodyId id) { Own o = own(id); return static_cast<OneWay>(o.c().rules(o.e).one_way); }
void set_one_way(BodyId id, OneWay face) {
  if (face > OneWay::right) throw Error("a body's one_way must be one of OneWay's values");
  set_rules(id, filter(id), is_sensor(id), face);
}

Color color(BodyId id) { Own o = own(id); return o.c().color[o.e]; }
void set_color(BodyId id, Color c) { Own o = own(id); o.c().color[o.e] = c; }
std::uint64_t user_data(BodyId id) { Own o = own(id); return o.w.table.user_data[o.e]; }
void set_user_data(BodyId id, std::uint64_t data) { Own o = own(id); o.w.table.user_data[o.e] = data; }

}  // namespace physics
