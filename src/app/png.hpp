// PNG files of the screenshots (`--screenshot FILE.png`, headless and in the
// window), written by stb_image_write from Debian's libstb-dev. Part of the
// application layer: the physics core neither draws nor writes pictures.
#pragma once

#include <cstdint>
#include <span>
#include <string>

namespace physics::Png {

// `rgb` holds width*height*3 bytes, rows top to bottom. Returns false on I/O error.
bool write_rgb(const std::string& path, int width, int height, std::span<const std::uint8_t> rgb);

}  // namespace physics::Png
