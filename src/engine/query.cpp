#include "engine/query.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

#include "engine/geometry.hpp"
#include "engine/sweep.hpp"

namespace physics {

namespace {

using Bounds = BroadPhase::Bounds;

void require_finite(Vector v, const char* what) {
  if (!std::isfinite(v.x) || !std::isfinite(v.y))
    throw std::invalid_argument(std::string("query: ") + what + " must be finite");
}

// A region [lo, hi] for query `what`: both corners finite, lo <= hi on each axis.
void require_region(Vector lo, Vector hi, const std::string& what) {
  require_finite(lo, (what + "'s lo").c_str());
  require_finite(hi, (what + "'s hi").c_str());
  if (lo.x > hi.x || lo.y > hi.y) throw std::invalid_argument("query: " + what + "'s lo must not exceed hi on an axis");
}

// Keeps the earlier hit; at the same fraction the lower id, so the answer
// does not depend on the order bodies are tested in.
void keep_first(std::optional<RayHit>& best, const std::optional<RayHit>& hit) {
  if (hit && (!best || hit->fraction < best->fraction || (hit->fraction == best->fraction && hit->body < best->body)))
    best = hit;
}

// The closed interval of fractions f at which o + f·t lies in [lo, hi].
Interval clip(double o, double t, double lo, double hi) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  if (t == 0.0) return (lo <= o && o <= hi) ? Interval{-inf, inf} : Interval{inf, -inf};
  const double a = (lo - o) / t, b = (hi - o) / t;
  return t > 0.0 ? Interval{a, b} : Interval{b, a};
}

}  // namespace

std::vector<EntityId> query_bodies(const World& w) {
  if (w.declares(SystemId::collision)) {
    const auto e = w.bodies(SystemId::collision);
    return {e.begin(), e.end()};
  }
  std::vector<EntityId> all(w.components.size());
  std::iota(all.begin(), all.end(), EntityId{0});
  return all;
}

Vector ray_travel(Vector origin, Vector direction, double max_distance) {
  require_finite(origin, "the ray's origin");
  require_finite(direction, "the ray's direction");
  if (!std::isfinite(max_distance) || max_distance < 0.0)
    throw std::invalid_argument("query: the ray's max_distance must be finite and >= 0");
  // Divided by its larger component first, so that its length cannot
  // overflow (a direction (1e308, 1e308)), and an axis stays exactly (0, ±1).
  const double big = std::max(std::abs(direction.x), std::abs(direction.y));
  if (big == 0.0) return {};
  const Vector u{direction.x / big, direction.y / big};
  const double len = Vector::norm(u);
  return {max_distance * (u.x / len), max_distance * (u.y / len)};
}

std::optional<RayHit> ray_hit(Vector origin, Vector travel, EntityId body, Vector p, Rect r) {
  // CCD's sweep with a point for one body: the body's Minkowski difference
  // with a box of size 0 at the origin moves by -travel while the ray's
  // fraction goes from 0 to 1; the ray enters the body when the difference
  // takes in the origin.
  const auto [s, size] = minkowski_difference(origin, Rect{}, p, r);
  const Vector d = -travel;
  const auto [enter, exit, along_x] = sweep(s, size, d);
  // enter < 0 < exit: the ray starts inside, and ignores the body.
  if (!(enter < exit) || !(enter >= 0.0) || enter > 1.0) return std::nullopt;
  // As in Ccd::time_of_impact: the face the difference moves in by.
  const double dn = along_x ? d.x : d.y;
  const double sign = dn > 0.0 ? 1.0 : -1.0;
  // On the face exactly (not origin + enter·travel, which rounding puts a
  // hair off it), and within it.
  const Vector along = origin + enter * travel;
  const Vector point = along_x ? Vector{dn > 0.0 ? p.x + r.width : p.x, std::clamp(along.y, p.y, p.y + r.height)}
                               : Vector{std::clamp(along.x, p.x, p.x + r.width), dn > 0.0 ? p.y + r.height : p.y};
  const Vector normal = along_x ? Vector{sign, 0.0} : Vector{0.0, sign};
  return RayHit{body, point, normal, enter + 0.0};  // + 0.0: a fraction -0 reads 0
}

