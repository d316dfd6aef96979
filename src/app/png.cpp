#include "app/png.hpp"

// stb_image_write rather than libpng: one call, no png_struct/png_info pair,
// no setjmp error handling, and header-only (this file compiles its
// implementation, private to it), so nothing to add to any link line: the
// game, the tests, the tools, the bench and the fuzzer link libphysics as
// before. Debian's libstb-dev also ships libstb.so; we don't need it.
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

namespace physics::Png {

bool write_rgb(const std::string& path, int width, int height, std::span<const std::uint8_t> rgb) {
  if (width <= 0 || height <= 0 || rgb.size() != static_cast<std::size_t>(width) * height * 3) return false;
  return stbi_write_png(path.c_str(), width, height, 3, rgb.data(), width * 3) != 0;
}

}  // namespace physics::Png
