#include "api/mover_cast.hpp"

#include <algorithm>
#include <cmath>

#include "engine/geometry.hpp"
#include "engine/rules.hpp"
#include "engine/sweep.hpp"

namespace physics::api {

namespace {

// A relative start within cast_snap of a face is on it.
double snapped(double s, double size) {
  if (std::abs(s) < cast_snap) return 0.0;
  if (std::abs(s + size) < cast_snap) return -size;
  return s;
}

// Whether a one-way face stops a box pushed back along `normal`.
bool stops(Face f, Vector n) {
  switch (f) {
    case Face::none: return true;
    case Face::up: return n.y < 0.0;
    case Face::down: return n.y > 0.0;
    case Face::left: return n.x < 0.0;
    case Face::right: return n.x > 0.0;
  }
  return true;
}

}  // namespace

std::optional<Cast> cast(Vector p, Rect r, Vector d, const Obstacle& o) {
  // The obstacle's Minkowski difference with the box moves by -d while the
  // box moves by d: the box enters the obstacle when it takes in the origin.
  auto [s, size] = minkowski_difference(p, r, o.position, o.size);
  s = {snapped(s.x, size.width), snapped(s.y, size.height)};
  const Interval ix = slab(s.x, size.width, -d.x), iy = slab(s.y, size.height, -d.y);
  const double enter = std::max(ix.lo, iy.lo), exit = std::min(ix.hi, iy.hi);
  if (!(enter < exit) || !(enter >= 0.0) || enter > 1.0) return std::nullopt;
  const bool along_x = ix.lo > iy.lo;  // a corner entered on both axes at once is a y hit
  const Vector n = along_x ? Vector{d.x > 0.0 ? -1.0 : 1.0, 0.0} : Vector{0.0, d.y > 0.0 ? -1.0 : 1.0};
  if (!stops(o.one_way, n)) return std::nullopt;
  return Cast{enter + 0.0, along_x, n, o};
}

Obstacles::Obstacles(const World& w, EntityId mover, double dt) : w_(w), mover_(mover), dt_(dt), index_(w) {
  const Components& k = w.components;
  for (const EntityId e : query_bodies(w))
    if (e != mover && !std::isfinite(k.mass[e]) && !(k.velocity[e] == Vector::zero()) && w.alive(e))
      moving_.push_back(e);
  std::sort(moving_.begin(), moving_.end());  // for binary_search
}

Obstacle Obstacles::body(EntityId e) const {
  const Components& k = w_.components;
  const bool fixed = !std::isfinite(k.mass[e]);
  const Vector p = fixed ? k.position[e] + dt_ * k.velocity[e] : k.position[e];
  return {e, p, k.box[e], k.rules(e).one_way, !fixed};
}

// Calls f(obstacle) for every obstacle that may meet the closed box [lo, hi]:
// the bodies a query finds in it grown by a pixel (touching is not meeting,
// for a query), the moving fixed bodies, and the strips of each layer near it.
template <class F>
void Obstacles::near(Vector lo, Vector hi, F&& f) const {
  const Components& k = w_.components;
  const ContactRules& mine = k.rules(mover_);
  const auto meets = [&](EntityId e) { return e != mover_ && filters_meet(mine, k.rules(e)) && !k.rules(e).sensor; };
  const bool tiles = !w_.tiles.empty();
  for (const EntityId e : index_.query_box(lo - Vector{1.0, 1.0}, hi + Vector{1.0, 1.0}))
    if (meets(e) && w_.alive(e) && !(tiles && w_.tiles.part_of_tiles(e)) &&
        !std::binary_search(moving_.begin(), moving_.end(), e))
      f(body(e));
  for (const EntityId e : moving_)
    if (meets(e)) f(body(e));
  for (const TileLayer& l : w_.tiles.layers()) {
    if (!meets(l.body()) || !w_.alive(l.body())) continue;
    const Vector o = k.position[l.body()];
    const int cs = l.grid().cell;
    l.near(lo.x - o.x, lo.y - o.y, hi.x - o.x, hi.y - o.y, [&](std::uint32_t, const Strip& s) {
      f(Obstacle{l.body(), o + Vector{double(s.col) * cs, double(s.row) * cs}, Rect{s.cols * cs, s.rows * cs},
                 s.one_way ? Face::up : Face::none, false, s.col, s.row, s.cols, s.rows, cs});
    });
  }
}

std::optional<Cast> Obstacles::first(Vector p, Rect r, Vector d, EntityId skip, bool pass_one_way) const {
  const Vector q = p + d;
  const Vector lo{std::min(p.x, q.x), std::min(p.y, q.y)};
  const Vector hi{std::max(p.x, q.x) + r.width, std::max(p.y, q.y) + r.height};
  std::optional<Cast> best;
  near(lo, hi, [&](const Obstacle& o) {
    if (o.body == skip || (pass_one_way && o.one_way != Face::none)) return;
    const auto c = cast(p, r, d, o);
    // The earliest; at the same time the lower id, so that the order of the candidates does not matter.
    if (c && (!best || c->time < best->time || (c->time == best->time && c->what.body < best->what.body))) best = c;
  });
  return best;
}

std::vector<Obstacle> Obstacles::overlapping(Vector p, Rect r) const {
  std::vector<Obstacle> out;
  const Vector hi = p + Vector{double(r.width), double(r.height)};
  near(p, hi, [&](const Obstacle& o) {
    if (o.pushable || o.one_way != Face::none) return;
    auto [s, size] = minkowski_difference(p, r, o.position, o.size);
    const Vector in{std::min(-s.x, s.x + size.width), std::min(-s.y, s.y + size.height)};
    if (in.x > cast_snap && in.y > cast_snap) out.push_back(o);
  });
  return out;
}

}  // namespace physics::api
