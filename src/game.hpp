// The game (course: game.ml): the walls of question 1, the scene of question 9,
// and the headless run. The command line is cli.hpp; the window loop and
// main() are in game.cpp behind GAME_NO_MAIN, with the SDL front end in
// window.hpp. What this header declares builds and runs without SDL.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <string>

#include "scene.hpp"
#include "world.hpp"

namespace physics::Game {

inline constexpr int width = default_width;   // px, the course's window
inline constexpr int height = default_height;
inline constexpr int wall_thickness = physics::wall_thickness;
inline constexpr Color wall_blue = physics::wall_blue;    // horizontal walls
inline constexpr Color wall_black = physics::wall_black;  // vertical walls

// Q1. Four walls of infinite mass on the edges of a width × height screen:
// top and bottom blue and full width, left and right black and between them,
// 40 px thick, not overlapping. Scenes with `walls: true` are built with it.
void init_walls(World& w, int width = Game::width, int height = Game::height, double restitution = 1.0);

// Q9, the built-in scene `many` (the default): the walls, the red block of
// questions 3-4 (40×40, mass 10, initial force (0.25, 0.25)) and ten squares
// with a random side in [20, 40], a random mass in [1, 20) and a random
// initial impulse in [0, 0.25) per axis, on a grid so that nothing overlaps.
void init_scene(World& w, std::uint64_t seed = 42);

// Runs `frames` physics frames without any window and prints a summary.
struct Summary {
  std::int64_t frames = 0;
  std::size_t bodies = 0, mobile = 0;
  double ke_start = 0, ke_end = 0;
  Vector p_start{}, p_end{};
};
// `after_step` (may be empty) sees the world after every frame: the trace.
Summary run_headless(World& w, std::int64_t frames);
template <class AfterStep>
Summary run_headless(World& w, std::int64_t frames, AfterStep&& after_step);
void print_summary(std::ostream& out, const World& w, const Summary& s, const std::string& why,
                   const std::string& scene = "");

// "forces 0.0012  move off ...": physics ms per step of each system, `off`
// for the systems the scene left out.
std::string system_times(const World& w);

// The HUD line: fps, physics ms/step, body count, kinetic energy, momentum.
std::string hud_line(const World& w, double fps);

template <class AfterStep>
Summary run_headless(World& w, std::int64_t frames, AfterStep&& after_step) {
  Summary s;
  s.bodies = w.components.size();
  s.mobile = w.finite_bodies();
  for (std::int64_t f = 0; f < frames; ++f) {
    w.step();
    after_step(static_cast<const World&>(w));
    // Bodies start at rest with their first impulse pending in sum_forces;
    // the motion they start with is the one after the first frame.
    if (f == 0) {
      s.ke_start = w.kinetic_energy();
      s.p_start = w.momentum();
    }
  }
  s.frames = frames;
  s.ke_end = w.kinetic_energy();
  s.p_end = w.momentum();
  return s;
}

}  // namespace physics::Game
