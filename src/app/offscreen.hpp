// An offscreen picture of a world without SDL, for `--headless --screenshot`:
// a white background and every block registered with Draw filled in its
// colour, as the window's Draw system paints them (or in another drawing
// style, through the same app/style.hpp as the window) (no HUD: no font is loaded
// headless). Part of the physics library.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "scene/scene.hpp"
#include "engine/world.hpp"

namespace physics::Offscreen {

// width*height*3 bytes, RGB, rows top to bottom. A pixel belongs to a block
// when its centre lies inside the block's box.
std::vector<std::uint8_t> render(const World& w, int width, int height);
// The same in a drawing style (app/style.hpp); `roles` by entity id, for sprite.
std::vector<std::uint8_t> render(const World& w, int width, int height, Style style, std::span<const BlockRole> roles);

// render() saved as PNG; false on I/O error.
bool screenshot(const World& w, int width, int height, const std::string& path, Style style = Style::plain,
                std::span<const BlockRole> roles = {});

}  // namespace physics::Offscreen