bool overlaps_region(Vector p, Rect r, Vector lo, Vector hi) {
  // Open on both sides, as contains_origin (engine/geometry.hpp): touching is not overlapping.
  return lo.x < p.x + r.width && p.x < hi.x && lo.y < p.y + r.height && p.y < hi.y;
}

bool contains_point(Vector p, Rect r, Vector q) { return overlaps_region(p, r, q, q); }

QueryIndex::QueryIndex(const World& w) : ids_(query_bodies(w)), tiles_(&w.tiles) {
  for (const TileLayer& l : w.tiles.layers()) tile_origin_.push_back(w.components.position[l.body()]);
  const Components& k = w.components;
  const std::size_t n = ids_.size();
  position_.reserve(n);
  size_.reserve(n);
  std::vector<FloatBox> boxes;
  boxes.reserve(n);
  bool any = false;
  for (const EntityId e : ids_) {
    position_.push_back(k.position[e]);
    size_.push_back(k.box[e]);
    const FloatBox b = boxes.emplace_back(FloatBox::around(k.position[e], k.box[e], 0.0));
    if (!b.valid()) continue;  // a body at NaN, which nothing finds
    const Bounds f{b.min_x, b.min_y, b.max_x, b.max_y};
    bounds_ = any ? Bounds{std::min(bounds_.x0, f.x0), std::min(bounds_.y0, f.y0), std::max(bounds_.x1, f.x1),
                           std::max(bounds_.y1, f.y1)}
                  : f;
    any = true;
  }
  grid_.index(boxes);
  finite_bounds_ = any && std::isfinite(bounds_.x0) && std::isfinite(bounds_.y0) && std::isfinite(bounds_.x1) &&
                   std::isfinite(bounds_.y1);
}

std::optional<RayHit> QueryIndex::ray_cast(Vector origin, Vector direction, double max_distance) const {
  const Vector travel = ray_travel(origin, direction, max_distance);
  if (Vector::is_zero(travel)) return std::nullopt;  // enters nothing: the bodies holding the origin are ignored
  std::optional<RayHit> best = finite_bounds_ ? walk_grid(origin, travel) : test_all(origin, travel);
  if (!tiles_->empty()) keep_first(best, ray_tiles(origin, travel));
  return best;
}

