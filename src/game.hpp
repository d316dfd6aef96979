// The game (course: game.ml): the walls of question 1, the scene of question 9,
// and the main loop. The loop's window half lives behind window.hpp; what is
// here builds and runs without SDL, so the tests use it directly.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <string>

#include "world.hpp"

namespace physics::Game {

inline constexpr int width = 800;   // px, the course's window
inline constexpr int height = 600;
inline constexpr int wall_thickness = 40;
inline constexpr Color wall_blue{0, 0, 255, 255};    // horizontal walls
inline constexpr Color wall_black{0, 0, 0, 255};     // vertical walls

// Q1. Four walls of infinite mass on the edges of a width × height screen:
// top and bottom blue and full width, left and right black and between them,
// 40 px thick, not overlapping.
void init_walls(World& w, int width = Game::width, int height = Game::height);

// Q9. The walls, the red block of questions 3-4 (40×40, mass 10, initial force
// (0.25, 0.25)) and ten squares with a random side in [20, 40], a random mass
// in [1, 20) and a random initial impulse in [0, 0.25) per axis, on a grid so
// that nothing overlaps at start.
void init_scene(World& w, std::uint64_t seed = 42);

// Runs `frames` physics frames without any window and prints a summary.
struct Summary {
  std::int64_t frames = 0;
  std::size_t bodies = 0, mobile = 0;
  double ke_start = 0, ke_end = 0;
  Vector p_start{}, p_end{};
};
Summary run_headless(World& w, std::int64_t frames);
void print_summary(std::ostream& out, const World& w, const Summary& s, const std::string& why);

// The HUD line: fps, physics ms/step, body count, kinetic energy, momentum.
std::string hud_line(const World& w, double fps);

}  // namespace physics::Game
