// A box mover (docs/api.md, "Movers"): move_and_slide moves a fixed body
// the game positions itself (a player, an enemy) by a velocity for one step,
// swept against every body and tile strip along its way, sliding along what
// it meets, riding the floor it stands on, pushing crates, and says where it
// ended: on the floor, on a wall, on a ceiling, and what it touched. Godot's
// CharacterBody2D.move_and_slide is the model, without its slope options.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "physics/physics.hpp"

namespace physics {

// grounded: hits are floors, walls or ceilings by their normal against
// up_direction (a platformer); floating: every hit is a wall (top-down).
enum class MotionMode : std::uint8_t { grounded, floating };
// What the mover keeps of its floor's velocity when it leaves that floor.
enum class PlatformOnLeave : std::uint8_t { add_velocity, add_upward_velocity, do_nothing };

struct MoverDef {
  MotionMode motion_mode = MotionMode::grounded;
  Vec2 up_direction{0.0, -1.0};  // one of (0, -1), (0, 1), (-1, 0), (1, 0); y grows down: (0, -1) is up
  double floor_snap_length = 1.0;  // px, in [0, 1e6]: a mover on a floor follows it down by up to this much
  int max_slides = 4;              // in [1, 64]: hits resolved in one call before it stops where it is
  bool slide_on_ceiling = true;    // false: a ceiling hit also stops the motion along it
  std::uint32_t platform_floor_layers = 0xFFFFFFFFu;  // categories of floors whose velocity carries the mover
  PlatformOnLeave platform_on_leave = PlatformOnLeave::add_velocity;
  std::uint32_t push_layers = 0xFFFFFFFFu;  // categories of finite-mass bodies it pushes (0: none)
  // mass·px/ms, in [0, inf]: the most impulse it gives one body in one call.
  double max_push_impulse = std::numeric_limits<double>::infinity();
  bool pass_one_way = false;  // one-way faces do not stop it (drop-through)
};
MoverDef default_mover_def();  // Godot's defaults: grounded, up (0, -1), snap 1 px, 4 slides; pushes everything

struct MoverHit {
  BodyId body;     // a body, or a tile layer (then column and row name the cell)
  Vec2 normal;     // unit, axis-aligned: pushes the mover away from it
  Vec2 point;      // the middle of the part of the face the mover touches
  int column = -1, row = -1;
  double impulse = 0.0;  // what the mover gave it (a pushed crate), along -normal
};

struct MoverResult {
  Vec2 velocity;  // the velocity less its parts into what it hit, plus the floor's on leaving it (platform_on_leave)
  Vec2 travel;    // px moved in the call, riding included
  bool on_floor = false, on_wall = false, on_ceiling = false;
  BodyId floor;          // what it stands on (null_body in the air)
  Vec2 floor_velocity;   // px/ms, the floor's
  Vec2 wall_normal;      // the last wall's, when on_wall
  std::vector<MoverHit> hits;  // in the order met
};

// Moves `mover` (a fixed body: mass fixed_mass; its velocity is set to 0, the
// call places it) by velocity · dt of its world, before step(): first by its
// floor's motion in the coming step (the floor of `last`, the previous call's
// result), then by its own with up to max_slides slides, then down onto a
// floor within floor_snap_length if it stood on one and is not moving up.
// What it hits is every colliding body whose filter meets its own (sensors
// aside) and every tile layer's cells, where the fixed bodies that move will
// be after the step; a finite-mass body in push_layers it hits, but not one
// it stands on, gets an impulse towards the mover's velocity (at most
// max_push_impulse). Throws Error on a bad def, a body that is not fixed, or
// a tile layer.
MoverResult move_and_slide(BodyId mover, Vec2 velocity, const MoverDef& def = default_mover_def(),
                           const MoverResult& last = {});

}  // namespace physics
