// The built-in scenes, one per step of the sheet and a few more. Each is also
// a file in scenes/ (NAME.json) that reproduces it exactly (tested).
#pragma once

#include <span>
#include <string_view>

#include "scene/scene.hpp"

namespace physics {

// In the order of the testbed's keys 1-9: walls, drift, impulse, bounce,
// many, cradle, gas, stack.
std::span<const SceneSpec> builtin_scenes();

// nullptr when there is no built-in scene of that name.
const SceneSpec* find_builtin(std::string_view name);

inline constexpr std::string_view default_scene = "many";

}  // namespace physics
