// The public API's box mover (include/physics/mover.hpp; docs/api.md,
// "Movers"): a fixed body the call places, swept by the box cast of
// api/mover_cast.hpp. Each hit puts the box exactly on the face it hit (the
// axis of the face set to the face's coordinate, not start + time · motion),
// so that a box pushed into a corner frame after frame computes the same
// position every time: no jitter.
#include <algorithm>
#include <cmath>

#include "api/convert.hpp"
#include "api/mover_cast.hpp"
#include "api/registry.hpp"
#include "engine/geometry.hpp"
#include "physics/mover.hpp"

namespace physics {

namespace {

using api::Cast;

void check(const MoverDef& d) {
  const Vec2 u = d.up_direction;
  const bool axis = (u.x == 0.0 && std::abs(u.y) == 1.0) || (u.y == 0.0 && std::abs(u.x) == 1.0);
  api::require(axis, "a mover's up_direction", "one of (0, -1), (0, 1), (-1, 0), (1, 0)", u);
  api::require(d.floor_snap_length >= 0.0 && d.floor_snap_length <= 1e6, "a mover's floor_snap_length",
               "in [0, 1e6] px", d.floor_snap_length);
  api::require(d.max_slides >= 1 && d.max_slides <= 64, "a mover's max_slides", "in [1, 64]", d.max_slides);
  api::require(d.max_push_impulse >= 0.0, "a mover's max_push_impulse", "in [0, inf]", d.max_push_impulse);
  if (d.motion_mode > MotionMode::floating) throw Error("a mover's motion_mode must be one of MotionMode's values");
  if (d.platform_on_leave > PlatformOnLeave::do_nothing)
    throw Error("a mover's platform_on_leave must be one of PlatformOnLeave's values");
}

enum class Surface { floor, wall, ceiling };

// One call: the world, the box, what it met.
struct Run {
  WorldId world;
  api::Live& live;
  World& w;
  EntityId e;
  const MoverDef& def;
  const api::Obstacles& obstacles;
  Vector up;
  Rect r;
  Vector p;
  MoverResult out;
  std::vector<std::pair<EntityId, double>> given;  // impulse given each pushed body so far

