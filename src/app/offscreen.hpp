// An offscreen picture of a world without SDL, for `--headless --screenshot`:
// a white background and every block registered with Draw filled in its
// colour, as the window's Draw system paints them (no HUD: no font is loaded
// headless). Part of the physics library.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "engine/world.hpp"

namespace physics::Offscreen {

// width*height*3 bytes, RGB, rows top to bottom. A pixel belongs to a block
// when its centre lies inside the block's box.
std::vector<std::uint8_t> render(const World& w, int width, int height);

// render() saved as PNG; false on I/O error.
bool screenshot(const World& w, int width, int height, const std::string& path);

}  // namespace physics::Offscreen
