// Tiled's JSON map format (.tmj, https://doc.mapeditor.org/en/stable/reference/json-map-format/)
// read as a scene (map.hpp; the rules in docs/scenes.md, "Maps from Tiled and LDtk").
#pragma once

#include <string>
#include <string_view>

#include "scene/scene.hpp"

namespace physics {

// The map's scene, validated: its tile layers, its object layers' rectangles
// as blocks, its custom properties as the world's keys; the world the map's
// size. External tilesets (.tsj) are read from the map's folder. Throws
// SceneError "path: problem" for what it does not support.
SceneSpec read_tiled(std::string_view text, const std::string& path);

}  // namespace physics
