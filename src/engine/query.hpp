// Queries over a world's bodies, as a game asks them: the first body along a
// ray (line of sight, a bullet, the testbed's right drag), the bodies in a
// box (an explosion's reach, room to spawn), the bodies under a point (the
// body under the mouse).
//
// Bodies: the Collision system's (what can be hit is what collides; walls
// included); in a world without Collision, every entity. A body is its box
// `box[e]` at `position[e]` (top-left corner, y down).
//
// One rule for "inside", the engine's: interiors are open, as in the
// collision test (Rect::has_origin, Q7, where touching boxes do not
// collide). So a region that only touches a body does not overlap it, a
// point on a body's edge is in no body, and query_point(p) is query_box(p, p).
//
// Rays use the sweep of CCD (engine/sweep.hpp): a ray is a point moving from
// `origin` by `max_distance` along `direction`, cast against the Minkowski
// difference of each body and that point, so a body is hit when the segment
// enters its open interior: grazing an edge or passing exactly through a
// corner is no hit. A ray starting inside a body (or on its border, leaving
// it) ignores that body, as Box2D does: it reports the first body it enters.
// Ties: the lowest id among bodies entered at the same fraction; the face is
// the x one when both are entered at once (as in CCD).
//
// Speed: a QueryIndex puts the bodies' boxes in the broad phase's uniform
// grid (engine/broadphase.hpp), O(n) once; then a box or point query visits
// the few cells around it and a ray walks the cells along it, stopping at the
// first hit. The grid only chooses which bodies get the exact test, so the
// answers are exactly those of testing every body (tests/test_query.cpp).
// The world's own broad phase is not reused: its grid holds the boxes of the
// last pass, grown and possibly left behind since, not where bodies are now.
// The free functions build an index per call (O(n) each): for many queries
// on one frame, build a QueryIndex once.
//
// Bad input: a NaN or infinite coordinate, a negative max_distance, or lo >
// hi on an axis throws std::invalid_argument. A zero direction or a zero
// max_distance hits nothing (std::nullopt).
#pragma once

#include <optional>
#include <vector>

#include "engine/broadphase.hpp"
#include "engine/world.hpp"

namespace physics {

struct RayHit {
  EntityId body;    // a body, or a tile layer's body (then `column`, `row` name the cell)
  Vector point;     // where the ray enters the body's box, on its boundary
  Vector normal;    // the unit outward normal of the face entered: (±1, 0) or (0, ±1)
  double fraction;  // in [0, 1]: how far along the ray, in units of max_distance
  int column = -1, row = -1;  // the cell entered, when `body` is a tile layer
};

// Tile layers (engine/tiles.hpp) are queried cell by cell with the same
// rules: a ray enters a solid cell by any face and a one-way cell by its top
// face going down; the solid cells it starts in, and those it crosses before
// it first leaves the solid, are ignored (a ray from inside a wall reports
// what lies beyond the wall); a box or a point meets the non-empty cells
// whose open box it meets. The layer is listed by query_box / query_point
// when it meets one; cells_meeting names them.
struct TileCellHit {
  EntityId layer;
  TileCell cell;
};

// A snapshot of the bodies' boxes for queries: answers are about the world
// as it was when the index was built.
class QueryIndex {
 public:
  explicit QueryIndex(const World& w);

  std::optional<RayHit> ray_cast(Vector origin, Vector direction, double max_distance) const;
  // Bodies whose open box meets the open region (lo, hi), in increasing id order.
  std::vector<EntityId> query_box(Vector lo, Vector hi) const;
  // Bodies whose open box contains p, in increasing id order.
  std::vector<EntityId> query_point(Vector p) const;
  // The non-empty cells of every layer whose open box meets the open region (lo, hi): layer, then row, then column.
  std::vector<TileCellHit> cells_meeting(Vector lo, Vector hi) const;

 private:
  std::optional<RayHit> ray_tiles(Vector origin, Vector travel) const;
  std::optional<RayHit> walk_grid(Vector origin, Vector travel) const;
  std::optional<RayHit> test_all(Vector origin, Vector travel) const;

  std::vector<EntityId> ids_;     // by rank (the grid's index)
  std::vector<Vector> position_;  // by rank, copied: the snapshot
  std::vector<Rect> size_;        // by rank
  UniformGrid grid_;
  BroadPhase::Bounds bounds_{};   // around every box the grid holds, when finite
  bool finite_bounds_ = false;    // false: no body, or one beyond float range (then rays test every body)
  // The tile layers, read in place (their cells never change): the index must not outlive its world.
  const TileSet* tiles_;
  std::vector<Vector> tile_origin_;  // by layer, copied
};

std::optional<RayHit> ray_cast(const World& w, Vector origin, Vector direction, double max_distance);
std::vector<EntityId> query_box(const World& w, Vector lo, Vector hi);
std::vector<EntityId> query_point(const World& w, Vector p);

// The pieces, public so that tests can check the index against testing every
// body with them.
//
// The bodies queries look at (see above), in registration order.
std::vector<EntityId> query_bodies(const World& w);
// The whole move of a ray: max_distance along the unit direction. Validates
// (see above); {0, 0} for a zero direction or distance.
Vector ray_travel(Vector origin, Vector direction, double max_distance);
// The exact tests of one body at p of size r.
std::optional<RayHit> ray_hit(Vector origin, Vector travel, EntityId body, Vector p, Rect r);
bool overlaps_region(Vector p, Rect r, Vector lo, Vector hi);
bool contains_point(Vector p, Rect r, Vector q);

}  // namespace physics