  Surface surface(Vector n) const {
    if (def.motion_mode == MotionMode::floating) return Surface::wall;
    return n == up ? Surface::floor : n == -up ? Surface::ceiling : Surface::wall;
  }
  BodyId id(EntityId b) const { return api::id_of(world, live, b); }
};

// The box at p put on the face `c` hit, after moving by time · d.
Vector on_face(Vector p, Rect r, Vector d, const Cast& c) {
  const Vector at = p + c.time * d;
  const api::Obstacle& o = c.what;
  if (c.along_x) return {c.normal.x < 0.0 ? o.position.x - r.width : o.position.x + o.size.width, at.y};
  return {at.x, c.normal.y < 0.0 ? o.position.y - r.height : o.position.y + o.size.height};
}

// The middle of the touching part of the face, and the strip's cell there.
void locate(const Run& run, const Cast& c, MoverHit& h) {
  const api::Obstacle& o = c.what;
  const Vector a = run.p, b = o.position;
  const auto mid = [](double a0, double a1, double b0, double b1) { return 0.5 * (std::max(a0, b0) + std::min(a1, b1)); };
  if (c.along_x) h.point = {c.normal.x < 0.0 ? b.x : b.x + o.size.width, mid(a.y, a.y + run.r.height, b.y, b.y + o.size.height)};
  else h.point = {mid(a.x, a.x + run.r.width, b.x, b.x + o.size.width), c.normal.y < 0.0 ? b.y : b.y + o.size.height};
  if (o.columns == 0) return;
  const auto cell = [&](double v, double origin, int first, int n) {
    return std::clamp(static_cast<int>(std::floor((v - origin) / o.cell)) + first, first, first + n - 1);
  };
  h.column = cell(h.point.x, b.x, o.column, o.columns);
  h.row = cell(h.point.y, b.y, o.row, o.rows);
}

// Pushes a finite-mass body it hit (not its floor) towards the mover's
// velocity v along -normal, within what max_push_impulse leaves.
double push(Run& run, const Cast& c, Vector v) {
  const api::Obstacle& o = c.what;
  Components& k = run.w.components;
  if (!o.pushable || run.surface(c.normal) == Surface::floor || (k.rules(o.body).category & run.def.push_layers) == 0)
    return 0.0;
  const Vector dir = -c.normal;
  const double want = Vector::dot(v, dir) - Vector::dot(k.velocity[o.body], dir);
  if (!(want > 0.0)) return 0.0;
  auto it = std::find_if(run.given.begin(), run.given.end(), [&](const auto& g) { return g.first == o.body; });
  if (it == run.given.end()) it = run.given.insert(run.given.end(), {o.body, 0.0});
  const double j = std::min(k.mass[o.body] * want, run.def.max_push_impulse - it->second);
  if (!(j > 0.0)) return 0.0;
  it->second += j;
  k.velocity[o.body] = k.velocity[o.body] + (j / k.mass[o.body]) * dir;
  return j;
}

// Notes the hit: the surface it is, the floor's body and velocity, the push.
void record(Run& run, const Cast& c, const Vector* v) {
  MoverHit h{run.id(c.what.body), api::to_public(c.normal), {}, -1, -1, 0.0};
  locate(run, c, h);
  if (v) h.impulse = push(run, c, *v);
  switch (run.surface(c.normal)) {
    case Surface::floor:
      run.out.on_floor = true;
      run.out.floor = h.body;
      run.out.floor_velocity = c.what.columns ? Vec2{} : api::to_public(run.w.components.velocity[c.what.body]);
      break;
    case Surface::wall: run.out.on_wall = true, run.out.wall_normal = h.normal; break;
    case Surface::ceiling: run.out.on_ceiling = true; break;
  }
  run.out.hits.push_back(h);
}

// Moves the box by d, sliding along what it hits, `skip` aside; v (the
// mover's own motion; null for riding) loses its parts into the faces hit.
void slide(Run& run, Vector d, Vector* v, EntityId skip) {
  for (int i = 0; i < run.def.max_slides && !Vector::is_zero(d); ++i) {
    const auto c = run.obstacles.first(run.p, run.r, d, skip, run.def.pass_one_way);
    if (!c) {
      run.p = run.p + d;
      return;
    }
    run.p = on_face(run.p, run.r, d, *c);
    record(run, *c, v);
    Vector rest = (1.0 - c->time) * d;
    (c->along_x ? rest.x : rest.y) = 0.0;
    if (v) (c->along_x ? v->x : v->y) = 0.0;  // it moved into the face: d and v share their signs
    if (run.surface(c->normal) == Surface::ceiling && !run.def.slide_on_ceiling) {
      rest = {};
      if (v) (c->along_x ? v->y : v->x) = 0.0;
    }
    d = rest;
  }
}

// Out of the fixed bodies it starts in (a platform moved into it): along
// the shortest way out, onto the face.
void recover(Run& run) {
  for (int pass = 0; pass < 4; ++pass) {
    const auto in = run.obstacles.overlapping(run.p, run.r);
    if (in.empty()) return;
    const api::Obstacle& o = in.front();
    auto [s, size] = minkowski_difference(run.p, run.r, o.position, o.size);
    const Vector out = penetration_vector(s, size);
    const Cast c{1.0, out.x != 0.0, Vector::normalize(out), o};  // the normal points the way out
    run.p = on_face(run.p, run.r, out, c);
    record(run, c, nullptr);
  }
}

// The floor of the last call it rides: its body, and its velocity if its
// category is in platform_floor_layers (0 otherwise).
std::pair<EntityId, Vector> ridden(const Run& run, const MoverResult& last) {
  constexpr EntityId none = ~EntityId{0};
  if (!last.on_floor || !(last.floor.world == run.world) || !api::live(last.floor)) return {none, {}};
  const EntityId f = api::body(last.floor).entity;
  const Components& k = run.w.components;
  return {f, (k.rules(f).category & run.def.platform_floor_layers) != 0 ? k.velocity[f] : Vector{}};
}

// Down onto a floor within floor_snap_length, when it stood on one, found
// none this call and is not moving up.
void snap(Run& run, const MoverResult& last, Vector v) {
  if (run.out.on_floor || !last.on_floor || run.def.motion_mode != MotionMode::grounded ||
      run.def.floor_snap_length == 0.0 || Vector::dot(v, run.up) > 0.0)
    return;
  const Vector d = -run.def.floor_snap_length * run.up;
  const auto c = run.obstacles.first(run.p, run.r, d, ~EntityId{0}, run.def.pass_one_way);
  if (!c || run.surface(c->normal) != Surface::floor) return;
  run.p = on_face(run.p, run.r, d, *c);
  record(run, *c, nullptr);
}

// platform_on_leave: what of the floor's velocity it keeps on leaving it.
Vector kept(const MoverDef& def, Vector floor_v, Vector up) {
  switch (def.platform_on_leave) {
    case PlatformOnLeave::add_velocity: return floor_v;
    case PlatformOnLeave::add_upward_velocity: {
      const double along = Vector::dot(floor_v, up);
      return along > 0.0 ? along * up : Vector{};
    }
    case PlatformOnLeave::do_nothing: break;
  }
  return {};
}

}  // namespace

MoverDef default_mover_def() { return MoverDef{}; }

MoverResult move_and_slide(BodyId id, Vec2 velocity, const MoverDef& def, const MoverResult& last) {
  check(def);
  api::check_motion(velocity, "a mover's velocity");
  const api::Named n = api::body(id);
  World& w = *n.live.world;
  Components& k = w.components;
  if (w.tiles.part_of_tiles(n.entity)) throw Error(api::describe(id) + " is a tile layer: it cannot be a mover");
  if (std::isfinite(k.mass[n.entity]))
    throw Error(api::describe(id) + " is not fixed: a mover's body has mass fixed_mass (the call places it)");
  const double dt = w.params.dt;
  const api::Obstacles obstacles(w, n.entity, dt);
  Run run{id.world, n.live, w, n.entity, def, obstacles, api::to_engine(def.up_direction), k.box[n.entity],
          k.position[n.entity], {}, {}};
  const Vector start = run.p;
  const auto [floor, ride] = ridden(run, last);
  slide(run, dt * ride, nullptr, floor);
  recover(run);  // after riding: the floor it rides is where it will be, not in it
  Vector v = api::to_engine(velocity);
  slide(run, dt * v, &v, ~EntityId{0});
  snap(run, last, v);
  if (last.on_floor && !run.out.on_floor) v = v + kept(def, ride, run.up);
  k.position[n.entity] = run.p;
  k.velocity[n.entity] = Vector{};
  run.out.velocity = api::to_public(v);
  run.out.travel = api::to_public(run.p - start);
  return run.out;
}

}  // namespace physics