namespace {

// The cells [c0, c1] x [r0, r1] of a layer whose open boxes meet the open
// region (lo, hi), lo and hi relative to the layer's corner: a cell c spans
// (c·cs, (c + 1)·cs), so c·cs < hi and lo < (c + 1)·cs.
struct CellRange {
  int c0, c1, r0, r1;
};
CellRange cells_of(const TileGrid& g, Vector lo, Vector hi) {
  const double cs = g.cell;
  const auto first = [&](double v, int n) { return static_cast<int>(std::clamp(std::floor(v / cs), 0.0, double(n))); };
  const auto last = [&](double v, int n) { return static_cast<int>(std::clamp(std::ceil(v / cs) - 1, -1.0, n - 1.0)); };
  return {first(lo.x, g.columns), last(hi.x, g.columns), first(lo.y, g.rows), last(hi.y, g.rows)};
}

// The first cell of layer l (its corner at o) the segment enters, as the
// header says: cells visited in the order the segment reaches them (a
// digital differential analyser), each tested exactly with ray_hit.
std::optional<RayHit> ray_layer(const TileLayer& l, Vector o, Vector origin, Vector travel) {
  const TileGrid& g = l.grid();
  const double cs = g.cell;
  const Vector a = origin - o;  // relative to the layer
  // The part of the segment over the layer: [f0, f1].
  const Interval cx = clip(a.x, travel.x, 0.0, cs * g.columns), cy = clip(a.y, travel.y, 0.0, cs * g.rows);
  const double f0 = std::max({0.0, cx.lo, cy.lo}), f1 = std::min({1.0, cx.hi, cy.hi});
  if (!(f0 <= f1)) return std::nullopt;
  const Vector start = a + f0 * travel;
  // The cell holding the start, the one ahead when it lies on a cell's edge.
  const auto cell = [&](double v, double t, int n) {
    const double q = v / cs;
    int c = static_cast<int>(std::floor(q));
    if (t < 0.0 && q == std::floor(q)) --c;
    return std::clamp(c, 0, n - 1);
  };
  int c = cell(start.x, travel.x, g.columns), r = cell(start.y, travel.y, g.rows);
  const int sc = travel.x > 0 ? 1 : -1, sr = travel.y > 0 ? 1 : -1;
  // Fractions at which the segment crosses the next column and row boundary.
  const auto next = [&](int i, int step, double v0, double t) {
    return t == 0.0 ? infinity : ((i + (step > 0 ? 1 : 0)) * cs - v0) / t;
  };
  double tx = next(c, sc, a.x, travel.x), ty = next(r, sr, a.y, travel.y);
  const double dx = travel.x == 0.0 ? infinity : cs / std::abs(travel.x);
  const double dy = travel.y == 0.0 ? infinity : cs / std::abs(travel.y);
  // Still in the solid cells the ray starts in (if its origin is in one; not
  // `start`, which rounding may put a hair inside the cell it enters).
  bool in_solid = f0 == 0.0 && g.at(c, r) == Tile::solid && contains_point(Vector{c * cs, r * cs}, Rect{g.cell, g.cell}, a);
  for (;;) {
    const Tile t = g.at(c, r);
    in_solid = in_solid && t == Tile::solid;
    if (t != Tile::empty && !in_solid) {
      const Vector p = o + Vector{c * cs, r * cs};
      if (auto hit = ray_hit(origin, travel, l.body(), p, Rect{g.cell, g.cell});
          hit && (t == Tile::solid || hit->normal == Vector{0.0, -1.0})) {
        hit->column = c, hit->row = r;
        return hit;
      }
    }
    if (std::min(tx, ty) > f1) return std::nullopt;
    if (tx <= ty) c += sc, tx += dx;
    else r += sr, ty += dy;
    if (c < 0 || r < 0 || c >= g.columns || r >= g.rows) return std::nullopt;
  }
}

}  // namespace

std::optional<RayHit> QueryIndex::ray_tiles(Vector origin, Vector travel) const {
  std::optional<RayHit> best;
  const auto layers = tiles_->layers();
  for (std::size_t i = 0; i < layers.size(); ++i) keep_first(best, ray_layer(layers[i], tile_origin_[i], origin, travel));
  return best;
}

std::vector<TileCellHit> QueryIndex::cells_meeting(Vector lo, Vector hi) const {
  require_region(lo, hi, "cells_meeting");
  std::vector<TileCellHit> out;
  const auto layers = tiles_->layers();
  for (std::size_t i = 0; i < layers.size(); ++i) {
    const TileGrid& g = layers[i].grid();
    const CellRange cr = cells_of(g, lo - tile_origin_[i], hi - tile_origin_[i]);
    for (int r = cr.r0; r <= cr.r1; ++r)
      for (int c = cr.c0; c <= cr.c1; ++c)
        if (const Tile t = g.at(c, r); t != Tile::empty) out.push_back({layers[i].body(), {c, r, t}});
  }
  return out;
}

std::optional<RayHit> QueryIndex::test_all(Vector origin, Vector travel) const {
  std::optional<RayHit> best;
  for (std::size_t i = 0; i < ids_.size(); ++i)
    keep_first(best, ray_hit(origin, travel, ids_[i], position_[i], size_[i]));
  return best;
}

