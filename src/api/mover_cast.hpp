// The mover's box cast (api/mover.cpp): what a box moving in a straight
// line meets first, among a world's colliding bodies and its tile layers'
// strips (engine/tiles.hpp: runs of exposed faces, so a seam between two
// tiles is no face to hit). The candidates come from the engine's queries
// (engine/query.hpp: a QueryIndex built once per call, asked for the box
// around each sweep) and from the layers' strip index; each gets the exact
// Minkowski sweep of CCD and rays (engine/sweep.hpp).
//
// Rules: a box already overlapping something does not hit it (as a ray
// ignores the body it starts in); touching and moving into it is a hit at
// time 0; a face is within `snap` px counts as touching (rounding of a
// position put on a face cannot leave it a hair inside and let it pass);
// when both axes are entered at once (a corner, exactly), the hit is the
// y one, so a box landing on a seam between two blocks lands. A one-way
// face stops only a box entering it through that face.
#pragma once

#include <optional>
#include <vector>

#include "engine/query.hpp"
#include "engine/world.hpp"

namespace physics::api {

// Where things will be after the coming step, for a mover moving in it.
struct Obstacle {
  EntityId body;    // the body, or the tile layer's body
  Vector position;  // top-left corner; a fixed body with a velocity: where the step will put it
  Rect size;
  Face one_way = Face::none;
  bool pushable = false;          // finite mass (the mover decides what it pushes)
  int column = -1, row = -1;      // a strip's first cell
  int columns = 0, rows = 0;      // a strip's extent in cells (0: a body)
  int cell = 0;                   // a strip's cell size
};

struct Cast {
  double time;     // in [0, 1] of the motion
  bool along_x;    // the face entered is an x face
  Vector normal;   // unit, pushes the box back out
  Obstacle what;
};

inline constexpr double cast_snap = 1e-7;  // px

class Obstacles {
 public:
  // What the box of body `mover` (its filter) meets in a step of dt ms.
  Obstacles(const World& w, EntityId mover, double dt);

  // The first thing the box at p of size r meets moving by d, `skip` aside
  // (a body the mover rides), one-way faces ignored if pass_one_way.
  std::optional<Cast> first(Vector p, Rect r, Vector d, EntityId skip, bool pass_one_way) const;
  // The fixed two-way obstacles the box overlaps by more than cast_snap.
  std::vector<Obstacle> overlapping(Vector p, Rect r) const;

 private:
  template <class F>
  void near(Vector lo, Vector hi, F&& f) const;
  Obstacle body(EntityId e) const;
  const World& w_;
  EntityId mover_;
  double dt_;
  QueryIndex index_;
  std::vector<EntityId> moving_;  // fixed bodies with a velocity: found by no query at where they will be
};

// The sweep of the box at p of size r by d against one obstacle.
std::optional<Cast> cast(Vector p, Rect r, Vector d, const Obstacle& o);

}  // namespace physics::api
