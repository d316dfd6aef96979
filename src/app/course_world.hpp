// The sheet's main program (`--course`): the worlds of the sheet's scenes
// built by the course's own functions (src/course/game.cpp: Game::init_walls,
// red_block_with_velocity, red_block_with_force, init_scene, with
// Block::make), not from their descriptions. In the exercise mode these are
// the student's answers, so `make exercise-run Q=4` shows their red block
// drifting. tests/test_course_world.cpp checks both builds agree to the bit.
#pragma once

#include <span>
#include <string_view>
#include <vector>

#include "scene/scene.hpp"

namespace physics::CourseWorld {

// The built-in scenes the course builds: walls, drift, impulse, bounce, many.
std::span<const std::string_view> scenes();
bool builds(std::string_view scene);

// The world of built-in scene s (one of scenes(), after the command line's
// overrides: its parameters, systems, walls' restitution and seed), made by
// the course's functions; any other scene, from its description (`bodies`,
// from expand: make_world), which the window's scene keys switch to.
World make(const SceneSpec& s, const std::vector<Body>& bodies, bool with_draw);

}  // namespace physics::CourseWorld
