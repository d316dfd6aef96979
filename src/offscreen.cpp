#include "offscreen.hpp"

#include <algorithm>
#include <cmath>

#include "utils/png.hpp"

namespace physics::Offscreen {

std::vector<std::uint8_t> render(const World& w, int width, int height) {
  std::vector<std::uint8_t> rgb(static_cast<std::size_t>(width) * height * 3, 255);
  if (!w.systems.draw) return rgb;
  const Components& c = w.components;
  for (const EntityId e : w.systems.draw->entities()) {
    const Vector p = c.position[e];
    const Rect r = c.box[e];
    if (!(std::abs(p.x) < 1e9 && std::abs(p.y) < 1e9)) continue;  // NaN or far away
    // Pixel (i, j) has its centre at (i + 0.5, j + 0.5).
    const auto first = [](double lo) { return static_cast<long>(std::ceil(lo - 0.5)); };
    const long x0 = std::max(0L, first(p.x)), x1 = std::min<long>(width, first(p.x + r.width));
    const long y0 = std::max(0L, first(p.y)), y1 = std::min<long>(height, first(p.y + r.height));
    const Color col = c.color[e];
    for (long y = y0; y < y1; ++y)
      for (long x = x0; x < x1; ++x) {
        std::uint8_t* px = &rgb[(static_cast<std::size_t>(y) * width + x) * 3];
        px[0] = col.r, px[1] = col.g, px[2] = col.b;
      }
  }
  return rgb;
}

bool screenshot(const World& w, int width, int height, const std::string& path) {
  return Png::write_rgb(path, width, height, render(w, width, height));
}

}  // namespace physics::Offscreen
