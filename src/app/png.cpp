#include "app/png.hpp"

// stb_image_write rather than libpng: one call, no png_struct/png_info pair,
// no setjmp error handling, and header-only (this file compiles its
// implementation, private to it), so nothing to add to any link line: the
// game, the tests, the tools, the bench and the fuzzer link libphysics as
// before. Debian's libstb-dev also ships libstb.so; we don't need it.
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

#include <fstream>

namespace physics::Png {

bool write_rgb(const std::string& path, int width, int height, std::span<const std::uint8_t> rgb) {
  if (width <= 0 || height <= 0 || rgb.size() != static_cast<std::size_t>(width) * height * 3) return false;
  // Encoded in memory, then written and flushed here: stbi_write_png does not
  // check its fwrite, so a full disk gave a broken file and success.
  int size = 0;
  unsigned char* png = stbi_write_png_to_mem(rgb.data(), width * 3, width, height, 3, &size);
  if (!png) return false;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(png), size);
  STBIW_FREE(png);
  return static_cast<bool>(out.flush());
}

}  // namespace physics::Png
