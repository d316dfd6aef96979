// LDtk's JSON project format (.ldtk, https://ldtk.io/json/) read as a scene
// (map.hpp; the rules in docs/scenes.md, "Maps from Tiled and LDtk").
#pragma once

#include <string>
#include <string_view>

#include "scene/scene.hpp"

namespace physics {

// The project's first level as a scene, validated: its IntGrid layers as tile
// layers, its entities as blocks, its fields as the world's keys; the world
// the level's size. Throws SceneError "path: problem" for what it does not support.
SceneSpec read_ldtk(std::string_view text, const std::string& path);

}  // namespace physics
