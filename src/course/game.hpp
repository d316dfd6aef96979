// The game (course: game.ml): the walls of question 1, the scene of question
// 9, and the frame the main program calls, in the sheet's order: Forces,
// Move, Collision, then Draw. The window and the command line are the
// application's (src/app/); nothing here needs SDL.
#pragma once

#include <cstdint>

#include "engine/world.hpp"
#include "course/entities/block.hpp"
#include "course/systems/draw.hpp"

namespace physics::Game {

inline constexpr int width = 800;  // px, the course's window
inline constexpr int height = 600;
inline constexpr int wall_thickness = 40;
inline constexpr int wall_count = 4;  // init_walls makes them first, in this number
inline constexpr Color wall_blue{0, 0, 255, 255};  // horizontal walls
inline constexpr Color wall_black{0, 0, 0, 255};   // vertical walls
inline constexpr Color red{255, 0, 0, 255};        // the block of questions 4, 5 and 9

// Random colours (drawn in [40, 220] per channel) stay at least this far
// (RGB distance) from the walls' blue and black: one too close is mirrored
// in [40, 220] (c -> 260 - c per channel: dark turns pale, blue turns
// yellow), after the draw, so the generator consumes the same numbers.
inline constexpr int min_wall_color_distance = 150;
inline Color away_from_walls(Color c) {
  const auto near = [&](Color w) {
    const auto d = [](int a, int b) { return (a - b) * (a - b); };
    return d(c.r, w.r) + d(c.g, w.g) + d(c.b, w.b) < min_wall_color_distance * min_wall_color_distance;
  };
  if (!near(wall_blue) && !near(wall_black)) return c;
  const auto mirror = [](std::uint8_t v) { return static_cast<std::uint8_t>(260 - v); };
  return {mirror(c.r), mirror(c.g), mirror(c.b), c.a};
}

// Q1. Four walls of infinite mass on the edges of a width × height screen:
// top and bottom blue and full width, left and right black and between them,
// 40 px thick, not overlapping. Scenes with `walls: true` are built with it.
void init_walls(World& w, int width = Game::width, int height = Game::height, double restitution = 1.0);

// The red block of questions 4, 5 and 9: 40×40 at (100, 100), mass 10.
Block::t red_block(World& w);
// Q4. The red block with the velocity (0.25, 0.25): with Move alone it
// drifts through the walls (built-in scene `drift`).
Block::t red_block_with_velocity(World& w);
// Q5. The red block set going by the force (0.25, 0.25) on the first frame
// instead: the same motion (built-in scene `impulse`).
Block::t red_block_with_force(World& w);

// Q9, the built-in scene `many` (the default): the walls, the red block set
// going by the force (0.25, 0.25), and ten squares with a random side in
// [20, 40], a random mass in [1, 20) and a random initial impulse in
// [0, 0.25) per axis, on a grid so that nothing overlaps.
void init_scene(World& w, std::uint64_t seed = 42);

// One frame of physics (the sheet: "call update in the main program"):
// Forces, Move, Collision, each `substeps` times with dt / substeps: the
// engine's frame (engine/step.hpp, run_frame) running the course's systems.
// The public API's step runs the engine's copies of them instead, to the bit.
void step(World& w);

// Draw's part of the frame, on whatever canvas the front end gives.
void draw(const World& w, Canvas& canvas);

}  // namespace physics::Game
