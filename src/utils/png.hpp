// Minimal PNG writer (RGB, 8 bits, stored deflate blocks): enough for
// screenshots without pulling in SDL2_image or libpng.
#pragma once

#include <cstdint>
#include <span>
#include <string>

namespace physics::Png {

// `rgb` holds width*height*3 bytes, rows top to bottom. Returns false on I/O error.
bool write_rgb(const std::string& path, int width, int height, std::span<const std::uint8_t> rgb);

}  // namespace physics::Png
