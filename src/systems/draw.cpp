#include "systems/draw.hpp"

#include <cmath>

namespace physics {

void Draw::update(const Components& c, Canvas& canvas) const {
  for (const EntityId e : entities_) {
    const Vector p = c.position[e];
    // Skip what cannot be drawn (NaN, or far outside int range) rather than
    // hand the canvas an undefined conversion.
    if (!(std::abs(p.x) < 1e9 && std::abs(p.y) < 1e9)) continue;
    canvas.fill_rect(p, c.box[e], c.color[e]);
    outline(p, c.box[e], c.color[e], canvas);
  }
}

Color outline_color(Color c) {
  const auto dark = [](std::uint8_t v) { return static_cast<std::uint8_t>(v * 11 / 20); };
  return {dark(c.r), dark(c.g), dark(c.b), c.a};
}

void outline(Vector p, Rect r, Color c, Canvas& canvas) {
  if (r.width < min_outlined || r.height < min_outlined) return;
  const Color o = outline_color(c);
  canvas.fill_rect(p, {r.width, 1}, o);
  canvas.fill_rect({p.x, p.y + r.height - 1}, {r.width, 1}, o);
  canvas.fill_rect({p.x, p.y + 1}, {1, r.height - 2}, o);
  canvas.fill_rect({p.x + r.width - 1, p.y + 1}, {1, r.height - 2}, o);
}

}  // namespace physics