// The ray cut into pieces at most a cell long on each axis, in order; each
// piece's box (grown by a slack) asks the grid for the bodies near it, which
// get the exact test. A body the grid has not reported by the end of a piece
// lies more than the slack away from the ray so far, so the ray enters it
// after that piece: once a hit lies within the pieces walked, it is the
// first. (Ties: a hit at the piece's very end does not stop the walk.)
std::optional<RayHit> QueryIndex::walk_grid(Vector origin, Vector travel) const {
  std::optional<RayHit> best;
  const auto test = [&](std::uint32_t i) {
    keep_first(best, ray_hit(origin, travel, ids_[i], position_[i], size_[i]));
  };
  const Bounds& b = bounds_;
  // Points along the ray are computed to a few ulps of these coordinates;
  // 2^-32 of them is far more, and still a tiny fraction of a pixel.
  const double slack = (std::abs(origin.x) + std::abs(origin.y) + std::max(std::abs(b.x0), std::abs(b.x1)) +
                        std::max(std::abs(b.y0), std::abs(b.y1))) * 0x1p-32 + 0x1p-32;
  // Only the part [f0, f1] of the ray within the bodies' bounds can hit.
  const Interval cx = clip(origin.x, travel.x, b.x0 - slack, b.x1 + slack);
  const Interval cy = clip(origin.y, travel.y, b.y0 - slack, b.y1 + slack);
  const double f0 = std::max({0.0, cx.lo, cy.lo}), f1 = std::min({1.0, cx.hi, cy.hi});
  if (!(f0 <= f1)) return best;
  const double span = (f1 - f0) * std::max(std::abs(travel.x), std::abs(travel.y));
  const double pieces = std::max(1.0, std::ceil(span / grid_.cell_size()));
  // More pieces than cells walks cells again and again (bodies in a line far
  // from a huge one): testing every body is then cheaper.
  if (!(pieces <= 2.0 * static_cast<double>(grid_.cells()) + 64.0)) return test_all(origin, travel);
  const int n = static_cast<int>(pieces);
  for (int c = 0; c < n; ++c) {
    const double fa = f0 + (f1 - f0) * c / n;
    const double fb = c + 1 == n ? f1 : f0 + (f1 - f0) * (c + 1) / n;
    const Vector pa = origin + fa * travel, pb = origin + fb * travel;
    grid_.query(FloatBox::outward(std::min(pa.x, pb.x) - slack, std::min(pa.y, pb.y) - slack,
                              std::max(pa.x, pb.x) + slack, std::max(pa.y, pb.y) + slack),
                test);
    if (best && best->fraction < fb) break;
  }
  return best;
}

std::vector<EntityId> QueryIndex::query_box(Vector lo, Vector hi) const {
  require_region(lo, hi, "query_box");
  std::vector<EntityId> out;
  // The grid's closed float boxes hold the open ones: it reports a superset.
  grid_.query(FloatBox::outward(lo.x, lo.y, hi.x, hi.y), [&](std::uint32_t i) {
    if (overlaps_region(position_[i], size_[i], lo, hi)) out.push_back(ids_[i]);
  });
  if (!tiles_->empty())
    for (const TileCellHit& h : cells_meeting(lo, hi))
      if (out.empty() || out.back() != h.layer) out.push_back(h.layer);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::vector<EntityId> QueryIndex::query_point(Vector p) const {
  require_finite(p, "query_point's point");
  return query_box(p, p);
}

std::optional<RayHit> ray_cast(const World& w, Vector origin, Vector direction, double max_distance) {
  return QueryIndex(w).ray_cast(origin, direction, max_distance);
}

std::vector<EntityId> query_box(const World& w, Vector lo, Vector hi) { return QueryIndex(w).query_box(lo, hi); }

std::vector<EntityId> query_point(const World& w, Vector p) { return QueryIndex(w).query_point(p); }

}  // namespace physics
